"""Sonar localization: optbound's ``localize`` vs codac 2 separators on the same model.

Problem: the LJMW97 triangle reproduction (``papers_repro/ljmw97_triangle.py``: our triangle,
four sonars, noise-free readings of q* = (−2, 3, 0), 2 %, ±12°), X0 = [−10, 10]² × [−π, π],
ε = 0.04, no prior.

codac, "the straightforward way": each sonar's simulation function f_i of [LJMW97, eq. (2)] is
written as one ``codac.AnalyticFunction`` with the same formula as
:func:`optbound.localization.geometry.nearest_in_cone`. Each candidate of the nearest point
(end points, foot of the perpendicular, hits of the two cone edges) keeps its distance where
the minimum of its validity margins is >= 0 and ``d_max`` elsewhere
(``chi(-margin, distance, d_max)``). The minimum runs over candidates and segments. Then
``SepInverse(f_i, [d_i])`` for each sonar, their intersection (``&``) and ``codac.pave``
(forward-backward contractors on the expression tree, bisection of the widest side). Note the
one semantic difference: codac's test treats the strict margins (reflecting side, ray toward
the face) as non-strict. That matters only on a set of measure zero.

Importing codac switches the process to round-upward, so codac runs in a **child process**
(``python -m optbound.bench.sonar_codac --child EPS``) that reports its time and boxes as JSON.
optbound runs in this process in round-to-nearest. Timing: median of ``repeats`` runs after a
warm-up for optbound (``optbound.bench.sivia_codac._median_time``). codac gets one timed run: it
takes minutes. Both are wall-clock on the same, possibly loaded, machine, measured in the
same run; the 1-min load average is reported.

Registration: a standalone script; ``python -m optbound.bench.sonar_codac`` prints the table
and ``run(eps)`` returns the rows (``ratio`` = codac wall / optbound wall). The codac child
runs in ``$OPTBOUND_CODAC_PYTHON`` when set (e.g. a venv with codac), else in this interpreter.

:func:`speedup_rows` measures, in the same run, ``localize`` against the old bisection-only
path (every sonar test evaluated on every box, ``q="auto"`` re-paving from scratch for each
q: :func:`old_localize`), and with the (x, y) contraction before bisection, on the triangle
and on a KJWM00 case (16 sonars, two random outliers, eps = 0.1). CPU seconds, median of
``repeats`` runs after a warm-up; ``ratio`` = old / new.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from optbound.bench.sivia_codac import _median_time
from optbound.interval import pave
from optbound.interval.fenv import get_rounding, set_rounding
from optbound.interval.paving import box_volumes
from optbound.interval.relaxed import min_outliers, relaxed_paving
from optbound.interval.sivia import FALSE, TRUE
from optbound.interval.tribool import as_tri, from_masks
from optbound.localization.sonar import (
    D_MAX,
    _initial_box,
    localize,
    measurement_box,
    simulate_ranges,
    sonar_tests,
)
from optbound.scenarios import rooms

EPS = 0.04
REPEATS = 5
#: Seconds the codac child may take before it is stopped and reported as "> timeout".
CHILD_TIMEOUT = 1800
WORLD, SONARS = rooms.TRIANGLE, rooms.triangle_sonars()
X0 = [[-10.0, 10.0], [-10.0, 10.0], [-np.pi, np.pi]]
ROOT = Path(__file__).resolve().parents[1]


def readings() -> np.ndarray:
    """Simulate the noise-free range readings of the triangle's true pose.

    Returns
    -------
    numpy.ndarray
        One range per sonar, at ``rooms.TRIANGLE_POSE``.
    """
    return simulate_ranges(WORLD, SONARS, rooms.TRIANGLE_POSE)


def _codac_sonar(codac, x, sonar):
    """codac expression of f_i(x, y, theta), the same candidates as ``cone_candidates``."""
    c = codac
    X, Y, TH = x[0], x[1], x[2]
    far = D_MAX + 0 * X  # a constant as an expression of x

    def det(ux, uy, vx, vy):
        return ux * vy - uy * vx

    sx, sy = sonar.position
    tx = X + c.cos(TH) * sx - c.sin(TH) * sy
    ty = Y + c.sin(TH) * sx + c.cos(TH) * sy
    phi = TH + sonar.orientation
    right = (c.cos(phi - sonar.half_aperture), c.sin(phi - sonar.half_aperture))
    left = (c.cos(phi + sonar.half_aperture), c.sin(phi + sonar.half_aperture))

    def in_cone(wx, wy):
        return c.min(det(*right, wx, wy), det(wx, wy, *left))

    best = far
    for a, b in WORLD:
        ex, ey = float(b[0] - a[0]), float(b[1] - a[1])
        length = float(np.hypot(ex, ey))
        ax, ay, bx, by = a[0] - tx, a[1] - ty, b[0] - tx, b[1] - ty
        front = -det(tx - a[0], ty - a[1], ex, ey)
        perp = front / length
        candidates = [
            (c.sqrt(c.sqr(ax) + c.sqr(ay)), [front, in_cone(ax, ay)]),
            (c.sqrt(c.sqr(bx) + c.sqr(by)), [front, in_cone(bx, by)]),
            (
                perp,
                [
                    front,
                    -ax * ex - ay * ey,
                    bx * ex + by * ey,
                    in_cone(ey / length + 0 * X, -ex / length + 0 * X),
                ],
            ),
        ]
        for u in (right, left):
            toward = det(*u, ex, ey)
            hit = c.max(front / toward, perp)
            candidates.append((hit, [front, toward, det(ax, ay, *u), det(*u, bx, by)]))
        for distance, margins in candidates:
            margin = margins[0]
            for m in margins[1:]:
                margin = c.min(margin, m)
            best = c.min(best, c.chi(-margin, distance, far))
    return c.AnalyticFunction([x], best)


def _child(eps: float) -> dict:
    """Run in the child process: build the codac separator, pave once, report as a dict."""
    import codac

    codac_mode = get_rounding()  # as its import left it: what gaol expects
    x = codac.VectorVar(3)
    box = measurement_box(SONARS, readings())
    seps = [
        codac.SepInverse(_codac_sonar(codac, x, s), codac.Interval(lo, hi))
        for s, (lo, hi) in zip(SONARS, box, strict=True)
    ]
    sep = seps[0]
    for s in seps[1:]:
        sep = sep & s
    x0 = codac.IntervalVector(X0)
    set_rounding(codac_mode)  # optbound's interval work above restored it; be explicit
    start = time.perf_counter()
    paving = codac.pave(x0, sep, eps)
    seconds = time.perf_counter() - start

    def boxes(which):
        out = [[[b[i].lb(), b[i].ub()] for i in range(3)] for b in paving.boxes(which)]
        arr = np.array(out).reshape(-1, 3, 2)
        # Empty boxes (codac encodes them with non-finite bounds) hold no pose.
        return arr[
            np.all(np.isfinite(arr), axis=(1, 2)) & np.all(arr[:, :, 0] <= arr[:, :, 1], axis=1)
        ]

    inner, bound = boxes(codac.PavingInOut.inner), boxes(codac.PavingInOut.bound)
    return {
        "seconds": seconds,
        "n_inner": len(inner),
        "n_boundary": len(bound),
        "outer_volume": float(box_volumes(inner).sum() + box_volumes(bound).sum()),
    }


def _child_values(seed: int, n: int = 200) -> dict:
    """Run in the child process: codac's f at ``n`` seeded poses (midpoints of its intervals)."""
    import codac

    codac_mode = get_rounding()
    x = codac.VectorVar(3)
    funcs = [_codac_sonar(codac, x, s) for s in SONARS]
    poses = sample_poses(seed, n)
    set_rounding(codac_mode)
    values = [[f.eval(codac.IntervalVector(p.tolist())).mid() for f in funcs] for p in poses]
    return {"values": values}


def sample_poses(seed: int, n: int) -> np.ndarray:
    """Draw seeded poses around the triangle, for checking that both programs compute one f.

    Parameters
    ----------
    seed : int
        Seed of the poses.
    n : int
        Number of poses.

    Returns
    -------
    numpy.ndarray
        ``(n, 3)`` poses (x, y, theta).
    """
    rng = np.random.default_rng(seed)
    return np.column_stack([rng.uniform(-6, 3, n), rng.uniform(0, 7, n), rng.uniform(-4, 4, n)])


def codac_values(seed: int, n: int = 200) -> np.ndarray | None:
    """Evaluate codac's f at :func:`sample_poses`, in a child process.

    Parameters
    ----------
    seed : int
        Seed of the poses.
    n : int
        Number of poses.

    Returns
    -------
    numpy.ndarray or None
        The midpoints of codac's intervals, one row per pose, or None without codac (or when
        the child timed out).

    Raises
    ------
    RuntimeError
        If the codac child process fails for another reason than codac missing.
    """
    out = _in_child(["--values", str(seed), str(n)], CHILD_TIMEOUT)
    return None if "note" in out else np.array(out["values"])


def _eager_relaxed(tests, q: int):
    """The old relaxed test: every test on every box, then the counts."""
    m = len(tests)

    def test(*coords):
        tris = np.stack([as_tri(t(*coords)) for t in tests])
        n_true, n_false = (np.count_nonzero(tris == v, axis=0) for v in (TRUE, FALSE))
        return from_masks(n_true >= m - q, n_false > q)

    return test


def old_localize(world, sonars, ranges, X0, eps: float, q) -> tuple[int, object]:
    """Localize by the old bisection-only path: eager tests, ``q="auto"`` re-paving from q = 0.

    Parameters
    ----------
    world : sequence
        The room's segments.
    sonars : sequence
        The sonars on the robot.
    ranges : array_like
        One range reading per sonar.
    X0 : array_like
        The initial box, one ``[lo, hi]`` row per coordinate (x, y, theta).
    eps : float
        Paving precision.
    q : int or "auto"
        Outliers tolerated; ``"auto"`` takes the least q with a non-empty set.

    Returns
    -------
    q : int
        The q used.
    paving : Paving
        The paving of the pose set.
    """
    tests = sonar_tests(world, sonars, ranges)
    box, _ = _initial_box(X0)
    for k in range(len(tests) + 1) if q == "auto" else [q]:
        paving = pave(_eager_relaxed(tests, k), box, eps)
        if q != "auto" or not paving.is_empty:
            return k, paving
    raise ValueError("empty for every q")


def interval_layer_localize(world, sonars, ranges, X0, eps: float, q) -> tuple[int, object]:
    """``localize`` as it was before the compiled belt (the named reference of the speed-ups).

    The same SIVIA and the same per-sonar tests, evaluated with numpy ``Interval`` arrays:
    ``list(sonar_tests(...))`` drops their compiled q-relaxed conjunction, so
    :func:`~optbound.interval.relaxed_test` runs each sonar's test lazily on the boxes left
    undecided; levels below 1024 boxes are bisected untested (``pave``'s default).

    Parameters
    ----------
    world : sequence
        The room's segments.
    sonars : sequence
        The sonars on the robot.
    ranges : array_like
        One range reading per sonar.
    X0 : array_like
        The initial box, one ``[lo, hi]`` row per coordinate (x, y, theta).
    eps : float
        Paving precision.
    q : int or "auto"
        Outliers tolerated; ``"auto"`` takes the least q with a non-empty set.

    Returns
    -------
    q : int
        The q used.
    paving : Paving
        The paving of the pose set.
    """
    tests = list(sonar_tests(world, sonars, ranges))
    box, _ = _initial_box(X0)
    if q == "auto":
        return min_outliers(tests, box, eps)
    return q, relaxed_paving(tests, q, box, eps)


def _kjwm00_case() -> dict:
    from optbound.papers_repro import kjwm00_outliers

    return kjwm00_outliers.scenario(np.random.default_rng([0, 0, 0]), "random", 2)


def speedup_rows(repeats: int = 3) -> list[dict]:
    """Time the old path vs ``localize`` (lazy tests) vs ``localize(contract=True)``.

    Parameters
    ----------
    repeats : int
        Timed runs per path, after a warm-up; the median counts.

    Returns
    -------
    list of dict
        Per problem: CPU seconds of each path, the ratios old / new, outer volumes and box
        counts.
    """
    case = _kjwm00_case()
    kj_x0 = [[-5.5, 5.5], [-4.5, 4.5], [-np.pi, np.pi]]
    problems = [
        ("ljmw97 triangle, eps=0.04, q=0", WORLD, SONARS, readings(), X0, 0.04, 0),
        *(
            (
                f"kjwm00 16 sonars 2 outliers, eps=0.1, q={q}",
                case["world"],
                case["sonars"],
                case["ranges"],
                kj_x0,
                0.1,
                q,
            )
            for q in (0, 2, "auto")
        ),
    ]
    rows = []
    for name, *args, q in problems:
        (_, old_cpu), (_, old) = _median_time(lambda a=args, q=q: old_localize(*a, q), repeats)
        row = {"name": name, "old_cpu_seconds": old_cpu, "old_outer": old.volume_bounds()[1]}
        for label, contract in (("lazy", False), ("contract", True)):
            (_, cpu), paving = _median_time(
                lambda a=args, q=q, c=contract: localize(*a, q=q, contract=c), repeats
            )
            row[f"{label}_cpu_seconds"] = cpu
            row[f"{label}_ratio"] = old_cpu / cpu
            row[f"{label}_outer"] = paving.volume_bounds()[1]
            row[f"{label}_boxes"] = len(paving.inner) + len(paving.boundary)
        rows.append(row)
    return rows


def speedup_table(rows: list[dict]) -> str:
    """Format :func:`speedup_rows` as a Markdown table.

    Parameters
    ----------
    rows : list of dict
        The rows of :func:`speedup_rows`.

    Returns
    -------
    str
        The table.
    """
    lines = [
        "| problem | old CPU [s] | lazy CPU [s] (old / lazy) | lazy + contraction CPU [s] "
        "(old / it) | outer volume old / lazy / contraction |",
        "|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(
            f"| {r['name']} | {r['old_cpu_seconds']:.3f} | {r['lazy_cpu_seconds']:.3f} "
            f"({r['lazy_ratio']:.2f}×) | {r['contract_cpu_seconds']:.3f} "
            f"({r['contract_ratio']:.2f}×) | {r['old_outer']:.3e} / {r['lazy_outer']:.3e} / "
            f"{r['contract_outer']:.3e} |"
        )
    return "\n".join(lines)


def _codac_in_child(eps: float, timeout: float) -> dict:
    return _in_child(["--child", repr(eps)], timeout)


def _in_child(args: list[str], timeout: float) -> dict:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    python = os.environ.get("OPTBOUND_CODAC_PYTHON", sys.executable)
    try:
        done = subprocess.run(
            [python, "-m", "optbound.bench.sonar_codac", *args],
            cwd=ROOT,
            env=env,
            capture_output=True,
            text=True,
            timeout=timeout,
        )
    except subprocess.TimeoutExpired:
        return {"seconds": np.inf, "note": f"stopped after {timeout:.0f} s"}
    if done.returncode != 0:
        if "No module named 'codac'" in done.stderr:
            return {"note": "codac not installed (pip install -e '.[bench]'): comparison skipped"}
        raise RuntimeError(f"codac child failed:\n{done.stderr}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def run(eps: float = EPS, repeats: int = REPEATS, timeout: float = CHILD_TIMEOUT) -> list[dict]:
    """Time ``localize`` on the triangle against codac (in a child process).

    Parameters
    ----------
    eps : float
        Paving precision.
    repeats : int
        Timed runs of ``localize`` after a warm-up; the median counts.
    timeout : float
        Seconds the codac child may take before it is stopped.

    Returns
    -------
    list of dict
        One row: both wall times, ``ratio`` = codac / optbound, box counts and outer volumes;
        without a codac time, a ``"note"`` says why.

    Raises
    ------
    RuntimeError
        If the codac child process fails for another reason than codac missing.
    """
    d = readings()
    (seconds, cpu), paving = _median_time(lambda: localize(WORLD, SONARS, d, X0, eps), repeats)
    load = os.getloadavg()[0]
    theirs = _codac_in_child(eps, timeout)
    row = {
        "name": f"ljmw97_triangle eps={eps}",
        "seconds": seconds,
        "cpu_seconds": cpu,
        "n_inner": len(paving.inner),
        "n_boundary": len(paving.boundary),
        "outer_volume": paving.volume_bounds()[1],
        "load_average": max(load, os.getloadavg()[0]),
        "ratio_label": "codac wall time / optbound wall time",
    }
    if "note" in theirs and "seconds" not in theirs:
        return [{**row, "note": theirs["note"]}]
    row.update({f"codac_{k}": v for k, v in theirs.items()})
    row["ratio"] = theirs["seconds"] / seconds
    return [row]


def table(rows: list[dict]) -> str:
    """Format :func:`run`'s rows as a Markdown table.

    Parameters
    ----------
    rows : list of dict
        The rows of :func:`run`.

    Returns
    -------
    str
        The table.
    """
    lines = [
        "| problem | optbound wall [s] | codac wall [s] | ratio codac / optbound "
        "| boxes inner+boundary optbound / codac | outer volume optbound / codac |",
        "|---|---|---|---|---|---|",
    ]
    for r in rows:
        if "codac_seconds" not in r:
            lines.append(f"| {r['name']} | {r['seconds']:.3f} | — | {r['note']} | | |")
            continue
        codac_s = r["codac_seconds"]
        ratio = f"{r['ratio']:.0f}x" if np.isfinite(codac_s) else f"> ({r['codac_note']})"
        lines.append(
            f"| {r['name']} | {r['seconds']:.3f} | {codac_s:.1f} | {ratio} "
            f"| {r['n_inner']}+{r['n_boundary']} / "
            f"{r.get('codac_n_inner', '?')}+{r.get('codac_n_boundary', '?')} "
            f"| {r['outer_volume']:.2e} / {r.get('codac_outer_volume', float('nan')):.2e} |"
        )
    load = max(r["load_average"] for r in rows)
    lines.append(
        f"\noptbound: median of {REPEATS} runs after a warm-up; codac: one run in a child "
        f"process. 1-min load average during the run <= {load:.1f}."
    )
    return "\n".join(lines)


def main(eps: float = EPS) -> list[dict]:
    """Print the speed-up table and the codac table.

    Parameters
    ----------
    eps : float
        Paving precision of the codac comparison.

    Returns
    -------
    list of dict
        The codac rows (:func:`run`).
    """
    print(speedup_table(speedup_rows()))
    rows = run(eps)
    print(table(rows))
    return rows


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--child":
        print(json.dumps(_child(float(sys.argv[2]))))
    elif len(sys.argv) == 4 and sys.argv[1] == "--values":
        print(json.dumps(_child_values(int(sys.argv[2]), int(sys.argv[3]))))
    elif len(sys.argv) == 2 and sys.argv[1] == "--speedup":
        print(speedup_table(speedup_rows()))
    else:
        main()
