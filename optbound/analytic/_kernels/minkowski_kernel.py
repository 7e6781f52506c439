"""Compiled core of the outer Minkowski sum [HS96, eq. (14)], over blocks of W instances.

Shared by :func:`minkowski_sum` (a batch of one) and :func:`minkowski_sum_batch`: the same
compiled code, so single and batched results agree bitwise. A batch is processed in blocks of
up to ``W`` instances, one per lane of lanes-last arrays (``lanes``), so
that every step is a SIMD loop over the lanes. Steps per block: validate both summands
(``lanes.check_ellipsoids``), choose p = (1 - kappa) / kappa, evaluate the member ``(1 + p)
(C1 / p + C2)`` and the centre ``c1 + c2`` in midpoint-radius arithmetic, inflate by the
certified margin (``lanes.inflate_lanes``, the lane form of ``midrad.inflate``, which keeps
the output in the domain). A lane never depends on another (branches are selects), and the
loops' vector bodies and scalar remainders perform the same IEEE operations (no fastmath), so
a lane gives the same bits in any block.

The volume-optimal p is the root of the increasing ``h(p) = p (p + 1) tr((C1 + p C2)^{-1} C2)
- n`` (the module docstring of :mod:`optbound.analytic.minkowski`: with the generalized
eigenvalues l_i of (C1, C2), ``tr((C1 + p C2)^{-1} C2) = sum_i 1 / (l_i + p)``), in
``[sqrt(l_min), sqrt(l_max)]``. :func:`p_volume_lanes` finds it for a block of lanes in two
stages, each a Newton iteration run in lockstep over the lanes (:func:`newton_lanes`):

1. Once per instance, the pencil is reduced to the standard form ``M = L2^{-1} C1 L2^{-T}``
   (L2 the Cholesky factor of C2, already computed by the validation) and M to a
   tridiagonal T by Householder reflections (one in 3-D). Then ``tr((C1 + p C2)^{-1} C2) =
   tr((T + p I)^{-1})``, which the LDL^T pivot recurrence of ``T + p I`` and its derivatives
   give in O(n) without cancellation or overflow (:func:`h_tridiagonal_lanes`); Newton's method
   safeguarded by a bracket solves h = 0 on it.
2. The standard form inherits cond(C2) cond(C1)-sized rounding errors, so the root is polished
   by Newton steps on h evaluated from the Cholesky factor of ``C1 + p C2`` (whose condition
   is at most max(cond C1, cond C2), :func:`h_shifted_lanes`): O(n^3), but usually one evaluation,
   which only confirms the stage-1 root.

The pencil is oriented so that the root is not small (p << 1 would cancel in h): if
``sqrt(tr C1 / tr C2) < 1`` both stages solve the swapped pencil (C2, C1), whose root is 1 / p.
Every p > 0 gives an outer bound (the certified margin is computed afterwards), so p needs no
rigor; it is always finite and > 0. Against a 50-digit eigenvalue solve (relative error): ~1e-15
for cond <= 1e2, <= ~1e-9 at cond 1e6 and 1e12, ~1e-5 where cond 1e12 meets summands 1e100
apart in size (``tests/analytic/test_minkowski_kernel.py``); the volume is flat at its
minimum, so its excess is of the order of the square of that.
The ``size_xy_psi`` p is the best root of the cubic [HS96, eqs. (15)-(17)]
(``cubic.real_roots``).
"""

from __future__ import annotations

import numpy as np

from optbound._core.jit import njit
from optbound._core.native_call import address, caller
from optbound.analytic._kernels.cubic import real_roots
from optbound.analytic._kernels.lanes import (
    CHECK_ROWS,
    W,
    check_ellipsoids,
    cholesky_lanes,
    first_error,
    inflate_lanes,
    load_matrices,
    load_vectors,
    store_matrices,
    store_vectors,
)
from optbound.analytic._kernels.midrad import U, mr_add, mr_div, mr_mul
from optbound.analytic._kernels.threads import workspace

P_VOLUME, P_TRACE, P_GIVEN, P_XY_PSI = range(4)
# Error codes: check_ellipsoid's (1..6) for the first summand, +10 for the second, and:
BAD_KAPPA, OUT_OF_DOMAIN = 21, 22
NEWTON_MAX_STEPS = 100
# Newton ends after a step below rtol q (its error is then ~ step^2): the tridiagonal stage may
# stop earlier, since the polishing step that follows squares its error again.
NEWTON_RTOL, TRIDIAGONAL_RTOL = 1e-9, 1e-6


@njit(cache=True, error_model="numpy", inline="always")
def solve_column(LB, r, X, j, m):
    """``X[:, j] = LB^{-1} X[:, j]`` in place per lane (forward substitution; r (n, W) holds
    LB's reciprocal diagonal)."""
    for i in range(X.shape[0]):
        for q in range(i):
            for k in range(m):
                X[i, j, k] -= LB[i, q, k] * X[q, j, k]
        for k in range(m):
            X[i, j, k] *= r[i, k]


@njit(cache=True, error_model="numpy", inline="always")
def reduce_pencil_lanes(A, LB, M, Y, r, m):
    """``M = LB^{-1} A LB^{-T}`` per lane (A symmetric, its lower triangle used; LB lower
    triangular): the standard form of the pencil (A, LB LB^T), same eigenvalues. Y (n, n, W)
    and r (n, W) are work space (r: LB's reciprocal diagonal, n divisions instead of 2 n^2)."""
    n = A.shape[0]
    for i in range(n):
        for k in range(m):
            r[i, k] = 1.0 / LB[i, i, k]
    for j in range(n):  # Y[:, j] = LB^{-1} A[:, j]
        for i in range(n):
            if j <= i:
                for k in range(m):
                    Y[i, j, k] = A[i, j, k]
            else:
                for k in range(m):
                    Y[i, j, k] = A[j, i, k]
        solve_column(LB, r, Y, j, m)
    for j in range(n):  # M[:, j] = LB^{-1} Y[j, :] (M = Y LB^{-T} is symmetric)
        for i in range(n):
            for k in range(m):
                M[i, j, k] = Y[j, i, k]
        solve_column(LB, r, M, j, m)


@njit(cache=True, error_model="numpy", inline="always")
def tridiagonalize_lanes(M, m, v, w, rows):
    """Householder reduction of the symmetric M (n, n, W; lower triangle) to tridiagonal form
    T in place, per lane: T's diagonal on M's, its sub-diagonal on M's (orthogonal similarity,
    same eigenvalues; n - 2 reflections, one in 3-D). v, w (n, W) and 4 rows are work
    space. Each reflector is built from the column scaled by its largest entry, so no square
    overflows; a lane whose column is already reduced (all zero) is left unchanged."""
    n = M.shape[0]
    s, sig, beta, vw = rows[0], rows[1], rows[2], rows[3]
    for c in range(n - 2):
        for k in range(m):
            s[k] = 0.0
            sig[k] = 0.0
            vw[k] = 0.0
        for i in range(c + 1, n):
            for k in range(m):
                s[k] = max(s[k], abs(M[i, c, k]))
        for i in range(c + 1, n):
            for k in range(m):
                v[i, k] = M[i, c, k] * (1.0 / s[k] if s[k] > 0.0 else 0.0)
                sig[k] += v[i, k] * v[i, k]
        for k in range(m):
            sg = np.sqrt(sig[k])
            u0 = v[c + 1, k]
            alpha = -sg if u0 >= 0.0 else sg  # -sign(u0) ||u||: no cancellation in v
            v[c + 1, k] = u0 - alpha
            # 2 / (v^T v); 0 (no reflection) for a reduced column
            beta[k] = 1.0 / (sg * (sg + abs(u0))) if s[k] > 0.0 else 0.0
            M[c + 1, c, k] = alpha * s[k] if s[k] > 0.0 else M[c + 1, c, k]
        for i in range(c + 1, n):  # w = beta B v on the trailing block B (symmetric)
            for k in range(m):
                w[i, k] = 0.0
            for j in range(c + 1, n):
                if j <= i:
                    for k in range(m):
                        w[i, k] += M[i, j, k] * v[j, k]
                else:
                    for k in range(m):
                        w[i, k] += M[j, i, k] * v[j, k]
            for k in range(m):
                w[i, k] *= beta[k]
                vw[k] += v[i, k] * w[i, k]
        for i in range(c + 1, n):
            for k in range(m):
                w[i, k] -= 0.5 * beta[k] * vw[k] * v[i, k]
        for i in range(c + 1, n):  # B -= v w^T + w v^T (lower triangle)
            for j in range(c + 1, i + 1):
                for k in range(m):
                    M[i, j, k] -= v[i, k] * w[j, k] + w[i, k] * v[j, k]


@njit(cache=True, error_model="numpy", inline="always")
def h_tridiagonal_lanes(T, q, m, h, dh, rows):
    """``h(q) = q (q + 1) tr((T + q I)^{-1}) - n`` and h'(q) per lane into h, dh (W,), for the
    tridiagonal T (diagonal and sub-diagonal of T (n, n, W)), in O(n), or nan where T + q I is
    not numerically positive definite (q below the rounding level of T's small eigenvalues).
    ``rows`` are 6 work rows.

    The LDL^T pivots ``d_i = t_ii + q - e_i^2 / d_{i-1}`` give ``tr((T + qI)^{-1}) =
    d/dq log det(T + qI) = sum_i d_i' / d_i`` and its derivative ``sum_i (d_i'' / d_i -
    (d_i' / d_i)^2)``. The recurrence carries g = d'/d and gam = d''/d, never d' or d'' (which
    can exceed the float range): ``d_i = t_ii + q - u``, ``g_i = (1 + u g_{i-1}) / d_i``,
    ``gam_i = u (gam_{i-1} - 2 g_{i-1}^2) / d_i`` with ``u = e_i^2 / d_{i-1} < t_ii + q``.
    All terms of both sums have one sign (d_i is concave in q), so they do not cancel."""
    n = T.shape[0]
    r, g, gam, f, df, ok = rows[0], rows[1], rows[2], rows[3], rows[4], rows[5]
    for k in range(m):  # one division per pivot: r = 1 / d_{i-1} serves u, g and gam
        d = T[0, 0, k] + q[k]
        ok[k] = 1.0 if d > 0.0 else 0.0
        r[k] = 1.0 / d
        g[k] = r[k]
        gam[k] = 0.0
        f[k] = g[k]
        df[k] = -g[k] * g[k]
    for i in range(1, n):
        for k in range(m):
            e = T[i, i - 1, k]
            u = (e * r[k]) * e  # e / d_{i-1} first: e^2 alone may overflow
            d = (T[i, i, k] + q[k]) - u
            ok[k] = ok[k] if d > 0.0 else 0.0
            r[k] = 1.0 / d
            num_gam = u * (gam[k] - 2.0 * g[k] * g[k])
            g[k] = (1.0 + u * g[k]) * r[k]
            gam[k] = num_gam * r[k]
            f[k] += g[k]
            df[k] += gam[k] - g[k] * g[k]
    for k in range(m):
        qq = q[k] * (q[k] + 1.0)
        h[k] = qq * f[k] - n if ok[k] > 0.0 else np.nan
        dh[k] = (2.0 * q[k] + 1.0) * f[k] + qq * df[k] if ok[k] > 0.0 else np.nan


@njit(cache=True, error_model="numpy", inline="always")
def h_shifted_lanes(A, B, LB, q, m, h, dh, S, L, X, rows):
    """h(q) and h'(q) per lane (module docstring) from the Cholesky factor L of ``S = A + q
    B``: with ``X = L^{-1} LB`` (LB the Cholesky factor of B), ``tr(S^{-1} B) = ||X||_F^2`` and
    ``tr((S^{-1} B)^2) = ||X X^T||_F^2``, so ``h = q (q + 1) ||X||_F^2 - n`` and ``h' =
    (2q + 1) ||X||_F^2 - q (q + 1) ||X X^T||_F^2``. O(n^3), but as accurate as the pencil
    allows (cond(S) <= max(cond A, cond B)); nan where the factorization fails. S, L, X
    (n, n, W) and 4 rows are work space."""
    n = A.shape[0]
    pivot, t1, t2, g = rows[0], rows[1], rows[2], rows[3]
    for i in range(n):
        for j in range(i + 1):
            for k in range(m):
                S[i, j, k] = A[i, j, k] + q[k] * B[i, j, k]
    cholesky_lanes(S, L, m, pivot, 0)
    for k in range(m):
        t1[k] = 0.0
        t2[k] = 0.0
    for j in range(n):  # X[:, j] = L^{-1} LB[:, j], lower triangular
        for i in range(j, n):
            for k in range(m):
                X[i, j, k] = LB[i, j, k]
            for c in range(j, i):
                for k in range(m):
                    X[i, j, k] -= L[i, c, k] * X[c, j, k]
            for k in range(m):
                X[i, j, k] /= L[i, i, k]
                t1[k] += X[i, j, k] * X[i, j, k]
    for i in range(n):  # G = X X^T (lower triangle), t2 = ||G||_F^2
        for j in range(i + 1):
            w = 1.0 if i == j else 2.0
            for k in range(m):
                g[k] = 0.0
            for c in range(j + 1):
                for k in range(m):
                    g[k] += X[i, c, k] * X[j, c, k]
            for k in range(m):
                t2[k] += w * g[k] * g[k]
    for k in range(m):
        qq = q[k] * (q[k] + 1.0)
        h[k] = qq * t1[k] - n if pivot[k] > 0.0 else np.nan
        dh[k] = (2.0 * q[k] + 1.0) * t1[k] - qq * t2[k] if pivot[k] > 0.0 else np.nan


@njit(cache=True, error_model="numpy", inline="always")
def sqrt_trace_ratio(C1, C2, m, out, t2):
    """``sqrt(tr C1 / tr C2)`` per lane into out (W,); t2 (W,) is work space."""
    for k in range(m):
        out[k] = 0.0
        t2[k] = 0.0
    for i in range(C1.shape[0]):
        for k in range(m):
            out[k] += C1[i, i, k]
            t2[k] += C2[i, i, k]
    for k in range(m):
        out[k] = np.sqrt(out[k] / t2[k])


@njit(cache=True, error_model="numpy", inline="always")
def newton_start(m, hi0, active, rows):
    """Initial state of :func:`newton_update` in ``rows`` (lo, hi, run; rows 2, 3 receive h
    and h'); returns the number of running lanes."""
    lo, hi, run = rows[0], rows[1], rows[4]
    running = 0
    for k in range(m):
        lo[k] = 0.0
        hi[k] = hi0[k]
        run[k] = active[k]
        running += 1 if active[k] > 0.0 else 0
    return running


@njit(cache=True, error_model="numpy", inline="always")
def newton_update(m, q, rtol, rows):
    """One step of Newton's method safeguarded by a bracket on every running lane, from h and
    h' at q (rows 2, 3); returns the number of lanes still running.

    The lanes iterate in lockstep while any of them runs; a lane that has stopped is no longer
    updated (selects, no branch), so its result does not depend on the other lanes. A Newton
    step leaving the bracket is replaced by a geometric bisection (or a division by 4 while
    the lower end is 0; a failed evaluation counts as h < 0: q too small). A step below
    ``rtol q`` is taken and ends the iteration: Newton's error after it is of the order of the
    step squared."""
    lo, hi, h, dh, run = rows[0], rows[1], rows[2], rows[3], rows[4]
    running = 0
    for k in range(m):
        qk, hk = q[k], h[k]
        up = hk > 0.0
        lok = lo[k] if up else qk
        hik = qk if up else hi[k]
        step = qk - hk / dh[k] if dh[k] > 0.0 else np.nan
        inside = lok < step < hik
        converged = inside and abs(step - qk) <= rtol * qk
        if not inside:
            step = np.sqrt(lok * hik) if lok > 0.0 else 0.25 * qk
        collapsed = not hik - lok > 4.0 * U * hik  # bracket at rounding level
        take = converged or not (hk == 0.0 or collapsed)
        stop = hk == 0.0 or converged or collapsed
        live = run[k] > 0.0
        q[k] = step if live and take else qk
        lo[k] = lok if live else lo[k]
        hi[k] = hik if live else hi[k]
        run[k] = 0.0 if stop else run[k]
        running += 1 if run[k] > 0.0 else 0
    return running


# newton_lanes and p_volume_lanes are compiled once, each in its own library, and called by
# address (``native_call``), never linked into a caller (where LLVM would optimize and emit
# their lane loop nests again); _nrt=False keeps their views free of atomic reference
# counting. The lane helpers are inlined into them.
@njit(cache=True, error_model="numpy", _nrt=False)
def newton_lanes(stage, A, B, LB, T, m, q, hi0, active, mats, rows):
    """Root of h in ``(0, hi0]`` per lane with ``active`` > 0, from q in (0, hi0] (q (W,) is
    updated in place to the root, finite and > 0), by :func:`newton_update`. Stage 1
    (``stage == 1``): h from :func:`h_tridiagonal_lanes` on T, to ``TRIDIAGONAL_RTOL``;
    stage 2: h from :func:`h_shifted_lanes` on (A, B, LB), to ``NEWTON_RTOL``. 3 mats
    (n, n, W) and 11 rows are work space."""
    rtol = TRIDIAGONAL_RTOL if stage == 1 else NEWTON_RTOL
    running = newton_start(m, hi0, active, rows)
    for _ in range(NEWTON_MAX_STEPS):
        if running == 0:
            break
        if stage == 1:
            h_tridiagonal_lanes(T, q, m, rows[2], rows[3], rows[5:])
        else:
            h_shifted_lanes(A, B, LB, q, m, rows[2], rows[3], mats[0], mats[1], mats[2], rows[5:])
        running = newton_update(m, q, rtol, rows)


_call_newton = caller(newton_lanes)


@njit(cache=True, error_model="numpy", _nrt=False)
def p_volume_lanes(C1, C2, L1, L2, m, active, p, mats, vecs, rows, newton):
    """The volume-optimal p (module docstring) of the lanes with ``active`` > 0, into p (W,):
    C1, C2 (n, n, W) the shapes, L1, L2 their Cholesky factors; 7 mats (n, n, W), 3 vecs
    (n, W) and 14 rows are work space; ``newton`` is the address of :func:`newton_lanes`
    (``entry_points()[NEWTON_ENTRY]``).

    Each lane solves the oriented pencil, so that its root is not small: if ``p0 =
    sqrt(tr C1 / tr C2)`` (in ``[sqrt(l_min), sqrt(l_max)]``, the root for equal eigenvalues)
    is below 1, the pencil is swapped to (C2, C1), whose root is 1 / p (for p << 1, h = p (p +
    1) tr(...) - n would lose the digits of p to cancellation; a root p << 1 has every l_i <~
    n p^2, so p0 <~ sqrt(n) p is small too). Stage 1 on the tridiagonal form (O(n) per step),
    stage 2 polishing with :func:`h_shifted_lanes` (usually one evaluation, which confirms the
    root), since the standard form loses accuracy when both shapes are ill-conditioned."""
    n = C1.shape[0]
    A, B, LB, M, Y = mats[0], mats[1], mats[2], mats[3], mats[4]
    swap, q, hi = rows[0], rows[1], rows[2]
    sqrt_trace_ratio(C1, C2, m, q, hi)
    for k in range(m):
        p0 = q[k]
        swap[k] = 0.0 if p0 >= 1.0 else 1.0
        q[k] = p0 if p0 >= 1.0 else 1.0 / p0
    for i in range(n):
        for j in range(i + 1):
            for k in range(m):
                a, b = C1[i, j, k], C2[i, j, k]
                A[i, j, k] = b if swap[k] > 0.0 else a
                B[i, j, k] = a if swap[k] > 0.0 else b
                LB[i, j, k] = L1[i, j, k] if swap[k] > 0.0 else L2[i, j, k]
    reduce_pencil_lanes(A, LB, M, Y, vecs[0], m)
    tridiagonalize_lanes(M, m, vecs[1], vecs[2], rows[3:])
    # h(sqrt(l_max)) >= 0: Gershgorin's bound on T's largest eigenvalue (in hi), times a
    # factor for the rounding of T's eigenvalues (normwise).
    for k in range(m):
        hi[k] = 0.0
    for i in range(n):
        for k in range(m):
            e = M[i, i, k]
            if i > 0:
                e += abs(M[i, i - 1, k])
            if i + 1 < n:
                e += abs(M[i + 1, i, k])
            hi[k] = max(hi[k], e)
    for k in range(m):
        hi[k] = np.sqrt(hi[k]) * 1.01
        q[k] = min(q[k], hi[k])
    # np.int64(): a typed stage number, where a literal would compile one specialization each
    _call_newton(newton, (np.int64(1), A, B, LB, M, m, q, hi, active, mats[4:], rows[3:]))
    _call_newton(newton, (np.int64(2), A, B, LB, M, m, q, hi, active, mats[4:], rows[3:]))
    for k in range(m):
        p[k] = 1.0 / q[k] if swap[k] > 0.0 else q[k]


call_p_volume = caller(p_volume_lanes)
call_check, call_inflate = caller(check_ellipsoids), caller(inflate_lanes)
NEWTON_ENTRY, P_VOLUME_ENTRY, CHECK_ENTRY, INFLATE_ENTRY = range(4)


def entry_points() -> np.ndarray:
    """The (4,) int64 addresses of the steps the sum calls by address (``native_call``), at
    ``NEWTON_ENTRY``, ``P_VOLUME_ENTRY``, ``CHECK_ENTRY`` (``lanes.check_ellipsoids``) and
    ``INFLATE_ENTRY`` (``lanes.inflate_lanes``), each compiled (or loaded from the cache)
    for the argument types of its call: arrays of the work space's dtypes and dimensions,
    tuples of its lengths, int64 counts."""
    m3, r1 = np.empty((1, 1, 1)), np.empty(1)
    newton = address(newton_lanes, 1, m3, m3, m3, m3, 0, r1, r1, r1, (m3,) * 3, (r1,) * 11)
    p_volume = address(
        p_volume_lanes, m3, m3, m3, m3, 0, r1, r1, (m3,) * 7, (np.empty((1, 1)),) * 3, (r1,) * 14, 0
    )
    m2, i1 = np.empty((1, 1)), np.empty(1, np.int64)
    check = address(check_ellipsoids, m2, m3, m3, 0, i1, r1)
    inflate = address(inflate_lanes, m3, m3, m2, m2, m3, m3, 0, r1, (r1,) * 19)
    return np.array([newton, p_volume, check, inflate], np.int64)


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
def p_xy_psi(C1, C2, planar, heading, p_trace):
    """p of the root of the cubic [HS96, eqs. (16)-(17)] in (0, 1) minimizing
    tr(proj_xy C) tr(proj_psi C); the trace-optimal kappa (from its p, ``p_trace``) is an
    always-valid extra candidate (a safety net, never worse)."""
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
    kap = 1.0 / (1.0 + p_trace)
    if not best_size <= _xy_psi_size(kap, t1, t2, h1, h2):
        best = kap
    return (1.0 - best) / best


def block_work(n: int, lanes: int = W) -> tuple:
    """Work space of one thread for blocks of up to ``lanes`` (<= W) lanes: (mats, vecs,
    rows, codes, check, entries), 12 matrices (n, n, lanes), 8 vectors (n, lanes), 24 rows
    (lanes,), two integer rows, the scratch of ``check_ellipsoids`` and the addresses of the
    steps called by address (:func:`entry_points`).

    Every array is allocated separately: a lane loop storing to one row of an array while
    reading another is not vectorized by LLVM (their distance depends on the runtime stride).
    Made in Python, not compiled: it runs once per thread and dimension
    (:func:`thread_work`), where compiling its ~40 allocations would cost more than it saves."""
    mats = tuple(np.empty((n, n, lanes)) for _ in range(12))
    vecs = tuple(np.empty((n, lanes)) for _ in range(8))
    rows = tuple(np.empty(lanes) for _ in range(24))
    codes = (np.empty(lanes, np.int64), np.empty(lanes, np.int64))
    return mats, vecs, rows, codes, np.empty(CHECK_ROWS * W), entry_points()


def thread_work(n: int) -> tuple:
    """The calling thread's :func:`block_work` for full blocks in dimension n (made once per
    thread and dimension by ``threads.workspace``)."""
    return workspace(block_work, n)


@njit(cache=True, error_model="numpy", nogil=True, _nrt=False)
def sum_blocks(c1, C1, c2, C2, mode, p_in, planar, heading, out, wk, start, stop):
    """The certified sums of instances ``start..stop`` (p_in broadcast to (B,) by the caller),
    in blocks of W lanes, ``wk`` = (mats, vecs, rows, codes, check, entries) the work space
    :func:`block_work`; ``out`` = (centres, shapes, code, p, margin). Returns the first
    instance with a non-zero code, or -1. Per block (lane k = instance ``base + k``): load,
    validate both summands, choose p, evaluate the member in midpoint-radius arithmetic,
    inflate, store; the validation, the p solver and the inflation are called by address
    (``entries``, :func:`entry_points`).

    The only compiled entry point of the sum, with the loop over the blocks and the block's
    steps written here rather than in a compiled caller or an inlined helper: a caller would
    link the lane loop nests in and LLVM would optimize and emit them again, and numba
    inlines a helper by copying and typing its IR again. Compiled without numba's reference counting
    (``_nrt=False``): every view and every work tuple taken per block would otherwise
    increment and decrement its parent's counter atomically (microseconds per block). Nothing
    here allocates. Each block is given views from its first instance (``lanes``: no
    wraparound code)."""
    mats, vecs, rows, codes, check, entries = wk
    c1s, c2s, oc, dc = vecs[0], vecs[1], vecs[2], vecs[3]
    C1s, C2s, L1, L2 = mats[0], mats[1], mats[2], mats[3]
    p, act, margin, onep, ronep = rows[0], rows[1], rows[2], rows[3], rows[4]
    for base in range(start, stop, W):
        m = min(W, stop - base)
        C1b, C2b, p_b = C1[base:], C2[base:], p_in[base:]
        code, p_out, margin_out = out[2][base:], out[3][base:], out[4][base:]
        load_vectors(c1[base:], m, c1s)
        load_matrices(C1b, m, C1s)
        load_vectors(c2[base:], m, c2s)
        load_matrices(C2b, m, C2s)
        call_check(entries[CHECK_ENTRY], (c1s, C1s, L1, m, codes[0], check))
        call_check(entries[CHECK_ENTRY], (c2s, C2s, L2, m, codes[1], check))
        code1, code2 = codes
        for k in range(m):
            c = code1[k]
            code1[k] = c if c != 0 else (code2[k] + 10 if code2[k] != 0 else 0)
            act[k] = 1.0 if code1[k] == 0 else 0.0
        n = c1s.shape[0]
        if mode == P_VOLUME:
            # Exactly the work space of its docstring (7 mats, 3 vecs, 14 rows): tuples of other
            # lengths are other types, and each would compile the solver again.
            call_p_volume(
                entries[P_VOLUME_ENTRY],
                (
                    C1s,
                    C2s,
                    L1,
                    L2,
                    m,
                    act,
                    p,
                    mats[4:11],
                    vecs[4:7],
                    rows[5:19],
                    entries[NEWTON_ENTRY],
                ),
            )
        elif mode == P_GIVEN:
            for k in range(m):
                p[k] = p_b[k]
        else:  # trace: kappa = sqrt(tr C2) / (sqrt(tr C1) + sqrt(tr C2)), a candidate of xy_psi
            sqrt_trace_ratio(C1s, C2s, m, p, rows[5])
            if mode == P_XY_PSI:
                for k in range(m):  # scalar calls: a short cubic per instance
                    if act[k] > 0.0:
                        p[k] = p_xy_psi(C1b[k], C2b[k], planar, heading, p[k])
        for k in range(m):
            if mode == P_GIVEN and code1[k] == 0 and not (np.isfinite(p[k]) and p[k] > 0.0):
                code1[k] = BAD_KAPPA
            onep[k], ronep[k] = mr_add(1.0, 0.0, p[k], 0.0)
        S, D = mats[4], mats[5]
        for i in range(n):
            for k in range(m):
                oc[i, k], dc[i, k] = mr_add(c1s[i, k], 0.0, c2s[i, k], 0.0)
            for j in range(i + 1):
                for k in range(m):
                    q, rq = mr_div(C1s[i, j, k], 0.0, p[k], 0.0)
                    s, rs = mr_add(q, rq, C2s[i, j, k], 0.0)
                    S[i, j, k], D[i, j, k] = mr_mul(onep[k], ronep[k], s, rs)
        T = mats[7]  # not S itself: in-place updates would defeat the vectorizer's alias checks
        call_inflate(entries[INFLATE_ENTRY], (S, D, oc, dc, T, mats[6], m, margin, rows[5:]))
        store_vectors(oc, m, out[0][base:])
        store_matrices(T, m, out[1][base:])
        for k in range(m):
            r = code1[k]
            if r == 0 and margin[k] < 0.0:
                r = OUT_OF_DOMAIN
            code[k] = r
            p_out[k] = p[k] if r == 0 or r == OUT_OF_DOMAIN else 0.0
            margin_out[k] = margin[k] if r == 0 else 0.0
    return first_error(out[2], start, stop)


def sum_range(c1, C1, c2, C2, mode, p_in, planar, heading, out, start, stop):
    """:func:`sum_blocks` with the calling thread's work space (:func:`thread_work`): the
    entry point of both :func:`minkowski_sum` (a batch of one: the same compiled code, so
    single and batched results agree bitwise) and :func:`minkowski_sum_batch`; both pass
    their inputs read-only, so that numba compiles it once. Returns the first instance with a
    non-zero code, or -1."""
    wk = thread_work(c1.shape[1])
    return sum_blocks(c1, C1, c2, C2, mode, p_in, planar, heading, out, wk, start, stop)
