"""References for the observers, per step: the exact set's size, its interval hull, its
minimum-volume ellipsoid and the optimal one-step ellipsoid.

The size of an ellipsoidal estimate ``E_k`` against the exact set ``X_k`` splits as

    vol E_k / vol X_k = [vol E_k / vol O_k] * [vol O_k / vol M_k] * [vol M_k / vol X_k],

``O_k`` the optimal ellipsoid of *one* step (the minimum-volume or -trace ellipsoid containing
the observer's own prediction ∩ the measurement strips, :func:`one_step_optimal`), ``M_k``
the minimum-volume ellipsoid of ``X_k`` (:func:`exact_mvee`): the first factor is the loss of
the analytic strip fusion in that step, the second the loss carried by the recursion (the
prediction from ``E_{k-1}`` instead of ``X_{k-1}``), the third what no ellipsoid can avoid.

What is certified:

- :func:`exact_area`: in 2-D, the polygon of the exact set's vertices found by float LPs
  (``ConstrainedZonotope.vertices``: exact up to the LP tolerance, *not* certified) and a
  certified upper bound: the polygon cut out by the certified support values
  (``ConstrainedZonotope.support``, LP duals checked in outward-rounded arithmetic) along the
  vertex polygon's edge normals, intersected and measured in exact rational arithmetic;
- :func:`proven_contains`: ``X_k ⊆ estimate`` decided in exact rational arithmetic on the
  exact polygon of ``optbound.estimation.exact_polygon`` (2-D; boxes, zonotopes, ellipsoids);
- :func:`interval_hull`: the exact set's interval hull by certified LP bounds (any n): the
  best box, rounded outward;
- :func:`exact_mvee`: ``optbound.optimal.mvee`` of those vertices (2-D; it contains every
  vertex, checked in float64, so it contains the polygon up to the LP tolerance);
- :func:`one_step_optimal`: ``optbound.optimal.outer_ellipsoid`` of the prediction ∩ the strips
  (certified S-procedure SDP).
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from optbound._core import Box
from optbound.estimation.ellipsoidal import CRITERIA, WEIGHTS, measurement_strips, predict
from optbound.estimation.noise import ellipsoid_of
from optbound.estimation.system import LinearSystem
from optbound.sets.constrained_zonotope import ConstrainedZonotope
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.zonotope import Zonotope


def _shoelace(P) -> Fraction:
    n = len(P)
    return abs(sum(P[k][0] * P[(k + 1) % n][1] - P[(k + 1) % n][0] * P[k][1] for k in range(n))) / 2


def _up(x: Fraction) -> float:
    f = float(x)
    return f if Fraction(f) >= x else float(np.nextafter(f, np.inf))


def certified_polygon(X: ConstrainedZonotope) -> tuple[np.ndarray, list]:
    """The LP vertex polygon of a 2-D set (floats, ccw) and the corners (Fractions) of a polygon
    proven to contain the set: the half-planes of the certified support values along the vertex
    polygon's edge normals, intersected exactly (module docstring)."""
    if X.dim != 2:
        raise ValueError(f"the exact-set polygon is for 2-D sets, got dimension {X.dim}")
    V = X.vertices()
    if len(V) < 3:
        raise ValueError("the set is flat or empty: it has no polygon")
    normals = np.array(
        [[q[1] - p[1], p[0] - q[0]] for p, q in zip(V, np.roll(V, -1, 0), strict=True)]
    )
    h = X.support(normals)
    N = [(Fraction(float(a)), Fraction(float(b))) for a, b in normals]
    H = [Fraction(float(x)) for x in h]
    corners = []
    for k in range(len(N)):  # corner between edge k-1 and edge k (exact 2x2 solve)
        (a1, b1), (a2, b2) = N[k - 1], N[k]
        det = a1 * b2 - a2 * b1
        corners.append(((H[k - 1] * b2 - H[k] * b1) / det, (a1 * H[k] - a2 * H[k - 1]) / det))
    return V, corners


def exact_area(X: ConstrainedZonotope) -> tuple[float, float]:
    """``(area, upper)`` of a 2-D exact set: the LP vertex polygon's area and a certified upper
    bound of the true area (module docstring)."""
    V, corners = certified_polygon(X)
    pts = [(Fraction(float(x)), Fraction(float(y))) for x, y in V]
    return float(_shoelace(pts)), _up(_shoelace(corners))


def proven_contains(outer, vertices: list) -> bool | None:
    """Whether ``outer`` contains the 2-D polygon with the exact (Fraction) ``vertices``
    (e.g. of :func:`optbound.estimation.exact_polygon.exact_polygons`), decided in exact
    rational arithmetic: a Box by its bounds, an Ellipsoid by ``(p - c)^T Q^{-1} (p - c) <= 1``
    at each vertex, a spanning Zonotope by its facet slabs ``|n^T (p - c)| <= sum_j |n^T
    g_j|`` (n a generator turned by 90 degrees). None: not decided for this type
    (constrained zonotopes, flat zonotopes)."""
    q = [(Fraction(p[0]), Fraction(p[1])) for p in vertices]
    if isinstance(outer, Box):
        lo, hi = [Fraction(float(x)) for x in outer.lo], [Fraction(float(x)) for x in outer.hi]
        return all(lo[i] <= p[i] <= hi[i] for p in q for i in (0, 1))
    if isinstance(outer, Ellipsoid):
        (a, b), (_, d) = [[Fraction(float(x)) for x in row] for row in outer.shape]
        c = [Fraction(float(x)) for x in outer.center]
        det = a * d - b * b
        return all(
            d * (p[0] - c[0]) ** 2 - 2 * b * (p[0] - c[0]) * (p[1] - c[1]) + a * (p[1] - c[1]) ** 2
            <= det
            for p in q
        )
    if isinstance(outer, Zonotope) and np.linalg.matrix_rank(outer.generators) == 2:
        c = [Fraction(float(x)) for x in outer.center]
        G = [(Fraction(float(g[0])), Fraction(float(g[1]))) for g in outer.generators.T]
        for g in G:
            n = (-g[1], g[0])
            h = sum(abs(n[0] * e[0] + n[1] * e[1]) for e in G)
            if any(abs(n[0] * (p[0] - c[0]) + n[1] * (p[1] - c[1])) > h for p in q):
                return False
        return True
    return None


def interval_hull(X: ConstrainedZonotope) -> Box:
    """The exact set's interval hull, certified (``ConstrainedZonotope.bounding_box``)."""
    return X.bounding_box()


def exact_mvee(X: ConstrainedZonotope):
    """``optbound.optimal.mvee`` of the exact set's vertices (2-D; module docstring)."""
    from optbound import optimal

    return optimal.mvee(X.vertices())


def one_step_optimal(system: LinearSystem, E_prev: Ellipsoid, y, method: str):
    """The optimal ellipsoid of one step of the ellipsoidal observer ``method``: the certified
    minimum-volume (``ellipsoid_volume``) or minimum-trace (``ellipsoid_trace``) ellipsoid
    containing the observer's prediction from ``E_prev`` ∩ the measurement strips of ``y``.

    Returns the ``OuterResult`` of :func:`optbound.optimal.outer_ellipsoid`.
    """
    from optbound import optimal

    criterion = CRITERIA[method]
    y = system.measurements(np.atleast_1d(np.asarray(y, dtype=float))[None, :])[0]
    pred = predict(system, E_prev, criterion, ellipsoid_of(system.W, WEIGHTS[criterion]))
    return optimal.outer_ellipsoid([pred, *measurement_strips(system, y, pred)], criterion)
