"""
LJMW97 / KJWM00: sonar localization by set inversion
====================================================

The user guide's sonar example (:doc:`/user_guide/localization`): four sonars in a triangular
room, no data association; the set of consistent poses has several connected components, each
with its association hypothesis [LJMW97, Sect. 4].
"""

import matplotlib.pyplot as plt
import numpy as np

from optbound.localization.sonar import localize, simulate_ranges
from optbound.scenarios import rooms

world, sonars = rooms.TRIANGLE, rooms.triangle_sonars()  # 4 sonars, +-12 deg, 2 %
truth = rooms.TRIANGLE_POSE  # (-2 m, 3 m, 0 rad)
d = simulate_ranges(world, sonars, truth)
paving = localize(world, sonars, d, [[-10, 10], [-10, 10], [-np.pi, np.pi]], 0.04)
components = paving.components()
print(len(components), "components; hypothesis of the first:", components[0].hypothesis)
lo, hi = components[0].hull().lo, components[0].hull().hi
print("truth in the first component's hull:", bool(np.all((lo <= truth) & (truth <= hi))))

fig, ax = plt.subplots(figsize=(6, 5))
for seg in np.asarray(world):
    ax.plot(*seg.T, "k-", lw=2)
paving.plot(ax=ax, dims=(0, 1))
ax.plot(*truth[:2], "C2*", ms=14, label="true position")
ax.set_aspect("equal")
ax.legend()
ax.set_title("consistent positions (projection of the pose paving)")
plt.show()
