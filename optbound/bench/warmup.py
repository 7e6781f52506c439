"""Compile the suite's largest kernels once, spread over the worker processes, before any task.

With an empty numba cache (the first run after an install, or after a kernel source changed),
the tasks' first calls compile the kernels. Tasks start two at a time on two workers, and the
first tasks of the suite mostly need the same kernels (the strip and Minkowski updates and the
SDP references' helpers), so each worker compiled them at the same moment: the same minutes of
CPU spent twice, and the serial families after the pool compiled theirs on one core.

Here the kernels are split into disjoint groups, each compiled by a few calls on one small
instance; when numba's cache lacks them, the groups run on a pool of their own (longest
first) before the suite's tasks start. Each group writes numba's on-disk cache, so every
process after it (the task workers, the parent running the serial families) loads its kernels
instead of compiling them. Kernels no group covers still compile on first use, as before. A
group whose probe kernel is already cached is skipped, so a warm run starts no pool. The
calls' results are discarded: only which machine code exists changes, never what a task
computes.
"""

from __future__ import annotations

import importlib
import time
from collections.abc import Callable

import numpy as np

from optbound.bench.executors import executor


def _ellipsoids():
    from optbound import Ellipsoid

    E1 = Ellipsoid(np.zeros(3), np.diag([1.0, 2.0, 3.0]))
    E2 = Ellipsoid(np.ones(3), np.diag([2.0, 1.0, 0.5]))
    return E1, E2


def _batch(n_batch: int = 1, n: int = 3) -> tuple:
    return np.zeros((n_batch, n)), np.repeat(np.eye(n)[None], n_batch, axis=0)


def _minkowski() -> None:
    """``analytic.minkowski_sum`` (every criterion the suite uses) and its batch form."""
    from optbound import analytic

    E1, E2 = _ellipsoids()
    for criterion in ("volume", "trace"):
        analytic.minkowski_sum(E1, E2, criterion=criterion)
    analytic.minkowski_sum(E1, E2, criterion="size_xy_psi", dims=([0, 1], [2]))
    analytic.minkowski_sum_batch(*_batch(), *_batch())


def _strip() -> None:
    """``analytic.intersect_strip`` and its batch form (one compiled entry point for all)."""
    from optbound import Strip, analytic

    E1, _ = _ellipsoids()
    analytic.intersect_strip(E1, Strip([1.0, 0.0, 0.0], 0.5))
    analytic.intersect_strip_batch(*_batch(), [1.0, 0.0, 0.0], 0.5)


def _optimal() -> None:
    """The certified SDP references' compiled helpers (``optimal._small``, ``lower``,
    ``khachiyan``): an intersection, a Minkowski sum and a point set's MVEE."""
    from optbound import Strip, optimal

    E1, E2 = _ellipsoids()
    optimal.outer_ellipsoid([E1, Strip([1.0, 0.0, 0.0], 0.5)], lower_bound=True)
    optimal.minkowski_outer(E1, E2)
    optimal.mvee(np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.5]]))


def _reference() -> None:
    """The speed benchmark's compiled baseline (``optbound.bench.analytic_reference``)."""
    from optbound.bench import analytic_reference as ref

    c, C = _batch()
    a, b = np.array([[1.0, 0.0, 0.0]]), np.array([0.5])
    ref.strip_batch(c, C, a, b)
    ref.minkowski_batch(c, C, c, C)
    oc, oC = np.empty((1, 3)), np.empty((1, 3, 3))
    ref.strip_range(c, C, a, b, oc, oC, 0, 1)
    ref.minkowski_range(c, C, c, C, oc, oC, 0, 1)


#: name -> (compile CPU seconds, roughly: the order they are submitted in; the group's calls;
#: ``"module:kernel"``, a kernel of the group whose presence in numba's cache means the group
#: is compiled).
GROUPS: dict[str, tuple[float, Callable[[], None], str]] = {
    "minkowski": (30.0, _minkowski, "optbound.analytic._kernels.minkowski_kernel:sum_blocks"),
    "optimal": (22.0, _optimal, "optbound.optimal.khachiyan:_iterate"),
    "strip": (20.0, _strip, "optbound.analytic._kernels.strip_kernel:fuse_range"),
    "reference": (6.0, _reference, "optbound.bench.analytic_reference:minkowski_blocks"),
}


def is_cached(dispatcher) -> bool:
    """Tell whether numba's on-disk cache holds a current compiled version of ``dispatcher``.

    Current means: for its source file as it is now. Anything unexpected (no cache, another
    numba's internals) counts as cached, so that the run goes on exactly as without a warm-up.

    Parameters
    ----------
    dispatcher : numba.core.registry.CPUDispatcher
        A kernel compiled with ``cache=True``.

    Returns
    -------
    bool
        False only when the cache is known to lack the kernel.
    """
    try:
        return bool(dispatcher._cache._cache_file._load_index())
    except Exception:
        return True


def cold_groups() -> list[str]:
    """List the groups whose kernels are not in numba's cache, longest first.

    Returns
    -------
    list of str
        Names of :data:`GROUPS` whose probe kernel is not cached (:func:`is_cached`).
    """
    cold = []
    for name, (_, _, probe) in GROUPS.items():
        module, _, kernel = probe.partition(":")
        if not is_cached(getattr(importlib.import_module(module), kernel)):
            cold.append(name)
    return sorted(cold, key=lambda name: -GROUPS[name][0])


def compile_group(name: str) -> tuple[str, float | str]:
    """Run group ``name``'s calls (in a worker), which compiles its kernels.

    A warm-up never stops the run: the error of a failed call is returned, and the task that
    needs the kernel then compiles it, and reports its own errors.

    Parameters
    ----------
    name : str
        A key of :data:`GROUPS`.

    Returns
    -------
    name : str
        The group's name.
    outcome : float or str
        CPU seconds of its calls, or ``"ErrorType: message"`` of the call that failed.
    """
    start = time.process_time()
    try:
        GROUPS[name][1]()
    except Exception as exc:
        return name, f"{type(exc).__name__}: {exc}"
    return name, time.process_time() - start


def compile_cold(jobs: int) -> dict[str, float | str]:
    """Compile the groups missing from numba's cache on a pool of ``jobs`` processes.

    The groups run longest first, and all of them are waited for. With ``jobs == 1`` or a
    warm cache, nothing runs: one process compiles each kernel once anyway, on first use.

    Parameters
    ----------
    jobs : int
        Worker processes of the suite (the pool takes at most one per cold group).

    Returns
    -------
    dict
        Group name -> what :func:`compile_group` returned for it: CPU seconds or an error
        (a worker lost on the way is reported the same way); empty when nothing ran.
    """
    names = cold_groups() if jobs > 1 else []
    if not names:
        return {}
    done: dict[str, float | str] = {}
    with executor("process", min(jobs, len(names))) as pool:
        futures = {
            pool.submit(compile_group, name, priority=GROUPS[name][0]): name for name in names
        }
        for future in pool.completed(futures):
            try:
                done.update([future.result()])
            except Exception as exc:  # a broken pool: the tasks compile what is missing
                done[futures[future]] = f"{type(exc).__name__}: {exc}"
    return done
