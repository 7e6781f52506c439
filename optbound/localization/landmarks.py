"""Pose from bearings to known landmarks [HS96, Sect. 3]: linear solver, exact set, fast bound.

A robot at ``(x, y)`` with heading ``psi`` measures the bearing ``alpha_i`` (radians, robot
frame, counter-clockwise) of landmark ``L_i``: ``alpha_i + psi = atan2(L_iy - y, L_ix - x)``
[HS96, eq. (18)] (eq. (3) prints the atan2 arguments swapped; eq. (18) is the convention that
makes eqs. (5)-(6) hold).

With ``gamma_i = alpha_{i+1} - alpha_i`` (indices modulo N), each pair gives [HS96, eq. (5)]::

    A_i = g_i^T (x, y) - (x^2 + y^2),
    A_i = x_i x_{i+1} + y_i y_{i+1} + cot(gamma_i) (x_{i+1} y_i - y_{i+1} x_i),
    g_i = (cot(gamma_i) (y_i - y_{i+1}) + x_{i+1} + x_i,
           cot(gamma_i) (x_{i+1} - x_i) + y_{i+1} + y_i),

and subtracting each equation's follower removes the quadratic term: ``z = H (x, y)^T`` with
``z_i = A_i - A_{i+1}``, ``h_i = g_i - g_{i+1}``, i = 0 .. N - 2 [HS96, eq. (6)]. Note: the
printed eq. (6) has ``x_{i+1}`` / ``y_{i+1}`` where ``g_i - g_{i+1}`` gives ``x_i`` / ``y_i``
in ``h_i``; the printed form does not recover the position (tested), the difference of eq. (5)
does.

Three functions, from cheapest to exact:

- :func:`linear_position`: least squares on eq. (6), exact on noise-free data, not a bound;
- :func:`linear_position_bound`: a guaranteed (x, y) box from eq. (6) with interval-valued
  ``H`` and ``z`` over all landmark pairs (preconditioned 2 x 2 interval system: exact
  regularity test, Cramer's rule, Gauss-Seidel);
- :func:`pose_paving`: the guaranteed (x, y, psi) set by interval set inversion of the bearing
  equations (the error propagation [HS96, Sect. 3] leaves out of scope).

Under the model contract of :mod:`optbound.localization` the last two are also named
:func:`localize` and :func:`exact_paving`.
"""

from __future__ import annotations

import math

import numpy as np

from optbound._core import validate as v
from optbound._core.jit import njit
from optbound.interval import Interval, Paving, Tri, atan2, intersection, pave, sqrt
from optbound.sets import Box, Ellipsoid

#: Default relative singularity threshold: smallest singular value of H over the size of the
#: terms that cancel in it (see :func:`linear_position`).
SINGULAR_RTOL = 1e-8
#: An outward enclosure of 2 pi: ``2 * np.pi`` is the correctly rounded value.
TWO_PI = Interval(np.nextafter(2.0 * np.pi, -np.inf), np.nextafter(2.0 * np.pi, np.inf))
GAUSS_SEIDEL_SWEEPS = 4
#: Rounds of the adaptive default resolution of :func:`pose_paving`.
REFINE = 3


# ----------------------------------------------------------------------------- validation
def as_landmarks(name: str, value, min_count: int = 1) -> np.ndarray:
    """Validate an (N, 2) array of finite real landmark positions."""
    arr = v.finite_matrix(name, v.real_array(name, value, "an (N, 2) array"), (None, 2))
    if arr.shape[0] < min_count:
        raise ValueError(f"{name} needs at least {min_count} landmarks, got {arr.shape[0]}")
    return arr


def as_angles(name: str, value, count: int | None = None) -> np.ndarray:
    """Validate a 1-D array of finite real angles (radians), optionally of a given length."""
    arr = v.finite_vector(name, value)
    if count is not None and arr.shape[0] != count:
        raise ValueError(f"{name} must have {count} entries (one per landmark), got {arr.shape[0]}")
    return arr


def as_bound(name: str, value) -> float:
    """Validate a finite, non-negative error bound."""
    out = v.finite_scalar(name, value)
    if out < 0.0:
        raise ValueError(f"{name} must be non-negative, got {out}")
    return out


def as_shapes(name: str, value, count: int) -> np.ndarray:
    """Landmark error ellipses ``C_i`` of [HS96, eq. (2)] as a (count, 2, 2) PSD array.

    ``None`` means exact landmarks (all zero); one (2, 2) matrix is shared by all landmarks.
    """
    if value is None:
        return np.zeros((count, 2, 2))
    arr = v.real_array(name, value)
    arr = np.broadcast_to(arr, (count, 2, 2)) if arr.shape == (2, 2) else arr
    if arr.shape != (count, 2, 2):
        raise ValueError(f"{name} must have shape ({count}, 2, 2) or (2, 2), got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite")
    if not np.allclose(arr, arr.transpose(0, 2, 1), rtol=1e-12, atol=0.0):
        raise ValueError(f"{name} must be symmetric")
    if np.any(np.linalg.eigvalsh(arr)[:, 0] < 0.0):
        raise ValueError(f"{name} must be positive semi-definite")
    return np.array(arr, dtype=float)


# ----------------------------------------------------------------------- linear solution
@njit(cache=True)
def _solve(L: np.ndarray, alphas: np.ndarray) -> tuple:
    """Least squares on eq. (6); returns (x, y, psi, s_min, scale, s_max, bad_pair).

    ``bad_pair`` >= 0 flags a pair of bearings equal modulo pi (cot(gamma) infinite).
    """
    n = L.shape[0]
    # Centred coordinates: eq. (5) is translation covariant and cancels less when centred.
    mx, my = 0.0, 0.0
    for i in range(n):
        mx += L[i, 0] / n
        my += L[i, 1] / n
    A = np.empty(n)
    gx = np.empty(n)
    gy = np.empty(n)
    size = np.empty(n)  # magnitude of the terms summed into g_i
    for i in range(n):
        j = (i + 1) % n
        gamma = alphas[j] - alphas[i]
        s = math.sin(gamma)
        if abs(s) < 1e-12:
            return 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, i
        cot = math.cos(gamma) / s
        xi, yi, xj, yj = L[i, 0] - mx, L[i, 1] - my, L[j, 0] - mx, L[j, 1] - my
        A[i] = xi * xj + yi * yj + cot * (xj * yi - yj * xi)
        gx[i] = cot * (yi - yj) + xj + xi
        gy[i] = cot * (xj - xi) + yj + yi
        size[i] = abs(cot) * math.hypot(xj - xi, yj - yi) + math.hypot(xi, yi) + math.hypot(xj, yj)
    # Normal equations of the (N-1) x 2 system; scale = size of the terms that cancel in H.
    m00 = m01 = m11 = r0 = r1 = 0.0
    scale = 0.0
    for i in range(n - 1):
        hx, hy = gx[i] - gx[i + 1], gy[i] - gy[i + 1]
        z = A[i] - A[i + 1]
        m00 += hx * hx
        m01 += hx * hy
        m11 += hy * hy
        r0 += hx * z
        r1 += hy * z
        scale = max(scale, size[i] + size[i + 1])
    half_tr = 0.5 * (m00 + m11)
    root = math.hypot(0.5 * (m00 - m11), m01)
    s_max = math.sqrt(half_tr + root)
    det = m00 * m11 - m01 * m01
    s_min = math.sqrt(max(det, 0.0) / (half_tr + root)) if half_tr + root > 0.0 else 0.0
    if det <= 0.0:
        return 0.0, 0.0, 0.0, s_min, scale, s_max, -1
    x = mx + (m11 * r0 - m01 * r1) / det
    y = my + (m00 * r1 - m01 * r0) / det
    # Heading: circular mean of atan2(L_i - p) - alpha_i over all landmarks.
    sx = sy = 0.0
    for i in range(n):
        psi_i = math.atan2(L[i, 1] - y, L[i, 0] - x) - alphas[i]
        sx += math.cos(psi_i)
        sy += math.sin(psi_i)
    return x, y, math.atan2(sy, sx), s_min, scale, s_max, -1


def linear_position(landmarks, alphas, rtol: float = SINGULAR_RTOL) -> tuple[float, float, float]:
    """Robot pose from N >= 3 bearings by the N - 1 linear equations [HS96, eqs. (5)-(6)].

    Parameters
    ----------
    landmarks : array_like, shape (N, 2)
        Positions of the landmarks the bearings belong to (in any order).
    alphas : array_like, shape (N,)
        Bearings in radians, robot frame, counter-clockwise: ``alpha_i + psi =
        atan2(L_iy - y, L_ix - x)`` [HS96, eq. (18)].
    rtol : float
        Singularity threshold (see Raises).

    Returns
    -------
    (x, y, psi) : tuple of float
        Least-squares position of eq. (6) and the heading as the circular mean of
        ``atan2(L_i - p) - alpha_i`` over all landmarks, in (-pi, pi]. Exact (to rounding) on
        noise-free data; with noisy data it is an estimate, not a bound (see
        :func:`linear_position_bound`, :func:`pose_paving`).

    Raises
    ------
    ValueError
        N < 3; two bearings equal modulo pi (the robot is in line with two landmarks); or H
        singular or nearly so: ``s_min(H) < rtol * scale``, where scale is the size of the terms
        summed into ``g_i`` and ``g_{i+1}`` (in coordinates centred on the landmarks), whose
        difference forms H's rows. With the robot on the circle
        through the landmarks H vanishes entirely while cond(H) can stay small [HS96 known
        fact], so H is judged against the terms that cancel in it; the message gives that
        relative condition number and cond(H).
    """
    L = as_landmarks("landmarks", landmarks, min_count=3)
    a = as_angles("alphas", alphas, L.shape[0])
    rtol = as_bound("rtol", rtol)
    x, y, psi, s_min, scale, s_max, bad = _solve(L, a)
    if bad >= 0:
        j = (bad + 1) % L.shape[0]
        raise ValueError(
            f"bearings {bad} and {j} are equal modulo pi (the robot is in line with landmarks "
            f"{bad} and {j}): cot(gamma_{bad}) of [HS96, eq. (5)] is infinite"
        )
    if not s_min > rtol * scale:
        rel = scale / s_min if s_min > 0.0 else math.inf
        cond = s_max / s_min if s_min > 0.0 else math.inf
        raise ValueError(
            "the linear system of [HS96, eq. (6)] is singular or nearly so (robot on or near the "
            "circle through the landmarks, or collinear with them): relative condition number "
            f"scale/s_min(H) = {rel:.3g} > 1/rtol = {1 / rtol:.3g} (cond(H) = {cond:.3g})"
        )
    return x, y, psi


# ------------------------------------------------------------------ interval ingredients
def _boxed(L: np.ndarray, shapes: np.ndarray) -> tuple[Interval, Interval]:
    """Outward boxes ``L_i +- sqrt(diag C_i)`` enclosing the landmark ellipses [HS96, eq. (2)]."""
    half = sqrt(Interval(np.diagonal(shapes, axis1=1, axis2=2))).hi
    return (
        Interval(L[:, 0]) + Interval(-half[:, 0], half[:, 0]),
        Interval(L[:, 1]) + Interval(-half[:, 1], half[:, 1]),
    )


def _cot(gamma: Interval) -> Interval:
    """Tight ``cot`` of intervals inside one branch ``(k pi, (k + 1) pi)`` (it decreases there)."""
    at_hi, at_lo = (np.cos(Interval(e)) / np.sin(Interval(e)) for e in (gamma.hi, gamma.lo))
    return Interval(at_hi.lo, at_lo.hi)


def _pair_equations(Lx: Interval, Ly: Interval, alphas: np.ndarray, delta: float):
    """Eq. (5) of every landmark pair whose bearing difference provably avoids multiples of pi.

    Eq. (5) holds for any pair ``(i, j)`` with ``gamma = alpha_j - alpha_i`` (the circle
    through ``L_i``, ``L_j`` and the robot), and it is symmetric in ``i``, ``j``; taking all
    pairs ``i < j`` makes the system independent of the landmarks' order. Returns ``(c, u,
    w, base, cross)`` per usable pair, with ``g = c u + w`` and ``A = base + c cross``, so each
    interval ``c = cot(gamma)`` enters every later sum once.
    """
    i, j = np.triu_indices(alphas.shape[0], 1)
    err = Interval(-2.0 * delta, 2.0 * delta) if delta > 0.0 else Interval(0.0)
    gamma = Interval(alphas[j]) - Interval(alphas[i]) + err
    sin_g = np.sin(gamma)
    usable = (sin_g.lo > 0.0) | (sin_g.hi < 0.0)
    c = _cot(gamma[usable])
    finite = np.isfinite(c.lo) & np.isfinite(c.hi)  # sin at an end point may round to 0
    i, j, c = i[usable][finite], j[usable][finite], c[finite]
    xi, yi, xj, yj = Lx[i], Ly[i], Lx[j], Ly[j]
    u, w = (yi - yj, xj - xi), (xi + xj, yi + yj)
    return c, u, w, xi * xj + yi * yj, xj * yi - yj * xi


def _weighted_sum(D: np.ndarray, items: Interval) -> Interval:
    """``sum_k D[k] items[k]`` for interval weights ``D`` (each entry an Interval)."""
    terms = D * items
    total = terms[0]
    for k in range(1, terms.shape[0]):
        total = total + terms[k]
    return total


def _zero_sum_weights(D: np.ndarray) -> Interval:
    """Enclosures of weights ``R_k - R_{k-1}`` (``R`` the cumulative sums of ``D``, ``R_{-1} =
    R_{K-1} = 0``): exactly zero-sum, so they cancel the ``|p|^2`` of eq. (5), and close to
    ``D``. Combining eq. (5) with them is combining the differences of eq. (6) with ``R``."""
    R = np.cumsum(D)
    R[-1] = 0.0
    return Interval(R) - Interval(np.r_[0.0, R[:-1]])


def linear_position_bound(landmarks, alphas, delta_alpha: float, landmark_shapes=None) -> Box:
    """Guaranteed (x, y) box from eq. (6) with interval-valued ``H`` and ``z`` [HS96, Sect. 3].

    Every term of eq. (5) is evaluated in outward-rounded interval arithmetic over the
    bearing errors ``|d alpha_i| <= delta_alpha`` and the landmark errors (each ellipse
    [HS96, eq. (2)] enclosed in its bounding box), for every landmark pair whose bearing
    difference provably avoids multiples of pi (so the order of the landmarks does not
    matter), in coordinates centred on the landmarks. Eq. (5) is linear in ``(x, y, |p|^2)``;
    the weighted least-squares inverse ``D`` of its midpoint (rows weighted by their interval
    radius) is turned into exactly zero-sum weights, which cancel ``|p|^2`` as eq. (6) does.
    With ``p0`` the midpoint solution, ``q = p - p0`` solves ``M q = b``, ``M = sum_k D_k
    g_k^T``, ``b = sum_k D_k (A_k - g_k^T p0)``, where each ``cot(gamma_k)`` enters every entry
    once (so the entries are tight). The 2 x 2 interval matrix ``M`` is regular iff its
    determinant, evaluated with each entry once, excludes 0; ``q`` is then enclosed by
    Cramer's rule and refined by interval Gauss-Seidel sweeps.

    Parameters
    ----------
    landmarks, alphas
        As in :func:`linear_position`.
    delta_alpha : float
        Bound on the bearing errors (radians).
    landmark_shapes : array_like, optional
        (N, 2, 2) or (2, 2) landmark error ellipses ``C_i``; default exact landmarks.

    Returns
    -------
    Box
        2-D box containing the true position (a guaranteed outer bound; it ignores the
        correlations between entries of ``M`` and ``b``, so it is loose when errors are large
        or the geometry is poor).

    Raises
    ------
    ValueError
        Bad inputs, N < 3, fewer than three landmark pairs whose bearings provably differ
        from a multiple of pi, an interval matrix ``M`` that is not provably regular (errors
        too large or the geometry near singular), or bearings that no position fits within
        the bounds.

    References
    ----------
    .. [HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
       on an angle measurement technique", IFAC, 1996.

    Examples
    --------
    Four landmarks at the corners of a room, robot at (1, 1) heading 0.2 rad, bearings
    known to 0.01 rad:

    >>> L = np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]])
    >>> alphas = np.arctan2(L[:, 1] - 1.0, L[:, 0] - 1.0) - 0.2
    >>> box = linear_position_bound(L, alphas, 0.01)
    >>> bool(box.contains([1.0, 1.0])), bool(np.all(box.widths < 0.1))
    (True, True)
    """
    L = as_landmarks("landmarks", landmarks, min_count=3)
    a = as_angles("alphas", alphas, L.shape[0])
    delta = as_bound("delta_alpha", delta_alpha)
    shapes = as_shapes("landmark_shapes", landmark_shapes, L.shape[0])
    mean = L.mean(axis=0)
    Lx, Ly = _boxed(L, shapes)
    c, u, w, base, cross = _pair_equations(Lx - mean[0], Ly - mean[1], a, delta)
    if c.shape[0] < 3:
        raise ValueError(
            "fewer than three landmark pairs have bearings that provably differ from a multiple "
            "of pi within the error bound: cot(gamma) of [HS96, eq. (5)] is unbounded, no "
            "finite bound exists"
        )
    g = [c * u[m] + w[m] for m in range(2)]
    A = base + c * cross
    # Weighted least squares on eq. (5) as linear in (x, y, |p|^2): rows scaled by 1 / radius.
    radius = 0.5 * (A.width() + np.abs(L - mean).max() * (g[0].width() + g[1].width()))
    scale = 1.0 / (radius + np.finfo(float).tiny)
    lifted = np.column_stack([g[0].midpoint(), g[1].midpoint(), -np.ones(c.shape[0])])
    D = (np.linalg.pinv(lifted * scale[:, None]) * scale)[:2]
    p0 = D @ A.midpoint()
    weights = [_zero_sum_weights(D[k]) for k in range(2)]
    M = [[_weighted_sum(weights[k], g[m]) for m in range(2)] for k in range(2)]
    rest = base - (w[0] * p0[0] + w[1] * p0[1]) + c * (cross - (u[0] * p0[0] + u[1] * p0[1]))
    b = [_weighted_sum(weights[k], rest) for k in range(2)]
    det = M[0][0] * M[1][1] - M[0][1] * M[1][0]
    if not (det.lo > 0.0 or det.hi < 0.0):
        raise ValueError(
            "the interval system of [HS96, eq. (6)] is not provably regular (the determinant "
            f"of the preconditioned 2 x 2 interval matrix spans [{det.lo:.3g}, {det.hi:.3g}]): "
            "the errors are too large for this geometry"
        )
    q = [(b[0] * M[1][1] - M[0][1] * b[1]) / det, (M[0][0] * b[1] - M[1][0] * b[0]) / det]
    for _ in range(GAUSS_SEIDEL_SWEEPS):
        for k in range(2):
            if M[k][k].lo > 0.0 or M[k][k].hi < 0.0:
                q[k] = intersection(q[k], (b[k] - M[k][1 - k] * q[1 - k]) / M[k][k])
    # Every pair equation must still admit the box: the true position satisfies all of them.
    fits = not (bool(q[0].is_empty) or bool(q[1].is_empty))
    if fits:
        X, Y = Interval(p0[0]) + q[0], Interval(p0[1]) + q[1]
        row = g[0] * X + g[1] * Y - (X**2 + Y**2) - A
        fits = bool(np.all((row.lo <= 0.0) & (row.hi >= 0.0)))
    if not fits:
        raise ValueError(
            "the bearings are inconsistent with the error bounds: no position solves the "
            "interval system of [HS96, eq. (6)]"
        )
    X, Y = X + mean[0], Y + mean[1]
    return Box(np.array([X.lo, Y.lo], dtype=float), np.array([X.hi, Y.hi], dtype=float))


# ------------------------------------------------------------------------- exact pose set
def _windows(psi_lo: float, psi_hi: float, alphas: np.ndarray) -> np.ndarray:
    """Integers k such that ``atan2(...) - psi - alpha_i`` can be near ``2 pi k``."""
    lo = -np.pi - psi_hi - alphas.max()
    hi = np.pi - psi_lo - alphas.min()
    return np.arange(math.floor(lo / (2 * np.pi)) - 1, math.ceil(hi / (2 * np.pi)) + 2)


def _ellipsoid_test(prior: Ellipsoid):
    """Tri test of ``|U (z - c)|^2 <= 1`` with ``U^T U`` the float inverse of the prior's shape."""
    U = np.linalg.cholesky(np.linalg.inv(prior.shape)).T
    c = prior.center

    def test(*z):
        d = [z[i] - c[i] for i in range(3)]
        total = None
        for row in U:
            u = d[0] * row[0] + d[1] * row[1] + d[2] * row[2]
            total = u * u if total is None else total + u * u
        return np.where(total.hi <= 1.0, Tri.TRUE, np.where(total.lo > 1.0, Tri.FALSE, Tri.UNKNOWN))

    return test


def _sight(theta, dx, dy, C, radius):
    """For lines of direction ``theta`` from the robot to a landmark offset ``(dx, dy)``:

    ``(n^T d)^2 - n^T C n`` (<= 0 iff the line meets the ellipse ``C`` around the landmark,
    ``n`` the line's normal) and ``u^T d + radius`` (< 0: the whole ellipse is behind).
    """
    s, c = np.sin(theta), np.cos(theta)
    spread = C[0, 0] * s**2 + C[1, 1] * c**2 - 2.0 * C[0, 1] * (s * c)
    return (c * dy - s * dx) ** 2 - spread, c * dx + s * dy + radius


def _bearing_test(L, shapes, alphas, delta, ks):
    """Tri test of all bearing constraints on boxes of (x, y, psi) (see :func:`pose_paving`).

    TRUE: the nominal landmark's bearing lies in ``alpha_i + psi +- delta`` (mod 2 pi) on the
    whole box, or the line of direction ``alpha_i + psi`` meets the ellipse, entirely ahead of
    the robot, on the whole box. FALSE: for every direction
    ``theta = alpha_i + psi + [-delta, delta]`` of the box, the line from the robot misses the
    landmark ellipse (``(n^T (L - p))^2 > n^T C n`` with ``n`` the line's normal), or the whole
    ellipse lies behind the robot (its disc of radius ``sqrt(lambda_max(C))``, rounded up,
    does).
    """
    lows = [k * TWO_PI - delta for k in ks]
    highs = [k * TWO_PI + delta for k in ks]
    radius = np.sqrt(np.maximum(np.linalg.eigvalsh(shapes)[:, 1], 0.0)) * (1 + 1e-9) + 1e-300
    window = Interval(-delta, delta)

    def test(x, y, psi):
        tri = None
        for i in range(alphas.shape[0]):
            dx, dy = L[i, 0] - x, L[i, 1] - y
            nominal = atan2(dy, dx) - psi - alphas[i]
            inside = np.zeros(nominal.shape, dtype=bool)
            for lo_k, hi_k in zip(lows, highs, strict=True):
                inside |= (nominal.lo >= lo_k.hi) & (nominal.hi <= hi_k.lo)
            # Inner also when the line at d alpha = 0 meets the ellipse ahead on the whole box.
            meet0, ahead0 = _sight(psi + alphas[i], dx, dy, shapes[i], radius[i])
            inside |= (meet0.hi <= 0.0) & (ahead0.lo - 2.0 * radius[i] > 0.0)
            meet, ahead = _sight(psi + alphas[i] + window, dx, dy, shapes[i], radius[i])
            miss, behind = meet.lo > 0.0, ahead.hi < 0.0
            t_i = np.where(inside, Tri.TRUE, np.where(miss | behind, Tri.FALSE, Tri.UNKNOWN))
            tri = t_i if tri is None else np.minimum(tri, t_i)
        return tri.astype(np.int8)

    return test


def heading_bound(L, Lx, Ly, alphas, delta, xy: Box) -> Interval:
    """Guaranteed heading interval for positions in ``xy``: intersection over the bearings.

    Each bearing gives ``psi in atan2(L_i - p) - alpha_i + [-delta, delta]`` (mod 2 pi);
    intervals narrower than pi are shifted by 2 pi k onto the first one and intersected.

    Parameters
    ----------
    L : numpy.ndarray, shape (N, 2)
        Landmark positions.
    Lx, Ly : Interval, shape (N,)
        Boxes enclosing the landmark ellipses [HS96, eq. (2)].
    alphas : numpy.ndarray, shape (N,)
        Measured bearings (radians).
    delta : float
        Bound on the bearing errors (radians).
    xy : Box
        2-D box of positions.

    Returns
    -------
    Interval
        Heading interval centred in ``[-pi, pi]``, containing every heading consistent with
        a position of ``xy``; ``[-pi, pi]`` if no bearing is informative, empty if the
        bearings are inconsistent.
    """
    x, y = Interval(xy.lo[0], xy.hi[0]), Interval(xy.lo[1], xy.hi[1])
    out = None
    for i in range(alphas.shape[0]):
        psi_i = atan2(Ly[i] - y, Lx[i] - x) - alphas[i] + Interval(-delta, delta)
        if float(psi_i.hi - psi_i.lo) >= np.pi:
            continue
        if out is None:
            out = psi_i
            continue
        k = round((float(psi_i.midpoint()) - float(out.midpoint())) / (2 * np.pi))
        out = intersection(out, psi_i - k * TWO_PI)
    if out is None or bool(out.is_empty):
        return Interval(-np.pi, np.pi) if out is None else out
    return out - round(float(out.midpoint()) / (2 * np.pi)) * TWO_PI  # centre in [-pi, pi]


def pose_test(landmarks, alphas, delta_alpha: float, landmark_shapes=None, psi_range=None):
    """The three-valued test of :func:`pose_paving`'s set on ``Interval`` ``(x, y, psi)`` boxes.

    ``psi_range`` ``(lo, hi)`` (default ``(-pi, pi)``): the headings the test must handle
    (boxes of other headings can only lose TRUE answers, never get a wrong one).

    Parameters
    ----------
    landmarks : array_like, shape (N, 2)
        Landmark positions.
    alphas : array_like, shape (N,)
        Measured bearings (radians).
    delta_alpha : float
        Bound on the bearing errors (radians).
    landmark_shapes : array_like, optional
        (N, 2, 2) or (2, 2) landmark error ellipses ``C_i``; default exact landmarks.
    psi_range : tuple of float, optional
        ``(lo, hi)`` headings the test must handle; default ``(-pi, pi)``.

    Returns
    -------
    callable
        ``test(x, y, psi)`` on ``Interval`` boxes: TRUE / FALSE / UNKNOWN per box.

    Raises
    ------
    ValueError
        On malformed landmarks, bearings, bound or shapes.
    """
    L = as_landmarks("landmarks", landmarks, min_count=1)
    a = as_angles("alphas", alphas, L.shape[0])
    delta = as_bound("delta_alpha", delta_alpha)
    shapes = as_shapes("landmark_shapes", landmark_shapes, L.shape[0])
    lo, hi = (-np.pi, np.pi) if psi_range is None else psi_range
    return _bearing_test(L, shapes, a, delta, _windows(lo, hi, a))


def pose_paving(
    landmarks,
    alphas,
    delta_alpha: float,
    landmark_shapes=None,
    X0=None,
    eps: float | None = None,
    prior: Ellipsoid | None = None,
) -> Paving:
    """Guaranteed pose set ``(x, y, psi)`` by interval set inversion of the bearings.

    The set is ``{(x, y, psi) : exists |d alpha_i| <= delta_alpha and landmark errors in the
    ellipses [HS96, eq. (2)] with alpha_i - d alpha_i + psi = atan2(L~_iy - y, L~_ix - x)
    (mod 2 pi) for all i}`` -- the exact error propagation of [HS96, Sect. 3] (no
    linearization). A box is *outside* when some bearing's line of sight misses the landmark's
    ellipse (or the ellipse is behind the robot) for every point of the box and every
    admissible angle error; it is *inner* when the nominal landmarks satisfy every bearing
    constraint on the whole box.
    So ``inner ⊂ set ⊂ inner ∪ boundary`` holds exactly (with outward rounding).

    Parameters
    ----------
    landmarks, alphas, delta_alpha, landmark_shapes
        As in :func:`linear_position_bound`.
    X0 : array_like (3, 2) or Box, optional
        Initial box of ``(x, y, psi)``; default the prior's bounding box if a prior is given,
        else the (guaranteed) box of :func:`linear_position_bound` times the heading interval
        it implies.
    eps : float, optional
        Paving resolution (widest side of an undecided box). Default: ``REFINE`` rounds, each
        paving at 1/40 of the current box's widest side and re-paving the hull of the result
        (the hull contains the set, so each round stays guaranteed).
    prior : Ellipsoid, optional
        A 3-D set the pose is also known to lie in (e.g. a predicted set), taken as
        ``{z : |U (z - c)|^2 <= 1}`` with ``U^T U`` the float inverse of its shape (the
        ellipsoid that representation defines, a rounding away from ``prior``).

    Returns
    -------
    Paving
        With ``.hull()`` (``None`` if the set is empty) and ``.components()``.

    Raises
    ------
    ValueError
        On malformed landmarks, bearings, bounds or shapes, an ``X0`` that is not a bounded
        3-D box with volume, or the errors of :func:`linear_position_bound` when ``X0`` and
        ``prior`` are not given.

    Examples
    --------
    >>> L = np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]])
    >>> alphas = np.arctan2(L[:, 1] - 1.0, L[:, 0] - 1.0) - 0.2
    >>> hull = pose_paving(L, alphas, 0.01, eps=0.02).hull()
    >>> bool(hull.contains([1.0, 1.0, 0.2])), bool(hull.widths[2] < 0.05)
    (True, True)
    """
    L = as_landmarks("landmarks", landmarks, min_count=1)
    a = as_angles("alphas", alphas, L.shape[0])
    delta = as_bound("delta_alpha", delta_alpha)
    shapes = as_shapes("landmark_shapes", landmark_shapes, L.shape[0])
    Lx, Ly = _boxed(L, shapes)
    given = X0 is not None
    if X0 is None and prior is not None:
        X0 = prior.bounding_box()
    elif X0 is None:
        xy = linear_position_bound(L, a, delta, shapes)
        psi = heading_bound(L, Lx, Ly, a, delta, xy)
        if bool(psi.is_empty):
            psi = Interval(-np.pi, np.pi)
        X0 = Box(np.r_[xy.lo, psi.lo], np.r_[xy.hi, psi.hi])
    elif not isinstance(X0, Box):
        X0 = Box.from_array(X0)
    if X0.dim != 3 or not X0.is_bounded:
        raise ValueError(f"X0 must be a bounded 3-D box of (x, y, psi), got {X0}")
    if given and not np.all(X0.widths > 0.0):
        raise ValueError(f"X0 must have a positive width on every axis, got widths {X0.widths}")
    ks = _windows(X0.lo[2], X0.hi[2], a)
    test = [_bearing_test(L, shapes, a, delta, ks)]
    if prior is not None:
        if not isinstance(prior, Ellipsoid) or prior.dim != 3:
            raise TypeError("prior must be a 3-D Ellipsoid of (x, y, psi)")
        test.append(_ellipsoid_test(prior))
    if eps is not None:
        return pave(test, X0, eps)
    # Adaptive default: pave coarsely, then re-pave the (guaranteed) hull, REFINE times.
    for _ in range(REFINE):
        paving = pave(test, X0, float(np.max(X0.widths)) / 40.0)
        hull = paving.hull()
        if hull is None:
            return paving
        X0 = hull
    return paving


# --------------------------------------------------------------- the model contract's verbs
#: The guaranteed bound of one scan (:mod:`optbound.localization` contract): the (x, y) box.
localize = linear_position_bound
#: The paving of the exact pose set.
exact_paving = pose_paving

__all__ = [
    "GAUSS_SEIDEL_SWEEPS",
    "REFINE",
    "SINGULAR_RTOL",
    "TWO_PI",
    "exact_paving",
    "heading_bound",
    "linear_position",
    "linear_position_bound",
    "localize",
    "pose_paving",
    "pose_test",
]
