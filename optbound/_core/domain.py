"""The supported domain of ellipsoids and strips, checked by one compiled kernel.

Every computation in ``optbound.analytic`` is guaranteed (its floats, read exactly, contain the
true set) for any input; the domain bounds *how much* the certified rounding margin can be and
keeps every intermediate quantity far from overflow and underflow:

- magnitudes: semi-axes in [1e-60, 1e60] (diagonal of C and Cholesky pivots in [1e-120, 1e120]),
  centre coordinates and ``1 / ||a||`` (strip widths) up to 1e60, strip offsets up to 1e120;
- condition: ``max diag(C) / min Cholesky pivot <= COND_MAX`` (a lower bound on cond(C): every
  pivot is >= the smallest eigenvalue and the largest diagonal entry <= the largest one);
- centre against size: ``|c|_inf <= RATIO_MAX * sqrt(min pivot)`` (the rounding of a centre
  far from the origin, relative to the set's size, is what the margin has to absorb).

Results of the analytic calculus are widened to ``COND_OUT`` and ``RATIO_OUT`` (a factor 100
and 10 inside), so a recursion never leaves the domain.
"""

from __future__ import annotations

import numpy as np

from optbound._core.jit import njit

MAG = 1e60
MAX_DIAG, MIN_PIVOT = 1e120, 1e-120  # MAG^2 and 1 / MAG^2, as exact literals
COND_MAX = 1e12
RATIO_MAX = 1e11
COND_OUT = 1e10
RATIO_OUT = 1e10
# Relative asymmetry below which a matrix is treated as symmetric up to rounding.
SYMMETRY_RTOL = 1e-9

# Error codes of ``check_ellipsoid`` (0 = valid) and their messages (argument name first).
OK, NON_FINITE, ASYMMETRIC, NOT_PD, ILL_CONDITIONED, SHAPE_RANGE, CENTER_RANGE = range(7)
MESSAGES = {
    NON_FINITE: "{shape} and {center} must be finite",
    ASYMMETRIC: "{shape} must be symmetric",
    NOT_PD: "{shape} must be positive definite (it is singular or not definite)",
    ILL_CONDITIONED: (
        f"{{shape}} is too ill-conditioned: max diag / min Cholesky pivot exceeds {COND_MAX:.0e} "
        "(the supported domain, see optbound._core.domain)"
    ),
    SHAPE_RANGE: (
        f"{{shape}} has semi-axes outside [{1 / MAG:.0e}, {MAG:.0e}] (the supported domain)"
    ),
    CENTER_RANGE: (
        f"{{center}} is too far from the origin: |c| must be <= {MAG:.0e} and <= "
        f"{RATIO_MAX:.0e} times the smallest semi-axis (the supported domain)"
    ),
}


@njit(cache=True, error_model="numpy")
def cholesky(A, L) -> float:
    """Float Cholesky of the lower triangle of A into L (upper part zeroed); returns the
    smallest pivot, or 0.0 as soon as a pivot is not positive."""
    n = A.shape[0]
    min_pivot = np.inf
    for j in range(n):
        d = A[j, j]
        for k in range(j):
            d -= L[j, k] * L[j, k]
        if not d > 0.0:
            return 0.0
        min_pivot = min(min_pivot, d)
        ljj = np.sqrt(d)
        L[j, j] = ljj
        for i in range(j + 1, n):
            s = A[i, j]
            for k in range(j):
                s -= L[i, k] * L[j, k]
            L[i, j] = s / ljj
        for i in range(j):
            L[i, j] = 0.0
    return min_pivot


@njit(cache=True, error_model="numpy", nogil=True)
def check_ellipsoid(c, C, L) -> int:
    """Validate centre ``c`` (n,) and shape ``C`` (n, n); write its Cholesky factor into ``L``.

    Only the lower triangle of C defines the matrix (the upper one is checked for symmetry up
    to ``SYMMETRY_RTOL``). Returns an error code (0 if valid).
    """
    n = c.shape[0]
    big = 0.0
    for i in range(n):
        if not np.isfinite(c[i]):
            return NON_FINITE
        for j in range(n):
            if not np.isfinite(C[i, j]):
                return NON_FINITE
            big = max(big, abs(C[i, j]))
    for i in range(n):
        for j in range(i):
            if abs(C[i, j] - C[j, i]) > SYMMETRY_RTOL * big:
                return ASYMMETRIC
    min_pivot = cholesky(C, L)
    if not min_pivot > 0.0:
        return NOT_PD
    max_diag = 0.0
    for j in range(n):
        max_diag = max(max_diag, C[j, j])
    if max_diag > COND_MAX * min_pivot:
        return ILL_CONDITIONED
    if max_diag > MAX_DIAG or min_pivot < MIN_PIVOT:
        return SHAPE_RANGE
    cmax = 0.0
    for i in range(n):
        cmax = max(cmax, abs(c[i]))
    if cmax > MAG or cmax > RATIO_MAX * np.sqrt(min_pivot):
        return CENTER_RANGE
    return OK


def raise_for(code: int, center: str, shape: str, where: str = "") -> None:
    """Raise the ``ValueError`` of a non-zero ``check_ellipsoid`` code."""
    if code != OK:
        raise ValueError(MESSAGES[code].format(center=center, shape=shape) + where)
