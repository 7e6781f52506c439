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

Blocks: a kernel passes each block its arrays as views starting at the block's first instance
(``c[base:]``), indexed by the lane k alone. An index ``base + k`` with a runtime base may be
negative as far as numba knows, and every such access then carries wraparound code (measured:
15 % of the strip kernel).
"""

from __future__ import annotations

import numpy as np

from optbound._core.domain import (
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
from optbound._core.jit import njit
from optbound.analytic._kernels.midrad import (
    RADIUS_SAFETY,
    TINY,
    U,
    output_floor,
    segment_scale,
    segment_term,
)

W = 128  # lanes per block (3-D strip kernel: 32, 64, 128, 256, 512 measured; 128 fastest)
CHECK_ROWS = 6  # rows of the scratch of check_ellipsoids


@njit(cache=True, error_model="numpy", inline="always")
def load_vectors(src, m, dst):
    """``dst[i, k] = src[k, i]`` for the m lanes of a block (src (m, n): a view from the
    block's first instance, see ``Blocks`` in the module docstring)."""
    for i in range(src.shape[1]):
        for k in range(m):
            dst[i, k] = src[k, i]


@njit(cache=True, error_model="numpy", inline="always")
def load_matrices(src, m, dst):
    """``dst[i, j, k] = src[k, i, j]`` for the m lanes of a block (src (m, n, n))."""
    n = src.shape[1]
    for i in range(n):
        for j in range(n):
            for k in range(m):
                dst[i, j, k] = src[k, i, j]


@njit(cache=True, error_model="numpy", inline="always")
def store_vectors(src, m, dst):
    """``dst[k, i] = src[i, k]`` (the inverse of :func:`load_vectors`; lanes innermost
    here too: measured twice as fast as a contiguous inner loop over i)."""
    for i in range(src.shape[0]):
        for k in range(m):
            dst[k, i] = src[i, k]


@njit(cache=True, error_model="numpy", inline="always")
def store_matrices(src, m, dst):
    """``dst[k, i, j] = src[i, j, k]`` (the inverse of :func:`load_matrices`)."""
    n = src.shape[0]
    for i in range(n):
        for j in range(n):
            for k in range(m):
                dst[k, i, j] = src[i, j, k]


@njit(cache=True, error_model="numpy", inline="always")
def cholesky_lanes(A, L, m, pivot, at):
    """Cholesky factors of the lower triangles of A (n, n, W) into L (upper parts zeroed), as
    ``_core.domain.cholesky`` per lane: the same operations in the same order, so the same bits.
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


@njit(cache=True, error_model="numpy", _nrt=False)
def cholesky_block(A, L, m, pivot):
    """:func:`cholesky_lanes` of a block as a compiled function of its own, for a caller that
    calls it by address (``native_call``) rather than compile its lane loops again."""
    cholesky_lanes(A, L, m, pivot, 0)


@njit(cache=True, error_model="numpy", _nrt=False)
def check_ellipsoids(c, C, L, m, code, s):
    """``_core.domain.check_ellipsoid`` for the m lanes of a block: centres c (n, W), shapes C
    (n, n, W); writes the Cholesky factors into L and the error codes (same codes and the same
    precedence as the scalar check) into ``code`` (W,) int. ``s`` is (CHECK_ROWS W,) scratch:
    rows at constant offsets (rows as views of a 2-D array would need run-time overlap checks,
    which keep a loop scalar once there are too many). Called once per block, not inlined: the
    strip and Minkowski kernels (both summands) pass the same types and share one compile.

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


@njit(cache=True, error_model="numpy", inline="always")
def trace_inverse_lanes(L, m, total):
    """``tr(A^{-1}) = ||L^{-1}||_F^2`` per lane (A = L L^T, L from :func:`cholesky_lanes`), as
    ``midrad.lambda_min_estimate`` (whose reciprocal it is): column j of X = L^{-1} by
    forward substitution, its strict lower part stored transposed in L's strict upper
    triangle. ``total`` (W,) receives the sums."""
    n = L.shape[0]
    for k in range(m):
        total[k] = 0.0
    for j in range(n):
        for k in range(m):
            xjj = 1.0 / L[j, j, k]
            total[k] += xjj * xjj
            L[j, j, k] = xjj  # L_jj is not read again; X_jj serves the rows below
        for i in range(j + 1, n):
            for k in range(m):
                L[j, i, k] = L[i, j, k] * L[j, j, k]
            for q in range(j + 1, i):
                for k in range(m):
                    L[j, i, k] += L[i, q, k] * L[j, q, k]
            for k in range(m):
                L[j, i, k] = -L[j, i, k] / L[i, i, k]
                total[k] += L[j, i, k] * L[j, i, k]


@njit(cache=True, error_model="numpy")
def inflate_lanes(S, D, c, d, T, L, m, margin, rows):
    """``midrad.inflate`` for the m lanes of a block: S, D, T, L (n, n, W), c, d (n, W);
    writes T (T may be S; L is work space) and each lane's margin (or -1.0 if T is too large
    for the domain) into ``margin`` (W,). ``rows``: 8 scratch rows (W,), separate arrays (see
    ``minkowski_kernel.block_work``). The same quantities as
    ``midrad.inflate`` (see there for the mathematics), computed lane by lane."""
    n = S.shape[0]
    trace, cmax, pivot, total = rows[0], rows[1], rows[2], rows[3]
    dd, DF, SF, mu = rows[4], rows[5], rows[6], rows[7]
    for k in range(m):
        trace[k] = 0.0
        cmax[k] = 0.0
        dd[k] = 0.0
        DF[k] = 0.0
        SF[k] = 0.0
    for i in range(n):
        for k in range(m):
            trace[k] += S[i, i, k]
            cmax[k] = max(cmax[k], abs(c[i, k]))
            dd[k] += d[i, k] * d[i, k]
    for i in range(n):
        for j in range(i + 1):
            w = 2.0 if i > j else 1.0
            for k in range(m):
                DF[k] += w * D[i, j, k] * D[i, j, k]
                SF[k] += w * S[i, j, k] * S[i, j, k]
    cholesky_lanes(S, L, m, pivot, 0)
    trace_inverse_lanes(L, m, total)
    sqn = np.sqrt(n)
    for k in range(m):
        floor = output_floor(trace[k], cmax[k])
        # lambda_min(S) estimated; 0 if S is (numerically) singular or beyond the estimate's
        # accuracy (~ cond U): full widening.
        lmin = 1.0 / total[k] if pivot[k] > 0.0 else 0.0
        if not trace[k] <= 1e14 * lmin:
            lmin = 0.0
        lref = max(lmin, floor)
        scale = segment_scale(dd[k], lref)
        rho = scale - 1.0
        df = np.sqrt(DF[k]) * (1.0 + 4.0 * U)
        sf = np.sqrt(SF[k]) * (1.0 + 4.0 * U)
        centre = segment_term(dd[k], rho)
        # Rounding of forming T: |F_ij| <= 2 U |T_ij|, and ||T||_F <= scale ||S||_F + sqrt(n) mu.
        need = scale * df + centre + 2.0 * U * scale * sf
        m_u = need * RADIUS_SAFETY / (1.0 - 2.0 * U * sqn * RADIUS_SAFETY) + TINY
        m_u = max(m_u, 2.0 * floor - scale * lmin)  # widening (only ever adds to mu)
        mu[k] = m_u
        total[k] = scale  # free again: keeps the scale for the loop below
        margin[k] = rho + m_u / lref if cmax[k] <= MAG else -1.0
    for i in range(n):
        for j in range(i + 1):
            for k in range(m):
                t = total[k] * S[i, j, k]
                if i == j:
                    t += mu[k]
                    if not t <= MAX_DIAG:
                        margin[k] = -1.0
                T[i, j, k] = t
                T[j, i, k] = t


@njit(cache=True, error_model="numpy", inline="always")
def first_error(code, start, stop):
    """The first ``i`` in ``start..stop`` with ``code[i] != 0``, or -1."""
    for i in range(start, stop):
        if code[i] != 0:
            return i
    return -1
