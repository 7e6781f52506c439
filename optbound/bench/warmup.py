"""Compile the suite's kernels once, spread over the worker processes, before any task.

With an empty numba cache (the first run after an install, or after a kernel source changed),
the tasks' first calls compile the kernels. Tasks start two at a time on two workers, and the
first tasks of the suite mostly need the same kernels (the strip and Minkowski updates and the
SDP references' helpers), so each worker compiled them at the same moment: the same minutes of
CPU spent twice, and the serial families after the pool compiled theirs on one core.

Here the kernels the quick suite uses are split into disjoint groups, each compiled by a few
calls on one small instance; when numba's cache lacks them, the groups run on a pool of their
own (longest first) before the suite's tasks start. The small kernels every group calls (the
domain check behind every ``Ellipsoid``) are compiled first, once, in the parent: the workers
inherit them (forked) or load them from the cache, instead of each compiling its own copy.
Kernels shared by two groups' calls are in one group (the strip and Minkowski updates share
their lane helpers, the speed baseline their p solver), so no kernel is compiled by two
processes. Each group writes numba's on-disk cache, so every process after it (the task
workers, the parent running the serial families) loads its kernels instead of compiling them.
A group whose probe kernels are all cached is skipped, so a warm run starts no pool. The
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


def _shared() -> None:
    """The domain check (``_core.domain.check_ellipsoid``) behind every group's ellipsoids."""
    _ellipsoids()


def _analytic() -> None:
    """``analytic.minkowski_sum`` (every criterion the suite uses), ``intersect_strip``, their
    batch forms and the speed benchmark's compiled baseline
    (``optbound.bench.analytic_reference``): one group, since the two kernels share their lane
    and cubic helpers and the baseline calls the Minkowski kernel's p solver and the lanes'
    Cholesky factors (in a process of its own it would compile them again: 12 s, not 3 s)."""
    from optbound import Strip, analytic
    from optbound.bench import analytic_reference as ref

    E1, E2 = _ellipsoids()
    for criterion in ("volume", "trace"):
        analytic.minkowski_sum(E1, E2, criterion=criterion)
    analytic.minkowski_sum(E1, E2, criterion="size_xy_psi", dims=([0, 1], [2]))
    analytic.minkowski_sum_batch(*_batch(), *_batch())
    analytic.intersect_strip(E1, Strip([1.0, 0.0, 0.0], 0.5))
    analytic.intersect_strip(E1, Strip([1.0, 0.0, 0.0], 0.5), criterion="projection", dims=(0, 1))
    analytic.intersect_strip_batch(*_batch(), [1.0, 0.0, 0.0], 0.5)
    c, C = _batch()
    a, b = np.array([[1.0, 0.0, 0.0]]), np.array([0.5])
    ref.strip_batch(c, C, a, b)
    ref.minkowski_batch(c, C, c, C)
    oc, oC = np.empty((1, 3)), np.empty((1, 3, 3))
    ref.strip_range(c, C, a, b, oc, oC, 0, 1)
    ref.minkowski_range(c, C, c, C, oc, oC, 0, 1)


def _localization() -> None:
    """The localization models' kernels: polygon and visibility predicates and the team
    sweep of the tracker [GLH12], the landmark solve [HS96], the affine map's inflation, a
    strip's quadratic form."""
    from optbound import QuadraticSet
    from optbound.analytic.affine import affine_map
    from optbound.localization import landmarks, visibility
    from optbound.localization.environment import Environment

    E1, _ = _ellipsoids()
    affine_map(E1, np.eye(3))
    QuadraticSet.from_bounds(np.array([1.0, 0.0, 0.0]), -1.0, 1.0)
    landmarks.linear_position([[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]], [0.1, 1.2, 2.3])
    square = np.array([[2.0, -1.0], [3.0, -1.0], [3.0, 1.0], [2.0, 1.0]])
    env = Environment.from_polygons([square], 0.1)
    boxes = np.array([[[0.0, 1.0], [-0.5, 0.5]], [[4.0, 5.0], [-0.5, 0.5]]])
    visibility.visibility_test(boxes[:1], boxes[1:], env.outer)
    visibility.luvia(0, [False, False], boxes, env, 0.5)
    y = visibility.measure(boxes.mean(axis=-1), env.exact)
    visibility.track(boxes, [0.9, 1.1], [[0.0, 0.0]], 0.01, y[None], env, 0.5)


def _sonar() -> None:
    """The sonar belt's compiled q-relaxed test [LJMW97], [KJWM00]."""
    from optbound.interval import Interval
    from optbound.localization import sonar

    world = np.array([[[0.0, 0.0], [4.0, 0.0]], [[4.0, 0.0], [4.0, 4.0]], [[4.0, 4.0], [0.0, 0.0]]])
    belt = [sonar.Sonar((0.0, 0.0), angle, 0.2, 0.05) for angle in (0.0, 2.0)]
    tests = sonar.sonar_tests(world, belt, [1.0, 1.5])
    box = [Interval(np.array([lo]), np.array([lo + 0.1])) for lo in (1.0, 1.0, 0.3)]
    tests.fused(1)(*box)


def _optimal() -> None:
    """The certified SDP references' compiled helpers (``optimal._small``, ``lower``,
    ``khachiyan``): an intersection, a Minkowski sum and a point set's MVEE."""
    from optbound import Strip, optimal

    E1, E2 = _ellipsoids()
    # Two strips: the extents solve that clips their ranges runs only for two rows or more.
    strips = [Strip([1.0, 0.0, 0.0], 0.5), Strip([0.0, 1.0, 0.0], 0.5)]
    optimal.outer_ellipsoid([E1, *strips], lower_bound=True)
    optimal.minkowski_outer(E1, E2)
    optimal.mvee(np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.5]]))


#: name -> (compile CPU seconds, roughly: the order they are submitted in; the group's calls;
#: ``"module:kernel"`` names of kernels of the group (one per source file it compiles most
#: of) whose presence in numba's cache means the group is compiled).
GROUPS: dict[str, tuple[float, Callable[[], None], tuple[str, ...]]] = {
    "analytic": (
        24.0,
        _analytic,
        (
            "optbound.analytic._kernels.minkowski_kernel:sum_blocks",
            "optbound.analytic._kernels.strip_kernel:fuse_range",
            "optbound.bench.analytic_reference:minkowski_blocks",
        ),
    ),
    "optimal": (13.0, _optimal, ("optbound.optimal.khachiyan:_iterate",)),
    "localization": (
        9.0,
        _localization,
        (
            "optbound.localization.visibility:_luvia_kernel",
            "optbound.localization.geometry.polygons:_segments_meet_polygons",
            "optbound.localization.landmarks:_solve",
        ),
    ),
    "sonar": (4.0, _sonar, ("optbound.localization._sonar_kernel:_relaxed",)),
}
#: Calls run in the parent, before the groups, when any group is cold: kernels several
#: groups would otherwise each compile.
SHARED: Callable[[], None] = _shared


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
        Names of :data:`GROUPS` with a probe kernel that is not cached (:func:`is_cached`).
    """
    cold = [name for name, (_, _, probes) in GROUPS.items() if not all(map(_cached, probes))]
    return sorted(cold, key=lambda name: -GROUPS[name][0])


def _cached(probe: str) -> bool:
    module, _, kernel = probe.partition(":")
    return is_cached(getattr(importlib.import_module(module), kernel))


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

    :data:`SHARED` runs first, here, then the groups, longest first, and all of them are
    waited for. With ``jobs == 1`` or a warm cache, nothing runs: one process compiles each
    kernel once anyway, on first use.

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
    try:
        SHARED()
    except Exception:  # never stops the run: whoever needs the kernels compiles them
        pass
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
