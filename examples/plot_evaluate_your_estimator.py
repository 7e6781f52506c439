"""
Evaluate your own estimator
===========================

The tutorial :doc:`/tutorials/evaluate_your_estimator` as a script: three estimators for the
``strip`` problems of the tiny suite (a sound but loose box, the optimal ellipsoid of
[HS96], and a deliberately unsound one) audited by ``optbound.evaluate``: size against the
exact set and the best bounds, and soundness proven or refuted at a point of the true set.
"""

import matplotlib.pyplot as plt
import numpy as np

from optbound import Box, analytic, evaluate, problems

suite = problems.suite("tiny", families=["strip"])


def prior_box(problem):
    """The prior ellipsoid's bounding box, widened by a relative 1e-12: loose, but sound."""
    E = problem.data["ellipsoid"]
    half = np.sqrt(np.diag(E.shape)) * (1 + 1e-12)
    return Box(E.center - half, E.center + half)


def fused_ellipsoid(problem):
    """The volume-optimal ellipsoid of HS96's ellipsoid ∩ strip update."""
    return analytic.intersect_strip(problem.data["ellipsoid"], problem.data["strip"]).ellipsoid


def too_small(problem):
    """The same ellipsoid with every semi-axis shrunk by 10 %: NOT a bound."""
    return fused_ellipsoid(problem).scaled(0.9)


results = {f.__name__: evaluate(f, suite) for f in (prior_box, fused_ellipsoid, too_small)}
for name, result in results.items():
    print(name, [row["soundness"].split(" at ")[0] for row in result.rows])

# %%
# The unsound estimator is refuted: the figure marks the point of the true set it excludes.
results["too_small"].figure()
plt.show()
