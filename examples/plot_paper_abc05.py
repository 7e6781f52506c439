"""
ABC05: zonotopes against ellipsoids in linear estimation
========================================================

[ABC05, Sect. 7.1]: the example of Alamo, Bravo & Camacho (data as in CORA's example), every
observer of ``optbound.estimation``: area at k = 20, ratio to the exact set and its MVEE,
containment decided in exact arithmetic at every step; the claims "zonotopes are tighter than
ellipsoids" and (Scott et al. 2016) "constrained zonotopes are tighter than zonotopes".

Reproduction: ``python -m optbound.papers_repro.alamo05_linear --quick``
(this page runs its quick mode; the claim table compares the values typed from the paper
with optbound's).
"""

import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

from optbound.papers_repro import alamo05_linear

out = Path(tempfile.mkdtemp())
result = alamo05_linear.main(out, quick=True)
print(result["markdown"])

# %%
# The observers' sets at k = 2, 5, 10, 20 against the exact set.
fig, ax = plt.subplots(figsize=(10, 8))
ax.imshow(plt.imread(out / "abc05_sets.png"))
ax.set_axis_off()
plt.show()
