"""The small dense computations of one SDP call, compiled.

numpy's ``eigvalsh`` spends about 4 µs per call on a 4 x 4 matrix in Python-level checks, as
long as LAPACK takes; the same LAPACK routine through numba takes about 1 µs in all. Every
tiny numpy call costs 1-3 µs of such overhead, so on small problems the steps around the solve
(``intersection``, ``emptiness``, ``certify``) are fused here into one kernel each; they were
a quarter of a cached call on the 3-D ellipsoid ∩ strip (``benchmarks/sdp_cache.py``). The
kernels compute the same formulas as the numpy they replace; sums may be taken in another
order, which every error bound below covers (they hold for any order).
"""

from __future__ import annotations

import numpy as np
from numba import njit

EPS = np.finfo(float).eps


@njit(cache=True)
def rounding_bound(size: int, magnitude: float | np.ndarray) -> float | np.ndarray:
    """Error bound ``16 size eps magnitude`` for forming or diagonalising a matrix (of each
    magnitude, for an array)."""
    return 16.0 * size * EPS * magnitude


@njit(cache=True)
def max_eig(A: np.ndarray) -> float:
    """Largest eigenvalue of the symmetric matrix A (its lower triangle is read)."""
    return np.linalg.eigvalsh(np.ascontiguousarray(A))[-1]


@njit(cache=True)
def _congruence(T: np.ndarray, F: np.ndarray) -> np.ndarray:
    """``T^T F T`` for small square matrices."""
    m = T.shape[0]
    FT = np.zeros((m, m))
    for i in range(m):
        for p in range(m):
            f = F[i, p]
            for j in range(m):
                FT[i, j] += f * T[p, j]
    out = np.zeros((m, m))
    for p in range(m):
        for i in range(m):
            t = T[p, i]
            for j in range(m):
                out[i, j] += t * FT[p, j]
    return out


@njit(cache=True)
def in_frame(forms: np.ndarray, frame: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``F_hat_i = T^T F_i T / norm_i`` (symmetrized, unit Frobenius norm), the norms, and
    bounds on the rounding of the congruence relative to ``F_hat_i``: ``rounding_bound`` of
    the Frobenius norm of ``|T|^T |F_i| |T|`` (an upper bound on its spectral norm)."""
    k, m = forms.shape[0], forms.shape[1]
    abs_frame = np.abs(frame)
    normalized = np.empty((k, m, m))
    norms = np.empty(k)
    errors = np.empty(k)
    for idx in range(k):
        scaled = _congruence(frame, forms[idx])
        magnitudes = _congruence(abs_frame, np.abs(forms[idx]))
        norm = np.sqrt(np.sum(scaled * scaled))
        for i in range(m):
            for j in range(m):
                normalized[idx, i, j] = 0.5 * (scaled[i, j] + scaled[j, i]) / norm
        norms[idx] = norm
        errors[idx] = rounding_bound(m, np.sqrt(np.sum(magnitudes * magnitudes))) / norm
    return normalized, norms, errors


@njit(cache=True)
def certificate_eigs(forms: np.ndarray) -> tuple[float, float]:
    """The smallest eigenvalue over the quadratic parts ``A_i`` (the leading ``n x n`` blocks
    of the stack), and the smallest eigenvalue of their sum."""
    n = forms.shape[1] - 1
    lowest = np.inf
    total = np.zeros((n, n))
    for idx in range(forms.shape[0]):
        part = np.ascontiguousarray(forms[idx, :n, :n])
        lowest = min(lowest, np.linalg.eigvalsh(part)[0])
        total += part
    return lowest, np.linalg.eigvalsh(total)[0]


@njit(cache=True)
def weighted_sum_eig(tau: np.ndarray, forms: np.ndarray, errors: np.ndarray) -> tuple[float, float]:
    """The smallest eigenvalue of ``S = sum_i tau_i F_i``, and a bound on its error: the
    rounding of forming and diagonalising S (``rounding_bound`` of ``sum_i tau_i ||F_i||_F``,
    Frobenius norms bounding the spectral ones from above) plus ``sum_i tau_i errors_i``."""
    m = forms.shape[1]
    S = np.zeros((m, m))
    magnitude = 0.0
    uncertainty = 0.0
    for idx in range(forms.shape[0]):
        S += tau[idx] * forms[idx]
        magnitude += tau[idx] * np.sqrt(np.sum(forms[idx] * forms[idx]))
        uncertainty += tau[idx] * errors[idx]
    return np.linalg.eigvalsh(S)[0], rounding_bound(m, magnitude) + uncertainty


@njit(cache=True)
def ellipsoid_in_x(
    M: np.ndarray, bt: np.ndarray, center: np.ndarray, W: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Centre ``c + W y0`` and shape ``W M^{-1} W^T`` (symmetrized) of the ellipsoid
    ``||A y + b|| <= 1`` (``M = A^2``, ``bt = A b``, centre ``y0 = -M^{-1} bt``) mapped back
    from the frame ``x = c + W y``."""
    shape_y = np.linalg.inv(M)
    x0 = center - W @ (shape_y @ bt)
    C = W @ shape_y @ W.T
    return x0, 0.5 * (C + C.T)
