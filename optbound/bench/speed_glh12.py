"""Speed of GLH12 visibility tracking: the compiled test and LUVIA against plain references.

Every ratio is taken between two timings of the same run on the same machine:

- ``visibility_test`` (compiled, three-valued, all obstacles) against the sign of eq. (19)
  alone evaluated with ``optbound.interval.Interval`` arrays on the same box pairs and edges
  (the reference does strictly less work: no inside/touching logic);
- ``luvia`` (compiled, one depth-first pass per hull side) against Algorithm 2 as written,
  breadth-first over every sub-box with one vectorized ``visibility_test`` call per level;
- one 1500-iteration run with 7 robots and 6 obstacles (the issue's budget: 20 s on one core),
  in CPU seconds of this process (the machine is shared: CPU time, not wall time).

Standalone: ``python -m optbound.bench.speed_glh12 [--suite tiny|quick|full]`` prints a Markdown
table. In ``optbound bench`` it is the serial family ``speed_glh12`` (one task).

Sampling (:func:`optbound.bench.timing.per_call`, the best of batches of back-to-back calls):
full suite 3 batches of >= 50 ms per timing; quick and tiny suites 2 batches of >= 20 ms
(Algorithm 2's reference takes ~0.1-0.3 s a call: a batch is one call, and the call that
checks its hulls against LUVIA's is its first batch). The tracking run is
simulated and tracked once: its last boxes are LUVIA's input when the run is at most 300
steps long (the quick and tiny suites), as the separate run of 300 steps would give.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from optbound.bench.family import Family
from optbound.bench.timing import batch_times, per_call, speed_record
from optbound.interval import Interval, Tri
from optbound.localization.geometry import intersect
from optbound.localization.visibility import luvia, track, visibility_test
from optbound.problems.generators import task_seeds
from optbound.scenarios import arena

NAME = "speed_glh12"
BUDGET_SECONDS = 20.0
LUVIA_STEPS = 300  # LUVIA is timed on the boxes after this many steps (or the run's, if shorter)
SIZES = {
    "tiny": {"pairs": 500, "steps": 100, "repeat": 2, "min_time": 0.02},
    "quick": {"pairs": 2000, "steps": 300, "repeat": 2, "min_time": 0.02},
    "full": {"pairs": 20000, "steps": 1500, "repeat": 3, "min_time": 0.05},
}


def _interval_signs(boxes1, boxes2, polygons) -> np.ndarray:
    """Reference: Tri sign ``intersect < 0`` of every (pair, edge) on ``Interval`` arrays."""
    a = np.concatenate(polygons)
    b = np.concatenate([np.roll(p, -1, axis=0) for p in polygons])

    def point(bx):
        return (
            Interval(bx[:, None, 0, 0], bx[:, None, 0, 1]),
            Interval(bx[:, None, 1, 0], bx[:, None, 1, 1]),
        )

    return intersect(point(boxes1), point(boxes2), (a[:, 0], a[:, 1]), (b[:, 0], b[:, 1])) < 0


def _algorithm2(i, y, boxes, env, eps, max_depth=10):
    """Reference: [GLH12, Algorithm 2] breadth-first, every sub-box bisected down to eps."""
    cur, kept = boxes[i][None], []
    others = np.array([j for j in range(len(boxes)) if j != i])
    for depth in range(max_depth + 1):
        k, o = np.repeat(np.arange(len(cur)), len(others)), np.tile(others, len(cur))
        result = np.empty(len(k), dtype=np.int8)
        seen = y[o]
        result[seen] = visibility_test(cur[k[seen]], boxes[o[seen]], env.inner)
        result[~seen] = visibility_test(cur[k[~seen]], boxes[o[~seen]], env.outer)
        refuted = np.zeros(len(cur), dtype=bool)
        refuted[k[np.where(seen, result == Tri.FALSE, result == Tri.TRUE)]] = True
        unknown = np.zeros(len(cur), dtype=bool)
        unknown[k[result == Tri.UNKNOWN]] = True
        size = np.prod(np.diff(cur)[:, :, 0], axis=1)
        split = ~refuted & unknown & (size > eps) & (depth < max_depth)
        kept.append(cur[~refuted & ~split])
        if not split.any():
            break
        cur = cur[split]
        axis = np.argmax(np.diff(cur)[:, :, 0], axis=1)
        rows = np.arange(len(cur))
        mid = 0.5 * (cur[rows, axis, 0] + cur[rows, axis, 1])
        low, high = cur.copy(), cur.copy()
        low[rows, axis, 1] = mid
        high[rows, axis, 0] = mid
        cur = np.concatenate([low, high])
    kept = np.concatenate(kept)
    return np.stack([kept[:, :, 0].min(0), kept[:, :, 1].max(0)], 1) if len(kept) else None


def bench_visibility(
    pairs: int, seed: int = 0, repeat: int = 3, min_time: float = 0.05
) -> list[dict]:
    """Time the compiled visibility test against the eq. (19) signs on ``Interval`` arrays.

    The reference does a subset of the work (signs alone), so the recorded ratio is a time
    ratio (ours / reference), not a speed-up.

    Parameters
    ----------
    pairs : int
        Number of random box pairs, tested against 6 obstacles.
    seed : int
        Seed of the boxes.
    repeat, min_time
        Sampling of each timing (:func:`optbound.bench.timing.per_call`).

    Returns
    -------
    list of dict
        The reference's speed record, then ours with the time ratio.
    """
    rng = np.random.default_rng(seed)
    env = arena.environment(6)
    lo1, lo2 = rng.uniform(0, 9, (pairs, 2)), rng.uniform(0, 9, (pairs, 2))
    b1 = np.stack([lo1, lo1 + rng.uniform(0.1, 1.0, (pairs, 2))], -1)
    b2 = np.stack([lo2, lo2 + rng.uniform(0.1, 1.0, (pairs, 2))], -1)
    ours = per_call(lambda: visibility_test(b1, b2, env.outer), repeat, min_time)
    ref = per_call(lambda: _interval_signs(b1, b2, env.outer), repeat, min_time)
    label = f"{pairs} box pairs x 6 obstacles (E⁺)"
    # The reference does a subset of the work, so this ratio is a time ratio (ours / ref),
    # not a speed-up: it says what the inside/touching logic and all obstacles cost on top.
    return [
        speed_record(NAME, f"eq. (19) signs on Interval arrays, {label}", ref),
        speed_record(
            NAME,
            f"visibility_test (compiled, three-valued), {label}",
            ours,
            ratio=ours / ref,
            ratio_label="time / eq. (19) signs alone on Interval arrays (less work)",
        ),
    ]


def _versus(reference: tuple[str, float], ours: tuple[str, float], ratio_label: str):
    """The reference's record, then ours with the ratio of the two times."""
    return [
        speed_record(NAME, *reference),
        speed_record(NAME, *ours, ratio=reference[1] / ours[1], ratio_label=ratio_label),
    ]


def tracked_run(steps: int, seed: int = 0) -> tuple:
    """Simulate a tracking run (7 robots, 6 obstacles) and track it, timing the tracking.

    Parameters
    ----------
    steps : int
        Tracking iterations.
    seed : int
        Seed of the simulated run.

    Returns
    -------
    run : arena run
        The simulated run (``arena.simulate``).
    boxes : numpy.ndarray
        The robots' boxes after the last step.
    cpu : float
        CPU seconds of this process for the tracking (compiled beforehand on two steps).
    """
    run = arena.simulate(7, 6, steps, seed)
    track(
        run.boxes0,
        run.distance,
        run.headings[:2],
        arena.HEADING_ERROR,
        run.visibility[:2],
        run.env,
        0.01,
    )  # fmt: skip  (compile outside the timing)
    cpu = time.process_time()
    boxes = track(run.boxes0, run.distance, run.headings, arena.HEADING_ERROR, run.visibility,
                  run.env, 0.01)  # fmt: skip
    cpu = time.process_time() - cpu
    return run, boxes[-1], cpu


def bench_luvia(
    steps: int, seed: int = 0, repeat: int = 3, min_time: float = 0.05, tracked=None
) -> list[dict]:
    """Time LUVIA against breadth-first [GLH12, Algorithm 2] on the boxes of a 7-robot run.

    The two are checked to give the same hulls before being timed.

    Parameters
    ----------
    steps : int
        The boxes are those after ``steps`` tracking steps.
    seed : int
        Seed of the simulated run.
    repeat, min_time
        Sampling of each timing (:func:`optbound.bench.timing.per_call`).
    tracked : tuple, optional
        :func:`tracked_run` ``(steps, seed)``'s result, if already computed.

    Returns
    -------
    list of dict
        The reference's speed record, then ours with the speed-up.
    """
    run, boxes, _ = tracked or tracked_run(steps, seed)
    y = run.visibility[-1]

    def reference() -> list:
        return [_algorithm2(i, y[i], boxes, run.env, 0.01) for i in range(7)]

    start = time.perf_counter()
    hulls = reference()  # a call of >= min_time is also the reference's first timing sample
    first = time.perf_counter() - start
    for i, b in enumerate(hulls):  # the two must agree before being timed
        a = luvia(i, y[i], boxes, run.env, 0.01)
        assert (a is None and b is None) or np.array_equal(a, b)
    ours = per_call(
        lambda: [luvia(i, y[i], boxes, run.env, 0.01) for i in range(7)], repeat, min_time
    )
    if first < min_time:
        ref = per_call(reference, repeat, min_time)
    else:
        ref = min([first, *(batch_times(reference, repeat - 1, min_time) if repeat > 1 else [])])
    area = float(np.prod(np.diff(boxes), axis=(1, 2)).mean())
    label = f"7 robots, mean box {area:.2f} m², eps 0.01"
    return _versus(
        (f"Algorithm 2 breadth-first (numpy), {label}", ref),
        (f"luvia (compiled hull search), {label}", ours),
        "faster than breadth-first Algorithm 2 (same hull)",
    )


def bench_run(steps: int, seed: int = 0, tracked=None) -> list[dict]:
    """Time one tracking run (7 robots, 6 obstacles) against the 20 s budget.

    Parameters
    ----------
    steps : int
        Tracking iterations.
    seed : int
        Seed of the simulated run.
    tracked : tuple, optional
        :func:`tracked_run` ``(steps, seed)``'s result, if already computed.

    Returns
    -------
    list of dict
        One speed record: the CPU seconds, with the ratio to the budget scaled to ``steps``.
    """
    _, _, cpu = tracked or tracked_run(steps, seed)
    return [
        speed_record(
            NAME,
            f"track: {steps} iterations, 7 robots, 6 obstacles (CPU s)",
            cpu,
            ratio=BUDGET_SECONDS * steps / 1500 / cpu,
            ratio_label=f"under the budget ({BUDGET_SECONDS:.0f} s per 1500 iterations)",
        )
    ]


def bench(suite: str = "quick", seed: int = 0) -> list[dict]:
    """Run every GLH12 timing of one suite.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run (:data:`SIZES`).
    seed : int
        Seed of the instances.

    Returns
    -------
    list of dict
        The records of :func:`bench_visibility`, :func:`bench_luvia` and :func:`bench_run`.
    """
    size = SIZES[suite]
    sampling = {"repeat": size["repeat"], "min_time": size["min_time"]}
    tracked = tracked_run(size["steps"], seed)
    luvia_steps = min(LUVIA_STEPS, size["steps"])
    shared = tracked if luvia_steps == size["steps"] else None
    return (
        bench_visibility(size["pairs"], seed, **sampling)
        + bench_luvia(luvia_steps, seed, **sampling, tracked=shared)
        + bench_run(size["steps"], seed, tracked)
    )


def tasks(suite: str, seed: int) -> list[dict]:
    """Build the single task of ``suite``: every GLH12 timing.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run.
    seed : int
        Suite seed; the task's seed is derived from it.

    Returns
    -------
    list of dict
        One JSON-able task, with its ``"seed"`` and ``"suite"``.
    """
    return [{"seed": task_seeds(seed, NAME, 1)[0], "suite": suite}]


def run(task: dict) -> dict:
    """Run the task's suite of GLH12 timings (:func:`bench`).

    Parameters
    ----------
    task : dict
        The task of :func:`tasks`.

    Returns
    -------
    dict
        ``{"records": [...]}``.
    """
    return {"records": bench(task["suite"], task["seed"])}


def cost(task: dict) -> float:
    """Estimate the seconds of the task, by suite.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    float
        Estimated seconds on one core.
    """
    return {"tiny": 2.0, "quick": 6.0, "full": 40.0}[task["suite"]]


FAMILY = Family(
    name=NAME,
    title="Speed: GLH12 visibility tracking (visibility test, LUVIA, one run)",
    kind="speed",
    requires=("optbound.localization.visibility:luvia",),
    tasks=tasks,
    run=run,
    parallel=False,
    cost=cost,
)


def markdown(records: list[dict]) -> str:
    """Format speed records as a Markdown table.

    Parameters
    ----------
    records : list of dict
        Speed records (:func:`optbound.bench.timing.speed_record`).

    Returns
    -------
    str
        One row per record: its name, seconds and ratio (or "reference").
    """
    lines = ["| measurement | seconds | ratio |", "|---|---|---|"]
    for r in records:
        ratio = f"{r['ratio']:.1f}x {r['ratio_label']}" if "ratio" in r else "reference"
        lines.append(f"| {r['name']} | {r['value']:.4g} | {ratio} |")
    return "\n".join(lines)


def main() -> list[dict]:
    """Run :func:`bench` from the command line (``--suite``, ``--seed``) and print the table.

    Returns
    -------
    list of dict
        The records printed.
    """
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--suite", choices=sorted(SIZES), default="quick")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    records = bench(args.suite, args.seed)
    print(markdown(records))
    return records


if __name__ == "__main__":
    main()
