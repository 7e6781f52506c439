"""Compiled core of ellipsoid ∩ strip fusion [HS96, eqs. (24)-(29)], one instance per call.

The same per-instance code serves :func:`intersect_strip` and :func:`intersect_strip_batch`,
so the two agree bitwise. Steps, all in the local frame of the ellipsoid's centre c:

1. validate the instance (``check_ellipsoid``, the strip's domain, lambda);
2. locate the strip relative to c: ``eps = b - a^T c`` in twice the working precision
   (``_midrad.offset``) and ``G = a^T C a`` with certified radii, so that the interval
   ``[lo, hi]`` of ``a^T (x - c)`` that is fused contains that of E ∩ S *exactly*;
   disjointness is declared only when even the outward interval misses E's outward extent;
3. clip (optionally) and floor the strip's width, normalize it to |a'^T x - b'| <= 1;
4. choose lambda (``_strip_lambda``: volume [HS96, eq. (26)], trace, projection
   [HS96, eqs. (27)-(28)], robust [HS96, eq. (30)] on either, or given);
5. evaluate the member [HS96, eq. (24)] with certified error bounds (each shape entry formed
   in double-double and rounded once) and inflate it by the certified margin of ``_midrad``
   (widened to the output domain if needed);
6. any failure (K not provably positive, output too large) falls back to E itself (lambda = 0),
   which always contains E ∩ S.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from optbound.analytic._midrad import (
    RADIUS_SAFETY,
    TINY,
    U,
    _fma,
    _two_prod,
    _two_sum,
    mr_add,
    mr_mul,
    offset,
    output_floor,
    segment_scale,
    segment_term,
    trace_inverse,
)
from optbound.analytic._strip_lambda import lam_projection, lam_trace, lam_volume
from optbound.sets._domain import MAG, MAX_DIAG, check_ellipsoid

NO_REDUCTION, CONSISTENT, PARTIAL, INCONSISTENT = range(4)
# How lambda is chosen (ROBUST_PROJECTION: [HS96, eq. (30)] with the projection-optimal lambda).
VOLUME, GIVEN, ROBUST, TRACE, PROJECTION, ROBUST_PROJECTION = range(6)
# Error codes beyond those of check_ellipsoid (1..6).
BAD_A, BAD_B, BAD_LAM = 7, 8, 9
# The fused strip is never thinner than this fraction of E's extent along a.
MIN_REL_WIDTH = 1e-6
# lambda is capped here (a larger one only gives a bound >= 1e8 times E in some direction).
LAM_MAX = 1e8
LAMG_MAX = 1e16


@njit(cache=True, error_model="numpy", inline="always")
def _strip_ok(a, b) -> int:
    n = a.shape[0]
    # No scaling is needed: |a| in [1 / MAG, MAG] puts |a|^2 in [1e-120, 1e120], far from
    # overflow and underflow; a non-finite entry makes the sum non-finite (and fails).
    ss = 0.0
    for i in range(n):
        ss += a[i] * a[i]
    if not (1.0 / (MAG * MAG) <= ss <= MAG * MAG):
        return BAD_A
    if not (np.isfinite(b) and abs(b) <= MAG * MAG):
        return BAD_B
    return 0


@njit(cache=True, error_model="numpy", inline="always")
def prepare(c, C, a, b, halfspace, clip, L, wh, wl, we):
    """Steps 1-3. Writes C's Cholesky factor into L and ``w = C a`` as ``wh + wl`` with error
    bounds ``we``. Returns (code, case, consistency, mid, half, G, G_lo, r_G): the fused strip
    is ``|a^T (x - c) - mid| <= half`` (mid, half exact floats), ``G + G_lo`` (exactly) is
    within r_G of a^T C a."""
    n = c.shape[0]
    code = check_ellipsoid(c, C, L)
    if code == 0:
        code = _strip_ok(a, b)
    if code != 0:
        return code, INCONSISTENT, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    g2 = 2.0 * (2 * n * U / (1.0 - 2 * n * U)) ** 2
    eps, reps = offset(b, a, c)
    # w = C a and G = a^T C a in twice the working precision (Dot2): a plain dot product has
    # a relative error of cond(C) U when a is close to a thin axis of E, and the member's
    # error would grow like cond(C)^2 U. Each w_i = s_i + t_i before rounding, with
    # |s_i + t_i - w_i| <= g2 m_i.
    Gs = 0.0
    Gt = 0.0
    mG = 0.0  # sum |a_i s_i| (Dot2 bound) ...
    dG = 0.0  # ... sum |a_i| g2 m_i (the w_i's own error) + 4 n U sum |a_i t_i| (plain part)
    for i in range(n):
        si = 0.0
        ti = 0.0
        mi = 0.0
        for j in range(n):
            cij = C[i, j] if j <= i else C[j, i]
            p, e = _two_prod(cij, a[j])
            si, f = _two_sum(si, p)
            ti += e + f
            mi += abs(p)
        wh[i] = si
        wl[i] = ti
        we[i] = g2 * mi + TINY
        p, e = _two_prod(a[i], si)
        Gs, f = _two_sum(Gs, p)
        Gt += e + f + a[i] * ti
        mG += abs(p)
        dG += abs(a[i]) * (g2 * mi + 4.0 * n * U * abs(ti))
    G, G_lo = _two_sum(Gs, Gt)  # G + G_lo = Gs + Gt exactly, within rG of a^T C a
    rG_dd = g2 * mG + dG + TINY
    rG = rG_dd + abs(G_lo)
    g = np.sqrt(G)
    g_hi = np.sqrt(G + rG) * (1.0 + 4.0 * U) + TINY
    g_lo = np.sqrt(max(G - rG, 0.0)) * (1.0 - 4.0 * U)

    # Outward (dn) and inward (up) bounds of the strip's interval for a^T (x - c).
    if halfspace:
        sl = 4.0 * U * (abs(eps) + reps) + TINY
        lo_dn = -np.inf
        lo_up = -np.inf
        lo = -np.inf
        hi_dn = eps - reps - sl
        hi_up = eps + reps + sl
        hi = eps
    else:
        sl = 4.0 * U * (abs(eps) + reps + 1.0) + TINY
        lo_dn = eps - reps - 1.0 - sl
        lo_up = eps + reps - 1.0 + sl
        hi_dn = eps - reps + 1.0 - sl
        hi_up = eps + reps + 1.0 + sl
        lo = eps - 1.0
        hi = eps + 1.0

    overlap = max(min(hi, g) - max(lo, -g), 0.0)
    consistency = min(max(overlap / (2.0 * np.sqrt(g)), 0.0), 1.0)  # [HS96, eq. (29)]
    if lo_dn > g_hi or hi_up < -g_hi:
        return 0, INCONSISTENT, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0  # proven disjoint
    if lo_up <= -g_lo and hi_dn >= g_lo:
        case = NO_REDUCTION  # proven: S covers E
    elif (-g < lo < g) and (-g < hi < g):
        case = CONSISTENT
    else:
        case = PARTIAL

    # The strip fused: contains [lo, hi] ∩ [-g, g] exactly (outward bounds only).
    lo_f, hi_f = lo_dn, hi_up
    if clip or halfspace:
        lo_f = max(lo_f, -g_hi)
    if clip:
        hi_f = min(hi_f, g_hi)
    floor = MIN_REL_WIDTH * g_hi
    mid = 0.5 * lo_f + 0.5 * hi_f
    if clip:
        mid = min(max(mid, -g_lo + floor), g_lo - floor)
    half = max(hi_f - mid, mid - lo_f) * (1.0 + 2.0 * U)
    half = max(half, floor)
    return 0, case, consistency, mid, half, G, G_lo, rG_dd


@njit(cache=True, error_model="numpy", inline="always")
def _shape_factor(gam, mid, half, G, G_lo, rG):
    """K = 1 + gam half^2 / (1 - gam G) - gam mid^2 for the exact G (within rG of G + G_lo) as
    a double-double ``Kh + Kl`` within ``rK`` of the exact K, and ``1 - gam G`` (float).
    Returns (Kh, Kl, rK, om), rK = -1.0 if ``1 - gam G`` is not provably positive.

    Error bound (every step exact or one rounding, |fl(x) - x| <= U |fl(x)|):
    ``gam (G + G_lo) = p + e + t1`` with p + e exact and t1 = fl(gam G_lo); ``1 - p = oh + ot``
    exactly, ``ol = fl(ot - fl(e + t1))``, so om* = 1 - gam G* is within
    ``rom = U (|t1| + |q| + |ol|) + gam rG`` of ``oh + ol``. ``om_low`` rounds
    ``oh - |ol| - rom`` down (two subtractions, each off by <= U (1 + U) |oh|, covered by the
    extra 3 U |oh|). The quotient lp = gam half^2 / om* is ``q1 + q2``: q1 = fl(gh / oh) has
    the exact remainder r1 = fma(-q1, oh, gh) (the remainder of a rounded division is a
    float); ``q2 = fl(res / oh)`` with res = fl(fl(r1 + gl) - fl(q1 ol)) within
    ``3 U (|r1| + |gl| + |q1 ol|)`` of gh + gl - q1 (oh + ol), and ``|res - q2 oh| <= U |res|``.
    So ``|gh + gl - (q1 + q2) om*| <= R + |q1 + q2| rom`` (R the terms above plus ``|q2 ol|``),
    and lp is within ``(R + rgl + |q1 + q2| rom) / om_low`` of q1 + q2. K then sums four
    exact parts (two two_sums) and three small ones (<= 4 U their magnitudes).
    """
    p, e = _two_prod(gam, G)
    t1 = gam * G_lo
    q = e + t1
    oh, ot = _two_sum(1.0, -p)
    ol = ot - q
    rom = U * (abs(t1) + abs(q) + abs(ol)) + gam * rG + TINY
    om_low = (oh - abs(ol)) - (rom + 3.0 * U * abs(oh))
    if not om_low > 0.0:
        return 1.0, 0.0, -1.0, 0.0
    hh, hl = _two_prod(half, half)
    gh, g2 = _two_prod(gam, hh)
    t2 = gam * hl
    gl = g2 + t2
    rgl = U * (abs(t2) + abs(gl))  # gh + gl is within rgl of gam half^2
    q1 = gh / oh
    r1 = _fma(-q1, oh, gh)
    res = (r1 + gl) - q1 * ol
    q2 = res / oh
    R = 3.0 * U * (abs(r1) + abs(gl) + abs(q1 * ol)) + U * abs(res) + abs(q2 * ol)
    rlp = (R + rgl + abs(q1 + q2) * rom) / om_low
    m1, m2 = _two_prod(gam, mid)  # gam mid^2 = n1 + n2 + m2 mid
    n1, n2 = _two_prod(m1, mid)
    t3 = m2 * mid
    nl = n2 + t3
    rgm2 = U * (abs(t3) + abs(nl))
    s1, u1 = _two_sum(1.0, q1)
    s2, u2 = _two_sum(s1, -n1)
    kl = ((u1 + u2) + q2) - nl
    Kh, Kl = _two_sum(s2, kl)
    rK = rlp + rgm2 + 4.0 * U * (abs(u1) + abs(u2) + abs(q2) + abs(nl)) + TINY
    return Kh, Kl, rK, oh + ol


@njit(cache=True, error_model="numpy", inline="always")
def member(c, C, a, gam, mid, half, G, G_lo, rG, wh, wl, we, L, out_c, out_C, buf):
    """Step 5: the member for the float parameter ``gam`` (> 0, with gam G < 1), inflated and
    written into out_c, out_C; ``L`` is the Cholesky factor of C (its strict upper part is
    overwritten), ``buf`` (>= (3, n)) scratch. Returns the margin, or -1.0 if it cannot be
    certified (the caller falls back to E).

    Parametrized by ``gam = lambda / (u half^2)`` itself, the member of [HS96, eq. (24)] for
    the fused strip reads, with w = C a exactly and ``lambda' = gam half^2 / (1 - gam G)``:

        centre = c + gam mid w,   shape = K (C - gam w w^T),   K = 1 + lambda' - gam mid^2,

    so no rounding of lambda, u or the normalization enters the matrix.

    Certified margin (the outward rule of ``_midrad``, evaluated so that each entry of the
    shape is rounded once): with the centre's error |d| and rho = scale - 1 chosen first,
    T = scale C* + mu I + F must dominate ``(1 + rho) C* + (1 + 1/rho) |d|^2 I`` (Schweppe's
    bound for the centre, C* the exact member), i.e. ``mu >= (1 + 1/rho) |d|^2 + ||F||_2``.
    Every entry ``scale K (C_ij - gam w_i w_j)`` is formed in double-double (``C - gam w w^T``
    as ``sh + sl``, K and ``scale K`` as ``Kh + Kl``) within a certified e_ij (O(U^2)) and then
    rounded once: ``|F_ij| <= e_ij + U |T_ij|`` off the diagonal (the stored float), and
    ``<= e_ii + U (|fl(l + mu)| + |T_ii|)`` on it (``T_ii = fl(h + fl(l + mu))``); ||F||_2 <=
    ||F||_F <= ||(e_ij)||_F + ||(rounding)||_F. mu is checked against that bound after the
    diagonal is rounded and raised until it holds (the bound grows by ~2 U sqrt(n) per unit of
    mu, so this ends at once).

    lambda_min(C*) (for rho, the widening and the reported margin) is estimated without a
    factorization: by Sherman-Morrison ``(C - gam w w^T)^{-1} = C^{-1} + gam a a^T / om``
    (w = C a, om = 1 - gam a^T C a), so ``tr(C*^{-1}) = (tr(C^{-1}) + gam |a|^2 / om) / K``,
    and ``1 / tr(X^{-1}) <= lambda_min(X) <= n / tr(X^{-1})``; tr(C^{-1}) = ||L^{-1}||_F^2.
    Only estimates: no guarantee rests on them (as in ``_midrad.inflate``).
    """
    n = c.shape[0]
    Kh, Kl, rK, om = _shape_factor(gam, mid, half, G, G_lo, rG)
    if not (rK >= 0.0 and Kh > 2.0 * (abs(Kl) + rK)):
        return -1.0
    gm, rgm = mr_mul(gam, 0.0, mid, 0.0)
    dd = 0.0
    cmax = 0.0
    aa = 0.0
    ww = 0.0
    trace_c = 0.0
    for i in range(n):
        fw, rfw = mr_mul(gm, rgm, wh[i], abs(wl[i]) + we[i])
        out_c[i], di = mr_add(c[i], 0.0, fw, rfw)
        dd += di * di
        cmax = max(cmax, abs(out_c[i]))
        aa += a[i] * a[i]
        ww += wh[i] * wh[i]
        trace_c += C[i, i]
    # Estimates of lambda_min(C*) and tr(C*) (see the docstring).
    lmin = Kh / (trace_inverse(L, buf[2]) + gam * aa / om)
    trace = Kh * max(trace_c - gam * ww, 0.0)
    floor = output_floor(trace, cmax)
    if not (lmin > 0.0 and trace <= 1e14 * lmin):  # beyond the estimate's accuracy
        lmin = 0.0
    lref = max(lmin, floor)
    scale = segment_scale(dd, lref)
    rho = scale - 1.0
    centre = segment_term(dd, rho)
    # scale K as a double-double within rS.
    p, e = _two_prod(scale, Kh)
    t = scale * Kl
    Sl0 = e + t
    Sh, Sl = _two_sum(p, Sl0)
    rS = scale * rK + U * (abs(t) + abs(Sl0)) + TINY
    Sa = Sh + abs(Sl) + rS  # >= |scale K| up to rounding (covered by RADIUS_SAFETY)
    # Error of the double-double entry h + lo against scale K* (C_ij - gam w*_i w*_j), derived
    # from |sK* - Sh - Sl| <= rS, the error err of sh + sl (the c0 bound of the old midrad code:
    # ``gam X_ij + 4 U (|ql| + |sl| + U |qh|)``), the dropped Sl sl and the four roundings of
    # lo (|e1| <= U |h|, |t4| <= (1 + U) Sh |sl|, |t5| <= (1 + U) |Sl| |sh|):
    #     e_ij <= Sa gam X_ij + alpha |sl| + beta |sh| + gamma (|ql| + U |qh|),
    # X_ij = W_i we_j + we_i W_j + |wl_i| |wl_j| + 4 U (|wh_i| |wl_j| + |wl_i| |wh_j|) a sum
    # of outer products, so ||X||_F <= 2 |W| |we| + |wl|^2 + 8 U |wh| |wl| (vector 2-norms).
    alpha = 4.0 * U * (Sa + Sh) + rS + abs(Sl)
    beta = rS + 4.0 * U * (abs(Sl) + U * Sh)
    gamma = 4.0 * U * Sa
    nW = 0.0
    nwe = 0.0
    nwl = 0.0
    nwh = 0.0
    for i in range(n):
        nW += (abs(wh[i]) + abs(wl[i]) + we[i]) ** 2
        nwe += we[i] * we[i]
        nwl += wl[i] * wl[i]
        nwh += wh[i] * wh[i]
    nX = 2.0 * np.sqrt(nW * nwe) + nwl + 8.0 * U * np.sqrt(nwh * nwl)
    hd, ld = buf[0], buf[1]  # the diagonal's h, lo before its rounding (mu is added first)
    e2 = 0.0  # sum of the e_ij parts but X over the whole matrix (off-diagonal twice)
    r2 = 0.0  # sum of T_ij^2 over the off-diagonal entries (their rounding: U |T_ij|)
    for i in range(n):
        for j in range(i + 1):
            ph, pl = _two_prod(wh[i], wh[j])
            cross = wh[i] * wl[j] + wl[i] * wh[j]
            pl += cross
            qh, ql = _two_prod(gam, ph)
            ql += gam * pl
            sh, sl = _two_sum(C[i, j], -qh)
            sl -= ql
            h, e1 = _two_prod(Sh, sh)
            lo = (e1 + Sh * sl) + Sl * sh
            eij = alpha * abs(sl) + beta * abs(sh) + gamma * (abs(ql) + U * abs(qh))
            if i == j:
                hd[i], ld[i] = h, lo
                e2 += eij * eij
            else:
                tij = h + lo
                out_C[i, j] = tij
                out_C[j, i] = tij
                e2 += 2.0 * eij * eij
                r2 += 2.0 * tij * tij
    # ||F||_F <= ||E||_F + ||rounding||_F (triangle inequality); the diagonal's rounding is
    # U (|fl(lo + mu)| + |T_ii|) (two roundings).
    en = Sa * gam * nX + np.sqrt(e2)
    d2 = 0.0
    for i in range(n):
        d2 += (abs(hd[i]) + 3.0 * abs(ld[i])) ** 2
    # A first guess that the check below accepts (the diagonal's rounding of mu: ~2 U mu).
    mu = (centre + en + U * np.sqrt(r2 + d2)) * RADIUS_SAFETY / (1.0 - 3.0 * U * np.sqrt(n))
    mu = max(mu + TINY, 2.0 * floor - scale * lmin)  # widening (only ever adds to mu)
    while True:
        d2 = 0.0
        for i in range(n):
            lm = ld[i] + mu
            tii = hd[i] + lm
            if not tii <= MAX_DIAG:
                return -1.0
            out_C[i, i] = tii
            d2 += (abs(lm) + abs(tii)) ** 2
        need = (centre + en + U * np.sqrt(r2 + d2)) * RADIUS_SAFETY + TINY
        if mu >= need:
            break
        mu = need * (1.0 + 4.0 * U * n)
    if not cmax <= MAG:
        return -1.0
    return rho + mu / lref


@njit(cache=True, error_model="numpy")
def _copy_input(c, C, out_c, out_C):
    n = c.shape[0]
    for i in range(n):
        out_c[i] = c[i]
        for j in range(n):
            out_C[i, j] = C[i, j] if j <= i else C[j, i]


@njit(cache=True, error_model="numpy")
def _lam_cubic(C, w, e, half, Gn, mode, idx, work):
    """Step 4 for the cubic criteria (trace, projection); the projection uses ``work`` as
    scratch (planes 3 and 1, row (0, 3)). Only the volume criterion's lambda is inlined into
    ``fuse_one``."""
    if mode == TRACE:
        return lam_trace(C, w, half, Gn, e)
    return lam_projection(C, w, half, Gn, e, idx, work[3], work[1], work[0, 3])


@njit(cache=True, error_model="numpy", inline="always")
def fuse_one(c, C, a, b, halfspace, clip, mode, lam_in, idx, steep, midp, out_c, out_C, work):
    """One full update (steps 1-6); ``idx`` are the coordinates of the projection criteria
    (unused otherwise). ``work`` is (4, max(n, 4), n) scratch. Inlined into its two callers:
    as a separate function, LLVM no longer inlined it into the batch loop once the criteria's
    branches were added (measured ~10 % slower per instance).

    Returns (code, case, consistency, lam, empty, margin).
    """
    n = c.shape[0]
    wh, wl, we, L = work[0, 0], work[0, 1], work[0, 2], work[2, :n]
    code, case, cons, mid, half, G, G_lo, rG = prepare(c, C, a, b, halfspace, clip, L, wh, wl, we)
    if code != 0:
        return code, case, 0.0, 0.0, True, 0.0
    if mode == GIVEN and not (np.isfinite(lam_in) and lam_in >= 0.0):
        return BAD_LAM, case, 0.0, 0.0, True, 0.0
    if case == INCONSISTENT:
        for i in range(n):
            out_c[i] = 0.0
            for j in range(n):
                out_C[i, j] = 0.0
        return 0, case, 0.0, 0.0, True, 0.0
    lam = 0.0
    Gn = G / (half * half)
    if case != NO_REDUCTION:
        if mode == GIVEN:
            lam = lam_in
        else:
            e = mid / half
            if mode == VOLUME or mode == ROBUST:
                lam = lam_volume(Gn, e, n)
            else:
                lam = _lam_cubic(C, wh, e, half, Gn, mode, idx, work)
            if mode == ROBUST or mode == ROBUST_PROJECTION:
                lam = lam / (1.0 + np.exp(-steep * (cons - midp)))  # [HS96, eq. (30)]
        lam = min(lam, LAM_MAX, LAMG_MAX / Gn)
    margin = 0.0
    if lam > 0.0:
        gam = lam / ((1.0 + lam * Gn) * (half * half))
        buf = work[1, :3]
        margin = member(c, C, a, gam, mid, half, G, G_lo, rG, wh, wl, we, L, out_c, out_C, buf)
    if not lam > 0.0 or margin < 0.0:
        _copy_input(c, C, out_c, out_C)
        return 0, case, cons, 0.0, False, 0.0
    return 0, case, cons, lam, False, margin


@njit(cache=True, error_model="numpy")
def fuse_single(c, C, a, b, halfspace, clip, mode, lam, idx, steep, midp):
    """One instance through the batch loop ``_fuse_loop`` (a batch of one: the same compiled
    code, so single and batched results agree bitwise and the kernel is compiled once), plus
    the result's Cholesky factor and its validation code (0 by construction: ``member`` keeps
    the result in the domain as ``_midrad.inflate`` does)."""
    n = c.shape[0]
    out = (
        np.empty((1, n)), np.empty((1, n, n)), np.zeros(1, np.int8), np.zeros(1, np.int8),
        np.zeros(1), np.zeros(1), np.zeros(1, np.bool_), np.zeros(1),
    )  # fmt: skip
    work = np.zeros((4, max(n, 4), n))
    one = n // n  # a runtime int: literal 0 and 1 would compile a specialization of their own
    _fuse_loop(
        np.ascontiguousarray(c).reshape((1, n)), np.ascontiguousarray(C).reshape((1, n, n)),
        np.ascontiguousarray(a).reshape((1, n)), np.full(1, b), halfspace, clip, mode,
        np.full(1, lam), idx, steep, midp, out, work, one - 1, one,
    )  # fmt: skip
    out_c, out_C = out[0][0], out[1][0]
    out_L = np.empty((n, n))
    valid = check_ellipsoid(out_c, out_C, out_L)
    r = (out[2][0], out[3][0], out[4][0], out[5][0], out[6][0], out[7][0])
    return out_c, out_C, out_L, valid, r


@njit(cache=True, error_model="numpy", nogil=True, _nrt=False)
def _fuse_loop(c, C, a, b, halfspace, clip, mode, lam, idx, steep, midp, out, work, start, stop):
    """The batch loop, compiled without numba's reference counting (``_nrt=False``): every
    per-instance view (``c[i]``, ``work[0, 0]``, ...) otherwise increments and decrements the
    parent array's counter atomically, a cache line both threads fight over (measured: half
    the time per instance). Nothing here allocates; the views live no longer than the call."""
    out_c, out_C, code, case, cons, lam_out, empty, margin = out
    for i in range(start, stop):
        r = fuse_one(
            c[i], C[i], a[i], b[i], halfspace, clip, mode, lam[i], idx, steep, midp,
            out_c[i], out_C[i], work,
        )  # fmt: skip
        code[i], case[i], cons[i], lam_out[i], empty[i], margin[i] = r


@njit(cache=True, error_model="numpy", nogil=True)
def fuse_range(c, C, a, b, halfspace, clip, mode, lam, idx, steep, midp, out, start, stop):
    """``fuse_one`` on instances ``start..stop`` (a, b, lam broadcast to (B, ...) by the
    caller). ``out`` = (centres, shapes, code, case, consistency, lam, empty, margin)."""
    n = c.shape[1]
    work = np.zeros((4, max(n, 4), n))
    _fuse_loop(c, C, a, b, halfspace, clip, mode, lam, idx, steep, midp, out, work, start, stop)
