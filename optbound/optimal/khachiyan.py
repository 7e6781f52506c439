"""Khachiyan's algorithm for the minimum-volume enclosing ellipsoid (an independent check).

Khachiyan (1996) with the away steps of Todd & Yildirim (2007), started from the initial core
set of Kumar & Yildirim (2005) (``core_set``: at most 2n points) instead of uniform weights:
from uniform weights every interior point needs an away step of its own before the tolerance
can hold, so the iteration count grew with the number of points. Lift the points to
``q_i = [p_i; 1]`` and iterate on weights ``u`` in the simplex. With
``X(u) = sum_i u_i q_i q_i^T`` and ``w_i = q_i^T X(u)^{-1} q_i`` (``d = n + 1``):

- forward step toward the point of largest ``w_j``: ``u <- (1 - s) u + s e_j`` with
  ``s = (w_j - d) / (d (w_j - 1)) > 0``;
- away step from the supporting point of smallest ``w_j``, the same formula (now ``s < 0``),
  limited by ``s >= -u_j / (1 - u_j)`` so the weight stays non-negative.
- or (``exchange=True``) both at once: the vertex-exchange step of Böhning (1986), weight
  ``delta`` moved from the supporting point ``i`` of smallest ``w_i`` to the point ``j`` of
  largest ``w_j``, with the exact line search of ``det X``:
  ``det X' / det X = 1 + delta (w_j - w_i) - delta^2 (w_i w_j - w_ij^2)`` with
  ``w_ij = q_i^T X^{-1} q_j``, so ``delta = min(u_i, (w_j - w_i) / (2 (w_i w_j - w_ij^2)))``.
  Where the points cluster near the contact (the polished points of
  ``optbound.optimal.lower``) the separate steps zigzag, moving weight back and forth
  between neighbours by tiny steps: 20 000 steps instead of 1 700 on a 3-D example.

Stop when ``max w <= (1 + tol) d`` and ``min_{u_i > 0} w_i >= (1 - tol) d``. The ellipsoid
``{x : (x - c)^T H (x - c) <= 1}`` with ``c = P u`` and ``H^{-1} = n (P diag(u) P^T - c c^T)``
then contains every point after scaling by ``sqrt(max level)`` (done, with the float64 margin,
by ``certify_points``), and its volume is within a factor ``(1 + tol)^{d/2}`` of the minimum.
"""

from __future__ import annotations

import numpy as np

from optbound._core.jit import njit
from optbound.optimal.certify import certify_points
from optbound.sets import Ellipsoid

_REFRESH = 500


def covariance(points: np.ndarray, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Weighted mean ``P u`` and covariance ``sum_i u_i (p_i - mean)(p_i - mean)^T``.

    Parameters
    ----------
    points : np.ndarray, shape (m, n)
        The points.
    u : np.ndarray, shape (m,)
        Weights in the simplex.

    Returns
    -------
    mean : np.ndarray, shape (n,)
        The weighted mean.
    cov : np.ndarray, shape (n, n)
        The weighted covariance.
    """
    mean = points.T @ u
    return mean, (points.T * u) @ points - np.outer(mean, mean)


def khachiyan_weights(
    points: np.ndarray,
    tol: float = 1e-7,
    max_iter: int = 100_000,
    start: np.ndarray | None = None,
    away_tol: float | None = None,
    exchange: bool = False,
) -> tuple[np.ndarray, bool]:
    """The weights ``u`` (simplex, ``(m,)``) of Khachiyan's algorithm with away steps.

    ``start``: initial weights (in the simplex, their ellipsoid full-dimensional), e.g. the
    answer for a subset of the points padded with zeros; default: the core set's.
    ``away_tol``: tolerance of the away condition ``min_{u_i > 0} w_i >= (1 - away_tol) d``
    (default ``tol``). ``inf`` stops on ``max w <= (1 + tol) d`` alone: that already puts the
    weights' volume bound within a factor ``(1 + tol d / n)^{n/2}`` of the minimum (every
    point's level in the weights' ellipsoid, shape ``n Sigma``, is at most
    ``1 + tol d / n``), and the away condition, which identifies the support points, can take
    thousands of steps more on clustered points.
    ``exchange``: take exchange steps instead (module docstring).

    A step ``X <- (1 - s) X + s q_j q_j^T`` updates ``X^{-1}`` and all ``w_i`` in O(m d) by the
    Sherman-Morrison formula (an exchange step: two such updates); they are recomputed from
    scratch every ``_REFRESH`` steps to keep rounding from accumulating. The loop is compiled
    (numba): one step costs about a microsecond per hundred points instead of tens of
    microseconds of numpy call overhead.

    Parameters
    ----------
    points : np.ndarray, shape (m, n)
        The points.
    tol : float, default 1e-7
        Stop when ``max w <= (1 + tol) d`` (and the away condition holds).
    max_iter : int, default 100000
        Largest number of steps.
    start : np.ndarray, shape (m,), optional
        Initial weights (default: the core set's).
    away_tol : float, optional
        Tolerance of the away condition (default ``tol``; ``inf`` ignores it).
    exchange : bool, default False
        Take exchange steps instead of forward/away steps.

    Returns
    -------
    u : np.ndarray, shape (m,)
        The weights.
    converged : bool
        Whether the tolerance was reached within ``max_iter`` steps (any weights still give
        the lower bound of ``optbound.optimal.lower``).
    """
    P = np.asarray(points, dtype=float)
    m = P.shape[0]
    Q = np.ascontiguousarray(np.hstack([P, np.ones((m, 1))]))  # rows q_i
    if start is None:
        u = np.zeros(m)
        core = core_set(P)
        u[core] = 1.0 / core.size
    else:
        u = np.array(start, dtype=float)
    away = float(tol if away_tol is None else away_tol)
    converged = _iterate(Q, u, float(tol), away, bool(exchange), int(max_iter), _REFRESH)
    return u, bool(converged)


def core_set(points: np.ndarray) -> np.ndarray:
    """Indices of the Kumar-Yildirim initial core set: at most 2n points whose ellipsoid is
    already within a factor ``n^2`` of the minimum volume [Kumar & Yildirim 2005, Lemma 3.1].

    For each of n directions, orthogonal to the differences of the pairs found so far, the
    points with the largest and the smallest coordinate along it.

    Parameters
    ----------
    points : np.ndarray, shape (m, n)
        The points.

    Returns
    -------
    np.ndarray of int
        Indices of at most 2n distinct points.
    """
    P = np.asarray(points, dtype=float)
    n = P.shape[1]
    basis = np.zeros((0, n))
    chosen: list[int] = []
    for _ in range(n):
        residual = np.eye(n) - basis.T @ basis  # projector off the differences found so far
        b = residual[int(np.argmax(np.sum(residual * residual, axis=0)))]
        along = P @ b
        top, bottom = int(np.argmax(along)), int(np.argmin(along))
        chosen += [top, bottom]
        diff = residual @ (P[top] - P[bottom])
        size = float(np.linalg.norm(diff))
        if size == 0.0:  # the points are flat: no direction left to add
            break
        basis = np.vstack([basis, diff / size])
    return np.unique(np.array(chosen))


@njit(cache=True)
def _refresh(Q: np.ndarray, u: np.ndarray, X_inv: np.ndarray, w: np.ndarray) -> None:
    """``X^{-1}`` and ``w_i = q_i^T X^{-1} q_i`` from scratch (in place)."""
    m, d = Q.shape
    weighted = np.empty((d, m))  # Q^T diag(u), in loops (no array expression)
    for a in range(d):
        for i in range(m):
            weighted[a, i] = Q[i, a] * u[i]
    inverse = np.linalg.inv(weighted @ Q)  # Fortran-ordered, as numba's inverses are
    for a in range(X_inv.shape[0]):
        for b in range(X_inv.shape[1]):
            X_inv[a, b] = inverse[a, b]
    for i in range(Q.shape[0]):
        w[i] = _quad(X_inv, Q[i])


@njit(cache=True)
def _quad(A: np.ndarray, q: np.ndarray) -> float:
    """``q^T A q`` by plain loops (a BLAS call per point would dominate at d <= 7)."""
    total = 0.0
    for a in range(q.shape[0]):
        row = 0.0
        for b in range(q.shape[0]):
            row += A[a, b] * q[b]
        total += q[a] * row
    return total


@njit(cache=True)
def _iterate(
    Q: np.ndarray,
    u: np.ndarray,
    tol: float,
    away_tol: float,
    exchange: bool,
    max_iter: int,
    refresh: int,
) -> bool:
    """Forward and away steps, or exchange steps, on ``u`` (in place) until the tolerance
    holds; whether it did.

    The products ``q_i^T z`` of a step are accumulated column by column over a transposed
    copy of Q: the same sums in the same order as a loop per point, but every column is one
    pass over contiguous memory that the compiler vectorises across the points.
    """
    m, d = Q.shape
    QT = np.ascontiguousarray(Q.T)
    X_inv = np.empty((d, d))
    w = np.empty(m)
    along_up, along_down = np.empty(m), np.empty(m)
    for it in range(max_iter):
        if it % refresh == 0:
            _refresh(Q, u, X_inv, w)
        up, down = np.int64(0), np.int64(-1)  # typed: literals would compile a specialization
        for i in range(m):
            if w[i] > w[up]:
                up = i
            if u[i] > 0.0 and (down < 0 or w[i] < w[down]):
                down = i
        if w[up] <= (1.0 + tol) * d and w[down] >= (1.0 - away_tol) * d:
            return True
        if not exchange:
            _todd_yildirim_step(Q, QT, u, X_inv, w, up, down, along_up)
            continue
        # Not converged, so w[up] >= d > w[down] or w[up] > d >= w[down] (sum u_i w_i = d):
        # the exchange raises det X for small delta.
        z_up = X_inv @ Q[up]
        cross = 0.0
        for a in range(d):
            cross += Q[down, a] * z_up[a]
        curvature = w[up] * w[down] - cross * cross  # >= 0 (Cauchy-Schwarz)
        delta = u[down]
        if curvature > 0.0:
            delta = min(delta, (w[up] - w[down]) / (2.0 * curvature))
        u[up] += delta
        u[down] = max(u[down] - delta, 0.0)
        # Sherman-Morrison twice: + delta q_up q_up^T, then - delta q_down q_down^T.
        den_up = 1.0 + delta * w[up]
        _rank_one(X_inv, z_up, -delta, den_up)
        z_down = X_inv @ Q[down]
        den_down = 1.0 - delta * _quad(X_inv, Q[down])
        _rank_one(X_inv, z_down, delta, den_down)
        _products(QT, z_up, along_up)
        _products(QT, z_down, along_down)
        for i in range(m):
            a_up, a_down = along_up[i], along_down[i]
            w[i] += delta * (a_down * a_down / den_down - a_up * a_up / den_up)
    return False


@njit(cache=True)
def _rank_one(X: np.ndarray, z: np.ndarray, factor: float, denom: float) -> None:
    """``X + factor z z^T / denom`` in place, entry by entry as numpy's
    ``X + factor * np.outer(z, z) / denom`` rounds it (``-factor``: the same as subtracting)."""
    d = z.shape[0]
    for a in range(d):
        for b in range(d):
            X[a, b] = X[a, b] + factor * (z[a] * z[b]) / denom


@njit(cache=True)
def _products(QT: np.ndarray, z: np.ndarray, out: np.ndarray) -> None:
    """``out_i = sum_a Q[i, a] z_a``, summed over ``a`` in order, from ``QT = Q^T``."""
    out[:] = 0.0
    for a in range(QT.shape[0]):
        row, za = QT[a], z[a]
        for i in range(row.shape[0]):
            out[i] += row[i] * za


@njit(cache=True)
def _todd_yildirim_step(Q, QT, u, X_inv, w, up: int, down: int, along: np.ndarray) -> None:
    """A forward step to ``up`` or an away step from ``down``, whichever violates more (in
    place on u, ``X^{-1}`` and w; ``along`` is a buffer of m)."""
    m, d = Q.shape
    j = up if w[up] - d >= d - w[down] else down
    step = (w[j] - d) / (d * (w[j] - 1.0))
    if j == down:
        step = max(step, -u[j] / (1.0 - u[j]))
    for i in range(m):
        u[i] = max(u[i] * (1.0 - step) + (step if i == j else 0.0), 0.0)  # 0: full away step
    # Sherman-Morrison for X' = (1 - s) X + s q_j q_j^T.
    z = X_inv @ Q[j]
    denom = (1.0 - step) + step * w[j]
    _products(QT, z, along)
    for i in range(m):
        qz = along[i]
        w[i] = (w[i] - step * qz * qz / denom) / (1.0 - step)
    for a in range(d):
        for b in range(d):
            X_inv[a, b] = (X_inv[a, b] - step * (z[a] * z[b]) / denom) / (1.0 - step)


def khachiyan_mvee(points: np.ndarray, tol: float = 1e-7, max_iter: int = 100_000) -> Ellipsoid:
    """Near-minimum-volume ellipsoid enclosing ``points`` (m, n), scaled to contain them all.

    The ellipsoid of Khachiyan's weights u (centre ``P u``, shape ``n Sigma_u``), then
    inflated by :func:`~optbound.optimal.certify.certify_points` until every point is inside.

    Parameters
    ----------
    points : np.ndarray, shape (m, n)
        The points.
    tol : float, default 1e-7
        Tolerance of :func:`khachiyan_weights`.
    max_iter : int, default 100000
        Largest number of steps.

    Returns
    -------
    Ellipsoid
        An ellipsoid containing every point, its volume within a factor of about
        ``(1 + tol)^{n/2}`` of the minimum.

    Raises
    ------
    RuntimeError
        If ``max_iter`` iterations do not reach the tolerance.
    CertificationError
        If the inflated ellipsoid cannot be certified.

    Examples
    --------
    The corners of the square ``[-1, 1]^2`` lie on the circle of radius sqrt(2):

    >>> import numpy as np
    >>> from optbound.optimal.khachiyan import khachiyan_mvee
    >>> corners = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])
    >>> E = khachiyan_mvee(corners)
    >>> np.round(E.shape, 6).tolist()
    [[2.0, 0.0], [0.0, 2.0]]
    >>> bool(np.all(E.contains(corners, tol=0.0)))
    True
    """
    P = np.asarray(points, dtype=float)
    u, converged = khachiyan_weights(P, tol, max_iter)
    if not converged:
        raise RuntimeError(f"Khachiyan's algorithm did not converge in {max_iter} iterations")
    center, cov = covariance(P, u)
    return certify_points(Ellipsoid(center, P.shape[1] * cov), P)[0]
