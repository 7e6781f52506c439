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
5. evaluate the member [HS96, eq. (24)] in midpoint-radius arithmetic and inflate it by the
   certified margin of ``_midrad.inflate`` (widened to the output domain if needed);
6. any failure (K not provably positive, output too large) falls back to E itself (lambda = 0),
   which always contains E ∩ S.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from optbound.analytic._midrad import (
    TINY,
    U,
    _two_prod,
    _two_sum,
    inflate,
    mr_add,
    mr_div,
    mr_mul,
    offset,
)
from optbound.analytic._strip_lambda import lam_projection, lam_trace, lam_volume
from optbound.sets._domain import MAG, check_ellipsoid

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


@njit(cache=True, inline="always")
def _strip_ok(a, b) -> int:
    n = a.shape[0]
    top = 0.0
    for i in range(n):
        if not np.isfinite(a[i]):
            return BAD_A
        top = max(top, abs(a[i]))
    if top == 0.0:
        return BAD_A
    ss = 0.0
    for i in range(n):
        ss += (a[i] / top) ** 2
    norm = top * np.sqrt(ss)
    if not (1.0 / MAG <= norm <= MAG):
        return BAD_A
    if not (np.isfinite(b) and abs(b) <= MAG * MAG):
        return BAD_B
    return 0


@njit(cache=True)
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


@njit(cache=True)
def member(c, C, gam, mid, half, G, G_lo, rG, wh, wl, we, out_c, out_C, L, D, dc):
    """Step 5: the member for the float parameter ``gam`` (> 0, with gam G < 1), written into
    out_c, out_C (inflated) with its Cholesky factor in L. Returns the margin, or -1.0 if it
    cannot be certified (the caller falls back to E).

    Parametrized by ``gam = lambda / (u half^2)`` itself, the member of [HS96, eq. (24)] for
    the fused strip reads, with w = C a exactly and ``lambda' = gam half^2 / (1 - gam G)``:

        centre = c + gam mid w,   shape = K (C - gam w w^T),   K = 1 + lambda' - gam mid^2,

    so no rounding of lambda, u or the normalization enters the matrix; ``C - gam w w^T``
    (where the cancellation is) is formed in twice the working precision.
    """
    n = c.shape[0]
    # 1 - gam G without cancellation error (it is ~ 1 / u, small when lambda G is large).
    p, e = _two_prod(gam, G)
    q = e + gam * G_lo
    om = (1.0 - p) - q
    rom = U * abs(1.0 - p) + 2.0 * U * (abs(q) + abs(om)) + gam * rG + TINY
    if not om - rom > 0.0:
        return -1.0
    hh, rhh = mr_mul(half, 0.0, half, 0.0)
    gh, rgh = mr_mul(gam, 0.0, hh, rhh)
    lp, rlp = mr_div(gh, rgh, om, rom)
    gm, rgm = mr_mul(gam, 0.0, mid, 0.0)
    gm2, rgm2 = mr_mul(gm, rgm, mid, 0.0)
    k1, rk1 = mr_add(1.0, 0.0, lp, rlp)
    K, rK = mr_add(k1, rk1, -gm2, rgm2)
    if not K - rK > 0.0:
        return -1.0
    for i in range(n):
        fw, rfw = mr_mul(gm, rgm, wh[i], abs(wl[i]) + we[i])
        out_c[i], dc[i] = mr_add(c[i], 0.0, fw, rfw)
        Wi = abs(wh[i]) + abs(wl[i]) + we[i]
        for j in range(i + 1):
            Wj = abs(wh[j]) + abs(wl[j]) + we[j]
            ph, pl = _two_prod(wh[i], wh[j])
            cross = wh[i] * wl[j] + wl[i] * wh[j]
            pl += cross
            qh, ql = _two_prod(gam, ph)
            ql += gam * pl
            sh, sl = _two_sum(C[i, j], -qh)
            sl -= ql
            c0 = sh + sl
            err = gam * (
                Wi * we[j] + we[i] * Wj + abs(wl[i] * wl[j])
                + 4.0 * U * (abs(wh[i] * wl[j]) + abs(wl[i] * wh[j]))
            ) + 4.0 * U * (abs(ql) + abs(sl)) + U * abs(c0)  # fmt: skip
            out_C[i, j], D[i, j] = mr_mul(K, rK, c0, err)
    margin = inflate(out_C, D, out_c, dc, out_C, L)
    return margin


@njit(cache=True)
def _copy_input(c, C, L, out_c, out_C, out_L):
    n = c.shape[0]
    for i in range(n):
        out_c[i] = c[i]
        for j in range(n):
            out_C[i, j] = C[i, j] if j <= i else C[j, i]
            out_L[i, j] = L[i, j]


@njit(cache=True)
def _lam_cubic(C, w, e, half, Gn, mode, idx, work):
    """Step 4 for the cubic criteria (trace, projection); the projection uses ``work`` as
    scratch (planes 3 and 1, row (0, 3)). Only the volume criterion's lambda is inlined into
    ``fuse_one``."""
    if mode == TRACE:
        return lam_trace(C, w, half, Gn, e)
    return lam_projection(C, w, half, Gn, e, idx, work[3], work[1], work[0, 3])


@njit(cache=True, inline="always")
def fuse_one(
    c, C, a, b, halfspace, clip, mode, lam_in, idx, steep, midp, out_c, out_C, out_L, work
):
    """One full update (steps 1-6); ``idx`` are the coordinates of the projection criteria
    (unused otherwise). ``work`` is (4, max(n, 4), n) scratch. Inlined into its two callers:
    as a separate function, LLVM no longer inlined it into the batch loop once the criteria's
    branches were added (measured ~10 % slower per instance).

    Returns (code, case, consistency, lam, empty, margin).
    """
    n = c.shape[0]
    wh, wl, we, dc, D, L = work[0, 0], work[0, 1], work[0, 2], work[0, 3], work[1, :n], work[2, :n]
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
                out_L[i, j] = 0.0
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
        margin = member(c, C, gam, mid, half, G, G_lo, rG, wh, wl, we, out_c, out_C, out_L, D, dc)
    if not lam > 0.0 or margin < 0.0:
        _copy_input(c, C, L, out_c, out_C, out_L)
        return 0, case, cons, 0.0, False, 0.0
    return 0, case, cons, lam, False, margin


@njit(cache=True)
def fuse_single(c, C, a, b, halfspace, clip, mode, lam, idx, steep, midp):
    """One instance, without slicing (the same ``fuse_one`` as the batch), plus the result's
    Cholesky factor and its validation code (0 by construction, see ``_midrad.inflate``)."""
    n = c.shape[0]
    out_c = np.empty(n)
    out_C = np.empty((n, n))
    out_L = np.empty((n, n))
    work = np.zeros((4, max(n, 4), n))
    r = fuse_one(
        c, C, a, b, halfspace, clip, mode, lam, idx, steep, midp, out_c, out_C, out_L, work
    )
    valid = check_ellipsoid(out_c, out_C, out_L)
    return out_c, out_C, out_L, valid, r


@njit(cache=True, nogil=True)
def fuse_range(c, C, a, b, halfspace, clip, mode, lam, idx, steep, midp, out, start, stop):
    """``fuse_one`` on instances ``start..stop`` (a, b, lam broadcast to (B, ...) by the
    caller). ``out`` = (centres, shapes, chol, code, case, consistency, lam, empty, margin)."""
    out_c, out_C, out_L, code, case, cons, lam_out, empty, margin = out
    n = c.shape[1]
    work = np.zeros((4, max(n, 4), n))
    for i in range(start, stop):
        r = fuse_one(
            c[i], C[i], a[i], b[i], halfspace, clip, mode, lam[i], idx, steep, midp,
            out_c[i], out_C[i], out_L[i], work,
        )  # fmt: skip
        code[i], case[i], cons[i], lam_out[i], empty[i], margin[i] = r
