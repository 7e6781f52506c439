"""
HS96: the landmark solver and the guaranteed pose set
=====================================================

The user guide's example of angle-measurement localization (:doc:`/user_guide/localization`):
the closed-form solver of [HS96, eqs. (5)-(6)] is exact on noise-free bearings, and
``pose_paving`` paves the guaranteed (x, y, ψ) set for bounded angle and landmark errors
[HS96, eq. (2)].
"""

import matplotlib.pyplot as plt
import numpy as np

from optbound.localization.landmarks import linear_position, pose_paving

L = np.array([[5.0, 0.0], [0.0, 4.0], [-4.0, 1.0], [-1.0, -5.0]])
pose = np.array([0.4, -0.3, 0.2])
alphas = np.arctan2(L[:, 1] - pose[1], L[:, 0] - pose[0]) - pose[2]
x, y, psi = linear_position(L, alphas)  # exact on noise-free bearings
paving = pose_paving(L, alphas, delta_alpha=1e-3, landmark_shapes=np.eye(2) * 0.01**2)
hull = paving.hull()  # guaranteed box of (x, y, psi)
assert np.allclose([x, y, psi], pose) and np.all(hull.lo <= pose) and np.all(pose <= hull.hi)
print("solver:", np.round([x, y, psi], 12))
print("guaranteed box:", np.round(hull.lo, 4), np.round(hull.hi, 4))

fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(11, 4.5))
ax0.plot(*L.T, "ks", label="landmarks")
ax0.plot(*pose[:2], "C3o", label="robot")
for lm in L:
    ax0.plot([pose[0], lm[0]], [pose[1], lm[1]], "C0-", lw=0.6)
ax0.set_aspect("equal")
ax0.legend(fontsize=8)
ax0.set_title("bearings to four landmarks")
paving.plot(ax=ax1, dims=(0, 1))
ax1.plot(*pose[:2], "C3+", ms=12)
ax1.set_title("guaranteed pose set, projected on (x, y)")
plt.show()
