"""
Linear estimation: every observer against the exact set
=======================================================

The comparison of :doc:`/user_guide/estimation` on the example of [ABC05, Sect. 7.1]: the
interval, zonotope, constrained-zonotope and ellipsoidal observers of
``optbound.estimation`` over 20 measurements, each set's area over the exact set's
(constrained zonotopes without reduction).
"""

import matplotlib.pyplot as plt

from optbound import estimation
from optbound.estimation import references
from optbound.scenarios import alamo2005 as data
from optbound.sets import Box, Ellipsoid


def area(S):
    """Area of a 2-D set: ellipse or box formula, a zonotope's certified upper bound, or the
    vertex polygon of a constrained zonotope."""
    if isinstance(S, Box | Ellipsoid):
        return S.volume()
    if hasattr(S, "volume_bounds"):
        return S.volume_bounds()[1]
    return references.exact_area(S)[0]


system = data.system()
exact = estimation.exact_sets(system, data.X0, data.MEASUREMENTS)
methods = ("interval", "zonotope", "constrained_zonotope", "ellipsoid_volume")
sets = {m: estimation.observe(system, data.X0, data.MEASUREMENTS, method=m) for m in methods}
exact_area = [area(X) for X in exact]
for m, S in sets.items():
    ratio = area(S[-1]) / exact_area[-1]
    print(f"{m:22s} area at k = 20: {area(S[-1]):.4f}, ratio to exact {ratio:.3f}")

fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(11, 4.5))
k = range(1, len(exact) + 1)
for m, S in sets.items():
    ax0.plot(k, [area(X) / e for X, e in zip(S, exact_area, strict=True)], "o-", ms=3, label=m)
ax0.set_yscale("log")
ax0.set_xlabel("k")
ax0.set_ylabel("area / exact area")
ax0.legend(fontsize=8)
for m, S in sets.items():
    if m != "interval":  # the box is hundreds of times larger: left out of the picture
        ax1.plot(*S[9].boundary().T, lw=1.5, label=m)
ax1.plot(*exact[9].boundary().T, "k-", lw=2.5, label="exact")
ax1.set_title("the sets at k = 10 (the interval box is off the picture)")
ax1.legend(fontsize=7)
plt.show()
