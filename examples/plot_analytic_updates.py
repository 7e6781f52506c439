"""
Analytic ellipsoid calculus: the strip cases, clipping and Minkowski sums
=========================================================================

The user guide's analytic example (:doc:`/user_guide/analytic`): the four cases of
ellipsoid ∩ strip [HS96, Fig. 1], the volume saved by clipping the strip to the ellipsoid
first, and the volume- and trace-optimal members of Schweppe's Minkowski family [HS96,
eq. (14)].
"""

import matplotlib.pyplot as plt
import numpy as np

import optbound as ob
from optbound import analytic

E = ob.Ellipsoid([0.0, 0.0], np.diag([2.0, 1.0]))
strips = {
    "no_reduction": ob.Strip.from_bounds([1.0, 0.0], -2.0, 2.0),
    "consistent": ob.Strip.from_bounds([1.0, 0.0], -0.4, 0.6),
    "partial": ob.Strip.from_bounds([1.0, 0.0], 0.6, 3.0),
    "inconsistent": ob.Strip.from_bounds([1.0, 0.0], 2.0, 3.0),
}
fig, axes = plt.subplots(1, 4, figsize=(12, 3.2), sharey=True)
for ax, (name, S) in zip(axes, strips.items(), strict=True):
    f = analytic.intersect_strip(E, S)
    raw = analytic.intersect_strip(E, S, clip=False)
    print(f"{name:13s} case {f.case:13s} consistency {f.consistency:.3f}")
    ax.plot(*E.boundary().T, "k--", label="E")
    for x in (S.b - 1, S.b + 1):
        ax.axvline(x / S.a[0], color="C0", lw=1)
    if f.ellipsoid is not None:
        ax.plot(*f.ellipsoid.boundary().T, "C3-", lw=2, label="clipped (default)")
    if raw.ellipsoid is not None and name == "partial":
        ax.plot(*raw.ellipsoid.boundary().T, "C1:", lw=2, label="raw strip")
    ax.set_title(f"{name}\n({f.case})", fontsize=9)
    ax.set_xlim(-2.5, 3.2)
    ax.set_aspect("equal")
axes[2].legend(fontsize=7, loc="lower left")
plt.tight_layout()

# %%
# Minkowski sum of two ellipsoids: the volume-optimal κ is the minimum-volume ellipsoid
# containing the sum (Durieu, Walter & Polyak 2001); the trace-optimal κ has a closed form.
E1 = ob.Ellipsoid([0.0, 0.0], np.diag([4.0, 1.0]))
E2 = ob.Ellipsoid([0.0, 0.0], np.eye(2))
vol = analytic.minkowski_sum(E1, E2)
tr = analytic.minkowski_sum(E1, E2, criterion="trace")
print(f"volume-optimal kappa {vol.kappa:.10f}, trace-optimal kappa {tr.kappa:.6f}")

rng = np.random.default_rng(0)
points = E1.sample(4000, rng) + E2.sample(4000, rng)  # points of the sum
fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(*points.T, ",", color="0.6")
for m, style, label in ((vol, "C3-", "min volume"), (tr, "C2--", "min trace")):
    ax.plot(*m.ellipsoid.boundary().T, style, lw=2, label=label)
ax.set_aspect("equal")
ax.legend()
ax.set_title("E1 + E2 and two members of the family C1/(1−κ) + C2/κ")
plt.show()
