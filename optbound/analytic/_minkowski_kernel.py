"""Compiled core of the outer Minkowski sum [HS96, eq. (14)], one instance per call.

Shared by :func:`minkowski_sum` and :func:`minkowski_sum_batch` (bitwise agreement). Steps:
validate both summands (``check_ellipsoid``), choose p = (1 - kappa) / kappa, evaluate the
member ``(1 + p) (C1 / p + C2)`` and the centre ``c1 + c2`` in midpoint-radius arithmetic,
inflate by the certified margin (``_midrad.inflate``, which keeps the output in the domain).

The volume-optimal p is the root of the increasing ``h(p) = p (p + 1) tr((C1 + p C2)^{-1} C2)
- n`` (the module docstring of :mod:`optbound.analytic.minkowski`: with the generalized
eigenvalues l_i of (C1, C2), ``tr((C1 + p C2)^{-1} C2) = sum_i 1 / (l_i + p)``), in
``[sqrt(l_min), sqrt(l_max)]``. :func:`p_volume` finds it per instance in two stages:

1. Once per instance, the pencil is reduced to the standard form ``M = L2^{-1} C1 L2^{-T}``
   (L2 the Cholesky factor of C2, already computed by ``check_ellipsoid``) and M to a
   tridiagonal T by Householder reflections (one in 3-D). Then ``tr((C1 + p C2)^{-1} C2) =
   tr((T + p I)^{-1})``, which the LDL^T pivot recurrence of ``T + p I`` and its derivatives
   give in O(n) without cancellation or overflow (:func:`h_tridiagonal`); Newton's method
   safeguarded by a bracket solves h = 0 on it.
2. The standard form inherits cond(C2) cond(C1)-sized rounding errors, so the root is polished
   by Newton steps on h evaluated from the Cholesky factor of ``C1 + p C2`` (whose condition
   is at most max(cond C1, cond C2), :func:`h_shifted`): O(n^3), but usually one evaluation,
   which only confirms the stage-1 root.

The pencil is oriented so that the root is not small (p << 1 would cancel in h): if
``sqrt(tr C1 / tr C2) < 1`` both stages solve the swapped pencil (C2, C1), whose root is 1 / p.
Every p > 0 gives an outer bound (the certified margin is computed afterwards), so p needs no
rigor; it is always finite and > 0. Against a 50-digit eigenvalue solve (relative error): ~1e-15
for cond <= 1e2, <= ~1e-9 at cond 1e6 and 1e12, ~1e-5 where cond 1e12 meets summands 1e100
apart in size (``tests/analytic/test_minkowski_kernel.py``); the volume is flat at its
minimum, so its excess is of the order of the square of that.
The ``size_xy_psi`` p is the best root of the cubic [HS96, eqs. (15)-(17)]
(``_cubic.real_roots``).
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
# Newton ends after a step below rtol q (its error is then ~ step^2): the tridiagonal stage may
# stop earlier, since the polishing step that follows squares its error again.
NEWTON_RTOL, TRIDIAGONAL_RTOL = 1e-9, 1e-6


@njit(cache=True, error_model="numpy", inline="always")
def reduce_pencil(A, LB, M, Y, r):
    """``M = LB^{-1} A LB^{-T}`` (A symmetric, its lower triangle used; LB lower triangular):
    the standard form of the pencil (A, LB LB^T), same eigenvalues. Y (n, n) and r (n,) are
    work space (r: LB's reciprocal diagonal, n divisions instead of 2 n^2)."""
    n = A.shape[0]
    for i in range(n):
        r[i] = 1.0 / LB[i, i]
    for j in range(n):  # Y[:, j] = LB^{-1} A[:, j]
        for i in range(n):
            s = A[i, j] if j <= i else A[j, i]
            for k in range(i):
                s -= LB[i, k] * Y[k, j]
            Y[i, j] = s * r[i]
    for j in range(n):  # M[:, j] = LB^{-1} Y[j, :] (M = Y LB^{-T} is symmetric)
        for i in range(n):
            s = Y[j, i]
            for k in range(i):
                s -= LB[i, k] * M[k, j]
            M[i, j] = s * r[i]


@njit(cache=True, error_model="numpy", inline="always")
def tridiagonalize(M, v, w):
    """Householder reduction of the symmetric M (lower triangle) to tridiagonal form T in
    place: T's diagonal on M's, its sub-diagonal on M's (orthogonal similarity, same
    eigenvalues; n - 2 reflections, one in 3-D). v, w are (n,) work space. Each reflector is
    built from the column scaled by its largest entry, so no square overflows."""
    n = M.shape[0]
    for k in range(n - 2):
        s = 0.0
        for i in range(k + 1, n):
            s = max(s, abs(M[i, k]))
        if s == 0.0:  # column already reduced
            continue
        sig = 0.0
        rs = 1.0 / s
        for i in range(k + 1, n):
            v[i] = M[i, k] * rs
            sig += v[i] * v[i]
        sig = np.sqrt(sig)
        u0 = v[k + 1]
        alpha = -sig if u0 >= 0.0 else sig  # -sign(u0) ||u||: no cancellation in v
        v[k + 1] = u0 - alpha
        beta = 1.0 / (sig * (sig + abs(u0)))  # 2 / (v^T v)
        M[k + 1, k] = alpha * s
        vw = 0.0
        for i in range(k + 1, n):  # w = beta B v on the trailing block B (symmetric)
            t = 0.0
            for j in range(k + 1, n):
                t += (M[i, j] if j <= i else M[j, i]) * v[j]
            w[i] = beta * t
            vw += v[i] * w[i]
        half = 0.5 * beta * vw
        for i in range(k + 1, n):
            w[i] -= half * v[i]
        for i in range(k + 1, n):  # B -= v w^T + w v^T (lower triangle)
            for j in range(k + 1, i + 1):
                M[i, j] -= v[i] * w[j] + w[i] * v[j]


@njit(cache=True, error_model="numpy", inline="always")
def h_tridiagonal(T, q):
    """``h(q) = q (q + 1) tr((T + q I)^{-1}) - n`` and h'(q) for the tridiagonal T (diagonal
    and sub-diagonal of the array T), in O(n), or (nan, nan) if T + q I is not numerically
    positive definite (q below the rounding level of T's small eigenvalues).

    The LDL^T pivots ``d_i = t_ii + q - e_i^2 / d_{i-1}`` give ``tr((T + qI)^{-1}) =
    d/dq log det(T + qI) = sum_i d_i' / d_i`` and its derivative ``sum_i (d_i'' / d_i -
    (d_i' / d_i)^2)``. The recurrence carries g = d'/d and gam = d''/d, never d' or d'' (which
    can exceed the float range): ``d_i = t_ii + q - u``, ``g_i = (1 + u g_{i-1}) / d_i``,
    ``gam_i = u (gam_{i-1} - 2 g_{i-1}^2) / d_i`` with ``u = e_i^2 / d_{i-1} < t_ii + q``.
    All terms of both sums have one sign (d_i is concave in q), so they do not cancel."""
    n = T.shape[0]
    r = 1.0
    g = 0.0
    gam = 0.0
    f = 0.0
    df = 0.0
    for i in range(n):  # one division per pivot: r = 1 / d_{i-1} serves u, g and gam
        d = T[i, i] + q
        num_g = 1.0
        num_gam = 0.0
        if i > 0:
            e = T[i, i - 1]
            u = (e * r) * e  # e / d_{i-1} first: e^2 alone may overflow
            d -= u
            num_g += u * g
            num_gam = u * (gam - 2.0 * g * g)
        if not d > 0.0:
            return np.nan, np.nan
        r = 1.0 / d
        g = num_g * r
        gam = num_gam * r
        f += g
        df += gam - g * g
    qq = q * (q + 1.0)
    return qq * f - n, (2.0 * q + 1.0) * f + qq * df


@njit(cache=True, error_model="numpy", inline="always")
def h_shifted(A, B, LB, q, S, L, W):
    """h(q) and h'(q) (module docstring) from the Cholesky factor L of ``S = A + q B``:
    with ``W = L^{-1} LB`` (LB the Cholesky factor of B), ``tr(S^{-1} B) = ||W||_F^2`` and
    ``tr((S^{-1} B)^2) = ||W W^T||_F^2``, so ``h = q (q + 1) ||W||_F^2 - n`` and ``h' =
    (2q + 1) ||W||_F^2 - q (q + 1) ||W W^T||_F^2``. O(n^3), but as accurate as the pencil
    allows (cond(S) <= max(cond A, cond B)); (nan, nan) if the factorization fails. S, L, W
    are (n, n) work space; S's strict upper triangle keeps L's reciprocal diagonal."""
    n = A.shape[0]
    for i in range(n):
        for j in range(i + 1):
            S[i, j] = A[i, j] + q * B[i, j]
    if not cholesky(S, L) > 0.0:
        return np.nan, np.nan
    t1 = 0.0
    for j in range(n):  # W[:, j] = L^{-1} LB[:, j], lower triangular
        for i in range(j, n):
            s = LB[i, j]
            for k in range(j, i):
                s -= L[i, k] * W[k, j]
            W[i, j] = s / L[i, i]
            t1 += W[i, j] * W[i, j]
    t2 = 0.0
    for i in range(n):  # G = W W^T (lower triangle), t2 = ||G||_F^2
        for j in range(i + 1):
            g = 0.0
            for k in range(j + 1):
                g += W[i, k] * W[j, k]
            t2 += g * g if i == j else 2.0 * g * g
    qq = q * (q + 1.0)
    return qq * t1 - n, (2.0 * q + 1.0) * t1 - qq * t2


# newton and p_volume are compiled once and called (inlining them into every caller tripled the
# fresh-compile time, 12 s -> 42 s); _nrt=False keeps their views free of atomic reference
# counting. The small helpers are inlined into them.
@njit(cache=True, error_model="numpy", _nrt=False)
def newton(shifted, A, B, LB, T, L, X, q, hi):
    """Root of the increasing h in ``(0, hi]`` by Newton's method safeguarded by a bracket,
    started at q in (0, hi]; the result is finite and > 0. h is :func:`h_tridiagonal` on T,
    or :func:`h_shifted` on (A, B, LB) if ``shifted`` (T, L, X its work space); its stopping
    tolerance rtol is ``NEWTON_RTOL`` or ``TRIDIAGONAL_RTOL`` accordingly.

    A Newton step leaving the bracket is replaced by a geometric bisection (or a division by 4
    while the lower end is 0; a failed evaluation counts as h < 0: q too small). A step below
    ``rtol q`` is taken and ends the iteration: Newton's error after it is of the order of the
    step squared."""
    rtol = NEWTON_RTOL if shifted else TRIDIAGONAL_RTOL
    lo = 0.0
    for _ in range(NEWTON_MAX_STEPS):
        if shifted:
            h, dh = h_shifted(A, B, LB, q, T, L, X)
        else:
            h, dh = h_tridiagonal(T, q)
        if h == 0.0:
            break
        if h > 0.0:
            hi = q
        else:
            lo = q
        step = q - h / dh if dh > 0.0 else np.nan
        if lo < step < hi:
            if abs(step - q) <= rtol * q:
                return step
        elif lo > 0.0:
            step = np.sqrt(lo * hi)
        else:
            step = 0.25 * q
        if not hi - lo > 4.0 * U * hi:  # bracket at rounding level
            break
        q = step
    return q


@njit(cache=True, error_model="numpy", inline="always")
def gershgorin_max(T) -> float:
    """Gershgorin's upper bound on the largest eigenvalue of the tridiagonal T."""
    n = T.shape[0]
    big = 0.0
    for i in range(n):
        r = T[i, i]
        if i > 0:
            r += abs(T[i, i - 1])
        if i + 1 < n:
            r += abs(T[i + 1, i])
        big = max(big, r)
    return big


@njit(cache=True, error_model="numpy", inline="always")
def root_oriented(A, B, LB, q, M, Y, Z):
    """Root of h for the pencil (A, B), LB the Cholesky factor of B, from the start q > 0:
    stage 1 on the tridiagonal form (O(n) per step), stage 2 polishing with
    :func:`h_shifted` (usually one evaluation, which confirms the root), since the standard
    form loses accuracy when both shapes are ill-conditioned. M, Y, Z are work space."""
    reduce_pencil(A, LB, M, Y, Z[0])
    if A.shape[0] > 2:
        tridiagonalize(M, Y[0], Y[1])
    # h(sqrt(l_max)) >= 0; the factor covers the rounding of T's eigenvalues (normwise).
    hi = np.sqrt(gershgorin_max(M)) * 1.01
    q = newton(False, A, B, LB, M, Y, Z, min(q, hi), hi)
    return newton(True, A, B, LB, M, Y, Z, q, hi)


@njit(cache=True, error_model="numpy", _nrt=False)
def p_volume(C1, C2, L1, L2, M, Y, Z):
    """The volume-optimal p (module docstring): L1, L2 are the Cholesky factors of C1, C2;
    M, Y, Z are (n, n) work space.

    Oriented so that the solved root is not small: if ``p0 = sqrt(tr C1 / tr C2)`` (in
    ``[sqrt(l_min), sqrt(l_max)]``, the root for equal eigenvalues) is below 1, the pencil is
    swapped to (C2, C1), whose root is 1 / p (for p << 1, h = p (p + 1) tr(...) - n would lose
    the digits of p to cancellation; a root p << 1 has every l_i <~ n p^2, so p0 <~ sqrt(n) p
    is small too)."""
    t1 = 0.0
    t2 = 0.0
    for i in range(C1.shape[0]):
        t1 += C1[i, i]
        t2 += C2[i, i]
    p0 = np.sqrt(t1 / t2)
    if p0 >= 1.0:
        return root_oriented(C1, C2, L2, p0, M, Y, Z)
    return 1.0 / root_oriented(C2, C1, L1, 1.0 / p0, M, Y, Z)


@njit(cache=True, error_model="numpy")
def _trace(C, idx):
    t = 0.0
    for i in idx:
        t += C[i, i]
    return t


@njit(cache=True, error_model="numpy")
def _xy_psi_size(k, t1, t2, h1, h2):
    """tr(proj_xy C) tr(proj_psi C) of the member kappa [HS96, eq. (15)]."""
    return (t1 / (1.0 - k) + t2 / k) * (h1 / (1.0 - k) + h2 / k)


@njit(cache=True, error_model="numpy")
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


@njit(cache=True, error_model="numpy", inline="always")
def sum_one(c1, C1, c2, C2, mode, p_in, planar, heading, out_c, out_C, work):
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
        p = p_volume(C1, C2, L1, L2, A, X, D)
    onep, ronep = mr_add(1.0, 0.0, p, 0.0)
    for i in range(n):
        out_c[i], dc[i] = mr_add(c1[i], 0.0, c2[i], 0.0)
        for j in range(i + 1):
            q, rq = mr_div(C1[i, j], 0.0, p, 0.0)
            s, rs = mr_add(q, rq, C2[i, j], 0.0)
            out_C[i, j], D[i, j] = mr_mul(onep, ronep, s, rs)
    margin = inflate(out_C, D, out_c, dc, out_C, A)  # A: free work space by now
    if margin < 0.0:
        return OUT_OF_DOMAIN, p, 0.0
    return 0, p, margin


@njit(cache=True, error_model="numpy")
def sum_single(c1, C1, c2, C2, mode, p_in, planar, heading):
    """One instance through the batch loop ``_sum_loop`` (a batch of one: the same compiled
    code, so single and batched results agree bitwise and the kernel is compiled once), plus
    the result's Cholesky factor and its validation code (0 by construction, see
    ``_midrad.inflate``)."""
    n = c1.shape[0]
    out = (np.empty((1, n)), np.empty((1, n, n)), np.zeros(1, np.int8), np.empty(1), np.empty(1))
    work = np.zeros((6, max(n, 1), n))
    one = n // n  # a runtime int: literal 0 and 1 would compile a specialization of their own
    _sum_loop(
        np.ascontiguousarray(c1).reshape((1, n)), np.ascontiguousarray(C1).reshape((1, n, n)),
        np.ascontiguousarray(c2).reshape((1, n)), np.ascontiguousarray(C2).reshape((1, n, n)),
        mode, np.full(1, p_in), planar, heading, out, work, one - 1, one,
    )  # fmt: skip
    out_c, out_C = out[0][0], out[1][0]
    out_L = np.empty((n, n))
    valid = check_ellipsoid(out_c, out_C, out_L)
    return out_c, out_C, out_L, valid, (out[2][0], out[3][0], out[4][0])


@njit(cache=True, error_model="numpy", nogil=True, _nrt=False)
def _sum_loop(c1, C1, c2, C2, mode, p_in, planar, heading, out, work, start, stop):
    """The batch loop, compiled without numba's reference counting (``_nrt=False``, as
    ``_strip_kernel._fuse_loop``): every per-instance view otherwise increments and decrements
    its parent's counter atomically, a cache line both threads fight over. Nothing here
    allocates; the views live no longer than the call."""
    out_c, out_C, code, p, margin = out
    for i in range(start, stop):
        r = sum_one(
            c1[i], C1[i], c2[i], C2[i], mode, p_in[i], planar, heading, out_c[i], out_C[i], work
        )
        code[i], p[i], margin[i] = r


@njit(cache=True, error_model="numpy", nogil=True)
def sum_range(c1, C1, c2, C2, mode, p_in, planar, heading, out, start, stop):
    """``sum_one`` on instances ``start..stop`` (p_in broadcast to (B,) by the caller).
    ``out`` = (centres, shapes, code, p, margin); no Cholesky factors (the batch returns none).
    """
    n = c1.shape[1]
    work = np.zeros((6, max(n, 1), n))
    _sum_loop(c1, C1, c2, C2, mode, p_in, planar, heading, out, work, start, stop)
