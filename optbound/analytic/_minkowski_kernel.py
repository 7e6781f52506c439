"""Compiled core of the outer Minkowski sum [HS96, eq. (14)], one instance per call.

Shared by :func:`minkowski_sum` and :func:`minkowski_sum_batch` (bitwise agreement). Steps:
validate both summands (``check_ellipsoid``), choose p = (1 - kappa) / kappa, evaluate the
member ``(1 + p) (C1 / p + C2)`` and the centre ``c1 + c2`` in midpoint-radius arithmetic,
inflate by the certified margin (``_midrad.inflate``, which keeps the output in the domain).

The volume-optimal p is the root of the increasing ``h(p) = p (p + 1) tr((C1 + p C2)^{-1} C2)
- n`` (the module docstring of :mod:`optbound.analytic.minkowski`: with the generalized
eigenvalues l_i of (C1, C2), ``tr((C1 + p C2)^{-1} C2) = sum_i 1 / (l_i + p)``). It is solved
per instance by Newton's method safeguarded by a bracket, so each instance stops as soon as it
has converged (no eigendecomposition needed). The ``size_xy_psi`` p is the best root of the
cubic [HS96, eqs. (15)-(17)] (``_cubic.real_roots``).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from optbound.analytic._cubic import real_roots
from optbound.analytic._midrad import U, inflate, mr_add, mr_div, mr_mul
from optbound.sets._domain import check_ellipsoid, cholesky

P_VOLUME, P_TRACE, P_GIVEN, P_XY_PSI = range(4)
# Error codes: check_ellipsoid's (1..6) for the first summand, +10 for the second, and:
BAD_KAPPA, OUT_OF_DOMAIN = 21, 22
NEWTON_MAX_STEPS = 100


@njit(cache=True)
def _h(C1, C2, p, A, L, X):
    """h(p) and h'(p) (module docstring); X = (C1 + p C2)^{-1} C2 as work space."""
    n = C1.shape[0]
    for i in range(n):
        for j in range(i + 1):
            A[i, j] = C1[i, j] + p * C2[i, j]
    if not cholesky(A, L) > 0.0:
        return np.nan, np.nan
    for col in range(n):  # X[:, col] = L^{-T} L^{-1} C2[:, col]
        for i in range(n):
            s = C2[i, col] if col <= i else C2[col, i]
            for k in range(i):
                s -= L[i, k] * X[k, col]
            X[i, col] = s / L[i, i]
        for i in range(n - 1, -1, -1):
            s = X[i, col]
            for k in range(i + 1, n):
                s -= L[k, i] * X[k, col]
            X[i, col] = s / L[i, i]
    t1 = 0.0
    t2 = 0.0
    for i in range(n):
        t1 += X[i, i]
        for j in range(n):
            t2 += X[i, j] * X[j, i]
    q = p * (p + 1.0)
    return q * t1 - n, (2.0 * p + 1.0) * t1 - q * t2


@njit(cache=True)
def p_volume(C1, C2, L1, L2, A, L, X):
    """Root of h by bracketed Newton, started at (det C1 / det C2)^(1 / 2n)."""
    n = C1.shape[0]
    p = 1.0
    for i in range(n):
        p *= (L1[i, i] / L2[i, i]) ** (1.0 / n)
    lo, hi = 0.0, np.inf
    for _ in range(NEWTON_MAX_STEPS):
        h, dh = _h(C1, C2, p, A, L, X)
        if not np.isfinite(h) or h == 0.0:
            break
        if h < 0.0:
            lo = p
        else:
            hi = p
        step = p - h / dh
        if not (lo < step < hi):  # outside the bracket: geometric bisection or expansion
            if lo > 0.0 and hi < np.inf:
                step = np.sqrt(lo * hi)
            else:
                step = 4.0 * p if h < 0.0 else 0.25 * p
        done = abs(step - p) <= 4.0 * U * p
        p = step
        if done:
            break
    return p


@njit(cache=True)
def _trace(C, idx):
    t = 0.0
    for i in idx:
        t += C[i, i]
    return t


@njit(cache=True)
def _xy_psi_size(k, t1, t2, h1, h2):
    """tr(proj_xy C) tr(proj_psi C) of the member kappa [HS96, eq. (15)]."""
    return (t1 / (1.0 - k) + t2 / k) * (h1 / (1.0 - k) + h2 / k)


@njit(cache=True)
def p_xy_psi(C1, C2, planar, heading):
    """p of the root of the cubic [HS96, eqs. (16)-(17)] in (0, 1) minimizing
    tr(proj_xy C) tr(proj_psi C); the trace-optimal kappa is an always-valid extra candidate
    (a safety net, never worse)."""
    t1, t2 = _trace(C1, planar), _trace(C2, planar)
    h1, h2 = _trace(C1, heading), _trace(C2, heading)
    m11, m22, m12, m21 = t1 * h1, t2 * h2, t1 * h2, t2 * h1  # M_AB [HS96, eq. (15)]
    k, x1, x2, x3 = real_roots(
        2.0 * (m11 + m22 - m12 - m21),
        3.0 * (m12 + m21 - 2.0 * m22),
        6.0 * m22 - m12 - m21,
        -2.0 * m22,
    )
    best, best_size = 0.0, np.inf
    for j, kap in enumerate((x1, x2, x3)):
        if j < k and 0.0 < kap < 1.0:
            size = _xy_psi_size(kap, t1, t2, h1, h2)
            if size < best_size:
                best, best_size = kap, size
    n = C1.shape[0]
    T1 = 0.0
    T2 = 0.0
    for i in range(n):
        T1 += C1[i, i]
        T2 += C2[i, i]
    kap = 1.0 / (1.0 + np.sqrt(T1 / T2))
    if not best_size <= _xy_psi_size(kap, t1, t2, h1, h2):
        best = kap
    return (1.0 - best) / best


@njit(cache=True, inline="always")
def sum_one(c1, C1, c2, C2, mode, p_in, planar, heading, out_c, out_C, out_L, work):
    """One certified sum; ``planar``, ``heading`` are the coordinates of ``P_XY_PSI`` (unused
    otherwise). ``work`` is (6, max(n, 1), n) scratch. Returns (code, p, margin). Inlined into
    its two callers (as ``_strip_kernel.fuse_one``)."""
    n = c1.shape[0]
    L1, L2, A, X, D = work[0, :n], work[1, :n], work[2, :n], work[3, :n], work[4, :n]
    dc = work[5, 0]
    code = check_ellipsoid(c1, C1, L1)
    if code != 0:
        return code, 0.0, 0.0
    code = check_ellipsoid(c2, C2, L2)
    if code != 0:
        return code + 10, 0.0, 0.0
    if mode == P_GIVEN:
        p = p_in
        if not (np.isfinite(p) and p > 0.0):
            return BAD_KAPPA, 0.0, 0.0
    elif mode == P_TRACE:
        t1 = 0.0
        t2 = 0.0
        for i in range(n):
            t1 += C1[i, i]
            t2 += C2[i, i]
        p = np.sqrt(t1 / t2)  # kappa = sqrt(tr C2) / (sqrt(tr C1) + sqrt(tr C2))
    elif mode == P_XY_PSI:
        p = p_xy_psi(C1, C2, planar, heading)
    else:
        p = p_volume(C1, C2, L1, L2, A, out_L, X)
    onep, ronep = mr_add(1.0, 0.0, p, 0.0)
    for i in range(n):
        out_c[i], dc[i] = mr_add(c1[i], 0.0, c2[i], 0.0)
        for j in range(i + 1):
            q, rq = mr_div(C1[i, j], 0.0, p, 0.0)
            s, rs = mr_add(q, rq, C2[i, j], 0.0)
            out_C[i, j], D[i, j] = mr_mul(onep, ronep, s, rs)
    margin = inflate(out_C, D, out_c, dc, out_C, out_L)
    if margin < 0.0:
        return OUT_OF_DOMAIN, p, 0.0
    return 0, p, margin


@njit(cache=True)
def sum_single(c1, C1, c2, C2, mode, p_in, planar, heading):
    """One instance (the same ``sum_one`` as the batch), plus the result's Cholesky factor and
    its validation code (0 by construction, see ``_midrad.inflate``)."""
    n = c1.shape[0]
    out_c = np.empty(n)
    out_C = np.empty((n, n))
    out_L = np.empty((n, n))
    work = np.zeros((6, max(n, 1), n))
    r = sum_one(c1, C1, c2, C2, mode, p_in, planar, heading, out_c, out_C, out_L, work)
    valid = check_ellipsoid(out_c, out_C, out_L)
    return out_c, out_C, out_L, valid, r


@njit(cache=True, nogil=True)
def sum_range(c1, C1, c2, C2, mode, p_in, planar, heading, out, start, stop):
    """``sum_one`` on instances ``start..stop`` (p_in broadcast to (B,) by the caller).
    ``out`` = (centres, shapes, chol, code, p, margin)."""
    out_c, out_C, out_L, code, p, margin = out
    n = c1.shape[1]
    work = np.zeros((6, max(n, 1), n))
    for i in range(start, stop):
        r = sum_one(
            c1[i], C1[i], c2[i], C2[i], mode, p_in[i], planar, heading,
            out_c[i], out_C[i], out_L[i], work,
        )  # fmt: skip
        code[i], p[i], margin[i] = r
