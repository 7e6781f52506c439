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

    Parameters
    ----------
    X : ConstrainedZonotope
        A 2-D exact set (e.g. of :func:`optbound.estimation.exact_sets`).

    Returns
    -------
    area : float
        The area of the polygon of the LP vertices (exact up to the LP tolerance, not
        certified).
    upper : float
        A certified upper bound of the true area: the exact area of
        :func:`optbound.sets.constrained_zonotope_polygon.outer_polygon`, rounded up.

    Raises
    ------
    ValueError
        If ``X`` is not 2-D, or flat or empty (it has no polygon).

    Notes
    -----
    Each certified support value ``h(d) >= max_{x in X} d^T x`` gives a half-plane
    ``d^T x <= h(d)`` containing X; their intersection is exact in rational arithmetic and
    measured by the shoelace formula ``|sum_k (x_k y_{k+1} - x_{k+1} y_k)| / 2``.
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
    type); a constrained zonotope is never refuted (False).

    Parameters
    ----------
    outer : Box, Ellipsoid, Zonotope or ConstrainedZonotope
        The estimate, its floats read exactly.
    vertices : iterable of sequences of Fraction
        The exact vertices of the polytope (e.g. ``RationalPolytope.vertices``).

    Returns
    -------
    bool or None
        True: the polytope is proven inside ``outer``; False: a vertex is proven outside;
        None: undecided.

    Notes
    -----
    A convex ``outer`` contains a polytope iff it contains its vertices, so the test at the
    exact vertices decides the containment with no tolerance. A constrained zonotope
    ``<c, G, A, b>`` (Scott et al. [1]_) holds p iff some ``xi`` with ``|xi|_inf <= 1`` has
    ``G xi = p - c`` and ``A xi = b``; an exact such ``xi`` is the certificate.

    References
    ----------
    .. [1] J. K. Scott, D. M. Raimondo, G. R. Marseglia, R. D. Braatz, "Constrained zonotopes:
       A new tool for set-based estimation and fault detection", Automatica 69, 2016.

    Examples
    --------
    >>> from optbound import Box
    >>> from optbound.estimation import LinearSystem, exact_polytopes, observe
    >>> from optbound.estimation.references import proven_contains
    >>> A, C = [[1.0, 0.5], [0.0, 1.0]], [[1.0, 0.0]]
    >>> system = LinearSystem(A, C, W=Box([-0.1, -0.1], [0.1, 0.1]), V=Box([-0.2], [0.2]))
    >>> X0, ys = Box([-1.0, -1.0], [1.0, 1.0]), [0.3, 0.5, 0.9]
    >>> P = exact_polytopes(system, X0, ys)[-1]
    >>> round(float(P.volume), 9)  # the floats 0.1, 0.2, ... read as exact rationals
    0.4075
    >>> B = observe(system, X0, ys, method="interval")[-1]
    >>> proven_contains(B, P.vertices), proven_contains(Box([0.8, 0.0], [1.0, 1.0]), P.vertices)
    (True, False)
    """
    return proven_inside(outer, vertices)


def interval_hull(X: ConstrainedZonotope) -> Box:
    """The exact set's interval hull, certified (``ConstrainedZonotope.bounding_box``).

    Parameters
    ----------
    X : ConstrainedZonotope
        An exact set (e.g. of :func:`optbound.estimation.exact_sets`).

    Returns
    -------
    Box
        The smallest box containing ``X``, its bounds from LP duals checked in outward-rounded
        arithmetic (any n).
    """
    return X.bounding_box()


def exact_mvee(X: ConstrainedZonotope):
    """``optbound.optimal.mvee`` of the exact set's vertices (2-D; module docstring).

    Parameters
    ----------
    X : ConstrainedZonotope
        A 2-D exact set.

    Returns
    -------
    OuterResult
        As :func:`optbound.optimal.mvee`: the minimum-volume ellipsoid of the LP vertices
        (contains the polygon up to the LP tolerance, not certified exactly; for that use
        :func:`polytope_mvee`).
    """
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

    Parameters
    ----------
    P : RationalPolytope
        A full-dimensional exact polytope (e.g. of
        :func:`optbound.estimation.exact_polytope.exact_polytopes`).

    Returns
    -------
    OuterResult
        As :func:`optbound.optimal.mvee`; ``inflation`` includes the exact check's factor.

    Raises
    ------
    ValueError
        If the polytope is flat (no ellipsoid of positive volume is its MVEE).
    optbound.optimal.CertificationError
        If eight inflations still leave an exact vertex outside.

    Notes
    -----
    The MVEE of a polytope is the MVEE of its vertices: ``min -log det L`` subject to
    ``|L v_i + d| <= 1`` for every vertex (Boyd & Vandenberghe [1]_, Sect. 8.4.1). Inflating
    ``E(c, Q)`` to ``E(c, t^2 Q)`` with ``t >= sqrt(max_i level_i)`` puts every vertex inside.

    References
    ----------
    .. [1] S. Boyd, L. Vandenberghe, *Convex Optimization*, Cambridge University Press, 2004.
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

    Parameters
    ----------
    system : LinearSystem
        The model.
    E_prev : Ellipsoid
        The observer's previous estimate ``E_{k-1}``.
    y : array_like, shape (p,)
        The measurement of ``x_k``.
    method : {"ellipsoid_volume", "ellipsoid_trace"}
        The observer, hence the criterion.

    Returns
    -------
    OuterResult
        As :func:`optbound.optimal.outer_ellipsoid`: the certified optimum ``O_k`` of the
        module docstring's split.

    Notes
    -----
    The S-procedure SDP (Boyd, El Ghaoui, Feron & Balakrishnan [1]_) over the prediction
    ellipsoid and the strips ``|a_i^T x - b_i| <= 1``; ``vol E_k / vol O_k`` is the loss of the
    analytic strip fusion in that step.

    References
    ----------
    .. [1] S. Boyd, L. El Ghaoui, E. Feron, V. Balakrishnan, *Linear Matrix Inequalities in
       System and Control Theory*, SIAM, 1994.
    """
    from optbound import optimal

    criterion = CRITERIA[method]
    y = system.measurements(np.atleast_1d(np.asarray(y, dtype=float))[None, :])[0]
    pred = predict(system, E_prev, criterion, ellipsoid_of(system.W, WEIGHTS[criterion]))
    return optimal.outer_ellipsoid([pred, *measurement_strips(system, y, pred)], criterion)
