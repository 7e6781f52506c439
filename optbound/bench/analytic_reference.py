"""The plain formulas of ``optbound.analytic.reference``, compiled, as the speed baseline.

No validation, no certified error bounds, no margin, no output checks: what the analytic core
would cost if it trusted its inputs and its floating point. ``optbound.bench.speed_analytic``
reports our kernels' time as a ratio to these, measured in the same run (same threads).
The reference functions are compiled unchanged, with the same options as our kernels
(``error_model="numpy"``: no zero-division branch per division). The strip reference runs one
instance per loop iteration (LLVM does not vectorize across instances there; ours are laid out
so that it does, see ``optbound.analytic._kernels.lanes``); the Minkowski reference shares our
lane-parallel p solver and evaluates the member with the plain formula.
"""

from __future__ import annotations

from functools import cache, partial
from pathlib import Path
from types import FunctionType

import numpy as np
from numba import prange

from optbound import _jit_cache
from optbound._core.jit import njit
from optbound._core.native_call import address, caller
from optbound.analytic import reference
from optbound.analytic._kernels import strip_kernel, threads
from optbound.analytic._kernels.lanes import W, cholesky_block, load_matrices
from optbound.analytic._kernels.minkowski_kernel import (
    NEWTON_ENTRY,
    P_VOLUME_ENTRY,
    call_p_volume,
    thread_work,
)
from optbound.analytic._kernels.threads import ellipsoid_outputs, run_sliced

# Cached on disk (each bench run would otherwise compile them again: seconds of CPU), with the
# caches dropped whenever the reference, this file or any kernel they call changes (numba
# tracks only the defining file).
_jit_cache.refresh(
    cache_dirs=[
        Path(__file__).parent / "__pycache__",
        Path(reference.__file__).parent / "__pycache__",
    ],
    sources=[*_jit_cache.kernel_sources(), Path(reference.__file__), Path(__file__)],
    stamp="analytic_reference.stamp",
)
_OPTIONS = {"error_model": "numpy", "nogil": True, "cache": True}


def _compiled(function, **callees):
    """A reference function compiled unchanged, its calls of other reference functions bound
    to their compiled versions ``callees`` (a compiled function calls only compiled ones)."""
    bound = FunctionType(function.__code__, {**function.__globals__, **callees}, function.__name__)
    return njit(**_OPTIONS)(bound)


minkowski_member = _compiled(reference.minkowski_member)
strip_one = _compiled(
    reference.intersect_strip_volume,
    strip_lam_volume=_compiled(reference.strip_lam_volume),
    strip_member=_compiled(reference.strip_member),
)


@njit(**_OPTIONS, _nrt=False)
def _strip_loop(c, C, a, b, out_c, out_C, w, start, stop):
    """The batch loop, with views without reference counting (as ours), so that the ratio
    compares the work per instance only."""
    for i in range(start, stop):
        strip_one(c[i], C[i], a[i], b[i], out_c[i], out_C[i], w)


@njit(**_OPTIONS)
def strip_range(c, C, a, b, out_c, out_C, start, stop):
    """The batch loop on ``start..stop`` (a slice of ``analytic._kernels.threads``)."""
    _strip_loop(c, C, a, b, out_c, out_C, np.empty(c.shape[1]), start, stop)


_call_cholesky = caller(cholesky_block)


@cache
def _cholesky_address() -> int:
    """Address of ``lanes.cholesky_block`` for the work space's arrays (``native_call``)."""
    m3, r1 = np.empty((1, 1, 1)), np.empty(1)
    return address(cholesky_block, m3, m3, 0, r1)


@njit(**_OPTIONS, _nrt=False)
def minkowski_blocks(c1, C1, c2, C2, out_c, out_C, wk, cholesky, start, stop):
    """Volume-optimal Schweppe member [HS96, eq. (14)] with the same solver as ours, in the
    same blocks of W lanes and the same work space ``wk`` (``minkowski_kernel.thread_work``),
    so that the ratio compares the per-instance work only: Cholesky factors, p, the plain
    member ``reference.minkowski_member``. Its views are not reference counted (as ours and
    the strip reference's are not). The solver is called as ``sum_blocks`` calls it: by
    address (``wk``'s entries), with a work space of the same tuple lengths (7 mats, 3 vecs,
    14 rows), so that both run one compiled solver and neither links it in; the Cholesky
    factors by address too (``cholesky``, ``lanes.cholesky_block``)."""
    mats, vecs, rows, _, _, entries = wk
    C1s, C2s, L1, L2 = mats[0], mats[1], mats[2], mats[3]
    p, act, pivot = rows[0], rows[1], rows[2]
    for base in range(start, stop, W):
        m = min(W, stop - base)
        load_matrices(C1[base:], m, C1s)
        load_matrices(C2[base:], m, C2s)
        _call_cholesky(cholesky, (C1s, L1, m, pivot))
        _call_cholesky(cholesky, (C2s, L2, m, pivot))
        for k in range(m):
            act[k] = 1.0
        call_p_volume(
            entries[P_VOLUME_ENTRY],
            (C1s, C2s, L1, L2, m, act, p, mats[5:12], vecs[:3], rows[3:17], entries[NEWTON_ENTRY]),
        )
        for k in range(m):
            i = base + k
            minkowski_member(c1[i], C1[i], c2[i], C2[i], p[k], out_c[i], out_C[i])


def minkowski_range(c1, C1, c2, C2, out_c, out_C, start: int, stop: int) -> None:
    """:func:`minkowski_blocks` on ``start..stop`` (a slice of ``analytic._kernels.threads``)
    with the calling thread's work space, as ``minkowski_kernel.sum_range`` does ours.

    Parameters
    ----------
    c1, C1, c2, C2 : numpy.ndarray
        ``(B, n)`` centres and ``(B, n, n)`` shapes of the summands.
    out_c, out_C : numpy.ndarray
        ``(B, n)`` and ``(B, n, n)`` outputs, written on ``start..stop``.
    start, stop : int
        The instances to sum.
    """
    wk = thread_work(c1.shape[1])
    minkowski_blocks(c1, C1, c2, C2, out_c, out_C, wk, _cholesky_address(), start, stop)


def strip_batch(c, C, a, b) -> tuple[np.ndarray, np.ndarray]:
    """Run the reference strip update of a batch on all cores (same slices and threads as ours).

    The outputs are new arrays, as ours returns (their first touch is part of the cost).

    Parameters
    ----------
    c : numpy.ndarray
        ``(B, n)`` centres.
    C : numpy.ndarray
        ``(B, n, n)`` shape matrices.
    a : numpy.ndarray
        ``(B, n)`` strip normals.
    b : numpy.ndarray
        ``(B,)`` strip offsets (strip ``|a·x - b| <= 1``).

    Returns
    -------
    centers : numpy.ndarray
        ``(B, n)`` centres of the updated ellipsoids.
    shapes : numpy.ndarray
        ``(B, n, n)`` their shape matrices.
    """
    out_c, out_C = np.empty(c.shape), np.empty(C.shape)
    run_sliced(partial(strip_range, c, C, a, b, out_c, out_C), len(c))
    return out_c, out_C


def minkowski_batch(c1, C1, c2, C2) -> tuple[np.ndarray, np.ndarray]:
    """Run the reference volume-optimal Minkowski sum of a batch, as :func:`strip_batch`.

    Parameters
    ----------
    c1 : numpy.ndarray
        ``(B, n)`` centres of the first summands.
    C1 : numpy.ndarray
        ``(B, n, n)`` their shape matrices.
    c2 : numpy.ndarray
        ``(B, n)`` centres of the second summands.
    C2 : numpy.ndarray
        ``(B, n, n)`` their shape matrices.

    Returns
    -------
    centers : numpy.ndarray
        ``(B, n)`` centres of the sums.
    shapes : numpy.ndarray
        ``(B, n, n)`` their shape matrices.
    """
    out_c, out_C = np.empty(c1.shape), np.empty(C1.shape)
    run_sliced(partial(minkowski_range, c1, C1, c2, C2, out_c, out_C), len(c1))
    return out_c, out_C


# ---------------------------------------------------------------- threading schemes compared
# Our certified strip kernel (volume criterion, clipped) on the same slices, handed to the
# threads two ways; ``optbound.bench.speed_analytic.threading_timings`` times them interleaved.
# The Python-side validation of ``intersect_strip_batch`` is left out of both alike.


def _strip_outputs(n_batch: int, n: int) -> tuple:
    return ellipsoid_outputs(n_batch, n, *strip_kernel.OUT_DTYPES)


_NO_LAM, _NO_IDX = np.zeros(1), np.zeros(0, np.int64)


def strip_sliced(c, C, a, b) -> tuple:
    """Run the strip kernel on ``threads.run_sliced`` (a thread pool, the library's scheme).

    Parameters
    ----------
    c : numpy.ndarray
        ``(B, n)`` centres.
    C : numpy.ndarray
        ``(B, n, n)`` shape matrices.
    a : numpy.ndarray
        ``(B, n)`` strip normals.
    b : numpy.ndarray
        ``(B,)`` strip offsets (strip ``|a·x - b| <= 1``).

    Returns
    -------
    tuple of numpy.ndarray
        The kernel's outputs: centres ``(B, n)``, shapes ``(B, n, n)``, then its per-instance
        scalar outputs.
    """
    out = _strip_outputs(*c.shape)

    def call(start, stop):
        ws = threads.workspace(strip_kernel.workspace, c.shape[1])
        return strip_kernel.fuse_range(c, C, a, b, False, True, strip_kernel.VOLUME, _NO_LAM,
                                       _NO_IDX, 10.0, 0.5, out, ws, start, stop)  # fmt: skip

    run_sliced(call, len(c))
    return out


@njit(**_OPTIONS, parallel=True)
def _fuse_prange(c, C, a, b, lam, idx, out, ws, slices):
    """The strip kernel on ``slices`` contiguous slices under numba's ``prange`` (one
    iteration per thread of numba's threading layer), each with its own workspace."""
    n_batch = c.shape[0]
    for s in prange(slices):
        own = (ws[0][s], ws[1][s], ws[2][s], ws[3][s], ws[4][s], ws[5][s], ws[6][s], ws[7][s],
               ws[8][s], ws[9][s], ws[10][s])  # fmt: skip
        start, stop = s * n_batch // slices, (s + 1) * n_batch // slices
        strip_kernel.fuse_range(
            c,
            C,
            a,
            b,
            False,
            True,
            strip_kernel.VOLUME,
            lam,
            idx,
            10.0,
            0.5,
            out,
            own,
            start,
            stop,
        )


_STACKED: dict = {}


def strip_prange(c, C, a, b) -> tuple:
    """Run the strip kernel on the same slices under numba's ``prange``.

    Workspaces are made once per dimension, as ``threads.workspace`` does.

    Parameters
    ----------
    c : numpy.ndarray
        ``(B, n)`` centres.
    C : numpy.ndarray
        ``(B, n, n)`` shape matrices.
    a : numpy.ndarray
        ``(B, n)`` strip normals.
    b : numpy.ndarray
        ``(B,)`` strip offsets (strip ``|a·x - b| <= 1``).

    Returns
    -------
    tuple of numpy.ndarray
        The kernel's outputs: centres ``(B, n)``, shapes ``(B, n, n)``, then its per-instance
        scalar outputs.
    """
    out = _strip_outputs(*c.shape)
    n = c.shape[1]
    slices = max(1, min(threads.cores(), len(c) // threads.MIN_SLICE))
    if n not in _STACKED:
        per_slice = [strip_kernel.workspace(n) for _ in range(threads.cores())]
        _STACKED[n] = tuple(np.stack(parts) for parts in zip(*per_slice, strict=True))
    _fuse_prange(c, C, a, b, _NO_LAM, _NO_IDX, out, _STACKED[n], slices)
    return out
