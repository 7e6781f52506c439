"""Batched kernels on all cores: contiguous slices of the batch, one Python thread each.

The kernels release the GIL (``nogil=True``), so plain threads run them truly in parallel.
This is used instead of numba's ``parallel=True``: its OpenMP barriers spin, and on a shared,
oversubscribed machine a batch of 1e3 then took ~30 ms instead of ~0.3 ms.
"""

from __future__ import annotations

import os
import threading
from concurrent.futures import ThreadPoolExecutor

import numpy as np

MIN_SLICE = 2048  # below this, one thread (start-up costs more than it saves)
_LOCAL = threading.local()
_POOL: tuple[int, ThreadPoolExecutor] | None = None  # (owner pid, pool): a forked child
# inherits the pool object but not its threads, so it makes its own.


def run_sliced(kernel, n_batch: int, *args) -> None:
    """Call ``kernel(*args, start, stop)`` on slices covering ``range(n_batch)``: the calling
    thread runs the last slice itself (a dispatch to the pool costs ~15 µs, as much as 300
    strip updates), the pool the others."""
    global _POOL
    workers = min(os.cpu_count() or 1, max(1, n_batch // MIN_SLICE))
    if workers == 1:
        kernel(*args, 0, n_batch)
        return
    if _POOL is None or _POOL[0] != os.getpid():
        _POOL = (
            os.getpid(),
            ThreadPoolExecutor(os.cpu_count() or 1, thread_name_prefix="optbound"),
        )
    pool = _POOL[1]
    bounds = np.linspace(0, n_batch, workers + 1).astype(int)
    jobs = [pool.submit(kernel, *args, bounds[k], bounds[k + 1]) for k in range(workers - 1)]
    kernel(*args, bounds[-2], bounds[-1])
    for job in jobs:
        job.result()


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
    a single call would otherwise spend longer allocating its block scratch (~4 us) than
    computing. Per thread, so that concurrent single calls never share it."""
    cache = _LOCAL.__dict__.setdefault("workspaces", {})
    key = (factory, n)
    if key not in cache:
        cache[key] = factory(n)
    return cache[key]
