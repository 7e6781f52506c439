"""Run a suite: spread the families' tasks over worker processes and collect one results dict.

The results dict is everything the report needs (``optbound report DIR`` rebuilds the report
from its JSON alone)::

    {"schema": 1,
     "meta": {"command", "suite", "seed", "jobs", "executor", "families_run", "complete",
              "wall_time_s", "started", "load_average", "cpus", "processor", versions...},
     "families": {name: {"title", "kind", "status", "reason", "records", "figures",
                         "notes", "warnings", "errors", "task_seconds"}}}

``task_seconds`` holds ``[task index, wall seconds]`` pairs: what each task cost, to check
the families' cost estimates (``Family.cost``) against.

A run given a :class:`~optbound.bench.run_folder.RunFolder` stores each task's result as it
finishes and takes the tasks already stored there from it (``--resume``). A worker process
that dies (killed, out of memory) breaks a process pool: the tasks that were running are then
run again one by one, each in its own child process, the task whose process dies again is
recorded as failed with the signal that ended it, and a new pool runs the tasks not started.
"""

from __future__ import annotations

import multiprocessing
import os
import platform
import signal
import tempfile
import time
import warnings
from collections.abc import Callable
from concurrent.futures.process import BrokenProcessPool
from datetime import datetime, timezone

import numpy as np
from threadpoolctl import threadpool_limits

import optbound
from optbound.bench import warmup
from optbound.bench.executors import check_available, ignore_interrupts
from optbound.bench.executors import executor as make_executor
from optbound.bench.family import SUITES, Family
from optbound.bench.progress import Progress
from optbound.bench.registry import families as registered_families
from optbound.bench.run_folder import RunFolder
from optbound.bench.target import processor_name
from optbound.report.results import SCHEMA


def run_suite(
    suite: str = "quick",
    seed: int = 0,
    jobs: int = 1,
    progress: bool = True,
    names: list[str] | None = None,
    executor: str = "process",
    scheduler: str | None = None,
    where: Callable[[dict], bool] | None = None,
    command: str | None = None,
    folder: RunFolder | None = None,
) -> dict:
    """Run every available family of ``suite`` and return the results dict.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run; ``tiny`` is the seconds-long smoke test used by the test suite.
    seed : int
        Suite seed; every instance seed is derived from it (and recorded).
    jobs : int
        Worker processes for the parallel tasks (1 runs them in this process).
    progress : bool
        Show per-family progress bars on stderr (:mod:`optbound.bench.progress`).
    names : list of str, optional
        Run only these registered families (default: all of them).
    executor : {"process", "dask"}
        Where parallel tasks run (:mod:`optbound.bench.executors`); the results are the same.
    scheduler : str, optional
        Address of a running Dask scheduler (implies ``executor="dask"``).
    where : callable, optional
        Run only the tasks for which ``where(task)`` is true (``optbound repro KEY`` selects
        papers this way); the run is then not complete.
    command : str, optional
        The command line that repeats this run, for the progress bar and the report
        (default ``optbound bench --suite SUITE --seed SEED``); recorded as ``meta["command"]``.
    folder : RunFolder, optional
        Store each finished task's result there, and take the tasks already stored there
        instead of running them (``meta["resumed_tasks"]`` counts them).

    Returns
    -------
    dict
        ``{"schema": SCHEMA, "meta": {...}, "families": {name: entry}}``: the run's
        provenance (command, seeds, versions, machine, wall time) and, per family, its status
        and the merged records, figures, notes, warnings and errors of its tasks.

    Raises
    ------
    ValueError
        For an unknown ``suite``, a negative ``seed``, ``jobs`` < 1, unknown family
        ``names``, or an executor that cannot run
        (:func:`~optbound.bench.executors.check_available`).
    """
    if suite not in SUITES:
        raise ValueError(f"suite must be one of {SUITES}, got {suite!r}")
    if seed < 0:
        raise ValueError(f"seed must be a non-negative integer, got {seed}")
    if jobs < 1:
        raise ValueError(f"jobs must be a positive integer, got {jobs}")
    check_available(executor, scheduler)  # before any work or progress bar
    command = command or f"optbound bench --suite {suite} --seed {seed}"
    start, started = time.perf_counter(), datetime.now(timezone.utc)
    fams = registered_families()
    if names:
        unknown = sorted(set(names) - {fam.name for fam in fams})
        if unknown:
            raise ValueError(
                f"names has unknown families {unknown}; known: {[f.name for f in fams]}"
            )
        fams = [fam for fam in fams if fam.name in names]
    out = {fam.name: _family_entry(fam) for fam in fams}
    runnable = [fam for fam in fams if out[fam.name]["status"] == "ok"]
    tasks = [
        (fam, i, task, float(fam.cost(task)))
        for fam in runnable
        for i, task in enumerate(fam.tasks(suite, seed))
        if where is None or where(task)
    ]
    costs = {fam.name: [t[3] for t in tasks if t[0] is fam] for fam in runnable}
    resumed = 0
    with Progress(command, costs, progress) as bar:

        def finish(fam: Family, index: int, task: dict, cost: float, result: dict) -> None:
            if folder is not None:
                folder.save(fam.name, index, task, result)
            _merge(out[fam.name], index, result)
            bar.done(fam.name, cost)

        todo = []
        for fam, i, task, cost in tasks:
            stored = folder.load(fam.name, i, task) if folder is not None else None
            if stored is None:
                todo.append((fam, i, task, cost))
            else:
                _merge(out[fam.name], i, stored)
                bar.done(fam.name, cost)
                resumed += 1
        # Longest first: a long task started last would leave the other workers idle at the end.
        pooled = sorted((t for t in todo if t[0].parallel), key=lambda t: -t[3])
        if pooled and executor == "process" and scheduler is None and where is None and not names:
            warmup.compile_cold(jobs)  # a cold cache: the big kernels, once, over the cores
        _run_pooled(pooled, finish, executor, jobs, scheduler)
        for fam, i, task, cost in (t for t in todo if not t[0].parallel):
            run = _run_alone if fam.isolated else _run_registered
            finish(fam, i, task, cost, run((fam.name, i, task))[2])
    for entry in out.values():
        _sort_by_task(entry)
    meta = {
        "command": command,
        "suite": suite,
        "seed": seed,
        "jobs": jobs,
        "executor": "dask" if scheduler else executor,
        "families_run": [fam.name for fam in fams],
        "complete": where is None
        and (not names or set(names) >= {f.name for f in registered_families()}),
        "started": started.isoformat(timespec="seconds"),
        "wall_time_s": time.perf_counter() - start,
        "resumed_tasks": resumed,
        "load_average": _load_average(),
        "cpus": os.cpu_count(),
        "optbound": optbound.__version__,
        "python": platform.python_version(),
        "numpy": np.__version__,
        "machine": f"{platform.system()} {platform.machine()}",
        "processor": processor_name(),
    }
    return {"schema": SCHEMA, "meta": meta, "families": out}


def _load_average() -> list[float] | None:
    """1-, 5- and 15-minute load averages (None where the OS has none)."""
    try:
        return [round(x, 2) for x in os.getloadavg()]
    except (AttributeError, OSError):
        return None


def _family_entry(fam: Family) -> dict:
    missing = fam.missing()
    return {
        "title": fam.title,
        "kind": fam.kind,
        "status": "skipped" if missing else "ok",
        "reason": f"needs {', '.join(missing)} (not available)" if missing else "",
        "records": [],
        "figures": [],
        "notes": [],
        "warnings": [],
        "errors": [],
        "task_seconds": [],
        "attachments": {},
    }


def _run_pooled(pooled: list, finish: Callable, executor: str, jobs: int, scheduler) -> None:
    """Run the ``(family, index, task, cost)`` items on the executor, ``finish``-ing each.

    A task whose future raises (a Dask worker lost, say) is a failed task. A dead worker
    breaks a process pool and fails every unfinished future with it: the tasks that had
    started (each marks its start in a temporary folder) are run again alone
    (:func:`_run_alone`), and the others go to a new pool.
    """
    with tempfile.TemporaryDirectory(prefix="optbound-started-") as marks:
        while pooled:
            left = {(item[0].name, item[1]): item for item in pooled}
            with make_executor(executor, jobs, scheduler) as pool:
                futures = {
                    pool.submit(_run_marked, (marks, fam.name, i, task), priority=cost): key
                    for key, (fam, i, task, cost) in left.items()
                }
                for future in pool.completed(futures):
                    item = left[futures[future]]
                    try:
                        result = future.result()[2]
                    except BrokenProcessPool:
                        break
                    except Exception as exc:
                        result = _failed(item[2], f"{type(exc).__name__}: {exc}", 0.0)
                    del left[futures[future]]
                    finish(*item, result)
            started = [k for k in left if os.path.exists(os.path.join(marks, _mark(*k)))]
            # A pool that broke before any task started (a worker that cannot start) would
            # break again: then every task left runs alone, so the run always progresses.
            for key in started or list(left):
                fam, i, task, cost = left.pop(key)
                finish(fam, i, task, cost, _run_alone((fam.name, i, task))[2])
            pooled = list(left.values())


def _mark(name: str, index: int) -> str:
    return f"{name}-{index}"


def _run_marked(item: tuple[str, str, int, dict]) -> tuple[str, int, dict]:
    """A pool worker's task: mark its start in the folder ``item[0]``, then run it.

    A remote Dask worker has no such folder; it needs no mark (only a process pool breaks).
    """
    marks, name, index, task = item
    try:
        with open(os.path.join(marks, _mark(name, index)), "w") as fh:
            fh.write(str(os.getpid()))
    except OSError:
        pass
    return _run_registered((name, index, task))


def _run_alone(item: tuple[str, int, dict]) -> tuple[str, int, dict]:
    """Run one task in a single-use child process, so its side effects die with it.

    A child that dies before returning its result (a signal, the out-of-memory killer, an
    ``os._exit``) makes the task a failed one, with the reason; the run goes on.
    """
    context = multiprocessing.get_context()
    receive, send = context.Pipe(duplex=False)
    child = context.Process(target=_child, args=(item, send), daemon=True)
    start = time.perf_counter()
    child.start()
    send.close()
    try:
        return receive.recv()
    except EOFError:  # the child died without sending
        child.join()
        seconds = time.perf_counter() - start
        return item[0], item[1], _failed(item[2], _death(child.exitcode), seconds)
    finally:
        if child.is_alive():  # interrupted while waiting: do not leave the child running
            child.terminate()
        child.join()
        receive.close()


def _child(item: tuple[str, int, dict], send) -> None:
    ignore_interrupts()
    send.send(_run_registered(item))
    send.close()


def _death(exitcode: int | None) -> str:
    """Why a worker process ended without a result, from its exit code."""
    if exitcode is not None and exitcode < 0:
        name = signal.Signals(-exitcode).name
        return (
            f"WorkerDied: the process running this task was killed by {name} (the "
            "out-of-memory killer, a user or the system ended it)"
        )
    return f"WorkerDied: the process running this task exited with code {exitcode}"


def _failed(task: dict, reason: str, seconds: float) -> dict:
    return {"errors": [{"task": task, "error": reason}], "seconds": seconds}


def _run_registered(item: tuple[str, int, dict]) -> tuple[str, int, dict]:
    name, index, task = item
    fam = {f.name: f for f in registered_families()}[name]
    return name, index, _run_task(fam, task)


_BLAS_LIMITED_IN: int | None = None  # pid of the process whose BLAS was limited


def _single_threaded_blas() -> None:
    """Limit the BLAS/LAPACK libraries of this process to one thread (once per process).

    Tasks are the unit of parallelism (one per core). A threaded OpenBLAS on top of that
    oversubscribes the cores, and its small-matrix calls then wait for a worker thread's time
    slice: a 2x2 ``scipy.linalg.solve_triangular`` took ~8 ms instead of ~10 µs in a busy
    worker. threadpoolctl finds the loaded BLAS libraries (numpy's and scipy's) and sets them.
    """
    global _BLAS_LIMITED_IN
    if _BLAS_LIMITED_IN != os.getpid():
        threadpool_limits(1)
        _BLAS_LIMITED_IN = os.getpid()


def _run_task(fam: Family, task: dict) -> dict:
    """Run one task; an exception becomes an error entry (with the task) instead of a crash.

    Warnings raised by the code under test are collected for the report rather than printed
    over the progress bar. BLAS runs single-threaded (``_single_threaded_blas``).
    """
    _single_threaded_blas()
    start = time.perf_counter()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            result = fam.run(task)
        except Exception as exc:  # a failing instance is a finding to report, not a reason to stop
            result = {"errors": [{"task": task, "error": f"{type(exc).__name__}: {exc}"}]}
    seen = {f"{w.category.__name__}: {str(w.message).strip().splitlines()[0]}" for w in caught}
    return {**result, "warnings": sorted(seen), "seconds": time.perf_counter() - start}


def _merge(entry: dict, index: int, result: dict) -> None:
    for key in ("records", "figures", "errors"):
        entry[key].extend({**item, "task_index": index} for item in result.get(key, []))
    for key in ("notes", "warnings"):
        entry[key].extend(n for n in result.get(key, []) if n not in entry[key])
    entry["attachments"].update(result.get("attachments", {}))
    entry["task_seconds"].append([index, round(result["seconds"], 4)])


def _sort_by_task(entry: dict) -> None:
    # Pool results arrive in completion order; sort so that results.json is reproducible.
    for key in ("records", "figures", "errors"):
        entry[key].sort(key=lambda item: item["task_index"])
    entry["task_seconds"].sort()
