"""Speed of the HS96 localization model against its targets (issue 10), as a plain table.

Rows (median over repeats; every ratio is between two timings of this run):

- ``linear_position`` for N = 10 (target <= 50 us), against one ``numpy.linalg.lstsq`` of the
  same-sized (9 x 2) system (reference);
- ``associate`` with N = 8 bearings (one false) among the 22 office landmarks from a coarse
  prior (target <= 100 ms), median over course positions, with tree nodes expanded;
- the tracker at 20 scans/s x 22 landmarks, walls removed so that all 22 are seen (target
  >= 10x real time), per criterion, against the bare ``analytic.intersect_strip`` +
  ``minkowski_sum`` calls it makes (reference: the tracker's own overhead is the difference);
- the office reproduction, quick variant (target <= ~20 s) and, with ``--full``, the full
  10-lap run (target <= 2 min on 2 cores).

Run: ``python -m optbound.bench.speed_hs96 [--full]``. As the family ``speed_hs96`` of
``optbound bench`` (one task per part, run serially): tiny times ``linear_position`` and
``associate``; quick adds the tracker on 10 scans; full the tracker on 40 scans and both
office reproductions. Every part returns :func:`optbound.bench.timing.speed_record` s whose
``ratio`` is reference time / ours (or target / ours where the target is the reference).

Sampling: each per-call time is the median over batches of back-to-back calls
(:func:`optbound.bench.timing.median_per_call`). Full suite: ``linear_position`` and lstsq 7
batches of >= 50 ms each, the tracker's bare calls 7 of >= 50 ms, the tracker runs 3 of one
run each. Quick (and tiny) suite: 5 batches of >= 20 ms for ``linear_position`` and lstsq,
3 of >= 20 ms for the bare calls (a microsecond call still averages over thousands of calls
per batch). ``associate``: 3 batches per pose, 7 poses, of >= 20 ms (full, tiny) or >= 10 ms
(quick; a call takes about a millisecond).
"""

from __future__ import annotations

import argparse
import math
import statistics
import tempfile
import time
import timeit
from pathlib import Path

import numpy as np

from optbound import analytic
from optbound.bench.family import Family
from optbound.bench.timing import median_per_call, speed_record
from optbound.localization.association import associate
from optbound.localization.landmark_map import LandmarkMap
from optbound.localization.landmarks import linear_position
from optbound.localization.tracker import SetTracker
from optbound.problems.generators import task_seeds
from optbound.report.tables import fmt_factor, markdown_table
from optbound.scenarios import office
from optbound.sets import Ellipsoid

NAME = "speed_hs96"
REPEAT = 7
SCANS = 40  # two simulated seconds of tracking per criterion
LINEAR_TARGET, ASSOCIATE_TARGET, REALTIME_TARGET = 50e-6, 0.1, 10.0
REPRO_TARGETS = {True: 20.0, False: 120.0}  # quick / full office reproduction, seconds


def bench_linear(
    rng: np.random.Generator, repeat: int = REPEAT, min_time: float = 0.05
) -> list[dict]:
    """Time ``linear_position`` (N = 10 bearings) against one numpy least-squares solve.

    Parameters
    ----------
    rng : numpy.random.Generator
        Draws the landmarks and the reference's matrix.
    repeat : int
        Batches per timing (their median counts).
    min_time : float
        Minimum seconds per batch.

    Returns
    -------
    list of dict
        The reference's speed record, then ours with the ratio and its target.
    """
    phi = np.sort(rng.uniform(0, 2 * np.pi, 10))
    L = np.column_stack([6 * np.cos(phi), 6 * np.sin(phi)])
    alphas = np.arctan2(L[:, 1] - 0.4, L[:, 0] + 0.3) - 0.2
    linear_position(L, alphas)  # compile / load the numba cache outside the timing
    ours = median_per_call(lambda: linear_position(L, alphas), repeat, min_time)
    H, z = rng.normal(size=(9, 2)), rng.normal(size=9)
    ref = median_per_call(lambda: np.linalg.lstsq(H, z, rcond=None), repeat, min_time)
    return [
        speed_record(NAME, "one numpy lstsq (9 x 2), reference", ref),
        speed_record(
            NAME,
            "linear_position, N = 10",
            ours,
            ratio=ref / ours,
            ratio_label="the speed of one numpy lstsq (9 x 2)",
            target=f"<= {1e6 * LINEAR_TARGET:.0f} us",
        ),
    ]


def bench_associate(rng: np.random.Generator, min_time: float = 0.02) -> list[dict]:
    """Time ``associate`` on 8 bearings (1 false) of the office's 22 landmarks, at 7 poses.

    Parameters
    ----------
    rng : numpy.random.Generator
        Draws the poses, the landmarks seen, the noise.
    min_time : float
        Minimum seconds per batch (3 batches per pose, their median counts).

    Returns
    -------
    list of dict
        One speed record: the median time against the target, with the nodes expanded and
        how often the true association was found.
    """
    omap = office.office_map()
    times, nodes, unpruned, found = [], [], 0, 0
    for s in rng.uniform(0, office.lap_length(), 7):
        pose = office.course_pose(s)[0]
        seen = np.flatnonzero(omap.visible(pose[0], pose[1]))
        every = np.sort(
            np.mod(
                np.arctan2(omap.landmarks[seen, 1] - pose[1], omap.landmarks[seen, 0] - pose[0])
                - pose[2],
                2 * np.pi,
            )
        )
        keep = np.sort(rng.choice(seen, 7, replace=False))
        L = omap.landmarks[keep]
        alphas = np.arctan2(L[:, 1] - pose[1], L[:, 0] - pose[0]) - pose[2]
        alphas += rng.uniform(-1, 1, 7) * office.DELTA_ALPHA
        gaps = np.diff(np.r_[every, every[0] + 2 * np.pi])
        false = every[np.argmax(gaps)] + gaps.max() / 2  # far from every true bearing
        prior = Ellipsoid(
            pose + np.array([0.3, -0.2, math.radians(5)]),
            np.diag([0.5**2, 0.5**2, math.radians(10) ** 2]),
        )
        args = (prior, np.mod(np.r_[alphas, false], 2 * np.pi), omap, office.DELTA_ALPHA)
        result = associate(*args)
        times.append(median_per_call(lambda a=args: associate(*a), repeat=3, min_time=min_time))
        nodes.append(result.nodes_expanded)
        unpruned = result.nodes_unpruned
        found += any(np.array_equal(a.pairs[:7], keep) for a in result.associations)
    seconds = statistics.median(times)
    return [
        speed_record(
            NAME,
            "associate, N = 8 (1 false) of 22",
            seconds,
            ratio=ASSOCIATE_TARGET / seconds,
            ratio_label=f"under the {1e3 * ASSOCIATE_TARGET:.0f} ms target",
            target=f"<= {1e3 * ASSOCIATE_TARGET:.0f} ms",
            max_seconds=max(times),
            detail=f"{statistics.median(nodes):.0f} nodes expanded of {unpruned:.2g} unpruned; "
            f"true association found {found}/{len(times)}",
        )
    ]


def _scans(rng, omap: LandmarkMap, n: int):
    """n scans of all 22 landmarks from poses 10 cm apart, with odometry and noise."""
    poses = office.course_pose(np.arange(n + 1) * office.SPEED / office.SCAN_RATE)
    bounds = office.OdometryBounds()
    out = []
    for k in range(n):
        a, b = poses[k], poses[k + 1]
        c, s = math.cos(a[2]), math.sin(a[2])
        step = np.array(
            [c * (b[0] - a[0]) + s * (b[1] - a[1]), -s * (b[0] - a[0]) + c * (b[1] - a[1]), 0.0]
        )
        step[2] = b[2] - a[2]
        L = omap.landmarks
        alphas = np.arctan2(L[:, 1] - b[1], L[:, 0] - b[0]) - b[2]
        alphas += rng.uniform(-1, 1, L.shape[0]) * office.DELTA_ALPHA
        out.append((step, bounds.shape(step), alphas))
    return poses[0], out


def bench_tracker(
    rng: np.random.Generator, n_scans: int = SCANS, repeat: int = REPEAT, min_time: float = 0.05
) -> list[dict]:
    """Time tracker runs per criterion against their bare analytic calls.

    Parameters
    ----------
    rng : numpy.random.Generator
        Draws the bearing noise of the scans.
    n_scans : int
        Scans of all 22 landmarks per run.
    repeat : int
        Batches per timed reference call (their median counts).
    min_time : float
        Minimum seconds per batch of reference calls.

    Returns
    -------
    list of dict
        Per criterion, the bare calls' record and the tracker's, both against real time.
    """
    full = office.office_map()
    omap = LandmarkMap(full.landmarks, shapes=full.shapes)  # no walls: all 22 seen
    start, scans = _scans(rng, omap, n_scans)
    initial = Ellipsoid(start, np.diag([0.02**2, 0.02**2, math.radians(0.3) ** 2]))
    rows = []
    for criterion in ("projection", "volume", "robust"):

        def run(criterion=criterion):
            t = SetTracker(initial, omap, office.DELTA_ALPHA, criterion=criterion)
            for step, shape, alphas in scans:
                t.predict(step, shape)
                for j, alpha in enumerate(alphas):
                    t.update(alpha, j)
            return t

        tracker = run()  # warm-up; also gives the sets the reference calls reuse
        seconds = statistics.median(timeit.Timer(run).repeat(3, 1))  # one run = SCANS scans
        E = tracker.set
        strip = tracker.strip(scans[-1][2][0], 0)
        D = Ellipsoid(scans[-1][0], scans[-1][1])
        ref = len(scans) * (
            omap.size
            * median_per_call(
                lambda c=criterion, E=E, S=strip: analytic.intersect_strip(
                    E, S, criterion=c, dims=(0, 1)
                ),
                repeat,
                min_time,
            )
            + median_per_call(
                lambda E=E, D=D: analytic.minkowski_sum(E, D, criterion="size_xy_psi"),
                repeat,
                min_time,
            )
        )
        real = len(scans) / office.SCAN_RATE
        what = f"tracker, 20 scans/s x 22 landmarks, {criterion}, {len(scans)} scans"
        rows += [
            speed_record(
                NAME,
                f"bare analytic calls of the {what}, reference",
                ref,
                ratio=real / ref,
                ratio_label="faster than real time",
            ),
            speed_record(
                NAME,
                what,
                seconds,
                ratio=real / seconds,
                ratio_label="faster than real time",
                target=f">= {REALTIME_TARGET:.0f}x real time",
                per_update=seconds / (len(scans) * omap.size),
                overhead=seconds / ref - 1.0,
                detail=f"tracker overhead over the bare analytic calls "
                f"{100 * (seconds / ref - 1):.0f} %",
            ),
        ]
    return rows


def bench_repro(full: bool) -> list[dict]:
    """Time the office reproduction, quick variant, and with ``full`` also the 10-lap run.

    Parameters
    ----------
    full : bool
        Also time the full 10-lap run.

    Returns
    -------
    list of dict
        One speed record per variant, against its target.
    """
    from optbound.papers_repro import hs96_office

    rows = []
    for quick in (True, False) if full else (True,):
        with tempfile.TemporaryDirectory() as tmp:
            t0 = time.perf_counter()
            hs96_office.main(Path(tmp), quick=quick)
            seconds = time.perf_counter() - t0
        target = REPRO_TARGETS[quick]
        name = "office reproduction, " + ("quick" if quick else "full (10 laps)")
        rows.append(
            speed_record(
                NAME,
                name,
                seconds,
                ratio=target / seconds,
                ratio_label=f"under the {target:.0f} s target (one run)",
                target=f"<= {target:.0f} s",
            )
        )
    return rows


def table(records: list[dict]) -> str:
    """Format the records as a Markdown table.

    Parameters
    ----------
    records : list of dict
        Speed records of this module.

    Returns
    -------
    str
        Columns: what, median time, target, ratio against the reference.
    """
    rows = [
        (
            r["name"],
            f"{r['value']:.3g} s",
            r.get("target", ""),
            (f"{fmt_factor(r['ratio'])} {r['ratio_label']}" if "ratio" in r else "")
            + (f"; {r['detail']}" if "detail" in r else ""),
        )
        for r in records
    ]
    return markdown_table(("what", "measured (median)", "target", "against"), rows)


# --------------------------------------------------------------------------- bench family
#: Parts per suite, as (part, keyword arguments of its ``bench_*`` function).
PARTS = {
    "tiny": (("linear", {"repeat": 5, "min_time": 0.02}), ("associate", {})),
    "quick": (
        ("linear", {"repeat": 5, "min_time": 0.02}),
        ("associate", {"min_time": 0.01}),
        ("tracker", {"n_scans": 10, "repeat": 3, "min_time": 0.02}),
    ),
    "full": (("linear", {}), ("associate", {}), ("tracker", {}), ("repro", {"full": True})),
}
COST = {"linear": 2.0, "associate": 1.0, "tracker": 3.0, "repro": 130.0}


def tasks(suite: str, seed: int) -> list[dict]:
    """Build the tasks of ``suite``: one per benchmark part (:data:`PARTS`).

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run.
    seed : int
        Suite seed; each task's seed is derived from it.

    Returns
    -------
    list of dict
        One JSON-able task per part, with its ``"seed"``, ``"part"`` and ``"kwargs"``.
    """
    parts = PARTS[suite]
    seeds = task_seeds(seed, NAME, len(parts))
    return [
        {"seed": s, "part": part, "kwargs": dict(kwargs)}
        for s, (part, kwargs) in zip(seeds, parts, strict=True)
    ]


def run(task: dict) -> dict:
    """Run one part's ``bench_*`` function.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    dict
        ``{"records": [...]}``.
    """
    if task["part"] == "repro":
        return {"records": bench_repro(**task["kwargs"])}
    bench = {"linear": bench_linear, "associate": bench_associate, "tracker": bench_tracker}
    return {"records": bench[task["part"]](np.random.default_rng(task["seed"]), **task["kwargs"])}


def cost(task: dict) -> float:
    """Estimate the seconds of one part (the full tracker part runs 4x the quick one's scans).

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    float
        Estimated seconds on one core.
    """
    return COST[task["part"]] * (3.0 if task["kwargs"] == {} and task["part"] == "tracker" else 1)


FAMILY = Family(
    name=NAME,
    title="Speed: HS96 localization (linear fix, association, tracker)",
    kind="speed",
    requires=("optbound.localization.tracker:SetTracker",),
    tasks=tasks,
    run=run,
    parallel=False,
    cost=cost,
)


def main(full: bool = False, seed: int = 0) -> str:
    """Run every benchmark and return the Markdown table (printed by the command line).

    Parameters
    ----------
    full : bool
        Also time the full 10-lap reproduction.
    seed : int
        Seed of the instances.

    Returns
    -------
    str
        The table of :func:`table`.
    """
    rng = np.random.default_rng(seed)
    records = bench_linear(rng) + bench_associate(rng) + bench_tracker(rng) + bench_repro(full)
    return table(records)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--full", action="store_true", help="also time the full 10-lap run")
    print(main(full=parser.parse_args().full))
