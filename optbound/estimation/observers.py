"""Set-membership observers for linear systems: each step's set contains the exact set.

- ``"interval"``: box propagation. The prediction is the interval hull of ``A B + W`` and the
  correction contracts the box with each output row ``y_i - V_i ∋ c_i^T x`` by interval
  constraint propagation (``x_j in (t - sum_{k != j} c_ik x_k) / c_ij``), all in
  outward-rounded interval arithmetic.
- ``"zonotope"``: the observer of Alamo, Bravo & Camacho (Automatica 2005, Property 3 and
  Sect. 5): for any gain ``lam`` (n,), ``Z ∩ {x : |y - c_V - a^T x| <= s}`` lies in
  ``<c + lam (y - c_V - a^T c), [(I - lam a^T) G, -s lam]>`` (substitute ``x = x + lam (y -
  c_V - a^T x - s eta)``); ``lam = G G^T a / (a^T G G^T a + s^2)`` minimises the Frobenius
  radius (their F-radius criterion). One output row at a time (a zonotopic ``V`` is first
  boxed per row), then Girard reduction to ``order * n`` generators. The new data are
  enclosed in interval arithmetic, so the result contains the exact set.
- ``"zonotope_volume"``: the same recursion with the gain minimising the *volume* of each
  strip update exactly (a linear program, ``optbound.estimation.zonotope_gains``; the
  volume criterion of Alamo et al. 2005, Sect. 5). Its cost grows with the number of
  generator subsets, so it is for small ``n * order``.
- ``"constrained_zonotope"``: the exact recursion of ``optbound.estimation.exact`` followed by
  the budget of Scott et al. (Automatica 2016, Sect. 4.2 and 6): at most ``max_constraints``
  constraints (the excess eliminated, :meth:`ConstrainedZonotope.eliminate_constraints`) and
  at most ``order * n`` generators (lifted Girard reduction,
  :meth:`ConstrainedZonotope.reduce_order`). Defaults: ``order = 8``, ``max_constraints = 2``
  (stated budget; the reduction needs ``order * n >= n + max_constraints``).
- ``"ellipsoid_volume"``, ``"ellipsoid_trace"``: Schweppe's predictor and one strip fusion
  per output row with :mod:`optbound.analytic`, the member chosen by volume or trace
  (``optbound.estimation.ellipsoidal``).

Ellipsoidal noise or ``X0`` enters the polytopic observers as its certified enclosing
parallelotope, zonotopic noise the ellipsoidal ones as a certified enclosing ellipsoid
(``optbound.estimation.noise``).
"""

from __future__ import annotations

import numpy as np

from optbound._core import Box
from optbound.estimation.ellipsoidal import CRITERIA as ELLIPSOIDAL
from optbound.estimation.ellipsoidal import observe_ellipsoids
from optbound.estimation.exact import as_initial, measurement_set, predict_correct
from optbound.estimation.system import LinearSystem
from optbound.estimation.zonotope_gains import frobenius_gain, volume_gain
from optbound.sets.base import EmptySetError
from optbound.sets.zonotope import Zonotope

ZONOTOPE_GAINS = {"zonotope": "frobenius", "zonotope_volume": "volume"}
METHODS = (
    "interval",
    "zonotope",
    "zonotope_volume",
    "constrained_zonotope",
    "ellipsoid_volume",
    "ellipsoid_trace",
)


def _contract(lo_x: np.ndarray, hi_x: np.ndarray, C: np.ndarray, lo, hi) -> Box:
    """Interval constraint propagation of ``lo <= C x <= hi`` on the box ``[lo_x, hi_x]``
    (three sweeps, outward-rounded); raises EmptySetError when a coordinate becomes empty."""
    from optbound.interval import Interval, intersection

    lo_x, hi_x = lo_x.copy(), hi_x.copy()
    for _ in range(3):
        for i, row in enumerate(C):
            support = np.flatnonzero(row)
            for j in support:
                rest = Interval(0.0)
                for k in support:
                    if k != j:
                        rest = rest + row[k] * Interval(lo_x[k], hi_x[k])
                new = intersection(
                    Interval(lo_x[j], hi_x[j]), (Interval(lo[i], hi[i]) - rest) / row[j]
                )
                if np.any(new.is_empty):
                    raise EmptySetError(f"the box estimate became empty at output row {i}")
                lo_x[j], hi_x[j] = float(new.lo), float(new.hi)
    return Box(lo_x, hi_x)


def interval_step(system: LinearSystem, B: Box, y: np.ndarray) -> Box:
    """One step of the interval observer (module docstring).

    Parameters
    ----------
    system : LinearSystem
        The model.
    B : Box
        The box ``B_{k-1}`` containing ``X_{k-1}``.
    y : numpy.ndarray, shape (p,)
        The measurement of ``x_k``.

    Returns
    -------
    Box
        A box containing ``(A B + W) ∩ {x : y - C x in V}``: the interval hull of the
        prediction contracted by each output row (outward-rounded).

    Raises
    ------
    optbound.sets.base.EmptySetError
        If the contraction proves the box empty.
    """
    pred = Zonotope.from_box(B).affine_map(system.A).minkowski_sum(system.W_zonotope).bounding_box()
    Y = measurement_set(system, y).bounding_box()
    return _contract(pred.lo, pred.hi, system.C, Y.lo, Y.hi)


def alamo_strip(
    Z: Zonotope, a: np.ndarray, lo: float, hi: float, gain: str = "frobenius"
) -> Zonotope:
    """Zonotope containing ``Z ∩ {x : lo <= a^T x <= hi}`` with the gain ``gain`` of
    ``optbound.estimation.zonotope_gains`` (Alamo et al. 2005, Property 3).

    Parameters
    ----------
    Z : Zonotope
        The zonotope ``<c, G>`` to cut.
    a : numpy.ndarray, shape (n,)
        The strip's normal.
    lo, hi : float
        The strip's bounds on ``a^T x``.
    gain : {"frobenius", "volume"}
        The gain criterion (:func:`~optbound.estimation.zonotope_gains.frobenius_gain` or
        :func:`~optbound.estimation.zonotope_gains.volume_gain`).

    Returns
    -------
    Zonotope
        ``<c + lam (m - a^T c), [(I - lam a^T) G, -s lam]>`` enclosed in interval arithmetic
        (``Z`` itself when the gain is zero).

    Notes
    -----
    With ``m = (lo + hi) / 2`` and ``s = (hi - lo) / 2``, every x of the intersection is
    ``x = c + G xi`` with ``|m - a^T x| <= s``, i.e. ``m - a^T x = s eta``, ``|eta| <= 1``;
    substituting ``x = x + lam (m - a^T x - s eta)`` gives the zonotope above for any gain
    ``lam`` (Alamo et al. [1]_, Property 3).

    References
    ----------
    .. [1] T. Alamo, J. M. Bravo, E. F. Camacho, "Guaranteed state estimation by zonotopes",
       Automatica 41(6), 2005.
    """
    from optbound.interval import Interval
    from optbound.sets.certified import enclose, error_generators, matmul, point, split

    mid, s = split(Interval(lo, hi))
    c, G = Z.center, Z.generators
    lam = frobenius_gain(G, a, s) if gain == "frobenius" else volume_gain(G, a, s)
    if not np.any(lam):
        return Z
    lam_iv = point(lam)
    residual = point(mid) - matmul(a[None, :], c[:, None])[0, 0]
    c_iv = lam_iv * residual + c
    # (I - lam a^T) G = G - lam (a^T G): a rank-one update, O(n m) instead of O(n^2 m).
    G_iv = point(G) - matmul(lam[:, None], matmul(a[None, :], G))
    slack = lam_iv * -s
    c_new, G_new, r = enclose(
        c_iv,
        Interval(np.hstack([G_iv.lo, slack.lo[:, None]]), np.hstack([G_iv.hi, slack.hi[:, None]])),
    )
    return Zonotope._compacted(c_new, np.hstack([G_new, error_generators(r)]))


def zonotope_step(
    system: LinearSystem, Z: Zonotope, y: np.ndarray, order: float, gain: str = "frobenius"
) -> Zonotope:
    """One step of a zonotopic observer with the strip gain ``gain`` (module docstring).

    Parameters
    ----------
    system : LinearSystem
        The model.
    Z : Zonotope
        The zonotope containing ``X_{k-1}``.
    y : numpy.ndarray, shape (p,)
        The measurement of ``x_k``.
    order : float
        At most ``floor(order * n)`` generators after the step (Girard reduction).
    gain : {"frobenius", "volume"}
        The strip gain of :func:`alamo_strip`.

    Returns
    -------
    Zonotope
        A zonotope containing ``X_k`` whenever ``Z`` contains ``X_{k-1}``.

    Raises
    ------
    optbound.sets.base.EmptySetError
        If the prediction misses a measurement strip (inconsistent measurements).

    References
    ----------
    .. [1] T. Alamo, J. M. Bravo, E. F. Camacho, "Guaranteed state estimation by zonotopes",
       Automatica 41(6), 2005.
    """
    Z = Z.affine_map(system.A).minkowski_sum(system.W_zonotope)
    Y = measurement_set(system, y).bounding_box()
    for i, row in enumerate(system.C):
        if not Z.support(row) >= Y.lo[i] or not -Z.support(-row) <= Y.hi[i]:
            raise EmptySetError(f"the zonotope estimate misses the measurement strip of row {i}")
        Z = alamo_strip(Z, row, Y.lo[i], Y.hi[i], gain)
    return Z.reduce_order(order, "girard")


def observe(
    system: LinearSystem,
    X0,
    ys,
    method: str = "constrained_zonotope",
    order: float = 8.0,
    max_constraints: int = 2,
) -> list:
    """The sets ``[X_1, ..., X_N]`` of observer ``method`` (one of :data:`METHODS`).

    Parameters
    ----------
    system : LinearSystem
        The model.
    X0 : Box, Zonotope, ConstrainedZonotope or Ellipsoid
        The set of ``x_0`` (no measurement at k = 0); the ellipsoidal observers refuse a
        ConstrainedZonotope.
    ys : array_like, shape (N, p) or (N,) when p = 1
        ``ys[k-1]`` measures ``x_k``.
    method : str
        ``"interval"`` (returns Boxes), ``"zonotope"`` or ``"zonotope_volume"`` (Zonotopes),
        ``"constrained_zonotope"`` (ConstrainedZonotopes), ``"ellipsoid_volume"`` or
        ``"ellipsoid_trace"`` (Ellipsoids); see the module docstring.
    order, max_constraints
        The budget of the zonotopic observers: at most ``floor(order * n)`` generators (both)
        and ``max_constraints`` constraints (constrained zonotopes) after each step.

    Returns
    -------
    list
        One set per measurement; each contains the exact set ``X_k`` (guaranteed in floating
        point, see ``optbound.sets.constrained_zonotope``).

    Raises
    ------
    optbound.sets.base.EmptySetError
        If an estimate is proven empty (measurements inconsistent with the model).
    ValueError
        If ``method`` is unknown, ``ys`` is not finite with p columns, ``X0`` has the wrong
        dimension, or ``X0`` is a ConstrainedZonotope with constraints for a zonotope
        observer.
    TypeError
        If ``X0`` is not one of the accepted set types (a ConstrainedZonotope is not one for
        the ellipsoidal observers).

    Notes
    -----
    Every observer bounds the recursion ``X_k = (A X_{k-1} ⊕ W) ∩ {x : y_k - C x in V}``. The
    zonotopic ones use the strip update of Alamo et al. [1]_ (Property 3, :func:`alamo_strip`),
    the constrained-zonotope one the exact recursion with the budget of Scott et al. [2]_
    (Sect. 4.2 and 6), the ellipsoidal ones Schweppe's predictor with one strip fusion per
    output row (``optbound.estimation.ellipsoidal``).

    References
    ----------
    .. [1] T. Alamo, J. M. Bravo, E. F. Camacho, "Guaranteed state estimation by zonotopes",
       Automatica 41(6), 2005.
    .. [2] J. K. Scott, D. M. Raimondo, G. R. Marseglia, R. D. Braatz, "Constrained zonotopes:
       A new tool for set-based estimation and fault detection", Automatica 69, 2016.

    Examples
    --------
    >>> from optbound import Box
    >>> from optbound.estimation import LinearSystem, exact_polytopes, observe
    >>> from optbound.estimation.references import proven_contains
    >>> A, C = [[1.0, 0.5], [0.0, 1.0]], [[1.0, 0.0]]
    >>> system = LinearSystem(A, C, W=Box([-0.1, -0.1], [0.1, 0.1]), V=Box([-0.2], [0.2]))
    >>> X0, ys = Box([-1.0, -1.0], [1.0, 1.0]), [0.3, 0.5, 0.9]
    >>> Z = observe(system, X0, ys, method="zonotope")
    >>> type(Z[-1]).__name__, len(Z)
    ('Zonotope', 3)

    Each estimate contains the exact set, proven in rational arithmetic at its vertices:

    >>> exact = exact_polytopes(system, X0, ys)
    >>> [proven_contains(Zk, Pk.vertices) for Zk, Pk in zip(Z, exact)]
    [True, True, True]
    """
    if method not in METHODS:
        raise ValueError(f"method must be one of {METHODS}, got {method!r}")
    ys = system.measurements(ys)
    if method in ELLIPSOIDAL:
        return observe_ellipsoids(system, X0, ys, method)
    X = as_initial(X0, system.dim)
    out = []
    if method in ZONOTOPE_GAINS:
        if X.n_constraints:
            raise ValueError("X0 must be a Box, Zonotope or Ellipsoid for the zonotope observers")
        Z = Zonotope(X.center, X.generators)
        for y in ys:
            Z = zonotope_step(system, Z, y, order, ZONOTOPE_GAINS[method])
            out.append(Z)
        return out
    if method == "interval":
        B = X.bounding_box()
        for y in ys:
            B = interval_step(system, B, y)
            out.append(B)
        return out
    for y in ys:
        X = predict_correct(system, X, y)
        if X.is_empty():
            raise EmptySetError("the constrained-zonotope estimate is proven empty")
        if X.n_constraints > max_constraints:
            X = X.eliminate_constraints(X.n_constraints - max_constraints)
        X = X.reduce_order(order)
        out.append(X)
    return out
