"""Plain numba reference kernels for the speed benchmark: the same formulas, nothing else.

No validation, no certified error bounds, no margin, no output checks: what the analytic core
would cost if it trusted its inputs and its floating point. ``benchmarks.speed_analytic``
reports our kernels' time as a ratio to these, measured in the same run (same threads).
They are compiled with the same options as ours (``error_model="numpy"``: no zero-division
branch per division). The strip reference runs one instance per loop iteration (LLVM does not
vectorize across instances there; ours are laid out so that it does, see
``optbound.analytic._kernels.lanes``); the Minkowski reference shares our lane-parallel p solver.
"""

from __future__ import annotations

from functools import partial

import numpy as np
from numba import njit

from optbound.analytic._kernels.lanes import W, cholesky_lanes, load_matrices, store_matrices
from optbound.analytic._kernels.minkowski_kernel import block_work, p_volume_lanes
from optbound.analytic._kernels.spin import post_slices
from optbound.analytic._kernels.strip_lambda import lam_volume
from optbound.analytic._kernels.threads import run_sliced


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
def strip_range(c, C, a, b, out_c, out_C, start, stop, posts):
    """The batch loop on ``start..stop`` (``posts`` as in ``analytic._kernels.threads``)."""
    post_slices(posts)
    _strip_loop(c, C, a, b, out_c, out_C, np.empty(c.shape[1]), start, stop)


@njit(cache=True, error_model="numpy", nogil=True)
def minkowski_range(c1, C1, c2, C2, out_c, out_C, start, stop, posts):
    """Volume-optimal Schweppe member [HS96, eq. (14)] with the same solver as ours, in the
    same blocks of W lanes and work space (``analytic._kernels.minkowski_kernel.sum_range``),
    so that the ratio compares the per-instance work only: Cholesky factors, p, the float
    member."""
    post_slices(posts)
    n = c1.shape[1]
    mats, vecs, rows, _, _ = block_work(n, min(W, stop - start))
    C1s, C2s, L1, L2, S = mats[0], mats[1], mats[2], mats[3], mats[4]
    p, act, pivot = rows[0], rows[1], rows[2]
    for base in range(start, stop, W):
        m = min(W, stop - base)
        load_matrices(C1[base:], m, C1s)
        load_matrices(C2[base:], m, C2s)
        cholesky_lanes(C1s, L1, m, pivot, 0)
        cholesky_lanes(C2s, L2, m, pivot, 0)
        for k in range(m):
            act[k] = 1.0
        p_volume_lanes(C1s, C2s, L1, L2, m, act, p, mats[5:], vecs[:3], rows[3:])
        for i in range(n):
            for j in range(n):
                for k in range(m):
                    S[i, j, k] = (1.0 + p[k]) * (C1s[i, j, k] / p[k] + C2s[i, j, k])
        store_matrices(S, m, out_C[base:])
        for k in range(m):
            for i in range(n):
                out_c[base + k, i] = c1[base + k, i] + c2[base + k, i]


def strip_batch(c, C, a, b) -> tuple[np.ndarray, np.ndarray]:
    """The reference strip update of a batch on all cores (the same slices and threads as
    ours), into new arrays as ours returns (their first touch is part of the cost)."""
    out_c, out_C = np.empty(c.shape), np.empty(C.shape)
    run_sliced(partial(strip_range, c, C, a, b, out_c, out_C), len(c))
    return out_c, out_C


def minkowski_batch(c1, C1, c2, C2) -> tuple[np.ndarray, np.ndarray]:
    """As :func:`strip_batch` for the volume-optimal Minkowski sum."""
    out_c, out_C = np.empty(c1.shape), np.empty(C1.shape)
    run_sliced(partial(minkowski_range, c1, C1, c2, C2, out_c, out_C), len(c1))
    return out_c, out_C
