"""
Certified SDP references and gap metrics
========================================

The user guide's optimal example (:doc:`/user_guide/optimal`): the best ellipsoid containing
an ellipse ∩ strip ∩ half-plane ∩ outside of a disc, certified and bracketed by a lower bound
on the optimum over all ellipsoids, then the gap of an analytic bound to its optimum.
"""

import matplotlib.pyplot as plt
import numpy as np

import optbound as ob
from optbound import analytic, compare, interval, optimal

E = ob.Ellipsoid([0.0, 0.0], np.diag([4.0, 1.0]))
S = ob.Strip.from_bounds([1.0, 1.0], -0.5, 1.5)  # -0.5 <= x + y <= 1.5
H = ob.Halfspace([0.0, 1.0], 0.6)  # y <= 0.6
Q = ob.QuadraticSet(np.diag([-1.0, -1.0, 0.25]))  # outside the disc of radius 1/2
r = optimal.outer_ellipsoid([E, S, H, Q], objective="volume", lower_bound=True, rng=0)
print(r.status, "certified:", r.certified, f"inflation - 1: {r.inflation - 1:.1e}")
print(f"optimality bracket: optimum in [{r.lower_bound:.4f}, {r.objective:.4f}]")

a = analytic.intersect_strip(E, S).ellipsoid  # HS96 on E ∩ S alone
s = optimal.outer_ellipsoid([E, S])
print(f"analytic / SDP volume on E ∩ S: {compare.volume_ratio(a, s.ellipsoid):.6f}")

# %%
# The set and its certified outer ellipse.
exact = interval.pave(
    [
        lambda x, y: x**2 / 4 + y**2 <= 1,
        lambda x, y: abs(x + y - 0.5) <= 1,
        lambda x, y: y <= 0.6,
        lambda x, y: x**2 + y**2 >= 0.25,
    ],
    [[-2.2, 2.2], [-1.2, 1.2]],
    0.02,
)
fig, ax = plt.subplots(figsize=(7, 4))
exact.plot(ax=ax)
ax.plot(*E.boundary().T, "k--", label="E")
ax.plot(*r.ellipsoid.boundary().T, "C2-", lw=2, label="certified optimum of E ∩ S ∩ H ∩ Q")
ax.set_aspect("equal")
ax.legend(loc="lower left", fontsize=8)
plt.show()
