"""
BH: pseudo-ellipsoids for relative-bearing localization
=======================================================

The user guide's pseudo-ellipsoid example (:doc:`/user_guide/localization`): the BH filter
with the liftings L = 4 and L = 8 [BH, eqs. (22)-(23)] on the Sect. V geometry, each bound
*proven* to contain the exact set paved from the angle constraints.
"""

import matplotlib.pyplot as plt
import numpy as np

from optbound.localization import relative_bearing as rb

landmarks = np.array([[0.0, 1.0], [1.0, 1.0], [-1.0, 0.0]])  # BH Sect. V
pairs, gammas, eps = [(2, 0), (0, 1), (1, 2)], np.radians([90.0, 45.0, -135.0]), np.radians(4.0)
data = rb.measurements(landmarks, pairs, gammas, eps)
box = rb.prior_box(data)
exact = rb.exact_paving(landmarks, pairs, gammas, eps, np.stack([box.lo, box.hi], 1), 0.004)
bounds = {}
for order in (1, 2):
    bound = rb.localize(landmarks, pairs, gammas, eps, order=order).bound
    proof = rb.certify_contains(bound, data, exact)
    lo, hi = bound.area_bounds(0.004)
    bounds[bound.lift.size] = bound
    print(f"L = {bound.lift.size}: area in [{lo:.4f}, {hi:.4f}], proven {proof.proven}")
print("exact area in [{:.4f}, {:.4f}]".format(*exact.volume_bounds()))

fig, ax = plt.subplots(figsize=(6, 5))
exact.plot(ax=ax, show_outside=False)
for (size, bound), color in zip(bounds.items(), ("C0", "C3"), strict=True):
    for k, line in enumerate(bound.boundary(X0=box)):
        ax.plot(*line.T, color=color, lw=2, label=f"L = {size}" if k == 0 else None)
hull = exact.hull()
pad = 0.6 * (hull.hi - hull.lo)
ax.set_xlim(hull.lo[0] - pad[0], hull.hi[0] + pad[0])
ax.set_ylim(hull.lo[1] - pad[1], hull.hi[1] + pad[1])
ax.set_aspect("equal")
ax.legend()
ax.set_title("exact set (paving) and the two BH pseudo-ellipsoids")
plt.show()
