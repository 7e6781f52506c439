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

Run: ``python -m benchmarks.speed_hs96 [--full]``.
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
from optbound.localization import office
from optbound.localization.association import associate
from optbound.localization.landmark_map import LandmarkMap
from optbound.localization.landmarks import linear_position
from optbound.localization.tracker import SetTracker
from optbound.report.tables import markdown_table
from optbound.sets import Ellipsoid

REPEAT = 7
SCANS = 40  # two simulated seconds of tracking per criterion


def median_per_call(fn, repeat: int = REPEAT, min_time: float = 0.05) -> float:
    """Median over ``repeat`` batches of the seconds per call (batches of >= ``min_time``)."""
    timer = timeit.Timer(fn)
    number = 1
    while timer.timeit(number) < min_time:
        number *= 2
    return statistics.median(t / number for t in timer.repeat(repeat, number))


def bench_linear(rng: np.random.Generator) -> list[tuple]:
    phi = np.sort(rng.uniform(0, 2 * np.pi, 10))
    L = np.column_stack([6 * np.cos(phi), 6 * np.sin(phi)])
    alphas = np.arctan2(L[:, 1] - 0.4, L[:, 0] + 0.3) - 0.2
    linear_position(L, alphas)  # compile / load the numba cache outside the timing
    ours = median_per_call(lambda: linear_position(L, alphas))
    H, z = rng.normal(size=(9, 2)), rng.normal(size=9)
    ref = median_per_call(lambda: np.linalg.lstsq(H, z, rcond=None))
    return [
        (
            "linear_position, N = 10",
            f"{1e6 * ours:.1f} us",
            "<= 50 us",
            f"{ours / ref:.2f}x one numpy lstsq (9 x 2) = {1e6 * ref:.1f} us",
        )
    ]


def bench_associate(rng: np.random.Generator) -> list[tuple]:
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
        times.append(median_per_call(lambda a=args: associate(*a), repeat=3, min_time=0.02))
        nodes.append(result.nodes_expanded)
        unpruned = result.nodes_unpruned
        found += any(np.array_equal(a.pairs[:7], keep) for a in result.associations)
    return [
        (
            "associate, N = 8 (1 false) of 22",
            f"{1e3 * statistics.median(times):.1f} ms (max {1e3 * max(times):.1f})",
            "<= 100 ms",
            f"{statistics.median(nodes):.0f} nodes expanded of {unpruned:.2g} unpruned; "
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


def bench_tracker(rng: np.random.Generator) -> list[tuple]:
    full = office.office_map()
    omap = LandmarkMap(full.landmarks, shapes=full.shapes)  # no walls: all 22 seen
    start, scans = _scans(rng, omap, SCANS)
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
                )
            )
            + median_per_call(
                lambda E=E, D=D: analytic.minkowski_sum(E, D, criterion="size_xy_psi")
            )
        )
        real = len(scans) / office.SCAN_RATE
        rows.append(
            (
                f"tracker, 20 scans/s x 22 landmarks, {criterion}",
                f"{real / seconds:.1f}x real time ({1e6 * seconds / (len(scans) * 22):.0f} "
                "us/update)",
                ">= 10x real time",
                f"bare analytic calls alone: {real / ref:.1f}x real time "
                f"(tracker overhead {100 * (seconds / ref - 1):.0f} %)",
            )
        )
    return rows


def bench_repro(full: bool) -> list[tuple]:
    from papers_repro import hs96_office

    rows = []
    variants = [(True, "<= ~20 s")] + ([(False, "<= 2 min on 2 cores")] if full else [])
    for quick, target in variants:
        with tempfile.TemporaryDirectory() as tmp:
            t0 = time.perf_counter()
            hs96_office.main(Path(tmp), quick=quick)
            seconds = time.perf_counter() - t0
        name = "office reproduction, " + ("quick" if quick else "full (10 laps)")
        rows.append((name, f"{seconds:.1f} s wall", target, "one run"))
    return rows


def main(full: bool = False, seed: int = 0) -> str:
    """Run every benchmark and return the Markdown table (printed by the command line)."""
    rng = np.random.default_rng(seed)
    rows = bench_linear(rng) + bench_associate(rng) + bench_tracker(rng) + bench_repro(full)
    return markdown_table(("what", "measured (median)", "target", "against"), rows)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--full", action="store_true", help="also time the full 10-lap run")
    print(main(full=parser.parse_args().full))
