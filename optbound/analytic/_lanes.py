"""Lane-parallel building blocks: W instances at a time, stored lanes-last (structure of arrays).

The batched kernels process a batch in blocks of up to ``W`` instances. Inside a block every
quantity of an instance lives in one lane of a row ``x[..., k]``, and every step is a loop over
the lanes ``for k in range(m)`` with a straight-line body, which LLVM turns into SIMD code (8
lanes per AVX-512 register). Branches of the scalar algorithm become selects, so a lane never
depends on another: without fastmath, IEEE arithmetic gives the same bits in the vector body
and in the scalar remainder of such a loop, so a batch of one (a single call) and a lane of a
large batch agree bitwise.

Kernels using these loops must be compiled with ``error_model="numpy"``: numba's default
Python error model adds a zero-division branch to every division, which blocks vectorization.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from optbound.sets._domain import (
    ASYMMETRIC,
    CENTER_RANGE,
    COND_MAX,
    ILL_CONDITIONED,
    MAG,
    MAX_DIAG,
    MIN_PIVOT,
    NON_FINITE,
    NOT_PD,
    OK,
    RATIO_MAX,
    SHAPE_RANGE,
    SYMMETRY_RTOL,
)

W = 128  # lanes per block (3-D strip kernel: 32, 64, 128, 256, 512 measured; 128 fastest)
CHECK_ROWS = 6  # rows of the scratch of check_ellipsoids


@njit(cache=True, error_model="numpy", inline="always")
def load_vectors(src, base, m, dst):
    """``dst[i, k] = src[base + k, i]`` for the m lanes of a block (src (B, n))."""
    for i in range(src.shape[1]):
        for k in range(m):
            dst[i, k] = src[base + k, i]


@njit(cache=True, error_model="numpy", inline="always")
def load_matrices(src, base, m, dst):
    """``dst[i, j, k] = src[base + k, i, j]`` for the m lanes of a block (src (B, n, n))."""
    n = src.shape[1]
    for i in range(n):
        for j in range(n):
            for k in range(m):
                dst[i, j, k] = src[base + k, i, j]


@njit(cache=True, error_model="numpy", inline="always")
def store_vectors(src, base, m, dst):
    """``dst[base + k, i] = src[i, k]`` (the inverse of :func:`load_vectors`; lanes innermost
    here too: measured twice as fast as a contiguous inner loop over i)."""
    for i in range(src.shape[0]):
        for k in range(m):
            dst[base + k, i] = src[i, k]


@njit(cache=True, error_model="numpy", inline="always")
def store_matrices(src, base, m, dst):
    """``dst[base + k, i, j] = src[i, j, k]`` (the inverse of :func:`load_matrices`)."""
    n = src.shape[0]
    for i in range(n):
        for j in range(n):
            for k in range(m):
                dst[base + k, i, j] = src[i, j, k]


@njit(cache=True, error_model="numpy", inline="always")
def cholesky_lanes(A, L, m, pivot, at):
    """Cholesky factors of the lower triangles of A (n, n, W) into L (upper parts zeroed), as
    ``_domain.cholesky`` per lane: the same operations in the same order, so the same bits.
    ``pivot[at + k]`` receives lane k's smallest pivot, or 0.0 if a pivot is not positive (the
    lane's factor is then meaningless). The sums accumulate in L itself, so that the lane loop
    is always the innermost one."""
    n = A.shape[0]
    for k in range(m):
        pivot[at + k] = np.inf
    for j in range(n):
        for k in range(m):
            L[j, j, k] = A[j, j, k]
        for q in range(j):
            for k in range(m):
                L[j, j, k] -= L[j, q, k] * L[j, q, k]
        for k in range(m):
            d = L[j, j, k]
            pivot[at + k] = min(pivot[at + k], d) if d > 0.0 else 0.0
            L[j, j, k] = np.sqrt(abs(d))
        for i in range(j + 1, n):
            for k in range(m):
                L[i, j, k] = A[i, j, k]
            for q in range(j):
                for k in range(m):
                    L[i, j, k] -= L[i, q, k] * L[j, q, k]
            for k in range(m):
                L[i, j, k] /= L[j, j, k]
        for i in range(j):
            for k in range(m):
                L[i, j, k] = 0.0


@njit(cache=True, error_model="numpy", inline="always")
def check_ellipsoids(c, C, L, m, code, s):
    """``_domain.check_ellipsoid`` for the m lanes of a block: centres c (n, W), shapes C
    (n, n, W); writes the Cholesky factors into L and the error codes (same codes and the same
    precedence as the scalar check) into ``code`` (W,) int. ``s`` is (CHECK_ROWS W,) scratch:
    rows at constant offsets (rows as views of a 2-D array would need run-time overlap checks,
    which keep a loop scalar once there are too many).

    Every condition is accumulated branch-free and decided once at the end: ``0 * x`` is NaN
    exactly when x is inf or NaN, so a sum of them flags a non-finite entry."""
    n = c.shape[0]
    big, cmax, nonfinite, asym, pivot, max_diag = 0, W, 2 * W, 3 * W, 4 * W, 5 * W  # rows
    for k in range(m):
        s[big + k] = 0.0
        s[cmax + k] = 0.0
        s[nonfinite + k] = 0.0
        s[asym + k] = 0.0
    for i in range(n):
        for k in range(m):
            s[cmax + k] = max(s[cmax + k], abs(c[i, k]))
            s[nonfinite + k] += 0.0 * c[i, k]
        for j in range(n):
            for k in range(m):
                s[big + k] = max(s[big + k], abs(C[i, j, k]))
                s[nonfinite + k] += 0.0 * C[i, j, k]
    for i in range(n):
        for j in range(i):
            for k in range(m):
                s[asym + k] = max(s[asym + k], abs(C[i, j, k] - C[j, i, k]))
    cholesky_lanes(C, L, m, s, pivot)
    for k in range(m):
        s[max_diag + k] = 0.0
    for j in range(n):
        for k in range(m):
            s[max_diag + k] = max(s[max_diag + k], C[j, j, k])
    for k in range(m):
        p = s[pivot + k]
        r = OK
        if s[cmax + k] > MAG or s[cmax + k] > RATIO_MAX * np.sqrt(p):
            r = CENTER_RANGE
        if s[max_diag + k] > MAX_DIAG or p < MIN_PIVOT:
            r = SHAPE_RANGE
        if s[max_diag + k] > COND_MAX * p:
            r = ILL_CONDITIONED
        if not p > 0.0:
            r = NOT_PD
        if s[asym + k] > SYMMETRY_RTOL * s[big + k]:
            r = ASYMMETRIC
        if not s[nonfinite + k] == 0.0:
            r = NON_FINITE
        code[k] = r
