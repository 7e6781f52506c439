"""The small dense computations of one SDP call, compiled.

On a 4 x 4 matrix numpy's Python-level checks cost as much as the LAPACK call itself, and
every tiny numpy call carries such overhead, so on small problems the steps around the solve
(``intersection``, ``emptiness``, ``certify``) are fused here into one compiled kernel each
(``optbound/bench/sdp_cache.py`` measures a cached call). The kernels compute the same
formulas as the numpy they replace; sums may be taken in another order, which every error
bound below covers (they hold for any order). They compile once, in the first SDP call with
an empty numba cache; later processes load the cache.

Elementwise steps (``P - G``, ``|T|``, ``S += w M``, ``sum(A * A)``) are written as loops,
in the order numba's array expressions take (C order, sums from 0.0), so the floats are the
same: numba compiles each array expression and slice copy as code of its own, which made a
quarter of this module's compile time (issue 23).
"""

from __future__ import annotations

import numpy as np

from optbound._core import check_ellipsoid
from optbound._core.jit import njit

EPS = np.finfo(float).eps


@njit(cache=True)
def rounding_bound(size: int, magnitude: float | np.ndarray) -> float | np.ndarray:
    """Error bound ``16 size eps magnitude`` for forming or diagonalising a matrix (of each
    magnitude, for an array)."""
    return 16.0 * size * EPS * magnitude


@njit(cache=True)
def sum_squares(A: np.ndarray) -> float:
    """``sum_ij A_ij^2`` (the squared Frobenius norm) of a matrix, summed in C order from 0.0 as
    ``np.sum(A * A)`` is: the same float, without an array expression and its temporary."""
    total = 0.0
    for i in range(A.shape[0]):
        for j in range(A.shape[1]):
            total += A[i, j] * A[i, j]
    return total


@njit(cache=True)
def max_eig(A: np.ndarray) -> float:
    """Largest eigenvalue of the symmetric matrix A (its lower triangle is read)."""
    return np.linalg.eigvalsh(A)[-1]


@njit(cache=True)
def lmi_check(
    P: np.ndarray, G: np.ndarray, scale: float, uncertainty: float
) -> tuple[float, float]:
    """The largest eigenvalue of ``P - G``, and the margin it must clear (be below minus it):
    ``rounding_bound`` of ``||P||_F + scale`` (the Frobenius norm bounds the spectral norm from
    above; ``scale`` bounds ``||G||``) plus ``uncertainty``."""
    magnitude = np.sqrt(sum_squares(P)) + scale
    m = P.shape[0]
    difference = np.empty((m, m))  # P - G, in loops (no array expression)
    for i in range(m):
        for j in range(m):
            difference[i, j] = P[i, j] - G[i, j]
    return max_eig(difference), rounding_bound(m, magnitude) + uncertainty


@njit(cache=True)
def _product(A: np.ndarray, B: np.ndarray) -> np.ndarray:
    """``A B`` for small square matrices, in plain loops (no BLAS call)."""
    m = A.shape[0]
    out = np.zeros((m, m))
    for i in range(m):
        for p in range(m):
            a = A[i, p]
            for j in range(m):
                out[i, j] += a * B[p, j]
    return out


@njit(cache=True)
def _congruence(T: np.ndarray, F: np.ndarray) -> np.ndarray:
    """``T^T F T`` for small square matrices (``T^T`` copied to C order: one compiled
    ``_product``, the same sums in the same order)."""
    return _product(np.ascontiguousarray(T.T), _product(F, T))


@njit(cache=True)
def in_frame(forms: np.ndarray, frame: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``F_hat_i = T^T F_i T / norm_i`` (symmetrized, unit Frobenius norm), the norms, and
    bounds on the rounding of the congruence relative to ``F_hat_i``: ``rounding_bound`` of
    the Frobenius norm of ``|T|^T |F_i| |T|`` (an upper bound on its spectral norm)."""
    k, m = forms.shape[0], forms.shape[1]
    abs_frame, abs_form = np.empty((m, m)), np.empty((m, m))
    for i in range(m):  # |T| and below |F_i|, in loops (no array expressions)
        for j in range(m):
            abs_frame[i, j] = abs(frame[i, j])
    normalized = np.empty((k, m, m))
    norms = np.empty(k)
    errors = np.empty(k)
    for idx in range(k):
        scaled = _congruence(frame, forms[idx])
        for i in range(m):
            for j in range(m):
                abs_form[i, j] = abs(forms[idx, i, j])
        magnitudes = _congruence(abs_frame, abs_form)
        norm = np.sqrt(sum_squares(scaled))
        for i in range(m):
            for j in range(m):
                normalized[idx, i, j] = 0.5 * (scaled[i, j] + scaled[j, i]) / norm
        norms[idx] = norm
        errors[idx] = rounding_bound(m, np.sqrt(sum_squares(magnitudes))) / norm
    return normalized, norms, errors


@njit(cache=True)
def certificate_eigs(forms: np.ndarray) -> tuple[float, float]:
    """The smallest eigenvalue over the quadratic parts ``A_i`` (the leading ``n x n`` blocks
    of the stack), and the smallest eigenvalue of their sum."""
    n = forms.shape[1] - 1
    lowest = np.inf
    total, part = np.zeros((n, n)), np.empty((n, n))
    for idx in range(forms.shape[0]):
        for i in range(n):  # copied in loops (no slice copy, no array expression)
            for j in range(n):
                part[i, j] = forms[idx, i, j]
                total[i, j] += part[i, j]
        lowest = min(lowest, np.linalg.eigvalsh(part)[0])
    return lowest, np.linalg.eigvalsh(total)[0]


@njit(cache=True)
def weighted_sum(weights: np.ndarray, matrices: np.ndarray) -> tuple[np.ndarray, float]:
    """``S = sum_i w_i M_i`` and ``sum_i |w_i| ||M_i||_F`` (which bounds ``||S||_2``)."""
    S = np.zeros((matrices.shape[1], matrices.shape[2]))
    magnitude = 0.0
    for idx in range(matrices.shape[0]):
        for i in range(S.shape[0]):  # in loops (no array expression)
            for j in range(S.shape[1]):
                S[i, j] += weights[idx] * matrices[idx, i, j]
        magnitude += abs(weights[idx]) * np.sqrt(sum_squares(matrices[idx]))
    return S, magnitude


@njit(cache=True)
def weighted_sum_eig(tau: np.ndarray, forms: np.ndarray, errors: np.ndarray) -> tuple[float, float]:
    """The smallest eigenvalue of ``S = sum_i tau_i F_i`` (``tau >= 0``), and a bound on its
    error: the rounding of forming and diagonalising S (``rounding_bound`` of
    ``sum_i tau_i ||F_i||_F``, Frobenius norms bounding the spectral ones from above) plus
    ``sum_i tau_i errors_i``."""
    S, magnitude = weighted_sum(tau, forms)
    spread = 0.0  # sum_i tau_i errors_i, in order from 0.0 (as np.sum of the products)
    for idx in range(tau.shape[0]):
        spread += tau[idx] * errors[idx]
    bound = rounding_bound(forms.shape[1], magnitude) + spread
    return np.linalg.eigvalsh(S)[0], bound


@njit(cache=True)
def lifted_form(chol: np.ndarray, center: np.ndarray, frame: np.ndarray) -> np.ndarray:
    """``X^T X`` (exactly symmetric) for ``X = L^{-1} [W, c0 - c]``, by forward substitution:
    the form of the ellipsoid ``(c, L L^T)`` in ``[y; 1]`` for the frame
    ``T = [[W, c0], [0, 1]]``."""
    n = chol.shape[0]
    X = np.empty((n, n + 1))
    for j in range(n + 1):
        for i in range(n):
            value = frame[i, j] - center[i] if j == n else frame[i, j]
            for p in range(i):
                value -= chol[i, p] * X[p, j]
            X[i, j] = value / chol[i, i]
    P = np.empty((n + 1, n + 1))
    for i in range(n + 1):
        for j in range(i + 1):
            total = 0.0  # in order from 0.0, as np.sum of the products
            for p in range(n):
                total += X[p, i] * X[p, j]
            P[i, j] = P[j, i] = total
    return P


@njit(cache=True)
def smallest_inflation(
    P: np.ndarray, fixed: np.ndarray, S: np.ndarray, delta: float, betas: np.ndarray
) -> tuple[float, float]:
    """``min over betas of sqrt(max(1, lambda_max(P, R)))`` with ``R = G0 + beta S - delta I``,
    and its (first) minimising beta; ``(inf, nan)`` if no ``R`` is positive definite.

    With ``R = V D V^T`` (D > 0), ``lambda_max(P, R)`` is the largest eigenvalue of
    ``D^{-1/2} V^T P V D^{-1/2}``; betas whose ``R`` is not definite are skipped.
    """
    best_alpha, best_beta = np.inf, np.nan
    m = P.shape[0]
    R, scaled, scaled_t = np.empty((m, m)), np.empty((m, m)), np.empty((m, m))
    for beta in betas:
        for i in range(m):  # R, in loops: delta I's entries are delta * 1.0 and delta * 0.0
            for j in range(m):
                R[i, j] = fixed[i, j] + beta * S[i, j] - delta * (1.0 if i == j else 0.0)
        d, V = np.linalg.eigh(R)
        if not d[0] > 0:
            continue
        for j in range(m):  # V D^{-1/2} and its transpose, both C-ordered (one BLAS layout)
            root = np.sqrt(d[j])
            for i in range(m):
                scaled[i, j] = scaled_t[j, i] = V[i, j] / root
        form = scaled_t @ P @ scaled
        alpha = np.sqrt(max(1.0, np.linalg.eigvalsh(form)[-1]))
        if alpha < best_alpha:
            best_alpha, best_beta = alpha, beta
    return best_alpha, best_beta


@njit(cache=True)
def ellipsoid_in_x(
    M: np.ndarray, bt: np.ndarray, center: np.ndarray, W: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, int]:
    """Centre ``c + W y0`` and shape ``W M^{-1} W^T`` (symmetrized) of the ellipsoid
    ``||A y + b|| <= 1`` (``M = A^2``, ``bt = A b``, centre ``y0 = -M^{-1} bt``) mapped back
    from the frame ``x = c + W y``, with the Cholesky factor and status of
    ``_core.domain.check_ellipsoid`` (for ``Ellipsoid._from_kernel``)."""
    shape_y = np.linalg.inv(M)
    x0 = W @ (shape_y @ bt)
    for i in range(x0.shape[0]):  # c - W y0, in place (no array expression)
        x0[i] = center[i] - x0[i]
    product = W @ np.ascontiguousarray(shape_y) @ np.ascontiguousarray(W.T)
    n = product.shape[0]
    C = np.empty((n, n))
    for i in range(n):
        for j in range(n):
            C[i, j] = 0.5 * (product[i, j] + product[j, i])
    L = np.zeros((n, n))
    return x0, C, L, check_ellipsoid(x0, C, L)
