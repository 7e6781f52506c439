"""Batched kernels on all cores: contiguous slices of the batch, one thread each.

The kernels release the GIL (``nogil=True``), so plain threads run them truly in parallel: the
calling thread runs the first slice, a ``ThreadPoolExecutor`` made once per process the
others. numba's ``parallel=True`` is not used: its OpenMP layer spins between regions (on a
loaded 2-core machine a batch of 1e3 took up to ~30 times longer), and its workqueue layer
cannot be entered by two threads at once. ``python -m optbound.bench.speed_analytic --threads``
compares the three schemes.

A kernel run by ``run_sliced`` is called as ``call(start, stop)`` on ``range(start, stop)``.
"""

from __future__ import annotations

import os
import threading
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor, wait

import numpy as np

MIN_SLICE = 256  # no slice is smaller (below 2 MIN_SLICE, one thread: waking costs more)
_LOCAL = threading.local()
# (owner pid, executor): a forked child inherits the object but not its threads.
_POOL: tuple[int, ThreadPoolExecutor] | None = None
_POOL_MADE = threading.Lock()  # two threads starting their first batch make one pool


def cores() -> int:
    """The number of cores this process may run on."""
    if hasattr(os, "sched_getaffinity"):
        return len(os.sched_getaffinity(0))
    return os.cpu_count() or 1


def _pool() -> ThreadPoolExecutor:
    global _POOL
    if _POOL is None or _POOL[0] != os.getpid():
        with _POOL_MADE:
            if _POOL is None or _POOL[0] != os.getpid():
                workers = max(cores() - 1, 1)
                pool = ThreadPoolExecutor(workers, thread_name_prefix="optbound-worker")
                _POOL = (os.getpid(), pool)
    return _POOL[1]


def slice_bounds(n_batch: int, slices: int) -> list[int]:
    """Bounds of ``slices`` contiguous slices of ``range(n_batch)``, as equal as possible."""
    return [n_batch * k // slices for k in range(slices + 1)]


def run_sliced(call: Callable[[int, int], object], n_batch: int) -> list:
    """``call(start, stop)`` on contiguous slices covering ``range(n_batch)``, one per core;
    returns the slices' results in order and raises a slice's error in the caller. The
    calling thread runs the first slice. Concurrent callers share the workers."""
    slices = min(cores(), n_batch // MIN_SLICE)
    if slices <= 1:
        return [call(0, n_batch)]
    bounds = slice_bounds(n_batch, slices)
    pool = _pool()
    futures = [pool.submit(call, bounds[k], bounds[k + 1]) for k in range(1, slices)]
    try:
        mine = call(0, bounds[1])
    finally:  # never return while a worker still writes this batch's outputs
        wait(futures)
    return [mine, *(future.result() for future in futures)]


def ellipsoid_outputs(n_batch: int, n: int, *scalars) -> tuple:
    """Output arrays of a batched kernel: centres (B, n) and shapes (B, n, n), then one
    zero-filled (B,) array per dtype in ``scalars``."""
    return (
        np.empty((n_batch, n)),
        np.empty((n_batch, n, n)),
        *(np.zeros(n_batch, dtype) for dtype in scalars),
    )


def workspace(factory, n: int) -> tuple:
    """The scratch ``factory(n)`` of a compiled kernel, made once per thread and dimension:
    a call would otherwise spend microseconds allocating its block scratch (a single update
    longer than computing). Per thread, so that concurrent calls never share it."""
    cache = _LOCAL.__dict__.setdefault("workspaces", {})
    key = (factory, n)
    if key not in cache:
        cache[key] = factory(n)
    return cache[key]
