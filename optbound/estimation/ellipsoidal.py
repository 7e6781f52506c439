"""Ellipsoidal observers: Schweppe's predictor and one strip fusion per output row.

One step maps ``E_{k-1}`` by ``A`` (:func:`optbound.analytic.affine.affine_map`, certified),
adds ``W`` with :func:`optbound.analytic.minkowski_sum` (Schweppe's family [HS96, eq. (14)])
and fuses, row by row, the measurement strip ``y_i - hi_i <= c_i^T x <= y_i - lo_i``
(``[lo_i, hi_i]`` the interval hull of ``V``'s i-th coordinate) with
:func:`optbound.analytic.intersect_strip` ([HS96, eq. (24)]). The criterion (``"volume"`` or
``"trace"``) chooses the member of both families; this is the recursion of Schweppe (1968)
and Fogel & Huang (1982) as used by [HS96, Sect. 4] and by ``optbound.localization.tracker``.

Guarantee: each operation returns an outer bound of its exact result, its floats read
exactly. The strip bounds are rounded outward and the float strip ``|a'^T x - b'| <= 1`` is
widened by the rounding of ``a' = a / H``, ``b' = m / H`` over the current ellipsoid
(:func:`measurement_strip`), so every point of the exact set passes every fusion. Noise sets
become ellipsoids as in ``optbound.estimation.noise`` (flat ones are thickened, stated there).
"""

from __future__ import annotations

import numpy as np

from optbound import analytic
from optbound.analytic.affine import affine_map
from optbound.estimation.noise import coordinate_bounds, ellipsoid_of
from optbound.estimation.system import LinearSystem
from optbound.interval import Interval
from optbound.sets.base import EmptySetError
from optbound.sets.certified import row_sum_up
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.strip import Strip

U = 2.0**-53  # unit roundoff of binary64
CRITERIA = {"ellipsoid_volume": "volume", "ellipsoid_trace": "trace"}
WEIGHTS = {"volume": "unit", "trace": "norms"}  # member of Zonotope.outer_ellipsoid per criterion


def measurement_strip(a: np.ndarray, lo: float, hi: float, E: Ellipsoid) -> Strip:
    """A float strip containing ``{x in E : lo <= a^T x <= hi}`` exactly.

    With ``m = fl(lo / 2 + hi / 2)``, ``a' = fl(a / H)``, ``b' = fl(m / H)`` (relative errors
    at most U each), every such x satisfies ``|a'^T x - b'| H <= |a^T x - m| + U (sum_i |a_i|
    |x_i| + |m|)``; H is an upper bound of ``max(hi - m, m - lo) + 2 U (sum_i |a_i| X_i +
    |m|)`` with ``X_i >= |x_i|`` on E's interval hull, so the float strip holds all of them.
    A zero-width interval (``lo == hi``) thus still gives a strip of positive width.

    Parameters
    ----------
    a : numpy.ndarray, shape (n,)
        The strip's normal.
    lo, hi : float
        The bounds on ``a^T x``.
    E : Ellipsoid
        The ellipsoid whose points the strip must keep (it bounds ``|x_i|``).

    Returns
    -------
    Strip
        ``{x : |a'^T x - b'| <= 1}`` holding every x of E with ``lo <= a^T x <= hi``.

    Raises
    ------
    ValueError
        If the strip has zero width at the origin, or a quotient underflows.
    """
    box = Interval(E.center) + Interval(-1.0, 1.0) * np.sqrt(Interval(np.diag(E.shape)))
    X = np.maximum(-box.lo, box.hi)
    m = 0.5 * lo + 0.5 * hi
    total = row_sum_up(np.append((Interval(np.abs(a)) * X).hi, abs(m))[None, :])[0]
    half = max((Interval(hi) - m).hi, (Interval(m) - lo).hi)
    H = float((Interval(half) + Interval(2.0 * U) * total).hi)
    if not H > 0.0:
        raise ValueError("the measurement strip has zero width at the origin: widen V")
    a_new, b_new = a / H, m / H
    quotients = np.append(np.abs(a_new[a != 0]), abs(b_new) if m != 0 else 1.0)
    if np.any(quotients < 1e-290):  # a subnormal quotient would break the U bound
        raise ValueError("the measurement strip is outside the supported domain (underflow)")
    return Strip(a_new, b_new)


def initial_ellipsoid(X0, criterion: str) -> Ellipsoid:
    """``X0`` (Ellipsoid, Zonotope or Box) as an enclosing ellipsoid (``noise.ellipsoid_of``).

    Parameters
    ----------
    X0 : Ellipsoid, Zonotope or Box
        The set of ``x_0``.
    criterion : {"volume", "trace"}
        Selects the enclosing member (:data:`WEIGHTS`).

    Returns
    -------
    Ellipsoid
        An ellipsoid containing ``X0`` (``X0`` itself if it is one).

    Raises
    ------
    TypeError
        If ``X0`` is of another type.
    ValueError
        If ``X0`` is a single point.
    """
    return ellipsoid_of(X0, WEIGHTS[criterion])


def predict(system: LinearSystem, E: Ellipsoid, criterion: str, W: Ellipsoid) -> Ellipsoid:
    """Schweppe's outer ellipsoid of ``A E + W`` (certified affine map, then
    :func:`optbound.analytic.minkowski_sum` with ``criterion``).

    Parameters
    ----------
    system : LinearSystem
        The model (its A is used).
    E : Ellipsoid
        The ellipsoid containing ``X_{k-1}``.
    criterion : {"volume", "trace"}
        The member of Schweppe's family.
    W : Ellipsoid
        The process-noise ellipsoid.

    Returns
    -------
    Ellipsoid
        An ellipsoid containing ``A E + W``.

    Notes
    -----
    Schweppe's family [HS96, eq. (14)]: for ``E = E(c, Q)`` and ``W = E(c_W, Q_W)``, every
    ``E(A c + c_W, A Q A^T / (1 - kappa) + Q_W / kappa)`` with kappa in (0, 1) contains
    ``A E + W``; ``criterion`` picks kappa.
    """
    return analytic.minkowski_sum(affine_map(E, system.A), W, criterion=criterion).ellipsoid


def measurement_strips(system: LinearSystem, y: np.ndarray, E: Ellipsoid) -> list[Strip]:
    """One float strip per output row holding every x of ``E`` with ``y - C x in`` the box hull
    of ``V`` (bounds rounded outward, :func:`measurement_strip`).

    Parameters
    ----------
    system : LinearSystem
        The model (its C and V are used).
    y : numpy.ndarray, shape (p,)
        The measurement.
    E : Ellipsoid
        The prediction whose points the strips must keep.

    Returns
    -------
    list of Strip
        One strip per row of C.
    """
    Vb = coordinate_bounds(system.V)
    lo = (Interval(y) - Vb.hi).lo
    hi = (Interval(y) - Vb.lo).hi
    return [measurement_strip(row, float(lo[i]), float(hi[i]), E) for i, row in enumerate(system.C)]


def ellipsoid_step(
    system: LinearSystem, E: Ellipsoid, y: np.ndarray, criterion: str, W: Ellipsoid
) -> Ellipsoid:
    """One predict-correct step (module docstring); ``W`` is the noise ellipsoid.

    Parameters
    ----------
    system : LinearSystem
        The model.
    E : Ellipsoid
        The ellipsoid containing ``X_{k-1}``.
    y : numpy.ndarray, shape (p,)
        The measurement of ``x_k``.
    criterion : {"volume", "trace"}
        The member of Schweppe's family and of the strip-fusion family.
    W : Ellipsoid
        The process-noise ellipsoid.

    Returns
    -------
    Ellipsoid
        An ellipsoid containing ``X_k`` whenever ``E`` contains ``X_{k-1}``.

    Raises
    ------
    EmptySetError
        If a fusion proves the prediction and a measurement strip disjoint.
    """
    pred = predict(system, E, criterion, W)
    for i, strip in enumerate(measurement_strips(system, y, pred)):
        pred = analytic.intersect_strip(pred, strip, criterion=criterion).ellipsoid
        if pred is None:
            raise EmptySetError(f"the ellipsoid estimate misses the measurement strip of row {i}")
    return pred


def observe_ellipsoids(system: LinearSystem, X0, ys: np.ndarray, method: str) -> list[Ellipsoid]:
    """The sets ``[E_1, ..., E_N]`` of ``method`` in ``CRITERIA`` (module docstring).

    Parameters
    ----------
    system : LinearSystem
        The model.
    X0 : Ellipsoid, Zonotope or Box
        The set of ``x_0``.
    ys : numpy.ndarray, shape (N, p)
        The measurements (already checked by :meth:`LinearSystem.measurements`).
    method : {"ellipsoid_volume", "ellipsoid_trace"}
        The observer.

    Returns
    -------
    list of Ellipsoid
        One ellipsoid per measurement, each containing the exact set ``X_k``.

    Raises
    ------
    ValueError
        If ``X0`` does not have the system's dimension.
    optbound.sets.base.EmptySetError
        If a fusion proves the estimate empty.
    """
    criterion = CRITERIA[method]
    W = ellipsoid_of(system.W, WEIGHTS[criterion])
    E = initial_ellipsoid(X0, criterion)
    if E.dim != system.dim:
        raise ValueError(f"X0 must have dimension {system.dim}, got {E.dim}")
    out = []
    for y in ys:
        E = ellipsoid_step(system, E, y, criterion, W)
        out.append(E)
    return out
