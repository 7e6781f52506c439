"""Run a suite: spread the families' tasks over worker processes and collect one results dict.

The results dict is everything the report needs (``optbound report DIR`` rebuilds the report
from its JSON alone)::

    {"schema": 1,
     "meta": {"suite", "seed", "jobs", "wall_time_s", "started", versions...},
     "families": {name: {"title", "kind", "status", "reason",
                         "records", "figures", "notes", "warnings", "errors"}}}
"""

from __future__ import annotations

import multiprocessing
import platform
import time
import warnings
from datetime import datetime, timezone

import numpy as np
from tqdm import tqdm

import optbound
from benchmarks.family import SUITES, Family
from benchmarks.registry import families as registered_families
from optbound.report.results import SCHEMA


def run_suite(
    suite: str = "quick",
    seed: int = 0,
    jobs: int = 1,
    progress: bool = True,
    names: list[str] | None = None,
) -> dict:
    """Run every available family of ``suite`` and return the results dict.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run; ``tiny`` is the seconds-long smoke test used by the test suite.
    seed : int
        Suite seed; every instance seed is derived from it (and recorded).
    jobs : int
        Worker processes for the tightness tasks (1 runs them in this process).
    progress : bool
        Show a tqdm progress bar on stderr.
    names : list of str, optional
        Run only these registered families (default: all of them).
    """
    if suite not in SUITES:
        raise ValueError(f"suite must be one of {SUITES}, got {suite!r}")
    if seed < 0:
        raise ValueError(f"seed must be a non-negative integer, got {seed}")
    if jobs < 1:
        raise ValueError(f"jobs must be a positive integer, got {jobs}")
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
    tasks = [(fam, i, task) for fam in runnable for i, task in enumerate(fam.tasks(suite, seed))]
    pooled = [(fam.name, i, task) for fam, i, task in tasks if fam.parallel]
    serial = [(fam.name, i, task) for fam, i, task in tasks if not fam.parallel]
    isolated = {fam.name for fam in fams if fam.isolated}
    with tqdm(total=len(tasks), desc=f"optbound bench {suite}", disable=not progress) as bar:
        for name, index, result in _run_pooled(pooled, jobs):
            _merge(out[name], index, result)
            bar.update()
        for name, index, task in serial:
            run = _run_isolated if name in isolated else _run_registered
            _merge(out[name], index, run((name, index, task))[2])
            bar.update()
    for entry in out.values():
        _sort_by_task(entry)
    meta = {
        "suite": suite,
        "seed": seed,
        "jobs": jobs,
        "started": started.isoformat(timespec="seconds"),
        "wall_time_s": time.perf_counter() - start,
        "optbound": optbound.__version__,
        "python": platform.python_version(),
        "numpy": np.__version__,
        "machine": f"{platform.system()} {platform.machine()}",
    }
    return {"schema": SCHEMA, "meta": meta, "families": out}


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
    }


def _run_pooled(pooled: list[tuple[str, int, dict]], jobs: int):
    """Yield ``(name, index, result)`` as tasks finish, from a process pool when ``jobs > 1``."""
    if jobs == 1 or len(pooled) < 2:
        yield from map(_run_registered, pooled)
        return
    with multiprocessing.get_context().Pool(jobs) as pool:
        yield from pool.imap_unordered(_run_registered, pooled)


def _run_isolated(item: tuple[str, int, dict]) -> tuple[str, int, dict]:
    """Run one task in a single-use child process, so its side effects die with it."""
    with multiprocessing.get_context().Pool(1) as pool:
        return pool.apply(_run_registered, (item,))


def _run_registered(item: tuple[str, int, dict]) -> tuple[str, int, dict]:
    name, index, task = item
    fam = {f.name: f for f in registered_families()}[name]
    return name, index, _run_task(fam, task)


def _run_task(fam: Family, task: dict) -> dict:
    """Run one task; an exception becomes an error entry (with the task) instead of a crash.

    Warnings raised by the code under test are collected for the report rather than printed
    over the progress bar.
    """
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            result = fam.run(task)
        except Exception as exc:  # a failing instance is a finding to report, not a reason to stop
            result = {"errors": [{"task": task, "error": f"{type(exc).__name__}: {exc}"}]}
    seen = {f"{w.category.__name__}: {str(w.message).strip().splitlines()[0]}" for w in caught}
    return {**result, "warnings": sorted(seen)}


def _merge(entry: dict, index: int, result: dict) -> None:
    for key in ("records", "figures", "errors"):
        entry[key].extend({**item, "task_index": index} for item in result.get(key, []))
    for key in ("notes", "warnings"):
        entry[key].extend(n for n in result.get(key, []) if n not in entry[key])


def _sort_by_task(entry: dict) -> None:
    # Pool results arrive in completion order; sort so that results.json is reproducible.
    for key in ("records", "figures", "errors"):
        entry[key].sort(key=lambda item: item["task_index"])
