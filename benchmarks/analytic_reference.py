"""Plain numba reference kernels for the speed benchmark: the same formulas, nothing else.

No validation, no certified error bounds, no margin, no output checks: what the analytic core
would cost if it trusted its inputs and its floating point. ``benchmarks.speed_analytic``
reports our kernels' time as a ratio to these, measured in the same run (same threads).
They are compiled with the same options as ours (``error_model="numpy"``: no zero-division
branch per division), one instance per loop iteration (LLVM does not vectorize across
instances here; ours are laid out so that it does, see ``optbound.analytic._lanes``).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from optbound.analytic._minkowski_kernel import p_volume
from optbound.analytic._strip_lambda import lam_volume
from optbound.sets._domain import cholesky


@njit(cache=True, error_model="numpy", nogil=True)
def strip_one(c, C, a, b, out_c, out_C, w):
    """Clipped strip, volume lambda [HS96, eqs. (24), (26)], as in the float formula; ``w``
    (n,) is scratch (allocated once per slice, not per instance)."""
    n = c.shape[0]
    G = 0.0
    ac = 0.0
    for i in range(n):
        s = 0.0
        for j in range(n):
            s += C[i, j] * a[j]
        w[i] = s
        G += a[i] * s
        ac += a[i] * c[i]
    g = np.sqrt(G)
    lo = max(b - ac - 1.0, -g)
    hi = min(b - ac + 1.0, g)
    half = max(0.5 * (hi - lo), 1e-6 * g)
    eps = 0.5 * (lo + hi) / half
    Gs = G / (half * half)
    lam = lam_volume(Gs, eps, n)
    u = 1.0 + lam * Gs
    K = 1.0 + lam - lam * eps * eps / u
    gam = lam / u / (half * half)
    for i in range(n):
        out_c[i] = c[i] + gam * half * eps * w[i]
        for j in range(n):
            out_C[i, j] = K * (C[i, j] - gam * w[i] * w[j])


@njit(cache=True, error_model="numpy", nogil=True, _nrt=False)
def _strip_loop(c, C, a, b, out_c, out_C, w, start, stop):
    """The batch loop, with views without reference counting (as ours), so that the ratio
    compares the work per instance only."""
    for i in range(start, stop):
        strip_one(c[i], C[i], a[i], b[i], out_c[i], out_C[i], w)


@njit(cache=True, error_model="numpy", nogil=True)
def strip_range(c, C, a, b, out_c, out_C, start, stop):
    _strip_loop(c, C, a, b, out_c, out_C, np.empty(c.shape[1]), start, stop)


@njit(cache=True, error_model="numpy", nogil=True)
def minkowski_one(c1, C1, c2, C2, out_c, out_C, work):
    """Volume-optimal Schweppe member [HS96, eq. (14)] with the same Newton solver as ours."""
    n = c1.shape[0]
    L1, L2, M, Y, Z = work[0], work[1], work[2], work[3], work[4]
    cholesky(C1, L1)
    cholesky(C2, L2)
    p = p_volume(C1, C2, L1, L2, M, Y, Z)
    for i in range(n):
        out_c[i] = c1[i] + c2[i]
        for j in range(n):
            out_C[i, j] = (1.0 + p) * (C1[i, j] / p + C2[i, j])


@njit(cache=True, error_model="numpy", nogil=True, _nrt=False)
def _minkowski_loop(c1, C1, c2, C2, out_c, out_C, work, start, stop):
    """The same loop structure as ``optbound.analytic._minkowski_kernel._sum_loop`` (views
    without reference counting), so that the ratio compares the per-instance work only."""
    for i in range(start, stop):
        minkowski_one(c1[i], C1[i], c2[i], C2[i], out_c[i], out_C[i], work)


@njit(cache=True, error_model="numpy", nogil=True)
def minkowski_range(c1, C1, c2, C2, out_c, out_C, start, stop):
    n = c1.shape[1]
    _minkowski_loop(c1, C1, c2, C2, out_c, out_C, np.empty((5, n, n)), start, stop)
