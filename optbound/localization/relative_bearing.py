"""Relative-bearing localization with pseudo-ellipsoids [BH, Sects. II, IV, V].

A relative bearing between landmarks ``L_i`` and ``L_j`` seen from the position ``x`` is
[BH, eq. (2)]

    gamma_ij(x) = atan2(y - y_Li, x - x_Li) - atan2(y - y_Lj, x - x_Lj)   (wrapped to (-pi, pi]),

measured as ``gamma_hat = gamma_ij(x) + v``, ``|v| <= eps``. The feasible set of one
measurement is the crescent ``M_ij`` between two circles through the landmarks.

- **Exact set** (:func:`exact_paving`): SIVIA on ``|wrap(gamma_ij(x) - gamma_hat)| <= eps``
  written with one interval ``atan2`` (:func:`~.geometry.bearing_residual`), conjoined with
  the same constraint in sign form (:func:`~.geometry.bearing_sides`), independent of the
  rings.
- **Circle of constant bearing** (:func:`circle`) [BH, eqs. (17)-(19)]: centre
  ``M = (L_i + L_j) / 2 - cot(gamma) Delta_perp / 2`` (``Delta_perp`` the counter-clockwise
  rotation of ``L_j - L_i``), radius ``|L_j - L_i| / (2 |sin gamma|)``; for ``gamma > 0`` the
  arc lies on the clockwise side of ``L_i -> L_j``.
- **Rings** (:func:`rings`) [BH, eqs. (20)-(21), Fig. 3]: with ``g = |gamma_hat|``, circle 1
  of bearing ``g + eps`` (the crescent lies outside it) and circle 2 of ``g - eps`` (the
  crescent lies inside it). Along the symmetry axis the arc apex of bearing ``phi`` sits at
  ``a cot(phi / 2)`` from the chord (``a = |L_j - L_i| / 2``), so the ring thickness is the
  apex distance ``d = a [cot((g - eps) / 2) - cot((g + eps) / 2)]``: ring 1 is
  ``r1 <= |x - M1| <= r1 + d``, ring 2 is ``max(r2 - d, 0) <= |x - M2| <= r2`` (the clamp at
  0 is needed when ``M2`` lies outside circle 1, which happens for small ``g``). The crescent
  is exactly disc 2 minus the open disc 1 (the caps of the discs beyond the chord are nested the
  other way), so no extra linear constraint is needed, and it lies in both rings.
- **Pseudo-linear forms**: each ring is the distance measurement ``w = |x - M|^2`` in
  ``[lo^2, hi^2]``; ``w - |M|^2 = [-2 x_M, -2 y_M, 1, 1] [x, y, x^2, y^2]^T`` is one strip
  row in R^4 [BH, eq. (22)] (order 1), and ``eta(w) = [w, w^2]`` gives the two rows of
  [BH, eqs. (23)-(26)] in R^8 with the parabola-arc noise ellipse (order 2). The noise
  intervals printed after [BH, eq. (22)] have the sign convention of ``v = w - z_hat``, the
  opposite of [BH, eq. (11)]; here the interval is derived from the ring itself:
  ``v = z_hat - w`` with ``z_hat = (r1 + d/2)^2`` resp. ``(r2 - d/2)^2`` [BH, eq. (21)].

Numerics ("BH filter numerics" in the documentation's *Guarantees and numerics* page): the
filter runs in coordinates
``u = (x - o) / s`` centred and scaled on a box that provably contains the feasible set (the
intersection of the bounding boxes of the discs 2), and the prior is the smallest axis-aligned
lifted ellipsoid around the interval image of that box: it contains the lifted feasible set,
so it is non-informative in the sense of [BH, Sect. V] (``X^P ∩ X^M = X^M``), yet of the
problem's own size, so the lifted shapes stay well conditioned.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from optbound._core import validate as v
from optbound.analytic import lifted_update, parabola_arc_ellipse
from optbound.interval import Paving, constraint, pave, tri_and
from optbound.localization.geometry import bearing_residual, bearing_sides, wrap_angle
from optbound.sets import Box, Ellipsoid, PolynomialLifting, PseudoEllipsoid, QuadraticSet
from optbound.sets.pseudo_ellipsoid import CoverProof
from optbound.sets.result import BoundResult

ORDERS = (1, 2)
# Relative outward margin of the prior box and of the prior's lifted shape (rounding cover).
_PRIOR_MARGIN = 1e-9


# ----------------------------------------------------------------------------- validation
@dataclass(frozen=True)
class Measurements:
    """Validated relative-bearing data (built by :func:`measurements`).

    Parameters
    ----------
    landmarks : numpy.ndarray, shape (N, 2)
        Landmark positions.
    pairs : numpy.ndarray of int64, shape (P, 2)
        Landmark index pairs ``(i, j)``, one per measurement.
    gammas : numpy.ndarray, shape (P,)
        Measured relative bearings, wrapped to ``(-pi, pi]``.
    eps : numpy.ndarray, shape (P,)
        Noise bounds, in ``(0, pi/2)``.
    """

    landmarks: np.ndarray
    pairs: np.ndarray
    gammas: np.ndarray
    eps: np.ndarray

    def __len__(self) -> int:
        return self.pairs.shape[0]

    def pair(self, k: int) -> tuple[np.ndarray, np.ndarray, float, float]:
        """Return ``(L_i, L_j, gamma_hat, eps)`` of measurement k.

        Parameters
        ----------
        k : int
            Index of the measurement.

        Returns
        -------
        L_i, L_j : numpy.ndarray, shape (2,)
            The two landmarks.
        gamma_hat, eps : float
            The measured bearing and its noise bound.
        """
        i, j = self.pairs[k]
        return self.landmarks[i], self.landmarks[j], float(self.gammas[k]), float(self.eps[k])


def measurements(landmarks, pairs, gammas, eps) -> Measurements:
    """Validate the data of :func:`localize` / :func:`exact_paving`.

    Parameters
    ----------
    landmarks : array_like, shape (N, 2)
        Landmark positions (N >= 2).
    pairs : array_like of int, shape (P, 2)
        Landmark index pairs ``(i, j)``, ``i != j``.
    gammas : array_like, shape (P,)
        Measured relative bearings [rad].
    eps : float or array_like, shape (P,)
        Noise bound(s) [rad], in ``(0, pi/2)``.

    Returns
    -------
    Measurements
        The data as float / int64 arrays, bearings wrapped to ``(-pi, pi]``, ``eps`` one per
        pair.

    Raises
    ------
    TypeError
        ``pairs`` not integer index pairs.
    ValueError
        Non-finite or mis-shaped landmarks, indices out of range or equal, coincident
        landmarks in a pair, ``gamma`` equal to 0 or pi (after wrapping), ``eps`` not in
        ``(0, pi/2)``, or lengths that disagree.
    """
    L = v.finite_matrix("landmarks", _real("landmarks", landmarks), (None, 2))
    if L.shape[0] < 2:
        raise ValueError(f"landmarks must hold at least 2 points, got {L.shape[0]}")
    P = np.asarray(pairs)
    if P.size == 0:
        raise ValueError("pairs must not be empty")
    if not np.issubdtype(P.dtype, np.integer):
        raise TypeError(f"pairs must be integer (i, j) index pairs, got {pairs!r}")
    if P.ndim != 2 or P.shape[1] != 2:
        raise ValueError(f"pairs must be a sequence of (i, j) pairs, got shape {P.shape}")
    if np.any(P < 0) or np.any(P >= L.shape[0]):
        raise ValueError(f"pairs must index landmarks 0..{L.shape[0] - 1}, got {P.tolist()}")
    if np.any(P[:, 0] == P[:, 1]):
        raise ValueError("pairs must join two different landmarks (i != j)")
    if np.any(np.all(L[P[:, 0]] == L[P[:, 1]], axis=1)):
        raise ValueError("landmarks of a pair must not coincide (no bearing circle exists)")
    g = v.finite_vector("gammas", _real("gammas", gammas), P.shape[0])
    g = wrap_angle(g)
    if np.any(g == 0.0) or np.any(np.abs(g) == np.pi):
        raise ValueError("gammas must not be 0 or pi: the bearing locus is a line, not a circle")
    e = _real("eps", eps)
    if e.ndim > 1 or e.size not in (1, g.size):
        raise ValueError(f"eps must be a scalar or one value per pair ({g.size}), got {e.shape}")
    e = np.broadcast_to(e.astype(float), g.shape).copy()
    if not np.all(np.isfinite(e)):
        raise ValueError("eps must be finite")
    if np.any(e <= 0.0) or np.any(e >= np.pi / 2):
        raise ValueError(f"eps must lie in (0, pi/2) radians, got {e.tolist()}")
    return Measurements(L, P.astype(np.int64), g, e)


def _real(name: str, value) -> np.ndarray:
    """``value`` as a numeric real array, or a TypeError naming the argument."""
    arr = np.asarray(value)
    if arr.dtype.kind not in "biuf":
        raise TypeError(f"{name} must be real numbers, got dtype {arr.dtype}")
    return arr


# ------------------------------------------------------------------------- the exact set
def exact_tests(data: Measurements) -> list:
    """Two SIVIA tests per measurement: ``|bearing_residual| <= eps`` and its sign form.

    The atan2 form is the constraint of [BH, eq. (2)] itself; :func:`~.geometry.bearing_sides`
    states the same set without a branch cut, so that boxes on the circle's other arc can be
    excluded.

    Parameters
    ----------
    data : Measurements
        Validated measurements (:func:`measurements`).

    Returns
    -------
    list of callable
        ``2 P`` three-valued tests ``test(x, y)``.
    """
    tests = []
    for k in range(len(data)):
        li, lj, g, e = data.pair(k)

        def residual(x, y, li=li, lj=lj, g=g):
            return bearing_residual(x, y, li, lj, g)

        def sides(x, y, li=li, lj=lj, g=g, e=e):
            return bearing_sides(x, y, li, lj, g, e)

        tests.append(constraint(residual, [[-e, e]]))
        tests.append(constraint(sides, [[0.0, np.inf], [0.0, np.inf]]))
    return tests


def in_exact_set(data: Measurements, X) -> np.ndarray:
    """Test float64 membership of points in the exact feasible set (for plots and samples).

    Parameters
    ----------
    data : Measurements
        Validated measurements (:func:`measurements`).
    X : array_like, shape (m, 2) or (2,)
        Points.

    Returns
    -------
    numpy.ndarray of bool, shape (m,)
        ``|wrap(gamma_ij(x) - gamma_hat)| <= eps`` for every measurement, in float64 (not
        certified).
    """
    pts, _ = v.points("X", X, 2)
    ok = np.ones(pts.shape[0], dtype=bool)
    for k in range(len(data)):
        li, lj, g, e = data.pair(k)
        ok &= np.abs(bearing_residual(pts[:, 0], pts[:, 1], li, lj, g)) <= e
    return ok


def exact_paving(landmarks, pairs, gammas, eps, X0, eps_paving: float) -> Paving:
    """Paving of the exact feasible set from the angle constraints themselves [BH, Sect. II].

    Parameters
    ----------
    landmarks, pairs, gammas, eps
        As in :func:`localize`.
    X0 : (2, 2) rows or Box
        Search box.
    eps_paving : float
        Boxes at most this wide are not bisected.

    Returns
    -------
    Paving
        Inner, boundary and outside boxes of ``{x in X0 : |wrap(gamma_ij(x) - gamma_hat)| <=
        eps for every pair}``.

    Raises
    ------
    ValueError, TypeError
        Bad input (see :func:`measurements` and :func:`~optbound.interval.sivia.pave`).
    """
    data = measurements(landmarks, pairs, gammas, eps)
    return pave(exact_tests(data), X0, eps_paving)


# ----------------------------------------------------------------------- circles and rings
def circle(li, lj, gamma: float) -> tuple[np.ndarray, float]:
    """Compute the circle of constant bearing ``gamma`` [BH, eqs. (18)-(19)].

    Parameters
    ----------
    li, lj : array_like, shape (2,)
        The two landmarks.
    gamma : float
        The relative bearing [rad], not 0 or pi.

    Returns
    -------
    center : numpy.ndarray, shape (2,)
        ``M = (L_i + L_j) / 2 - cot(gamma) Delta_perp / 2``.
    radius : float
        ``|L_j - L_i| / (2 |sin gamma|)``.
    """
    li, lj = np.asarray(li, dtype=float), np.asarray(lj, dtype=float)
    delta = lj - li
    perp = np.array([-delta[1], delta[0]])  # counter-clockwise rotation
    center = li + 0.5 * delta - 0.5 / np.tan(gamma) * perp
    return center, float(np.linalg.norm(delta) / (2.0 * abs(np.sin(gamma))))


@dataclass(frozen=True)
class Ring:
    """A ring ``lo <= |x - center| <= hi`` and its nominal squared radius [BH, eq. (21)].

    Parameters
    ----------
    center : numpy.ndarray, shape (2,)
        The ring's centre M.
    lo, hi : float
        Inner and outer radius.
    z_hat : float
        The nominal squared radius ``z_hat`` of the pseudo-linear measurement.
    """

    center: np.ndarray
    lo: float
    hi: float
    z_hat: float

    def quadratics(self) -> list[QuadraticSet]:
        """Return the ring as QuadraticSets: ``|x - M|^2 <= hi^2`` and, if lo > 0, ``>= lo^2``.

        Returns
        -------
        list of QuadraticSet
            One or two quadratic constraints.
        """
        M = self.center
        out = [QuadraticSet.from_parts(np.eye(2), -M, M @ M - self.hi**2)]
        if self.lo > 0:
            out.append(QuadraticSet.from_parts(-np.eye(2), M, self.lo**2 - M @ M))
        return out

    def noise_interval(self) -> tuple[float, float]:
        """Return the range of ``v = z_hat - |x - M|^2`` over the ring.

        Returns
        -------
        lo, hi : float
            ``z_hat - hi^2`` and ``z_hat - lo^2`` ([BH, eq. (11)] sign convention).
        """
        return self.z_hat - self.hi**2, self.z_hat - self.lo**2


@dataclass(frozen=True)
class Rings:
    """The two rings of one relative bearing [BH, eqs. (20)-(21), Fig. 3] and thickness d.

    Parameters
    ----------
    outer : Ring
        Ring 1, ``r1 <= |x - M1| <= r1 + d`` (the crescent is outside circle 1).
    inner : Ring
        Ring 2, ``max(r2 - d, 0) <= |x - M2| <= r2`` (the crescent is inside circle 2).
    d : float
        Ring thickness ``a [cot((g - eps) / 2) - cot((g + eps) / 2)]``.
    """

    outer: Ring  # ring 1: r1 <= |x - M1| <= r1 + d (the crescent is outside circle 1)
    inner: Ring  # ring 2: max(r2 - d, 0) <= |x - M2| <= r2 (the crescent is inside circle 2)
    d: float

    def __iter__(self):
        return iter((self.outer, self.inner))


def rings(li, lj, gamma_hat: float, eps: float) -> Rings:
    """Compute the rings whose intersection is the crescent ``M_ij`` (module docstring).

    Parameters
    ----------
    li, lj : array_like, shape (2,)
        The two landmarks.
    gamma_hat : float
        Measured relative bearing [rad].
    eps : float
        Noise bound [rad], in ``(0, pi/2)``.

    Returns
    -------
    Rings
        Ring 1 of bearing ``|gamma_hat| + eps``, ring 2 of ``|gamma_hat| - eps`` and their
        thickness.

    Raises
    ------
    ValueError
        Unless ``eps < |gamma_hat| < pi - eps``: otherwise the feasible set contains points
        on both sides of the landmarks' line (or far away) and is no crescent.
    """
    data = measurements(np.array([li, lj]), [(0, 1)], [gamma_hat], eps)
    li, lj, g_hat, e = data.pair(0)
    g, sign = abs(g_hat), np.sign(g_hat)
    if not e < g < np.pi - e:
        raise ValueError(
            f"rings need eps < |gamma| < pi - eps, got |gamma| = {g}, eps = {e}: the feasible "
            "set is not a crescent"
        )
    a = 0.5 * float(np.linalg.norm(lj - li))
    d = a * (1.0 / np.tan(0.5 * (g - e)) - 1.0 / np.tan(0.5 * (g + e)))
    m1, r1 = circle(li, lj, sign * (g + e))
    m2, r2 = circle(li, lj, sign * (g - e))
    outer = Ring(m1, r1, r1 + d, (r1 + 0.5 * d) ** 2)
    inner = Ring(m2, max(r2 - d, 0.0), r2, (r2 - 0.5 * d) ** 2)
    return Rings(outer, inner, float(d))


def all_rings(data: Measurements) -> list[Rings]:
    """Compute the rings of every measurement, in order.

    Parameters
    ----------
    data : Measurements
        Validated measurements (:func:`measurements`).

    Returns
    -------
    list of Rings
        One per measurement.

    Raises
    ------
    ValueError
        If a bearing gives no crescent (see :func:`rings`).
    """
    return [rings(*data.pair(k)) for k in range(len(data))]


# -------------------------------------------------------------------------- lifted rows
def lifting(order: int, offset, scale: float) -> PolynomialLifting:
    """Build the L = 4 (order 1, [BH, eq. (22)]) or L = 8 (order 2, [BH, eq. (23)]) lifting.

    Parameters
    ----------
    order : {1, 2}
        The lifting order.
    offset : array_like, shape (2,)
        Origin o of the filter's frame ``u = (x - o) / s``.
    scale : float
        Scale s of the filter's frame.

    Returns
    -------
    PolynomialLifting
        The L = 4 or L = 8 lifting in that frame.

    Raises
    ------
    ValueError
        If ``order`` is not 1 or 2.
    """
    if order not in ORDERS:
        raise ValueError(f"order must be 1 (L = 4) or 2 (L = 8), got {order!r}")
    return (
        PolynomialLifting.bh4(offset, scale) if order == 1 else PolynomialLifting.bh8(offset, scale)
    )


def ring_rows(ring: Ring, order: int, offset, scale: float):
    """``(H, z, V, v_center)`` of one ring in the lifted frame ``u = (x - offset) / scale``.

    Order 1: one row ``w - |M|^2`` with the interval noise as a strip [BH, eq. (22)].
    Order 2: rows ``w - |M|^2`` and ``w^2 - |M|^4`` [BH, eqs. (24)-(26)] with the noise ellipse
    of the parabola arc ``eta([lo^2, hi^2])`` (``analytic.parabola_arc_ellipse``).

    The arc's ellipse has axes of order ``r w0`` and ``r^2 / w0`` (``w0``, ``r``: midpoint and
    half-width of ``[lo^2, hi^2]``), so its condition number grows like ``(w0 / r)^4``; for a
    ring far larger than its thickness in the filter's frame (``|gamma_hat|`` near
    ``pi - eps``, where circle 1 becomes a line, or a prior box small against the ring) it is
    singular in float64. Such a ring contributes only its first row with the strip noise: the
    same row as order 1, a valid and weaker constraint, so the bound stays guaranteed.

    Parameters
    ----------
    ring : Ring
        The ring.
    order : {1, 2}
        The lifting order.
    offset : array_like, shape (2,)
        Origin of the filter's frame.
    scale : float
        Scale of the filter's frame.

    Returns
    -------
    H : numpy.ndarray, shape (k, L)
        Measurement rows in the lifted coordinates.
    z : array_like, shape (k,)
        Pseudo-measurement.
    V : array_like, shape (k, k)
        Shape of the noise ellipsoid (a strip's half-width squared when k = 1).
    v_center : array_like, shape (k,)
        Centre of the noise set.
    """
    xm, ym = (ring.center - offset) / scale
    m2 = xm * xm + ym * ym
    s2 = scale * scale
    z_hat = ring.z_hat / s2
    v_lo, v_hi = (b / s2 for b in ring.noise_interval())
    strip = [z_hat - m2], [[(0.5 * (v_hi - v_lo)) ** 2]], [0.5 * (v_lo + v_hi)]
    if order == 1:
        return np.array([[-2.0 * xm, -2.0 * ym, 1.0, 1.0]]), *strip
    first = [-2.0 * xm, -2.0 * ym, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0]
    arc = parabola_arc_ellipse(ring.lo**2 / s2, ring.hi**2 / s2)
    try:
        v.spd_matrix("V", arc.shape)
    except ValueError:
        return np.array([first]), *strip
    H = np.array(
        [
            first,
            [
                -4.0 * xm * m2,
                -4.0 * ym * m2,
                8.0 * xm * ym,
                6.0 * xm * xm + 2.0 * ym * ym,
                2.0 * xm * xm + 6.0 * ym * ym,
                -4.0 * xm,
                -4.0 * ym,
                1.0,
            ],
        ]
    )
    eta_hat = np.array([z_hat, z_hat * z_hat])
    # z* = eta(z_hat) - [|M|^2, |M|^4]; v* = eta(z_hat) - eta(w) ranges over the reflected arc.
    return H, eta_hat - np.array([m2, m2 * m2]), arc.shape, eta_hat - arc.center


# ----------------------------------------------------------------------------- the filter
def prior_box(data: Measurements, ring_list: Sequence[Rings] | None = None) -> Box:
    """Bound the feasible set by the intersection of the bounding boxes of discs 2.

    Parameters
    ----------
    data : Measurements
        Validated measurements (:func:`measurements`).
    ring_list : sequence of Rings, optional
        The rings of ``data`` if already computed.

    Returns
    -------
    Box
        The box, widened by a relative margin of 1e-9 to cover rounding.

    Raises
    ------
    ValueError
        If the discs do not intersect (inconsistent measurements).
    """
    ring_list = all_rings(data) if ring_list is None else ring_list
    lo = np.max([r.inner.center - r.inner.hi for r in ring_list], axis=0)
    hi = np.min([r.inner.center + r.inner.hi for r in ring_list], axis=0)
    if np.any(lo > hi):
        raise ValueError("the measurements are inconsistent: their discs do not intersect")
    pad = _PRIOR_MARGIN * (np.abs(lo) + np.abs(hi) + (hi - lo))
    return Box(lo - pad, hi + pad)


def lifted_prior(lift: PolynomialLifting, box: Box) -> PseudoEllipsoid:
    """Smallest axis-aligned lifted ellipsoid around the interval image of ``box``.

    ``T(box)`` lies in the image box ``[c - h, c + h]`` (interval arithmetic), and that box
    lies in ``{sum_k (x*_k - c_k)^2 / (L h_k^2) <= 1}`` (its corners are on the boundary).

    Parameters
    ----------
    lift : PolynomialLifting
        The lifting T.
    box : Box
        The prior box of positions.

    Returns
    -------
    PseudoEllipsoid
        A lifted ellipsoid containing ``T(box)``.
    """
    img = lift.box_image(np.stack([box.lo, box.hi], axis=-1)[None])[0]
    c = 0.5 * (img[:, 0] + img[:, 1])
    h = np.maximum(img[:, 1] - c, c - img[:, 0]) * (1.0 + _PRIOR_MARGIN)
    return PseudoEllipsoid(lift, c, np.diag(lift.size * h * h))


@dataclass(frozen=True)
class BearingResult(BoundResult):
    """Result of :func:`localize`.

    As a ``BoundResult``: ``set`` is ``bound``, certified; ``margin`` is the largest relative
    inflation any ring update applied (``analytic.lifted_update``).

    Parameters
    ----------
    bound : PseudoEllipsoid or None
        The final bound (None if proven empty).
    steps : list of PseudoEllipsoid
        The bound after each pair.
    prior : PseudoEllipsoid
        The lifted prior.
    lams : list of float
        The lambda of each ring update.
    margins : list of float
        The certified relative inflation of each ring update.
    """

    set_attribute = "bound"
    certified = True

    bound: PseudoEllipsoid | None
    steps: list[PseudoEllipsoid]
    prior: PseudoEllipsoid
    lams: list[float]
    margins: list[float] = field(default_factory=list)

    @property
    def margin(self) -> float:
        return max(self.margins, default=0.0)


def localize(
    landmarks,
    pairs,
    gammas,
    eps,
    order: int = 2,
    criterion: str = "volume",
    prior: Box | None = None,
) -> BearingResult:
    """Pseudo-ellipsoidal localization from relative bearings [BH, Sects. IV-V].

    Parameters
    ----------
    landmarks : array_like, shape (N, 2)
        Landmark positions.
    pairs : sequence of (i, j)
        Landmark index pairs, one per measurement.
    gammas : array_like, shape (P,)
        Measured relative bearings in radians [BH, eq. (2)].
    eps : float or array_like (P,)
        Noise bound(s) in radians, in (0, pi/2).
    order : {1, 2}
        1: L = 4 lifting [BH, eq. (22)]; 2: L = 8 with eta(z) = [z, z^2] [BH, eq. (23)].
    criterion : {"volume", "area"}
        Choice of lambda in each update (``analytic.lifted_update``).
    prior : Box, optional
        Prior knowledge of the position (default :func:`prior_box`, which provably contains
        the feasible set, so that the prior is non-informative); the bound contains the
        feasible set ∩ prior. The filter's frame and lifted prior are built on it.

    Returns
    -------
    BearingResult
        Each ring is one update (two per pair), in the order of [BH, eq. (20)].

    Raises
    ------
    ValueError, TypeError
        Bad input (see :func:`measurements` and :func:`rings`).

    Notes
    -----
    Each ring ``lo <= |x - M| <= hi`` is the pseudo-linear measurement ``z_hat = |x - M|^2 +
    v`` [BH, eq. (21)], linear in the lifted coordinates ``[x, y, x^2, y^2]`` [BH, eq. (22)]
    (order 1) or, with ``eta(w) = [w, w^2]``, in the L = 8 lifting [BH, eqs. (23)-(26)]
    (order 2); each is fused with the current pseudo-ellipsoid by the certified update of
    ``analytic.lifted_update``.

    References
    ----------
    .. [BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
       bearing measurements", IEEE Transactions on Robotics and Automation, 2004.

    Examples
    --------
    The setting of [BH, Sect. V]: vehicle at the origin, three landmarks, eps = 4 degrees:

    >>> L = np.array([[0.0, 1.0], [1.0, 1.0], [-1.0, 0.0]])
    >>> pairs = [(2, 0), (0, 1), (1, 2)]
    >>> gammas = bearings([0.0, 0.0], L, pairs)
    >>> np.degrees(gammas).round(9).tolist()
    [90.0, 45.0, -135.0]
    >>> result = localize(L, pairs, gammas, np.radians(4))
    >>> len(result.steps), bool(result.bound.contains([0.0, 0.0]))
    (3, True)
    """
    data = measurements(landmarks, pairs, gammas, eps)
    ring_list = all_rings(data)
    box = prior_box(data, ring_list) if prior is None else prior
    if not isinstance(box, Box) or box.dim != 2 or not box.is_bounded:
        raise ValueError(f"prior must be a bounded 2-D Box, got {prior!r}")
    offset = 0.5 * (box.lo + box.hi)
    scale = float(0.5 * np.max(box.hi - box.lo))
    lift = lifting(order, offset, scale)
    prior = lifted_prior(lift, box)
    P, steps, lams, margins = prior, [], [], []
    for pair_rings in ring_list:
        for ring in pair_rings:
            H, z, V, v_center = ring_rows(ring, order, offset, scale)
            update = lifted_update(P, H, z, V, v_center, criterion=criterion)
            lams.append(update.lam)
            margins.append(update.margin)
            if update.bound is None:
                return BearingResult(None, steps, prior, lams, margins)
            P = update.bound
        steps.append(P)
    return BearingResult(P, steps, prior, lams, margins)


# ---------------------------------------------------------------------- containment proof
def exact_test(data: Measurements):
    """Build the conjunction of :func:`exact_tests`: one Tri test of the exact set on boxes.

    Parameters
    ----------
    data : Measurements
        Validated measurements (:func:`measurements`).

    Returns
    -------
    callable
        ``test(x, y)``: TRUE / FALSE / UNKNOWN per box.
    """
    tests = exact_tests(data)

    def test(*coords):
        return tri_and(*(t(*coords) for t in tests))

    return test


def certify_contains(bound: PseudoEllipsoid, data: Measurements, paving: Paving) -> CoverProof:
    """Prove ``exact set ⊂ bound`` by ``bound.tri_contains`` on the paving's inner ∪ boundary.

    Boxes not proven inside at once (boundary boxes stick out of the exact set by up to their
    width) are bisected, and sub-boxes the exact tests prove disjoint from the set are dropped
    (``PseudoEllipsoid.prove_covers``).

    Parameters
    ----------
    bound : PseudoEllipsoid
        The bound to certify.
    data : Measurements
        Validated measurements (:func:`measurements`).
    paving : Paving
        A paving of the exact set (:func:`exact_paving`).

    Returns
    -------
    CoverProof
        The outcome of ``PseudoEllipsoid.prove_covers``.

    Raises
    ------
    TypeError
        Naming an argument of another type.
    """
    for name, value, kind in (
        ("bound", bound, PseudoEllipsoid),
        ("data", data, Measurements),
        ("paving", paving, Paving),
    ):
        if not isinstance(value, kind):
            raise TypeError(f"{name} must be a {kind.__name__}, got {type(value).__name__}")
    return bound.prove_covers(paving.outer(), exact_test(data))


def bound_ellipse_quadratics(data: Measurements) -> list[QuadraticSet]:
    """List every ring of every measurement as QuadraticSets.

    Parameters
    ----------
    data : Measurements
        Validated measurements (:func:`measurements`).

    Returns
    -------
    list of QuadraticSet
        The input of ``optimal.outer_ellipsoid``.
    """
    return [q for pair_rings in all_rings(data) for ring in pair_rings for q in ring.quadratics()]


@dataclass(frozen=True)
class EllipseBracket:
    """Bracket of the smallest ellipse containing the exact set (:func:`best_ellipse`).

    Parameters
    ----------
    sdp : Ellipsoid
        The S-procedure SDP ellipse.
    boxes : Ellipsoid
        The MVEE of the paving's box corners.
    best : Ellipsoid
        The smaller of the two (both certified outer ellipses).
    lower : float
        An area no outer ellipse of the exact set can beat (weak duality, ``optimal.lower``).
    """

    sdp: Ellipsoid
    boxes: Ellipsoid
    best: Ellipsoid
    lower: float


def best_ellipse(data: Measurements, paving: Paving) -> EllipseBracket:
    """Bracket of the smallest ellipse containing the exact set [BH, Sect. III-B, "Tighter bound"].

    - ``sdp``: ``optimal.outer_ellipsoid`` of the rings [BH, eqs. (20)-(21)] ∩ the paving's
      hull. The rings' "outside a disc" constraints are non-convex, the S-procedure relaxation
      is loose, and the hull's four linear constraints (which contain the exact set and select
      the arcs' part of the plane) are what make it usable; its ``lower_bound`` is a
      weak-duality bound on points of the set (``optimal.lower``), valid for every outer
      ellipse;
    - ``boxes``: ``optimal.mvee`` of the corners of every inner and boundary box, certified to
      contain them, hence (being convex) every box and the exact set.

    Cost: one SDP with ``lower_bound=True`` plus one MVEE over the corners.

    Parameters
    ----------
    data : Measurements
        Validated measurements (:func:`measurements`).
    paving : Paving
        A paving of the exact set (:func:`exact_paving`).

    Returns
    -------
    EllipseBracket
        The two outer ellipses, the smaller one and the lower bound on the optimal area.
    """
    from optbound import optimal  # cvxpy is imported only when a reference is asked for

    sdp = optimal.outer_ellipsoid(
        [*bound_ellipse_quadratics(data), paving.hull()], lower_bound=True
    )
    outer = paving.outer()
    corners = np.unique(
        np.concatenate([outer[:, [0, 1], [i, j]] for i in (0, 1) for j in (0, 1)]), axis=0
    )
    boxes = optimal.mvee(corners).ellipsoid
    best = boxes if boxes.volume() < sdp.ellipsoid.volume() else sdp.ellipsoid
    return EllipseBracket(sdp.ellipsoid, boxes, best, float(sdp.lower_bound))


# ------------------------------------------------------------------------------ measurement
def bearings(x, landmarks, pairs) -> np.ndarray:
    """Compute noise-free relative bearings [BH, eq. (2)] of landmark pairs seen from ``x``.

    Parameters
    ----------
    x : array_like, shape (2,)
        Position of the vehicle.
    landmarks : array_like, shape (N, 2)
        Landmark positions.
    pairs : sequence of (i, j)
        Landmark index pairs.

    Returns
    -------
    numpy.ndarray, shape (P,)
        ``wrap(atan2(y - y_Li, x - x_Li) - atan2(y - y_Lj, x - x_Lj))`` per pair, in
        ``(-pi, pi]``.
    """
    L = np.asarray(landmarks, dtype=float)
    ang = np.arctan2(x[1] - L[:, 1], x[0] - L[:, 0])
    return wrap_angle([ang[i] - ang[j] for i, j in pairs])


#: The model contract's measurement verb (:mod:`optbound.localization`).
measure = bearings


__all__ = [
    "ORDERS",
    "BearingResult",
    "EllipseBracket",
    "Measurements",
    "Ring",
    "Rings",
    "all_rings",
    "bearings",
    "best_ellipse",
    "bound_ellipse_quadratics",
    "certify_contains",
    "circle",
    "exact_paving",
    "exact_test",
    "exact_tests",
    "in_exact_set",
    "lifted_prior",
    "lifting",
    "localize",
    "measure",
    "measurements",
    "prior_box",
    "ring_rows",
    "rings",
]
