"""Batched kernels on all cores: contiguous slices of the batch, one thread each.

The kernels release the GIL (``nogil=True``), so plain threads run them truly in parallel.
This is used instead of numba's ``parallel=True``: its OpenMP threads spin between regions,
and on a shared, oversubscribed machine a batch of 1e3 then took ~30 ms instead of ~0.3 ms.

The worker threads are made once per process and each is handed its slice through two raw
locks: a ``ThreadPoolExecutor`` round trip (future, queue, condition variable) cost ~17 µs on
the 2-core test machine, as much as 300 strip updates, the locks ~14 µs (mostly the wake-up of
an idle core). The calling thread runs a slice itself, and since it starts while the workers
are still waking up, its slice is the larger one for small batches (``LEAD``).
"""

from __future__ import annotations

import _thread
import os
import threading
from collections.abc import Callable

import numpy as np

MIN_SLICE = 256  # no slice is smaller (below 2 MIN_SLICE, one thread: waking costs more)
LEAD = 64  # the calling thread's head start, in instances (see ``slice_bounds``)
_LOCAL = threading.local()


class _Worker:
    """A daemon thread that runs one ``call(start, stop)`` at a time."""

    def __init__(self) -> None:
        self._go = _thread.allocate_lock()
        self._go.acquire()
        self._done = _thread.allocate_lock()
        self._done.acquire()
        self._job: tuple | None = None
        self._result: tuple | None = None
        threading.Thread(target=self._serve, name="optbound-worker", daemon=True).start()

    def _serve(self) -> None:
        while True:
            self._go.acquire()
            call, start, stop = self._job
            try:
                self._result = (call(start, stop), None)
            except BaseException as exc:  # raised again in the caller
                self._result = (None, exc)
            self._done.release()

    def start(self, call: Callable, start: int, stop: int) -> None:
        self._job = (call, start, stop)
        self._go.release()

    def join(self) -> tuple:
        """``(result, exception or None)`` of the slice, once done; forgets the batch."""
        self._done.acquire()
        outcome, self._job, self._result = self._result, None, None
        return outcome


# (owner pid, workers): a forked child inherits the objects but not their threads.
_POOL: tuple[int, list[_Worker]] | None = None
_POOL_BUSY = threading.Lock()  # one batch at a time on the workers; a concurrent one runs alone


def _workers() -> list[_Worker]:
    global _POOL
    if _POOL is None or _POOL[0] != os.getpid():
        cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else None
        _POOL = (os.getpid(), [_Worker() for _ in range((cores or os.cpu_count() or 1) - 1)])
    return _POOL[1]


def slice_bounds(n_batch: int, slices: int) -> list[int]:
    """Bounds of ``slices`` contiguous slices of ``range(n_batch)``, as equal as possible but
    for the first, the calling thread's: it is ``LEAD`` instances longer, since the others
    start only once their workers are awake (~7 µs on the test machine; what that is worth in
    instances depends on the kernel, so LEAD is a compromise that matters for small batches
    only)."""
    share = (n_batch - LEAD) / slices
    return [0, *(LEAD + round(share * k) for k in range(1, slices)), n_batch]


def run_sliced(call: Callable[[int, int], object], n_batch: int) -> list:
    """``call(start, stop)`` on contiguous slices covering ``range(n_batch)``, one per core;
    returns the slices' results in order. The calling thread runs the first slice."""
    slices = min(len(_workers()) + 1, n_batch // MIN_SLICE)
    if slices <= 1 or not _POOL_BUSY.acquire(blocking=False):
        return [call(0, n_batch)]
    try:
        bounds = slice_bounds(n_batch, slices)
        started = []
        try:
            for k, worker in enumerate(_workers()[: slices - 1], start=1):
                worker.start(call, bounds[k], bounds[k + 1])
                started.append(worker)
            mine = call(0, bounds[1])
        finally:  # never leave a worker holding this batch, even if the caller's slice raised
            outcomes = [worker.join() for worker in started]
    finally:
        _POOL_BUSY.release()
    for _, exc in outcomes:
        if exc is not None:
            raise exc
    return [mine, *(value for value, _ in outcomes)]


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
