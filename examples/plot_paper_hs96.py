"""
HS96: the four cases of ellipsoid ∩ strip fusion
================================================

[HS96, Fig. 1]: the four configurations of a strip and an ellipse (no reduction, consistent,
partial, inconsistent), the case and consistency measure (eq. 29) of each, the eq. (26) bound
on the raw strip (the paper's equations), on the strip clipped to the ellipse (optbound's
default) and the certified SDP minimum.

Reproduction: ``python -m optbound.papers_repro.hs96_fusion --quick``
(this page runs its quick mode; the claim table compares the values typed from the paper
with optbound's).
"""

import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

from optbound.papers_repro import hs96_fusion

out = Path(tempfile.mkdtemp())
result = hs96_fusion.main(out, quick=True)
print(result["markdown"])

# %%
# The four fusion cases of [HS96, Fig. 1] (the paper's figure is lost; these are optbound's).
fig, ax = plt.subplots(figsize=(10, 8))
ax.imshow(plt.imread(out / "hs96_fig1_cases.png"))
ax.set_axis_off()
plt.show()
