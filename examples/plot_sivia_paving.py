"""
SIVIA: bracketing an exact set by a paving
===========================================

The user guide's interval example (:doc:`/user_guide/interval`), the set of [LJMW97,
Appendix A]: ``{x² + y² ≤ 1, 2x² + y² ≥ 1}``. Inner boxes (red) are proven inside,
boundary boxes (yellow) are undecided, outside boxes (blue) are proven outside; the area is
bracketed around ``π (1 − 1/√2) = 0.9202``.
"""

import matplotlib.pyplot as plt
import numpy as np

from optbound import interval as iv

p = iv.sivia(
    lambda x, y: (x**2 + y**2, 2 * x**2 + y**2),  # f(*coords) -> p outputs
    [[-np.inf, 1], [1, np.inf]],  # Y: one row per output
    [[-2.5, 2.5], [-2, 2]],  # X0
    eps=0.01,
)
lo, hi = p.volume_bounds()
print(f"area in [{lo:.4f}, {hi:.4f}] around {np.pi * (1 - 1 / np.sqrt(2)):.4f}")
print(len(p.inner), "inner,", len(p.boundary), "boundary boxes;", len(p.components()), "components")

fig, ax = plt.subplots(figsize=(7, 5.6))
p.plot(ax=ax)
ax.set_title("SIVIA paving of the LJMW97 Appendix A set, eps = 0.01")
plt.show()
