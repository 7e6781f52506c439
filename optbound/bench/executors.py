"""Where the parallel tasks of a suite run: this process, a local process pool, or Dask.

Every executor offers the same two calls, ``submit(fn, arg, priority)`` and
``completed(futures)`` (yield the futures as they finish), so the runner does not know which
one it drives. Tasks are submitted longest first; a pool takes them in submission order and
Dask by ``priority``, so the longest tasks start first either way.

Dask (``pip install "optbound[dask]"``) is imported only when asked for:

- ``scheduler="tcp://HOST:PORT"`` connects to a running cluster (``dask scheduler`` and
  ``dask worker tcp://HOST:PORT`` started by the user; the workers need optbound installed);
- ``kind="dask"`` without an address starts a ``LocalCluster`` of ``jobs`` single-threaded
  worker processes for the run.

Results do not depend on the executor: every task carries its own seed and the runner sorts
the results by task.
"""

from __future__ import annotations

import concurrent.futures as cf
import importlib.util
import multiprocessing
import signal
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager

EXECUTORS = ("process", "dask")
CONNECT_TIMEOUT = "10s"  # an unreachable scheduler fails fast (dask's default waits 30 s)
DASK_MISSING = 'the dask executor needs dask.distributed: pip install "optbound[dask]"'


def check_available(kind: str = "process", scheduler: str | None = None) -> None:
    """Raise now, before any work, if the executor ``kind`` (or ``scheduler``) cannot run.

    Parameters
    ----------
    kind : {"process", "dask"}
        The executor.
    scheduler : str, optional
        Address of a running Dask scheduler.

    Raises
    ------
    ValueError
        For an unknown ``kind``, or dask requested (``kind="dask"`` or a ``scheduler``)
        but dask.distributed not installed.

    Examples
    --------
    >>> from optbound.bench.executors import check_available
    >>> check_available("process")
    >>> check_available("threads")
    Traceback (most recent call last):
        ...
    ValueError: executor must be one of ('process', 'dask'), got 'threads'
    """
    if kind not in EXECUTORS:
        raise ValueError(f"executor must be one of {EXECUTORS}, got {kind!r}")
    if (scheduler is not None or kind == "dask") and importlib.util.find_spec(
        "distributed"
    ) is None:
        raise ValueError(DASK_MISSING)


def ignore_interrupts() -> None:
    """Ignore Ctrl-C in a worker process (the pool's worker initializer).

    Ctrl-C reaches the whole process group, but only the parent should handle it (it stops
    the workers); a worker would print its own traceback.
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)


class _Inline:
    """Runs the tasks in this process (``--jobs 1``), each when the runner asks for the next
    finished one, so the runner handles (and stores) each result before the next task runs."""

    def __init__(self):
        self.calls: dict[cf.Future, tuple[Callable, object]] = {}

    def submit(self, fn: Callable, arg, priority: float = 0.0) -> cf.Future:
        future: cf.Future = cf.Future()
        self.calls[future] = (fn, arg)
        return future

    def completed(self, futures: Iterable[cf.Future]) -> Iterator[cf.Future]:
        for future in list(futures):
            fn, arg = self.calls.pop(future)
            try:
                future.set_result(fn(arg))
            except Exception as exc:
                future.set_exception(exc)
            yield future


class _Pool:
    """A ``concurrent.futures`` process pool; it starts tasks in submission order."""

    def __init__(self, pool: cf.ProcessPoolExecutor):
        self.pool = pool

    def submit(self, fn: Callable, arg, priority: float = 0.0) -> cf.Future:
        return self.pool.submit(fn, arg)

    def completed(self, futures: Iterable[cf.Future]) -> Iterator[cf.Future]:
        yield from cf.as_completed(list(futures))


class _Dask:
    """A ``dask.distributed`` client; higher ``priority`` starts first."""

    def __init__(self, client):
        self.client = client

    def submit(self, fn: Callable, arg, priority: float = 0.0):
        # pure=False: two equal tasks are still two runs (they never are, but do not assume).
        return self.client.submit(fn, arg, priority=priority, pure=False)

    def completed(self, futures: Iterable) -> Iterator:
        from distributed import as_completed

        yield from as_completed(list(futures))


@contextmanager
def executor(kind: str = "process", jobs: int = 1, scheduler: str | None = None):
    """The executor for a run (a context manager that shuts it down afterwards).

    Parameters
    ----------
    kind : {"process", "dask"}
        ``process``: ``jobs`` worker processes (``jobs == 1`` runs in this process);
        ``dask``: a Dask cluster, the one at ``scheduler`` or a new ``LocalCluster``.
    jobs : int
        Worker processes of the pool or of the LocalCluster.
    scheduler : str, optional
        Address of a running Dask scheduler, e.g. ``"tcp://10.0.0.5:8786"`` (implies dask).

    Yields
    ------
    object
        The executor the runner submits tasks to: in-process, a process pool or a Dask
        client, each shut down when the block is left.

    Raises
    ------
    ValueError
        For an unknown ``kind``, ``jobs < 1``, or dask requested but not installed.
    """
    check_available(kind, scheduler)
    if jobs < 1:
        raise ValueError(f"jobs must be a positive integer, got {jobs}")
    if scheduler is not None or kind == "dask":
        with _dask_client(jobs, scheduler) as client:
            yield _Dask(client)
    elif jobs == 1:
        yield _Inline()
    else:
        with _process_pool(jobs) as pool:
            yield _Pool(pool)


@contextmanager
def _process_pool(jobs: int):
    """A process pool whose workers ignore Ctrl-C and are stopped, not awaited, when the run
    is interrupted or fails (``shutdown(wait=True)`` would first finish every running task)."""
    pool = cf.ProcessPoolExecutor(
        jobs, mp_context=multiprocessing.get_context(), initializer=ignore_interrupts
    )
    try:
        yield pool
    except BaseException:
        # Python < 3.14 has no public way to stop the running workers.
        for process in list((pool._processes or {}).values()):
            process.terminate()
        pool.shutdown(wait=False, cancel_futures=True)
        raise
    pool.shutdown()


@contextmanager
def _dask_client(jobs: int, scheduler: str | None):
    from distributed import Client, LocalCluster  # check_available: it is installed

    if scheduler is not None:
        with Client(scheduler, timeout=CONNECT_TIMEOUT) as client:
            yield client
        return
    with (
        LocalCluster(
            n_workers=jobs, threads_per_worker=1, processes=True, dashboard_address=None
        ) as cluster,
        Client(cluster) as client,
    ):
        yield client
