"""
KJWM00: robustness to outliers by relaxed intersection
======================================================

[KJWM00]: no data association, robustness to outliers by a relaxed intersection that tolerates
q wrong readings, with q raised until the set is non-empty (q = "auto"). Success rate (truth in
the set), set volume and time for q = 0, q = 2 and q = "auto" on a 16-sonar belt. Quick mode: 2
random readings with 16 sonars and one with 3-7 sonars, 20 seeded trials each.

Reproduction: ``python -m optbound.papers_repro.kjwm00_outliers --quick``
(this page runs its quick mode; the claim table compares the values typed from the paper
with optbound's).
"""

import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

from optbound.papers_repro import kjwm00_outliers

out = Path(tempfile.mkdtemp())
result = kjwm00_outliers.main(out, quick=True)
print(result["markdown"])

# %%
# Success rates with 95 % Wilson intervals.
fig, ax = plt.subplots(figsize=(10, 6))
ax.imshow(plt.imread(out / "kjwm00_success.png"))
ax.set_axis_off()
plt.show()
