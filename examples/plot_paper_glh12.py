"""
GLH12: how many robots does visibility-only tracking need?
==========================================================

[GLH12, Sect. 5, Figs. 8-9]: visibility-only pose tracking (LUVIA) in a 10 x 10 m room; the
paper's claims "at least 7 robots are necessary" and "over 9 robots the results are similar",
judged over seeded random rooms and paths. Quick mode: 150 steps, 2 seeds per count.

Reproduction: ``python -m optbound.papers_repro.glh12_visibility --quick``
(this page runs its quick mode; the claim table compares the values typed from the paper
with optbound's).
"""

import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

from optbound.papers_repro import glh12_visibility

out = Path(tempfile.mkdtemp())
result = glh12_visibility.main(out, quick=True)
print(result["markdown"])

# %%
# Final mean box area per number of robots [GLH12, Fig. 8].
fig, ax = plt.subplots(figsize=(10, 6))
ax.imshow(plt.imread(out / "glh12_robots.png"))
ax.set_axis_off()
plt.show()
