"""
GLH12: visibility-only pose tracking
====================================

The user guide's visibility example (:doc:`/user_guide/localization`): five robots know only
whether they see each other [GLH12]; LUVIA contracts their boxes at every step, and every box
contains its robot's true position.
"""

import matplotlib.pyplot as plt
import numpy as np

from optbound.interval import Tri
from optbound.localization.environment import Environment
from optbound.localization.visibility import track, visibility_test
from optbound.scenarios import arena

wall = np.array([[4.0, 0.0], [6.0, 0.0], [6.0, 10.0], [4.0, 10.0]])
env = Environment.from_polygons([wall], margin=0.05)
left, right = np.array([[[1.0, 2.0], [4.0, 5.0]]]), np.array([[[8.0, 9.0], [4.0, 5.0]]])
assert visibility_test(left, right, env.inner)[0] == Tri.FALSE  # the wall blocks every pair

run = arena.simulate(n_robots=5, n_obstacles=6, steps=50, seed=0)  # the designed 10 x 10 m room
boxes = track(
    run.boxes0, run.distance, run.headings, arena.HEADING_ERROR, run.visibility, run.env, eps=0.01
)
assert np.all((boxes[..., 0] <= run.truth) & (run.truth <= boxes[..., 1]))  # guaranteed
areas = np.prod(boxes[..., 1] - boxes[..., 0], axis=-1)  # (steps + 1, robots)
print(f"mean box area: {areas[0].mean():.3f} m² at first, {areas[-1].mean():.3f} m² at the end")

fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(11, 4.5))
for polygon in run.env.outer:
    ax0.fill(*np.asarray(polygon).T, color="0.8")
for i in range(boxes.shape[1]):
    ax0.plot(*run.truth[:, i].T, "-", lw=1, color=f"C{i}")
    (x0, x1), (y0, y1) = boxes[-1, i]
    ax0.add_patch(plt.Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, color=f"C{i}", lw=2))
ax0.set_aspect("equal")
ax0.set_title("paths and the final boxes")
ax1.plot(areas.mean(axis=1))
ax1.set_xlabel("step")
ax1.set_ylabel("mean box area [m²]")
ax1.set_title("mean box area: 5 robots, fewer than the 7 GLH12 need", fontsize=10)
plt.show()
