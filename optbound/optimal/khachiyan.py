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
from numba import njit

from optbound.optimal.certify import certify_points
from optbound.sets import Ellipsoid

_REFRESH = 500


def covariance(points: np.ndarray, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Weighted mean ``P u`` and covariance ``sum_i u_i (p_i - mean)(p_i - mean)^T``."""
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

    Returns the weights and whether the tolerance was reached within ``max_iter`` steps (any
    weights still give the lower bound of ``optbound.optimal.lower``).

    A step ``X <- (1 - s) X + s q_j q_j^T`` updates ``X^{-1}`` and all ``w_i`` in O(m d) by the
    Sherman-Morrison formula (an exchange step: two such updates); they are recomputed from
    scratch every ``_REFRESH`` steps to keep rounding from accumulating. The loop is compiled
    (numba): one step costs about a microsecond per hundred points instead of tens of
    microseconds of numpy call overhead.
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
    X_inv[:, :] = np.linalg.inv((Q.T * u) @ Q)
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
    holds; whether it did."""
    m, d = Q.shape
    X_inv = np.empty((d, d))
    w = np.empty(m)
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
            X_inv = _todd_yildirim_step(Q, u, X_inv, w, up, down)
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
        X_inv = X_inv - delta * np.outer(z_up, z_up) / den_up
        z_down = X_inv @ Q[down]
        den_down = 1.0 - delta * _quad(X_inv, Q[down])
        X_inv = X_inv + delta * np.outer(z_down, z_down) / den_down
        for i in range(m):
            a_up, a_down = 0.0, 0.0
            for a in range(d):
                a_up += Q[i, a] * z_up[a]
                a_down += Q[i, a] * z_down[a]
            w[i] += delta * (a_down * a_down / den_down - a_up * a_up / den_up)
    return False


@njit(cache=True)
def _todd_yildirim_step(Q, u, X_inv, w, up: int, down: int) -> np.ndarray:
    """A forward step to ``up`` or an away step from ``down``, whichever violates more (in
    place on u and w); the new ``X^{-1}``."""
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
    for i in range(m):
        qz = 0.0
        for a in range(d):
            qz += Q[i, a] * z[a]
        w[i] = (w[i] - step * qz * qz / denom) / (1.0 - step)
    return (X_inv - step * np.outer(z, z) / denom) / (1.0 - step)


def khachiyan_mvee(points: np.ndarray, tol: float = 1e-7, max_iter: int = 100_000) -> Ellipsoid:
    """Near-minimum-volume ellipsoid enclosing ``points`` (m, n), scaled to contain them all.

    Raises
    ------
    RuntimeError
        If ``max_iter`` iterations do not reach the tolerance.
    """
    P = np.asarray(points, dtype=float)
    u, converged = khachiyan_weights(P, tol, max_iter)
    if not converged:
        raise RuntimeError(f"Khachiyan's algorithm did not converge in {max_iter} iterations")
    center, cov = covariance(P, u)
    return certify_points(Ellipsoid(center, P.shape[1] * cov), P)[0]
