"""Compiled core of ellipsoid ∩ strip fusion [HS96, eqs. (24)-(29)], one instance per call.

The same per-instance code serves :func:`intersect_strip` and :func:`intersect_strip_batch`,
so the two agree bitwise. Steps, all in the local frame of the ellipsoid's centre c:

1. validate the instance (``check_ellipsoid``, the strip's domain, lambda);
2. locate the strip relative to c: ``eps = b - a^T c`` in twice the working precision
   (``_midrad.offset``) and ``G = a^T C a`` with certified radii, so that the interval
   ``[lo, hi]`` of ``a^T (x - c)`` that is fused contains that of E ∩ S *exactly*;
   disjointness is declared only when even the outward interval misses E's outward extent;
3. clip (optionally) and floor the strip's width, normalize it to |a'^T x - b'| <= 1;
4. choose lambda (volume root [HS96, eq. (26)], robust [HS96, eq. (30)], or given);
5. evaluate the member [HS96, eq. (24)] in midpoint-radius arithmetic and inflate it by the
   certified margin of ``_midrad.inflate`` (widened to the output domain if needed);
6. validate the output (``check_ellipsoid``); any failure falls back to E itself (lambda = 0),
   which always contains E ∩ S.
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange

from optbound.analytic._midrad import (
    TINY,
    U,
    inflate,
    mr_add,
    mr_div,
    mr_mul,
    offset,
)
from optbound.sets._domain import MAG, check_ellipsoid

NO_REDUCTION, CONSISTENT, PARTIAL, INCONSISTENT = range(4)
VOLUME, GIVEN, ROBUST = range(3)
# Error codes beyond those of check_ellipsoid (1..6).
BAD_A, BAD_B, BAD_LAM = 7, 8, 9
# The fused strip is never thinner than this fraction of E's extent along a.
MIN_REL_WIDTH = 1e-6
# lambda is capped here (a larger one only gives a bound >= 1e8 times E in some direction).
LAM_MAX = 1e8
LAMG_MAX = 1e16
CHUNK = 256


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
def prepare(c, C, a, b, halfspace, clip, L, wn, rwn):
    """Steps 1-3. Writes C's Cholesky factor into L and the normalized ``C a'`` (with radii)
    into wn, rwn. Returns (code, case, consistency, eps', r_eps', G', r_G')."""
    n = c.shape[0]
    code = check_ellipsoid(c, C, L)
    if code == 0:
        code = _strip_ok(a, b)
    if code != 0:
        return code, INCONSISTENT, 0.0, 0.0, 0.0, 0.0, 0.0
    gn = n * U / (1.0 - n * U)
    eps, reps = offset(b, a, c)
    G = 0.0
    mG = 0.0
    rGw = 0.0
    for i in range(n):
        s = 0.0
        m = 0.0
        for j in range(n):
            cij = C[i, j] if j <= i else C[j, i]
            s += cij * a[j]
            m += abs(cij * a[j])
        wn[i] = s
        rwn[i] = gn * m
        G += a[i] * s
        mG += abs(a[i] * s)
        rGw += abs(a[i]) * rwn[i]
    rG = gn * mG + rGw
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
        return 0, INCONSISTENT, 0.0, 0.0, 0.0, 0.0, 0.0  # proven disjoint
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
    # Normalized strip |a^T (x - c) / half - mid / half| <= 1 (half, mid exact floats).
    epsn, repsn = mr_div(mid, 0.0, half, 0.0)
    for i in range(n):
        wn[i], rwn[i] = mr_div(wn[i], rwn[i], half, 0.0)
    hh, rhh = mr_mul(half, 0.0, half, 0.0)
    Gn, rGn = mr_div(G, rG, hh, rhh)
    return 0, case, consistency, epsn, repsn, Gn, rGn


@njit(cache=True, inline="always")
def lam_volume(Gn, e, n):
    """Most positive root of [HS96, eq. (26)] with N = n (0 if none): it exists iff
    G > n (1 - eps^2); the roots then have opposite signs (stable quadratic formula)."""
    qa = (n - 1) * Gn * Gn
    qb = (2 * n - 1 + e * e - Gn) * Gn
    qc = n * (1 - e * e) - Gn
    if not qc < 0:
        return 0.0
    sq = np.sqrt(qb * qb - 4 * qa * qc)
    return 2 * qc / (-qb - sq) if qb >= 0 else (-qb + sq) / (2 * qa)


@njit(cache=True)
def member(c, C, lam, epsn, repsn, Gn, rGn, wn, rwn, out_c, out_C, L, D, dc):
    """Steps 5-6 for lambda > 0: writes the inflated member into out_c, out_C and its Cholesky
    factor into L. Returns the margin, or -1.0 if the member cannot be certified (the caller
    falls back to E)."""
    n = c.shape[0]
    lg, rlg = mr_mul(lam, 0.0, Gn, rGn)
    u, ru = mr_add(1.0, 0.0, lg, rlg)
    gam, rgam = mr_div(lam, 0.0, u, ru)
    e2, re2 = mr_mul(epsn, repsn, epsn, repsn)
    t, rt = mr_div(e2, re2, u, ru)
    lt, rlt = mr_mul(lam, 0.0, t, rt)
    k1, rk1 = mr_add(1.0, 0.0, lam, 0.0)
    K, rK = mr_add(k1, rk1, -lt, rlt)
    if not K - rK > 0.0:
        return -1.0
    f, rf = mr_mul(gam, rgam, epsn, repsn)
    for i in range(n):
        fw, rfw = mr_mul(f, rf, wn[i], rwn[i])
        out_c[i], dc[i] = mr_add(c[i], 0.0, fw, rfw)
        for j in range(i + 1):
            p, rp = mr_mul(wn[i], rwn[i], wn[j], rwn[j])
            gp, rgp = mr_mul(gam, rgam, p, rp)
            c0, rc0 = mr_add(C[i, j], 0.0, -gp, rgp)
            out_C[i, j], D[i, j] = mr_mul(K, rK, c0, rc0)
    margin = inflate(out_C, D, out_c, dc, out_C, L)
    if margin < 0.0 or check_ellipsoid(out_c, out_C, L) != 0:
        return -1.0
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
def fuse_one(c, C, a, b, halfspace, clip, mode, lam_in, steep, midp, out_c, out_C, out_L, work):
    """One full update (steps 1-6). ``work`` is (3, max(n, 3), n) scratch.

    Returns (code, case, consistency, lam, empty, margin).
    """
    n = c.shape[0]
    wn, rwn, dc, D, L = work[0, 0], work[0, 1], work[0, 2], work[1, :n], work[2, :n]
    code, case, cons, epsn, repsn, Gn, rGn = prepare(c, C, a, b, halfspace, clip, L, wn, rwn)
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
    if case != NO_REDUCTION:
        if mode == GIVEN:
            lam = lam_in
        else:
            lam = lam_volume(Gn, epsn, n)
            if mode == ROBUST:
                lam = lam / (1.0 + np.exp(-steep * (cons - midp)))  # [HS96, eq. (30)]
        lam = min(lam, LAM_MAX, LAMG_MAX / Gn)
    margin = 0.0
    if lam > 0.0:
        margin = member(c, C, lam, epsn, repsn, Gn, rGn, wn, rwn, out_c, out_C, out_L, D, dc)
    if not lam > 0.0 or margin < 0.0:
        _copy_input(c, C, L, out_c, out_C, out_L)
        return 0, case, cons, 0.0, False, 0.0
    return 0, case, cons, lam, False, margin


@njit(cache=True, parallel=True)
def fuse_batch(c, C, a, b, halfspace, clip, mode, lam, steep, midp):
    """``fuse_one`` over B instances (a, b, lam broadcast by the caller to (B, ...))."""
    B, n = c.shape
    out_c = np.empty((B, n))
    out_C = np.empty((B, n, n))
    out_L = np.empty((B, n, n))
    code = np.zeros(B, np.int8)
    case = np.zeros(B, np.int8)
    cons = np.zeros(B)
    lam_out = np.zeros(B)
    empty = np.zeros(B, np.bool_)
    margin = np.zeros(B)
    n_chunks = (B + CHUNK - 1) // CHUNK
    for k in prange(n_chunks):
        work = np.zeros((3, max(n, 3), n))
        for i in range(k * CHUNK, min(B, (k + 1) * CHUNK)):
            r = fuse_one(
                c[i], C[i], a[i], b[i], halfspace, clip, mode, lam[i], steep, midp,
                out_c[i], out_C[i], out_L[i], work,
            )  # fmt: skip
            code[i], case[i], cons[i], lam_out[i], empty[i], margin[i] = r
    return out_c, out_C, out_L, code, case, cons, lam_out, empty, margin


@njit(cache=True, parallel=True)
def prepare_batch(c, C, a, b, halfspace, clip):
    """Steps 1-3 over B instances, for the criteria whose lambda is chosen in numpy."""
    B, n = c.shape
    wn = np.empty((B, n))
    code = np.zeros(B, np.int8)
    case = np.zeros(B, np.int8)
    cons = np.zeros(B)
    epsn = np.zeros(B)
    Gn = np.ones(B)
    for i in prange(B):
        L = np.empty((n, n))
        rwn = np.empty(n)
        r = prepare(c[i], C[i], a[i], b[i], halfspace, clip, L, wn[i], rwn)
        code[i], case[i], cons[i], epsn[i], _, Gn[i], _ = r
    return code, case, cons, epsn, Gn, wn
