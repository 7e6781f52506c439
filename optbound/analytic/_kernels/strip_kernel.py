"""Compiled core of ellipsoid ∩ strip fusion [HS96, eqs. (24)-(29)], W instances at a time.

A batch is processed in blocks of up to W instances, one per SIMD lane (``lanes``): every
step below is a loop over the lanes with a straight-line body, and a lane never depends on
another. A single call is a block of one lane through the same compiled code, so
:func:`intersect_strip` and :func:`intersect_strip_batch` agree bitwise. Steps, all in the
local frame of the ellipsoid's centre c:

1. validate the instance (``check_ellipsoid``, the strip's domain, lambda);
2. locate the strip relative to c: ``eps = b - a^T c`` in twice the working precision
   (:func:`_offsets`) and ``G = a^T C a`` with certified radii, so that the interval
   ``[lo, hi]`` of ``a^T (x - c)`` that is fused contains that of E ∩ S *exactly*;
   disjointness is declared only when even the outward interval misses E's outward extent;
3. clip (optionally) and floor the strip's width, normalize it to |a'^T x - b'| <= 1;
4. choose lambda (``strip_lambda``: volume [HS96, eq. (26)], trace, projection
   [HS96, eqs. (27)-(28)], robust [HS96, eq. (30)] on either, or given);
5. evaluate the member [HS96, eq. (24)] with certified error bounds (each shape entry formed
   in double-double and rounded once) and inflate it by the certified margin of ``midrad``
   (widened to the output domain if needed);
6. any failure (K not provably positive, output too large) falls back to E itself (lambda = 0),
   which always contains E ∩ S.
"""

from __future__ import annotations

import numpy as np

from optbound._core import MAG, MAX_DIAG, check_ellipsoid
from optbound._core.jit import njit
from optbound._core.native_call import address, caller
from optbound.analytic._kernels import threads
from optbound.analytic._kernels.lanes import (
    CHECK_ROWS,
    W,
    check_ellipsoids,
    first_error,
    load_matrices,
    load_vectors,
    trace_inverse_lanes,
)
from optbound.analytic._kernels.midrad import (
    RADIUS_SAFETY,
    TINY,
    U,
    _fma,
    _two_prod,
    _two_sum,
    mr_add,
    mr_mul,
    output_floor,
    segment_scale,
    segment_term,
)
from optbound.analytic._kernels.strip_lambda import lam_projection, lam_trace, lam_volume

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
# Layout of the per-lane scalars of a block: one flat array ``t`` (``workspace``), row r at
# offset r W, so lane k of row ROW is ``t[ROW + k]``. Constant offsets let LLVM prove that two
# rows never overlap; rows as views of a 2-D array have a run-time stride, and the run-time
# overlap checks of ~20 rows in one loop exceed its limit (the loop then stays scalar: measured
# 8x slower). Rows, in the order the steps write them (step numbers of the module docstring):
(
    STRIP_B,  # 1  the strip's b (input)
    LAM_IN,  # 1  the given lambda (input, GIVEN mode)
    EPS,  # 2  eps = b - a^T c (Dot2)
    REPS,  # 2  certified radius of EPS
    GS,  # 2  a^T C a, high part
    GT,  # 2  a^T C a, low part
    RG,  # 2  certified radius of GS + GT
    CONS,  # 3  consistency [HS96, eq. (29)]
    MID,  # 3  the fused strip: |a^T (x - c) - MID| <= HALF
    HALF,  # 3
    GRAM,  # 3  G = a^T C a as a double-double GRAM + GRAM_LO
    GRAM_LO,  # 3
    LAM,  # 4  lambda of the normalized strip [HS96, eq. (24)]
    GAM,  # 4  gam = lambda / ((1 + lambda Gn) HALF^2)
    KH,  # 5  the factor K as a double-double KH + KL within RK
    KL,  # 5
    RK,  # 5  (-1: 1 - gam G not provably positive)
    OM,  # 5  1 - gam G
    ACTIVE,  # 5  1.0 where the member is evaluated, else 0.0
    DD,  # 5  squared norm of the centre's radii
    CMAX,  # 5  |centre|_inf
    AA,  # 5  |a|^2
    WW,  # 5  |w|^2 (w = C a, high part)
    TRC,  # 5  tr C
    TRINV,  # 5  tr C^{-1}
    LMIN,  # 5  estimate of lambda_min of the member (``_margin_terms``)
    LREF,  # 5  the reference eigenvalue of the margin
    RHO,  # 5  Schweppe's rho of the centre term (scale = 1 + rho)
    CENTRE,  # 5  Schweppe's centre term (1 + 1/rho) DD
    SH,  # 5  scale K as a double-double SH + SL within its radius
    SL,  # 5
    SA,  # 5  bound on |scale K|
    ALPHA,  # 5  coefficients of the entries' error bound (``_member_shape``)
    BETA,  # 5
    GAMMA,  # 5
    WIDEN,  # 5  the least mu that keeps the output in the domain
    MARGIN,  # 5-6  certified relative margin (-1: not certified)
    MU,  # 5  mu of T = scale C* + mu I
    EH,  # 5  one shape entry before its rounding, EH + EL
    EL,  # 5
    S0,  # scratch rows, reused by each step (see where they are written)
    S1,
    S2,
    S3,
    S4,
    S5,
    S6,
) = (W * r for r in range(47))  # fmt: skip
N_ROWS = S6 // W + 1
# dtypes of the per-instance outputs (code, case, consistency, lam, empty, margin).
OUT_DTYPES = (np.int8, np.int8, float, float, np.bool_, float)
# What a lane's output is: the certified member, E itself (lambda = 0), or zeros (no ellipsoid).
OUT_MEMBER, OUT_INPUT, OUT_NONE = 0.0, 1.0, 2.0


@njit(cache=True, error_model="numpy", _nrt=False)
def _validate(a, t, mode, m, code):
    """Step 1 for the block, after ``check_ellipsoids`` wrote its codes into ``code``: the
    strip's (b in row ``STRIP_B``) and lambda's (row ``LAM_IN``) codes where it found none."""
    n = a.shape[0]
    for k in range(m):
        t[S0 + k] = 0.0
    # No scaling is needed: |a| in [1 / MAG, MAG] puts |a|^2 in [1e-120, 1e120], far from
    # overflow and underflow; a non-finite entry makes the sum non-finite (and fails).
    for i in range(n):
        for k in range(m):
            t[S0 + k] += a[i, k] * a[i, k]
    for k in range(m):
        r = 0
        lam = t[LAM_IN + k]
        if mode == GIVEN and not (abs(lam) < np.inf and lam >= 0.0):
            r = BAD_LAM
        if not (abs(t[STRIP_B + k]) <= MAG * MAG):
            r = BAD_B
        if not (1.0 / (MAG * MAG) <= t[S0 + k] <= MAG * MAG):
            r = BAD_A
        if code[k] == 0:
            code[k] = r


@njit(cache=True, error_model="numpy", _nrt=False)
def _offsets(c, a, t, m):
    """``eps = b - a^T c`` per lane in twice the working precision (Dot2 of Ogita, Rump & Oishi
    2005), with the certified radius ``reps = 2 U |eps| + 2 gamma_{n+1}^2 (|b| + sum |a_i
    c_i|)``: the strip located relative to the ellipsoid's centre to full precision, whatever
    the centre's magnitude (the cancellation of a strip far from the origin)."""
    n = c.shape[0]
    comp, mag = S0, S1  # rows
    for k in range(m):
        t[EPS + k] = t[STRIP_B + k]
        t[comp + k] = 0.0
        t[mag + k] = abs(t[STRIP_B + k])
    for i in range(n):
        for k in range(m):
            p, e = _two_prod(-a[i, k], c[i, k])
            s, f = _two_sum(t[EPS + k], p)
            t[EPS + k] = s
            t[comp + k] += e + f
            t[mag + k] += abs(p)
    g = (n + 1) * U / (1.0 - (n + 1) * U)
    for k in range(m):
        res = t[EPS + k] + t[comp + k]
        t[EPS + k] = res
        t[REPS + k] = 2.0 * U * abs(res) + 2.0 * g * g * t[mag + k] + TINY


@njit(cache=True, error_model="numpy", _nrt=False)
def _project(C, a, m, wh, wl, we, t):
    """Step 2's ``w = C a`` and ``G = a^T C a`` per lane in twice the working precision (Dot2):
    a plain dot product has a relative error of cond(C) U when a is close to a thin axis of E,
    and the member's error would grow like cond(C)^2 U. Each ``w_i = wh_i + wl_i`` before
    rounding, within ``we_i = g2 m_i + TINY`` (``m_i = sum_j |C_ij a_j|``); ``Gs + Gt`` is
    within ``g2 mG + dG`` of a^T C a (``mG = sum |a_i wh_i|``, ``dG = sum |a_i| (g2 m_i +
    4 n U |wl_i|)``: the w_i's own errors and the plain part's)."""
    n = a.shape[0]
    g2 = 2.0 * (2 * n * U / (1.0 - 2 * n * U)) ** 2
    for k in range(m):
        t[GS + k] = 0.0
        t[GT + k] = 0.0
        t[S0 + k] = 0.0
        t[RG + k] = 0.0
    for i in range(n):
        for k in range(m):
            wh[i, k] = 0.0
            wl[i, k] = 0.0
            t[S1 + k] = 0.0
        for j in range(n):
            r, q = (i, j) if j <= i else (j, i)  # the lower triangle defines C
            for k in range(m):
                p, e = _two_prod(C[r, q, k], a[j, k])
                si, f = _two_sum(wh[i, k], p)
                wh[i, k] = si
                wl[i, k] += e + f
                t[S1 + k] += abs(p)
        for k in range(m):
            si, ti = wh[i, k], wl[i, k]
            we[i, k] = g2 * t[S1 + k] + TINY
            p, e = _two_prod(a[i, k], si)
            gs, f = _two_sum(t[GS + k], p)
            t[GS + k] = gs
            t[GT + k] += e + f + a[i, k] * ti
            t[S0 + k] += abs(p)
            t[RG + k] += abs(a[i, k]) * (g2 * t[S1 + k] + 4.0 * n * U * abs(ti))
    for k in range(m):
        t[RG + k] = g2 * t[S0 + k] + t[RG + k] + TINY  # row RG: the whole radius of Gs + Gt


@njit(cache=True, error_model="numpy", inline="always")
def locate(eps, reps, Gs, Gt, rG_dd, halfspace, clip):
    """Steps 2-3 for one lane: the strip's interval for ``a^T (x - c)`` against E's extent
    ``[-g, g]`` (g = sqrt(a^T C a)). ``eps`` is within reps of b - a^T c, ``Gs + Gt`` within
    rG_dd of a^T C a. Returns (case, consistency, mid, half, G, G_lo, rG): the fused strip is
    ``|a^T (x - c) - mid| <= half`` (mid, half exact floats) and contains the interval of
    E ∩ S *exactly* (outward bounds only); ``G + G_lo`` (exactly) is within rG of a^T C a.
    Disjointness is declared only when even the outward interval misses E's outward extent."""
    G, G_lo = _two_sum(Gs, Gt)  # G + G_lo = Gs + Gt exactly
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
        return INCONSISTENT, 0.0, 0.0, 0.0, G, G_lo, rG_dd  # proven disjoint
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
    return case, consistency, mid, half, G, G_lo, rG_dd


@njit(cache=True, error_model="numpy")
def _lam_cubic(C, w, e, half, Gn, mode, idx, work):
    """Step 4 for the cubic criteria (trace, projection); the projection uses ``work`` as
    scratch (planes 3 and 1, row (0, 3)). Called per lane (branches and logs); the volume
    criterion's lambda is a lane loop of ``_choose_lam``."""
    if mode == TRACE:
        return lam_trace(C, w, half, Gn, e)
    return lam_projection(C, w, half, Gn, e, idx, work[3], work[1], work[0, 3])


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


@njit(cache=True, error_model="numpy", _nrt=False)
def _member_centre(c, a, C, wh, wl, we, t, m, out_c):
    """Step 5's centre ``c + gam mid w`` in midpoint-radius arithmetic (``dd``: the squared
    norm of its radii), and per lane ``|out_c|_inf``, ``|a|^2``, ``|wh|^2``, ``tr C``."""
    n = c.shape[0]
    gm, rgm = S0, S1  # rows: gam mid and its radius
    for k in range(m):
        t[gm + k], t[rgm + k] = mr_mul(t[GAM + k], 0.0, t[MID + k], 0.0)
        t[DD + k] = 0.0
        t[CMAX + k] = 0.0
        t[AA + k] = 0.0
        t[WW + k] = 0.0
        t[TRC + k] = 0.0
    for i in range(n):
        for k in range(m):
            fw, rfw = mr_mul(t[gm + k], t[rgm + k], wh[i, k], abs(wl[i, k]) + we[i, k])
            ci, di = mr_add(c[i, k], 0.0, fw, rfw)
            out_c[i, k] = ci
            t[DD + k] += di * di
            t[CMAX + k] = max(t[CMAX + k], abs(ci))
            t[AA + k] += a[i, k] * a[i, k]
            t[WW + k] += wh[i, k] * wh[i, k]
            t[TRC + k] += C[i, i, k]


@njit(cache=True, error_model="numpy", inline="always")
def _margin_terms(Kh, Kl, rK, om, gam, tr_inv, aa, trace_c, ww, dd, cmax):
    """Step 5's scalars for one lane (see ``_member_shape``): the estimates of lambda_min(C*)
    and tr(C*), the output floor, Schweppe's scale and centre term, ``scale K`` as the
    double-double ``Sh + Sl`` within rS, and the coefficients of the entries' error bound.

    lambda_min(C*) is estimated without a factorization: by Sherman-Morrison ``(C - gam w
    w^T)^{-1} = C^{-1} + gam a a^T / om`` (w = C a, om = 1 - gam a^T C a), so ``tr(C*^{-1}) =
    (tr(C^{-1}) + gam |a|^2 / om) / K``, and ``1 / tr(X^{-1}) <= lambda_min(X) <= n /
    tr(X^{-1})``. Only estimates: no guarantee rests on them (as in ``midrad.inflate``)."""
    lmin = Kh / (tr_inv + gam * aa / om)
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
    alpha = 4.0 * U * (Sa + Sh) + rS + abs(Sl)
    beta = rS + 4.0 * U * (abs(Sl) + U * Sh)
    gamma = 4.0 * U * Sa
    widen = 2.0 * floor - scale * lmin
    return lmin, lref, rho, centre, Sh, Sl, Sa, alpha, beta, gamma, widen


@njit(cache=True, error_model="numpy", _nrt=False)
def _member_shape(C, wh, wl, we, t, m, T, hd, ld):
    """Step 5's shape for the lanes with ``t[ACTIVE + k] != 0``: writes the inflated shape into T
    (n, n, W) and returns its margin per lane in ``t[MARGIN]`` (-1.0 if it cannot be
    certified: the caller falls back to E). ``t`` holds the rows written by
    :func:`_margin_terms` and scratch rows; hd, ld (n, W) scratch; mu (W,) receives mu.

    Parametrized by ``gam = lambda / (u half^2)`` itself, the member of [HS96, eq. (24)] for
    the fused strip reads, with w = C a exactly and ``lambda' = gam half^2 / (1 - gam G)``:

        centre = c + gam mid w,   shape = K (C - gam w w^T),   K = 1 + lambda' - gam mid^2,

    so no rounding of lambda, u or the normalization enters the matrix.

    Certified margin (the outward rule of ``midrad``, evaluated so that each entry of the
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

    The error of the double-double entry h + lo against scale K* (C_ij - gam w*_i w*_j) is
    derived from |sK* - Sh - Sl| <= rS, the error err of sh + sl (``gam X_ij + 4 U (|ql| +
    |sl| + U |qh|)``), the dropped Sl sl and the four roundings of lo (|e1| <= U |h|, |t4| <=
    (1 + U) Sh |sl|, |t5| <= (1 + U) |Sl| |sh|):

        e_ij <= Sa gam X_ij + alpha |sl| + beta |sh| + gamma (|ql| + U |qh|),

    X_ij = W_i we_j + we_i W_j + |wl_i| |wl_j| + 4 U (|wh_i| |wl_j| + |wl_i| |wh_j|) a sum of
    outer products, so ||X||_F <= 2 |W| |we| + |wl|^2 + 8 U |wh| |wl| (vector 2-norms).
    """
    n = C.shape[0]
    # Rows S0..S6: |W|^2, |we|^2, |wl|^2, |wh|^2, e2, r2, d2 below (S0 then en).
    for k in range(m):
        t[S0 + k] = 0.0
        t[S1 + k] = 0.0
        t[S2 + k] = 0.0
        t[S3 + k] = 0.0
        t[S4 + k] = 0.0  # sum of the e_ij parts but X over the whole matrix (off-diagonal twice)
        t[S5 + k] = 0.0  # sum of T_ij^2 over the off-diagonal entries (their rounding: U |T_ij|)
        t[S6 + k] = 0.0
    for i in range(n):
        for k in range(m):
            t[S0 + k] += (abs(wh[i, k]) + abs(wl[i, k]) + we[i, k]) ** 2
            t[S1 + k] += we[i, k] * we[i, k]
            t[S2 + k] += wl[i, k] * wl[i, k]
            t[S3 + k] += wh[i, k] * wh[i, k]
    for i in range(n):
        for j in range(i + 1):
            for k in range(m):
                ph, pl = _two_prod(wh[i, k], wh[j, k])
                cross = wh[i, k] * wl[j, k] + wl[i, k] * wh[j, k]
                pl += cross
                qh, ql = _two_prod(t[GAM + k], ph)
                ql += t[GAM + k] * pl
                sh, sl = _two_sum(C[i, j, k], -qh)
                sl -= ql
                h, e1 = _two_prod(t[SH + k], sh)
                lo = (e1 + t[SH + k] * sl) + t[SL + k] * sh
                eij = (
                    t[ALPHA + k] * abs(sl)
                    + t[BETA + k] * abs(sh)
                    + t[GAMMA + k] * (abs(ql) + U * abs(qh))
                )
                t[EH + k], t[EL + k] = h, lo
                t[S4 + k] += (1.0 if i == j else 2.0) * eij * eij  # off-diagonal twice
            # Stored in a loop of its own: a loop writing to rows of t and to T (n, n, W)
            # needs more run-time overlap checks than LLVM allows, and stays scalar.
            if i == j:  # the diagonal's h, lo before its rounding (mu is added first)
                for k in range(m):
                    hd[i, k], ld[i, k] = t[EH + k], t[EL + k]
            else:
                for k in range(m):
                    tij = t[EH + k] + t[EL + k]
                    T[i, j, k] = tij
                    T[j, i, k] = tij
                    t[S5 + k] += 2.0 * tij * tij
    # ||F||_F <= ||E||_F + ||rounding||_F (triangle inequality); the diagonal's rounding is
    # U (|fl(lo + mu)| + |T_ii|) (two roundings).
    for k in range(m):
        nX = (
            2.0 * np.sqrt(t[S0 + k] * t[S1 + k])
            + t[S2 + k]
            + 8.0 * U * np.sqrt(t[S3 + k] * t[S2 + k])
        )
        t[S0 + k] = t[SA + k] * t[GAM + k] * nX + np.sqrt(t[S4 + k])
    for i in range(n):
        for k in range(m):
            t[S6 + k] += (abs(hd[i, k]) + 3.0 * abs(ld[i, k])) ** 2
    # A first guess that the check below accepts (the diagonal's rounding of mu: ~2 U mu).
    for k in range(m):
        g = (t[CENTRE + k] + t[S0 + k] + U * np.sqrt(t[S5 + k] + t[S6 + k])) * RADIUS_SAFETY
        g = g / (1.0 - 3.0 * U * np.sqrt(n))
        t[MU + k] = max(g + TINY, t[WIDEN + k])  # widening (only ever adds to mu)
        t[MARGIN + k] = 0.0 if t[ACTIVE + k] != 0.0 else -1.0  # -1: not certified (or not asked)
    pending = True
    while pending:
        for k in range(m):
            t[S6 + k] = 0.0
        for i in range(n):
            for k in range(m):
                lm = ld[i, k] + t[MU + k]
                tii = hd[i, k] + lm
                if not tii <= MAX_DIAG:
                    t[MARGIN + k] = -1.0
                T[i, i, k] = tii
                t[S6 + k] += (abs(lm) + abs(tii)) ** 2
        pending = False
        for k in range(m):
            need = (
                t[CENTRE + k] + t[S0 + k] + U * np.sqrt(t[S5 + k] + t[S6 + k])
            ) * RADIUS_SAFETY + TINY
            if t[MARGIN + k] == 0.0 and not t[MU + k] >= need:
                if need < np.inf:
                    t[MU + k] = need * (1.0 + 4.0 * U * n)
                    pending = True
                else:
                    t[MARGIN + k] = -1.0


def workspace(n: int) -> tuple:
    """Scratch of one thread: lane vectors (8, n, W), lane matrices (3, n, n, W), the per-lane
    scalars (N_ROWS W,), codes and cases (W,) each, the validation's scratch (CHECK_ROWS W,),
    the scalar criteria's (``_lam_cubic``: (4, max(n, 4), n), a vector (n,), a shape (n, n)
    and the ``idx`` copy (n,) int64), and the addresses of the steps (:func:`entry_points`).
    Made in Python (once per thread and dimension, ``threads.workspace``), not compiled."""
    return (
        np.zeros((8, n, W)), np.zeros((3, n, n, W)), np.zeros(N_ROWS * W),
        np.zeros(W, np.int64), np.zeros(W, np.int64), np.zeros(CHECK_ROWS * W),
        np.zeros((4, max(n, 4), n)), np.zeros(n), np.zeros((n, n)), np.zeros(n, np.int64),
        entry_points(),
    )  # fmt: skip


@njit(cache=True, error_model="numpy", _nrt=False)
def _choose_lam(Cs, mode, idx, steep, midp, m, n, code, case, t, wh, work, wvec, Ck):
    """Step 4 for the block: ``t[LAM]`` and ``t[GAM] = lam / ((1 + lam Gn) half^2)`` per lane
    (lambda = 0 where there is nothing to fuse: an error, no reduction, inconsistent). The
    scalar criteria get lane k's shape copied from Cs into Ck (n, n): the work space's arrays
    only, whatever the types of the caller's inputs (the step is called by address)."""
    for k in range(m):
        gn = t[GRAM + k] / (t[HALF + k] * t[HALF + k])
        x = 0.0
        if mode == GIVEN:
            x = t[LAM_IN + k]
        elif mode == VOLUME or mode == ROBUST:
            x = lam_volume(gn, t[MID + k] / t[HALF + k], n)
        t[LAM + k] = x
    if mode == TRACE or mode == PROJECTION or mode == ROBUST_PROJECTION:
        for k in range(m):  # scalar, per lane: the cubic criteria need branches and logs
            if code[k] == 0 and case[k] != INCONSISTENT and case[k] != NO_REDUCTION:
                for i in range(n):
                    wvec[i] = wh[i, k]
                    for j in range(n):
                        Ck[i, j] = Cs[i, j, k]
                Gn = t[GRAM + k] / (t[HALF + k] * t[HALF + k])
                t[LAM + k] = _lam_cubic(
                    Ck, wvec, t[MID + k] / t[HALF + k], t[HALF + k], Gn, mode, idx, work
                )
    if mode == ROBUST or mode == ROBUST_PROJECTION:
        for k in range(m):
            t[LAM + k] = t[LAM + k] / (
                1.0 + np.exp(-steep * (t[CONS + k] - midp))
            )  # [HS96, eq. (30)]
    for k in range(m):
        gn = t[GRAM + k] / (t[HALF + k] * t[HALF + k])
        x = min(t[LAM + k], LAM_MAX, LAMG_MAX / gn)
        if not (code[k] == 0 and case[k] != INCONSISTENT and case[k] != NO_REDUCTION):
            x = 0.0
        t[LAM + k] = x
        t[GAM + k] = x / ((1.0 + x * gn) * (t[HALF + k] * t[HALF + k]))


@njit(cache=True, error_model="numpy", _nrt=False)
def _finish(m, n, code, case, t, cs, Cs, oc, Os, out):
    """Step 6 and the block's outputs: a lane whose member was not certified falls back to E
    (lambda = 0); a lane with an error or proven disjoint gets zeros and ``empty``."""
    out_c, out_C, code_o, case_o, cons_o, lam_o, empty_o, margin_o = out
    kind = S0  # row
    for k in range(m):
        margin = t[RHO + k] + t[MU + k] / t[LREF + k]
        if not (t[MARGIN + k] == 0.0 and t[CMAX + k] <= MAG):
            margin = -1.0
        fused = code[k] == 0 and case[k] != INCONSISTENT
        t[kind + k] = OUT_NONE if not fused else (OUT_MEMBER if margin >= 0.0 else OUT_INPUT)
        t[MARGIN + k] = margin if t[kind + k] == OUT_MEMBER else 0.0
        t[CONS + k] = t[CONS + k] if fused else 0.0
        t[LAM + k] = t[LAM + k] if t[kind + k] == OUT_MEMBER else 0.0
    # One output array per loop (a loop storing to several arrays stays scalar, see
    # ``_member_shape``).
    for k in range(m):
        code_o[k] = code[k]
    for k in range(m):
        case_o[k] = case[k]
    for k in range(m):
        empty_o[k] = t[kind + k] == OUT_NONE
    for k in range(m):
        cons_o[k] = t[CONS + k]
    for k in range(m):
        lam_o[k] = t[LAM + k]
    for k in range(m):
        margin_o[k] = t[MARGIN + k]
    # The outputs, selected per lane while they are stored (lanes innermost, as ``lanes``).
    for i in range(n):
        for k in range(m):
            member, source = oc[i, k], cs[i, k]
            out_c[k, i] = (
                member
                if t[kind + k] == OUT_MEMBER
                else (source if t[kind + k] == OUT_INPUT else 0.0)
            )
        for j in range(n):
            r, q = (i, j) if j <= i else (j, i)  # E's shape: its lower triangle
            for k in range(m):
                member, source = Os[i, j, k], Cs[r, q, k]
                out_C[k, i, j] = (
                    member
                    if t[kind + k] == OUT_MEMBER
                    else (source if t[kind + k] == OUT_INPUT else 0.0)
                )


_call_check, _call_validate = caller(check_ellipsoids), caller(_validate)
_call_offsets, _call_project = caller(_offsets), caller(_project)
_call_choose_lam, _call_finish = caller(_choose_lam), caller(_finish)
_call_member_centre, _call_member_shape = caller(_member_centre), caller(_member_shape)
(
    CHECK_ENTRY,
    VALIDATE_ENTRY,
    OFFSETS_ENTRY,
    PROJECT_ENTRY,
    CHOOSE_LAM_ENTRY,
    MEMBER_CENTRE_ENTRY,
    MEMBER_SHAPE_ENTRY,
    FINISH_ENTRY,
) = range(8)


def entry_points() -> np.ndarray:
    """The (8,) int64 addresses of the steps :func:`fuse_range` calls by address
    (``native_call``), at the ``*_ENTRY`` indices, each compiled (or loaded from the cache)
    for the argument types of its call: arrays of the work space's and the outputs' dtypes
    and dimensions (never the caller's inputs, whose types vary: read-only or not), int64
    counts and mode, float parameters."""
    v2, v3, t, i1 = np.empty((1, 1)), np.empty((1, 1, 1)), np.empty(1), np.empty(1, np.int64)
    out = tuple(x[0:] for x in threads.ellipsoid_outputs(1, 1, *OUT_DTYPES))
    return np.array(
        [
            address(check_ellipsoids, v2, v3, v3, 0, i1, t),
            address(_validate, v2, t, 0, 0, i1),
            address(_offsets, v2, v2, t, 0),
            address(_project, v3, v2, 0, v2, v2, v2, t),
            address(_choose_lam, v3, 0, i1, 0.0, 0.0, 0, 0, i1, i1, t, v2, v3, t, v2),
            address(_member_centre, v2, v2, v3, v2, v2, v2, t, 0, v2),
            address(_member_shape, v3, v2, v2, v2, t, 0, v3, v2, v2),
            address(_finish, 0, 0, i1, i1, t, v2, v3, v2, v3, out),
        ],
        np.int64,
    )


@njit(cache=True, error_model="numpy", nogil=True, _nrt=False)
def fuse_range(c, C, a, b, halfspace, clip, mode, lam, idx, steep, midp, out, ws, start, stop):
    """Steps 1-6 on instances ``start..stop`` (a, b, lam broadcast to (B, ...) by the caller),
    ``ws`` the calling thread's ``workspace(n)``, ``out`` = (centres, shapes, code, case,
    consistency, lam, empty, margin). Returns the first instance with a non-zero code, or -1.

    Block by block: lane k of a block is instance ``base + k`` of the views ``c[base:]``, ...
    (``lanes``: no wraparound code), and each step is a loop over the lanes. This is the only
    compiled entry point of the update (single calls go through it too), with the loop over
    the blocks written here rather than in a compiled caller: a caller would link the lane loop
    nests in and LLVM would optimize and emit them again. For the same reason the steps are
    called by address (``native_call``; ``ws``'s entries, :func:`entry_points`): each is
    compiled once, in its own library, and none is linked in here. Compiled without numba's
    reference counting (``_nrt=False``): every view (``V[0]``, ``t[EPS]``, ``C[k]``) would otherwise
    increment and decrement its parent's counter atomically, a cache line both threads fight
    over. Nothing here allocates."""
    n = c.shape[1]
    V, M, t, code, case, scratch, work, wvec, Ck, dims, entries = ws
    for i in range(idx.size):  # a work space array: one type for the step, whatever idx's
        dims[i] = idx[i]
    sel = dims[: idx.size]
    mode, steep, midp = np.int64(mode), np.float64(steep), np.float64(midp)  # the steps' types
    cs, av, wh, wl, we, oc, hd, ld = V[0], V[1], V[2], V[3], V[4], V[5], V[6], V[7]
    Cs, L, Os = M[0], M[1], M[2]
    for base in range(start, stop, W):
        m = min(W, stop - base)
        Cb, bb = C[base:], b[base:]
        lam_b = lam[base:] if mode == GIVEN else lam  # (B,) in that mode only
        load_vectors(c[base:], m, cs)
        load_matrices(Cb, m, Cs)
        load_vectors(a[base:], m, av)
        for k in range(m):
            t[STRIP_B + k] = bb[k]
            t[LAM_IN + k] = lam_b[k] if mode == GIVEN else 0.0
        _call_check(entries[CHECK_ENTRY], (cs, Cs, L, m, code, scratch))
        _call_validate(entries[VALIDATE_ENTRY], (av, t, mode, m, code))
        _call_offsets(entries[OFFSETS_ENTRY], (cs, av, t, m))
        _call_project(entries[PROJECT_ENTRY], (Cs, av, m, wh, wl, we, t))
        for k in range(m):
            ck, cons, mid, half, g, glo, rg = locate(
                t[EPS + k], t[REPS + k], t[GS + k], t[GT + k], t[RG + k], halfspace, clip
            )
            case[k] = ck if code[k] == 0 else INCONSISTENT
            t[CONS + k], t[MID + k], t[HALF + k] = cons, mid, half
            t[GRAM + k], t[GRAM_LO + k], t[RG + k] = g, glo, rg
        _call_choose_lam(
            entries[CHOOSE_LAM_ENTRY],
            (Cs, mode, sel, steep, midp, m, n, code, case, t, wh, work, wvec, Ck),
        )
        for k in range(m):
            kh, kl, rk, om = _shape_factor(
                t[GAM + k], t[MID + k], t[HALF + k], t[GRAM + k], t[GRAM_LO + k], t[RG + k]
            )
            t[KH + k], t[KL + k], t[RK + k], t[OM + k] = kh, kl, rk, om
            ok = t[LAM + k] > 0.0 and rk >= 0.0 and kh > 2.0 * (abs(kl) + rk)
            t[ACTIVE + k] = 1.0 if ok else 0.0
        _call_member_centre(entries[MEMBER_CENTRE_ENTRY], (cs, av, Cs, wh, wl, we, t, m, oc))
        trace_inverse_lanes(L, m, t[TRINV : TRINV + W])  # L is not needed after this
        for k in range(m):
            terms = _margin_terms(
                t[KH + k], t[KL + k], t[RK + k], t[OM + k], t[GAM + k], t[TRINV + k],
                t[AA + k], t[TRC + k], t[WW + k], t[DD + k], t[CMAX + k],
            )  # fmt: skip
            lmin, lref, rho, centre, sh, sl, sa, alpha, beta, gamma, widen = terms
            t[LMIN + k], t[LREF + k], t[RHO + k], t[CENTRE + k] = lmin, lref, rho, centre
            t[SH + k], t[SL + k], t[SA + k], t[WIDEN + k] = sh, sl, sa, widen
            t[ALPHA + k], t[BETA + k], t[GAMMA + k] = alpha, beta, gamma
        _call_member_shape(entries[MEMBER_SHAPE_ENTRY], (Cs, wh, wl, we, t, m, Os, hd, ld))
        o = (out[0][base:], out[1][base:], out[2][base:], out[3][base:], out[4][base:],
             out[5][base:], out[6][base:], out[7][base:])  # fmt: skip
        _call_finish(entries[FINISH_ENTRY], (m, n, code, case, t, cs, Cs, oc, Os, o))
    return first_error(out[2], start, stop)


def _single_buffers(n: int) -> tuple:
    """Inputs and outputs of a batch of one in dimension n (``threads.workspace``'s factory):
    c, C, a, b, lam and the outputs of :func:`fuse_range`."""
    return (
        np.empty((1, n)), np.empty((1, n, n)), np.empty((1, n)), np.empty(1), np.empty(1),
        threads.ellipsoid_outputs(1, n, *OUT_DTYPES),
    )  # fmt: skip


def fuse_single(c, C, a, b, halfspace, clip, mode, lam, idx, steep, midp, ws):
    """One instance as a batch of one through :func:`fuse_range` (the same compiled code, so
    single and batched results agree bitwise and the kernel is compiled once), plus the
    result's Cholesky factor and its validation code (0 by construction: the member keeps
    the result in the domain as ``midrad.inflate`` does). ``ws`` is ``workspace(n)``.
    Returns (centre, shape, factor, code, (code, case, consistency, lam, empty, margin)).
    The instance is copied into the calling thread's buffers of a batch of one (writable
    arrays: the batch's argument types, so that numba compiles :func:`fuse_range` once)."""
    n = c.shape[0]
    c1, C1, a1, b1, lam1, out = threads.workspace(_single_buffers, n)
    c1[0], C1[0], a1[0], b1[0], lam1[0] = c, C, a, b, lam
    fuse_range(c1, C1, a1, b1, halfspace, clip, mode, lam1, idx, steep, midp, out, ws, 0, 1)
    out_c, out_C, out_L = out[0][0].copy(), out[1][0].copy(), np.empty((n, n))
    valid = check_ellipsoid(out_c, out_C, out_L)
    return out_c, out_C, out_L, valid, (out[2][0], out[3][0], out[4][0], out[5][0],
                                        out[6][0], out[7][0])  # fmt: skip
