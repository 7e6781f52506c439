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
  certified upper bound: the outer polygon of
  :func:`optbound.sets.constrained_zonotope_polygon.outer_polygon` (the certified
  support values along the axes and the vertex polygon's edge normals, LP duals checked in
  outward-rounded arithmetic, intersected and measured in exact rational arithmetic);
- the exact set itself for n <= 4: :func:`optbound.estimation.exact_polytope.exact_polytopes`,
  its vertices and volume exact in rational arithmetic (no rounding at all);
- :func:`proven_contains`: ``X_k ⊆ estimate`` decided in exact rational arithmetic at the
  exact vertices (any n; boxes, ellipsoids, zonotopes, and constrained zonotopes by exact
  parameter certificates, ``optbound.estimation.exact_membership``);
- :func:`interval_hull`: the exact set's interval hull by certified LP bounds (any n): the
  best box, rounded outward;
- :func:`exact_mvee`: ``optbound.optimal.mvee`` of the LP vertices (2-D; it contains every
  vertex, checked in float64, so it contains the polygon up to the LP tolerance);
  :func:`polytope_mvee`: the same of the exact vertices (n <= 4), every exact vertex proven
  inside in rational arithmetic (inflated if needed);
- :func:`one_step_optimal`: ``optbound.optimal.outer_ellipsoid`` of the prediction ∩ the strips
  (certified S-procedure SDP).
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction

import numpy as np

from optbound._core import Box
from optbound.estimation.ellipsoidal import CRITERIA, WEIGHTS, measurement_strips, predict
from optbound.estimation.exact_membership import max_level, proven_inside
from optbound.estimation.noise import ellipsoid_of
from optbound.estimation.rational_polytope import RationalPolytope
from optbound.estimation.system import LinearSystem
from optbound.sets.constrained_zonotope import ConstrainedZonotope
from optbound.sets.constrained_zonotope_polygon import outer_polygon, polygon_area, round_up
from optbound.sets.ellipsoid import Ellipsoid


def exact_area(X: ConstrainedZonotope) -> tuple[float, float]:
    """``(area, upper)`` of a 2-D exact set: the LP vertex polygon's area and a certified upper
    bound of the true area (module docstring).

    Raises
    ------
    ValueError
        If ``X`` is not 2-D, or flat or empty (it has no polygon).
    """
    V, outer = outer_polygon(X)
    pts = [(Fraction(float(x)), Fraction(float(y))) for x, y in V]
    return float(polygon_area(pts)), round_up(polygon_area(outer))


def proven_contains(outer, vertices) -> bool | None:
    """Whether ``outer`` contains the polytope with the exact (Fraction) ``vertices`` (e.g. of
    :func:`optbound.estimation.exact_polygon.exact_polygons` in 2-D or
    :func:`optbound.estimation.exact_polytope.exact_polytopes` for n <= 4), decided in exact
    rational arithmetic at each vertex by
    :func:`optbound.estimation.exact_membership.proven_inside`: a Box by its bounds, an
    Ellipsoid by ``(p - c)^T Q^{-1} (p - c) <= 1``, a spanning Zonotope by its facet slabs, a
    ConstrainedZonotope by an exact parameter certificate per vertex (Scott et al. 2016's
    representation). None: not decided (a flat zonotope, a failed certificate, another
    type); a constrained zonotope is never refuted (False)."""
    return proven_inside(outer, vertices)


def interval_hull(X: ConstrainedZonotope) -> Box:
    """The exact set's interval hull, certified (``ConstrainedZonotope.bounding_box``)."""
    return X.bounding_box()


def exact_mvee(X: ConstrainedZonotope):
    """``optbound.optimal.mvee`` of the exact set's vertices (2-D; module docstring)."""
    from optbound import optimal

    return optimal.mvee(X.vertices())


def polytope_mvee(P: RationalPolytope):
    """The minimum-volume ellipsoid of an exact polytope (n <= 4), certified exactly.

    ``optbound.optimal.mvee`` (the SDP of Boyd & Vandenberghe 2004, Sect. 8.4.1) of the
    vertices rounded to floats, then every exact vertex is checked in rational arithmetic
    (:func:`optbound.estimation.exact_membership.max_level`) and the ellipsoid inflated about
    its centre by ``sqrt`` of the worst level (rounded up) until all are inside: the result
    contains the exact polytope with no rounding assumption. Cost: one SDP with V points plus
    an exact ``n x n`` inversion and V exact quadratic forms per check.

    Returns
    -------
    OuterResult
        As :func:`optbound.optimal.mvee`; ``inflation`` includes the exact check's factor.

    Raises
    ------
    ValueError
        If the polytope is flat (no ellipsoid of positive volume is its MVEE).
    """
    from optbound import optimal

    if P.volume == 0:
        raise ValueError("P must be full-dimensional (it is flat or empty): it has no MVEE")
    res = optimal.mvee(P.as_array())
    E, alpha = res.ellipsoid, 1.0
    for _ in range(8):
        worst = max_level(E, P.vertices)
        if worst <= 1:
            return replace(res, ellipsoid=E, objective=E.volume(), inflation=res.inflation * alpha)
        step = round_up(Fraction(np.sqrt(float(worst)))) * (1.0 + 4.0 * np.finfo(float).eps)
        E, alpha = E.scaled(step), alpha * step
    raise optimal.CertificationError("the MVEE still misses an exact vertex after inflation")


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
