"""
LJMW97: sonar localization in a triangular room
===============================================

[LJMW97, Sect. 4, Figs. 4-5]: four sonars (±12°, 2 %), no data association; the set of
consistent poses splits into connected components, each with its association hypothesis and
whether it is proven (holds a pose checked consistent in interval arithmetic). The room and
sonar placement are ours (the paper's Fig. 4(a) is lost).

Reproduction: ``python -m optbound.papers_repro.ljmw97_triangle --quick``
(this page runs its quick mode; the claim table compares the values typed from the paper
with optbound's).
"""

import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

from optbound.papers_repro import ljmw97_triangle

out = Path(tempfile.mkdtemp())
result = ljmw97_triangle.main(out, quick=True)
print(result["markdown"])

# %%
# The components of the consistent pose set [LJMW97, Fig. 4].
fig, ax = plt.subplots(figsize=(10, 8))
ax.imshow(plt.imread(out / "ljmw97_fig4_components.png"))
ax.set_axis_off()
plt.show()
