"""Batched kernels on all cores: contiguous slices of the batch, one thread each.

The kernels release the GIL (``nogil=True``), so plain threads run them truly in parallel.
This is used instead of numba's ``parallel=True``: its OpenMP threads spin between regions,
and on a shared, oversubscribed machine a batch of 1e3 then took ~30 ms instead of ~0.3 ms.

The worker threads are made once per process. A slice is handed over through a raw lock and
a flag: a ``ThreadPoolExecutor`` round trip (future, queue, condition variable) cost ~17 µs on
the 2-core test machine, as much as 300 strip updates, and most of any handoff through locks
is the wake-up of a sleeping core. So after each slice a worker polls for the next one for
~100 µs before it sleeps, and the calling thread, done with its own slice, polls for the
workers' results (``spin``); back-to-back batches then never wait for a wake-up, at the cost
of up to ~100 µs of a polling core after each batch. The calling thread's slice is the larger
one for small batches (``LEAD``): it starts while the workers may still be waking up.

A kernel run by ``run_sliced`` is called as ``call(start, stop, posts)`` and must call
``spin.post_slices(posts)`` first, once it holds no GIL: that is what tells a polling worker
that its slice is ready (were it told earlier, it would wait for the GIL, asleep).
"""

from __future__ import annotations

import _thread
import os
import threading
from collections.abc import Callable

import numpy as np

from optbound.analytic._kernels.spin import handoff, wait_for

MIN_SLICE = 256  # no slice is smaller (below 2 MIN_SLICE, one thread: waking costs more)
LEAD = 64  # the calling thread's head start, in instances (see ``slice_bounds``)
POLLS = 4000  # polls of a flag before a thread sleeps (~26 ns each on the test machine)
NO_POSTS = np.zeros((0, 8), np.int64)  # ``posts`` of a kernel that hands no slices over
_LOCAL = threading.local()


def _cache_lines(count: int) -> np.ndarray:
    """``count`` rows of 8 int64, each filling one 64-byte cache line of its own, so that a
    polled flag never shares its line with data another core writes (where malloc puts a
    small array is chance; no effect was measurable on the test machine)."""
    buffer = np.zeros((count + 2) * 8, np.int64)
    first = 8 + (-buffer.ctypes.data % 64) // 8  # one line of padding before
    return buffer[first : first + count * 8].reshape(count, 8)


class _Worker:
    """A daemon thread that runs one ``call(start, stop, NO_POSTS)`` at a time. ``post`` is
    its row of the pool's posts: [0] the number of the last slice handed over (set by the
    caller's kernel), [1] the number of the slice to hand over next."""

    def __init__(self, post: np.ndarray) -> None:
        self._go = _thread.allocate_lock()
        self._go.acquire()
        self._done = _thread.allocate_lock()
        self._done.acquire()
        self._post = post
        self._flag = _cache_lines(1)[0]  # [0]: the number of the last slice done
        self._jobs = 0
        self._job: tuple | None = None
        self._result: tuple | None = None
        threading.Thread(target=self._serve, name="optbound-worker", daemon=True).start()

    def _serve(self) -> None:
        self._go.acquire()
        while True:
            call, start, stop, number = self._job
            try:
                self._result = (call(start, stop, NO_POSTS), None)
            except BaseException as exc:  # raised again in the caller
                self._result = (None, exc)
            self._done.release()  # before the flag: a caller that saw the flag never blocks
            handoff(self._flag, number, self._post, number + 1, POLLS)
            self._go.acquire()  # at once if the next slice was posted (its release came first)

    def start(self, call: Callable, start: int, stop: int) -> None:
        """Hand over a slice: now if the worker sleeps, else when the caller's kernel posts."""
        self._jobs += 1
        self._job = (call, start, stop, self._jobs)
        self._post[1] = self._jobs
        self._go.release()

    def join(self) -> tuple:
        """``(result, exception or None)`` of the slice, once done; forgets the batch."""
        wait_for(self._flag, self._jobs, POLLS)
        self._done.acquire()
        outcome, self._job, self._result = self._result, None, None
        return outcome


# (owner pid, workers, posts): a forked child inherits the objects but not their threads.
_POOL: tuple[int, list[_Worker], np.ndarray] | None = None
_POOL_BUSY = threading.Lock()  # one batch at a time on the workers; a concurrent one runs alone
_POOL_MADE = threading.Lock()  # two threads starting their first batch make one pool


def _pool() -> tuple[list[_Worker], np.ndarray]:
    global _POOL
    if _POOL is None or _POOL[0] != os.getpid():
        with _POOL_MADE:
            if _POOL is None or _POOL[0] != os.getpid():
                cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else None
                posts = _cache_lines((cores or os.cpu_count() or 1) - 1)
                _POOL = (os.getpid(), [_Worker(post) for post in posts], posts)
    return _POOL[1], _POOL[2]


def slice_bounds(n_batch: int, slices: int) -> list[int]:
    """Bounds of ``slices`` contiguous slices of ``range(n_batch)``, as equal as possible but
    for the first, the calling thread's: it is ``LEAD`` instances longer, since the others
    start only once their workers have seen the post (or woken up). What that delay is worth
    in instances depends on the kernel, so LEAD is a compromise; it matters for small batches
    only."""
    share = (n_batch - LEAD) / slices
    return [0, *(LEAD + round(share * k) for k in range(1, slices)), n_batch]


def run_sliced(call: Callable[[int, int, np.ndarray], object], n_batch: int) -> list:
    """``call(start, stop, posts)`` on contiguous slices covering ``range(n_batch)``, one per
    core (see the module docstring for ``posts``); returns the slices' results in order. The
    calling thread runs the first slice."""
    workers, posts = _pool()
    slices = min(len(workers) + 1, n_batch // MIN_SLICE)
    if slices <= 1 or not _POOL_BUSY.acquire(blocking=False):
        return [call(0, n_batch, NO_POSTS)]
    try:
        bounds = slice_bounds(n_batch, slices)
        started = []
        try:
            for k, worker in enumerate(workers[: slices - 1], start=1):
                worker.start(call, bounds[k], bounds[k + 1])
                started.append(worker)
            mine = call(0, bounds[1], posts[: len(started)])
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
