"""
BH: relative-bearing localization with pseudo-ellipsoids
========================================================

[BH, Sect. V, Figs. 4-8]: vehicle at [0, 0], landmarks [0, 1], [1, 1], [−1, 0], eps = 4°; the
exact set paved from the angle constraints, the L = 4 and L = 8 pseudo-ellipsoids proven to
contain it, the optimal pseudo-ellipsoids, the best ellipse and the best box. Quick mode: 4
sweep geometries, no area criterion, no L = 8 reference.

Reproduction: ``python -m optbound.papers_repro.bh_relative_bearing --quick``
(this page runs its quick mode; the claim table compares the values typed from the paper
with optbound's).
"""

import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

from optbound.papers_repro import bh_relative_bearing

out = Path(tempfile.mkdtemp())
result = bh_relative_bearing.main(out, quick=True)
print(result["markdown"])

# %%
# The final sets of [BH, Figs. 7-8]: exact set, the L = 4 and L = 8 bounds.
fig, ax = plt.subplots(figsize=(10, 8))
ax.imshow(plt.imread(out / "bh_fig7_8_final.png"))
ax.set_axis_off()
plt.show()
