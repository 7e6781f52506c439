"""Khachiyan's algorithm for the minimum-volume enclosing ellipsoid (an independent check).

Khachiyan (1996) with the away steps of Todd & Yildirim (2007). Lift the points to
``q_i = [p_i; 1]`` and iterate on weights ``u`` in the simplex. With
``X(u) = sum_i u_i q_i q_i^T`` and ``w_i = q_i^T X(u)^{-1} q_i`` (``d = n + 1``):

- forward step toward the point of largest ``w_j``: ``u <- (1 - s) u + s e_j`` with
  ``s = (w_j - d) / (d (w_j - 1)) > 0``;
- away step from the supporting point of smallest ``w_j``, the same formula (now ``s < 0``),
  limited by ``s >= -u_j / (1 - u_j)`` so the weight stays non-negative.

Stop when ``max w <= (1 + tol) d`` and ``min_{u_i > 0} w_i >= (1 - tol) d``. The ellipsoid
``{x : (x - c)^T H (x - c) <= 1}`` with ``c = P u`` and ``H^{-1} = n (P diag(u) P^T - c c^T)``
then contains every point after scaling by ``sqrt(max level)`` (done, with the float64 margin,
by ``certify_points``), and its volume is within a factor ``(1 + tol)^{d/2}`` of the minimum.
"""

from __future__ import annotations

import numpy as np

from optbound.optimal.certify import certify_points
from optbound.sets import Ellipsoid

_REFRESH = 500


def covariance(points: np.ndarray, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Weighted mean ``P u`` and covariance ``sum_i u_i (p_i - mean)(p_i - mean)^T``."""
    mean = points.T @ u
    return mean, (points.T * u) @ points - np.outer(mean, mean)


def khachiyan_weights(
    points: np.ndarray, tol: float = 1e-7, max_iter: int = 100_000
) -> tuple[np.ndarray, bool]:
    """The weights ``u`` (simplex, ``(m,)``) of Khachiyan's algorithm with away steps.

    Returns the weights and whether the tolerance was reached within ``max_iter`` steps (any
    weights still give the lower bound of ``optbound.optimal.lower``).

    A step ``X <- (1 - s) X + s q_j q_j^T`` updates ``X^{-1}`` and all ``w_i`` in O(m d) by the
    Sherman-Morrison formula; they are recomputed from scratch every ``_REFRESH`` steps to
    keep rounding from accumulating.
    """
    P = np.asarray(points, dtype=float)
    m, n = P.shape
    Q = np.vstack([P.T, np.ones(m)])
    d = n + 1
    u = np.full(m, 1.0 / m)
    for it in range(max_iter):
        if it % _REFRESH == 0:
            X_inv = np.linalg.inv((Q * u) @ Q.T)
            w = np.einsum("ij,ji->i", Q.T, X_inv @ Q)
        up = int(np.argmax(w))
        support = np.flatnonzero(u > 0)
        down = int(support[np.argmin(w[support])])
        if w[up] <= (1.0 + tol) * d and w[down] >= (1.0 - tol) * d:
            return u, True
        j = up if w[up] - d >= d - w[down] else down
        step = (w[j] - d) / (d * (w[j] - 1.0))
        if j == down:
            step = max(step, -u[j] / (1.0 - u[j]))
        u *= 1.0 - step
        u[j] += step
        u[u < 0] = 0.0  # rounding of a full away step
        # Sherman-Morrison for X' = (1 - s) X + s q_j q_j^T.
        z = X_inv @ Q[:, j]
        denom = (1.0 - step) + step * w[j]
        X_inv = (X_inv - step * np.outer(z, z) / denom) / (1.0 - step)
        w = (w - step * (Q.T @ z) ** 2 / denom) / (1.0 - step)
    return u, False


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
