"""The exact sets of a 2-D system as polygons in rational arithmetic (no rounding at all).

Every float of the data is read as the exact rational it is, and ``X_k = (A X_{k-1} + W) ∩
{x : y_k - C x in V}`` is computed in ``fractions.Fraction``: the vertices are mapped by A,
W (a zonotope) is added one generator at a time (the hull of ``P - g`` and ``P + g``), and
the polygon is clipped by the two lines of each output row (``y_i - hi_i <= c_i^T x <= y_i -
lo_i``, ``[lo_i, hi_i]`` the interval hull of V's i-th coordinate, exact for a box V). The
vertices, the area (:func:`optbound.sets.constrained_zonotope_polygon.polygon_area`) and any
membership test on them are therefore exact; this is the
reference against which containment is *proven* (:func:`optbound.estimation.references.
proven_contains`). Limited to n = 2 and box V (or p = 1 zonotope V, whose interval is exact);
:mod:`optbound.estimation.exact_polytope` computes the same sets (tested equal) for n <= 4.
"""

from __future__ import annotations

from fractions import Fraction

from optbound._core import Box
from optbound.estimation.exact_polytope import output_bounds
from optbound.estimation.system import LinearSystem
from optbound.sets.constrained_zonotope_polygon import Point, clip, convex_hull
from optbound.sets.zonotope import Zonotope


def _q(x) -> Fraction:
    return Fraction(float(x))


def _polygon(Z: Box | Zonotope) -> list[Point]:
    """The exact vertices of a 2-D box or zonotope (hull of the generator sums)."""
    if isinstance(Z, Box):
        return convex_hull([(_q(x), _q(y)) for x in (Z.lo[0], Z.hi[0]) for y in (Z.lo[1], Z.hi[1])])
    P = [(_q(Z.center[0]), _q(Z.center[1]))]
    for g in Z.generators.T:
        gx, gy = _q(g[0]), _q(g[1])
        P = convex_hull([(p[0] + s * gx, p[1] + s * gy) for p in P for s in (-1, 1)])
    return P


def exact_polygons(system: LinearSystem, X0, ys) -> list[list[Point]]:
    """The exact polygons ``[X_1, ..., X_N]`` (module docstring); an empty list element means
    the measurements are inconsistent from that step on.

    Raises
    ------
    ValueError
        If the system is not 2-D, the noise is not polytopic, or V is not a product of
        intervals (:func:`optbound.estimation.exact_polytope.output_bounds`).
    """
    if system.dim != 2 or not system.polytopic:
        raise ValueError("exact_polygons needs a 2-D system with Box or Zonotope noise")
    lo, hi = output_bounds(system)
    if not isinstance(X0, Box | Zonotope) or X0.dim != 2:
        raise TypeError("X0 must be a 2-D Box or Zonotope")
    A = [[_q(x) for x in row] for row in system.A]
    C = [(_q(r[0]), _q(r[1])) for r in system.C]
    W = _polygon(system.W)
    P = _polygon(X0)
    out = []
    for y in system.measurements(ys):
        P = convex_hull([tuple(row[0] * p[0] + row[1] * p[1] for row in A) for p in P])
        P = convex_hull([(p[0] + w[0], p[1] + w[1]) for p in P for w in W])
        for i, c in enumerate(C):
            if P:  # c^T x <= y_i - lo_i
                P = convex_hull(clip(P, c[0], c[1], _q(y[i]) - lo[i]))
            if P:  # c^T x >= y_i - hi_i
                P = convex_hull(clip(P, -c[0], -c[1], hi[i] - _q(y[i])))
        out.append(P)
    return out
