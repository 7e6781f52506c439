"""Compiled choice of lambda for ellipsoid ∩ strip fusion [HS96, eqs. (26)-(28)].

All functions take the fused strip normalized to ``|a'^T (x - c) - e| <= 1``, i.e.
``Gn = a'^T C a'`` and ``e`` (the offset of its midplane), and return the lambda >= 0 of
[HS96, eq. (24)] for that strip. Only *which* member is used depends on lambda: every member is
an outer bound and is inflated by its own certified margin, so the guarantee never depends on
the accuracy of these roots.

The cubics are solved by :func:`.cubic.real_roots`; the nonnegative real root
(or 0) with the smallest size measure wins, so the choice is never worse than lambda = 0 (E
itself) or any other stationary point.
"""

from __future__ import annotations

import numpy as np

from optbound._core import cholesky
from optbound._core.jit import njit
from optbound.analytic._kernels.cubic import real_roots


@njit(cache=True, error_model="numpy", inline="always")
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


@njit(cache=True, error_model="numpy")
def _shape_factor(lam, Gn, e):
    """K of [HS96, eq. (24)] for the normalized strip."""
    return 1.0 + lam - lam * e * e / (1.0 + lam * Gn)


_TRACE, _PROJECTION = range(2)


@njit(cache=True, error_model="numpy")
def _size(lam, Gn, e, kind, p, q):
    """Size measure of the member ``lam`` (+inf if K <= 0): for ``_TRACE`` tr(K C0) =
    K (tr C - lambda |C a'|^2 / u) with p = tr C, q = |C a'|^2 [HS96, eq. (24)]; for
    ``_PROJECTION`` the log of the projection's volume up to a constant [HS96, eq. (34)], with
    p = H [HS96, eq. (28)] and q = m the projection's dimension."""
    K = _shape_factor(lam, Gn, e)
    if not K > 0.0:
        return np.inf
    if kind == _TRACE:
        return K * (p - lam * q / (1.0 + lam * Gn))
    return q * np.log(K) + np.log1p(lam * (Gn - p)) - np.log1p(lam * Gn)


@njit(cache=True, error_model="numpy")
def _best_root(roots, Gn, e, kind, p, q):
    """The positive root (or 0) of ``roots = (k, x1, x2, x3)`` with the smallest size."""
    k, x1, x2, x3 = roots
    best, best_size = 0.0, _size(0.0, Gn, e, kind, p, q)
    for j, lam in enumerate((x1, x2, x3)):
        if j < k and lam > 0.0:
            size = _size(lam, Gn, e, kind, p, q)
            if size < best_size:
                best, best_size = lam, size
    return best


@njit(cache=True, error_model="numpy")
def lam_trace(C, w, half, Gn, e):
    """The root of the cubic d/dlambda tr(K C0) = 0 (derived from [HS96, eq. (24)]) that
    minimizes the trace; ``w`` = C a (unnormalized, ``w / half`` = C a')."""
    n = C.shape[0]
    T = 0.0
    W = 0.0
    for i in range(n):
        T += C[i, i]
        wi = w[i] / half
        W += wi * wi
    e2 = e * e
    D = Gn * T - W  # >= 0 by Cauchy-Schwarz
    roots = real_roots(
        Gn * Gn * D,
        3.0 * Gn * D,
        -Gn * T * e2 + 3.0 * Gn * T - Gn * W + 2.0 * W * e2 - 2.0 * W,
        T * (1.0 - e2) - W,
    )
    return _best_root(roots, Gn, e, np.int64(_TRACE), T, W)


@njit(cache=True, error_model="numpy")
def lam_projection(C, w, half, Gn, e, idx, P, LP, y):
    """The root of the cubic [HS96, eq. (27)] that minimizes the volume of the projection onto
    the coordinates ``idx``, with H of [HS96, eq. (28)]; ``P``, ``LP`` (>= (m, m)) and ``y``
    (>= m) are scratch. 0 if the projected shape cannot be factored."""
    m = idx.shape[0]
    # Contiguous (m, m) views of the scratch (one compiled cholesky for every caller).
    P = P.reshape(P.size)[: m * m].reshape((m, m))
    LP = LP.reshape(LP.size)[: m * m].reshape((m, m))
    for r in range(m):
        for s in range(r + 1):
            i, j = idx[r], idx[s]
            P[r, s] = C[i, j] if j <= i else C[j, i]
    if not cholesky(P, LP) > 0.0:
        return 0.0
    H = 0.0  # H = w_d^T P^{-1} w_d = |LP^{-1} w_d|^2 [HS96, eq. (28)]
    for r in range(m):
        s_r = w[idx[r]] / half
        for s in range(r):
            s_r -= LP[r, s] * y[s]
        y[r] = s_r / LP[r, r]
        H += y[r] * y[r]
    H = min(max(H, 0.0), Gn)  # 0 <= H <= G up to rounding
    e2 = e * e
    roots = real_roots(
        (Gn - H) * Gn * Gn * m,
        (m * (3.0 * Gn - 2.0 * H) - H) * Gn,
        (3.0 * Gn - H + e2 * (H - Gn)) * m - Gn * H - H + e2 * H,
        m * (1.0 - e2) - H,
    )
    return _best_root(roots, Gn, e, np.int64(_PROJECTION), H, float(m))
