"""SIVIA: optbound vs codac 2 on the two reference sets, same pavings, wall time.

Sets: LJMW97 Appendix A ``{x^2 + y^2 <= 1, 2 x^2 + y^2 >= 1}`` on [-2.5, 2.5] x [-2, 2]
(area pi (1 - 1/sqrt 2)) and the ring ``1 <= (x-1)^2 + (y-2)^2 <= 4`` on [-5, 5]^2 (area 3 pi).

Aligned semantics. codac's ``sivia`` bisects the first widest side at ratio 0.49 (stored as a
C ``float``, i.e. 0.49000000953674316) while the widest side exceeds eps; optbound is called
with the same ratio and stopping rule. codac evaluates ``f`` with its default mode
(natural ∩ centred form); here every variable occurs once per ``sqr`` term, so the natural
extension is already the exact range up to rounding and both programs classify the same
boxes. Residual differences: the area sums (~1e-15 relative, summation order) and the box
counts, since optbound bisects levels of fewer than 1024 boxes without testing them (same union).

Rounding mode. Importing codac switches the whole process to round-upward (gaol, its interval
library, sets the x86 rounding mode once and relies on it; numpy's vector ops follow it).
``run`` therefore calls codac in round-upward and optbound in round-to-nearest (the mode its
outward steps assume; optbound would switch to it by itself, but inside the timed call) and
restores the caller's mode at the end, so later numpy code in the process is unaffected.

Timing: after one warm-up call, median of ``repeats`` wall-clock runs of each ``sivia`` call
(garbage collection paused), codac's block right before optbound's for each (set, eps). The
codac time covers ``codac.sivia`` only, not the (slower) extraction of its boxes into numpy for
the area comparison. (Interleaving single calls was tried first: codac's large tree evicts
the caches, which slows the next optbound call by about 40 %.) CPU times are reported too: on
a loaded machine a 3 ms run that is preempted once waits a whole scheduler slice, which
inflates short wall times far more than long ones.

``python -m optbound.bench.sivia_codac`` prints the table.
"""

from __future__ import annotations

import gc
import os
import time

import numpy as np

from optbound import interval as iv
from optbound.interval.codac_interop import codac_boxes
from optbound.interval.fenv import FE_TONEAREST, get_rounding, round_to_nearest, set_rounding
from optbound.interval.paving import box_volumes

REPEATS = 5
#: codac's bisection ratio as it stores it (a C float).
CODAC_RATIO = float(np.float32(0.49))

CASES = {
    "ljmw97_appendix_a": dict(
        f=lambda x, y: (x**2 + y**2, 2 * x**2 + y**2),
        Y=[[-np.inf, 1.0], [1.0, np.inf]],
        X0=[[-2.5, 2.5], [-2.0, 2.0]],
        area=np.pi * (1 - 1 / np.sqrt(2)),
    ),
    "ring": dict(
        f=lambda x, y: (x - 1) ** 2 + (y - 2) ** 2,
        Y=[[1.0, 4.0]],
        X0=[[-5.0, 5.0], [-5.0, 5.0]],
        area=3 * np.pi,
    ),
}


def _codac_problem(codac, case: str):
    """The same function, image box and initial box in codac's types."""
    x = codac.VectorVar(2)
    if case == "ljmw97_appendix_a":
        f = codac.AnalyticFunction(
            [x],
            codac.vec(codac.sqr(x[0]) + codac.sqr(x[1]), 2 * codac.sqr(x[0]) + codac.sqr(x[1])),
        )
        y = codac.IntervalVector([[-codac.oo, 1.0], [1.0, codac.oo]])
    else:
        f = codac.AnalyticFunction([x], codac.sqr(x[0] - 1) + codac.sqr(x[1] - 2))
        y = codac.Interval(1.0, 4.0)
    return f, y, codac.IntervalVector(CASES[case]["X0"])


def _codac_boxes(codac, paving, which) -> np.ndarray:
    return codac_boxes(paving.boxes(which), paving.size())


def _median_time(fn, repeats: int):
    """Median wall and CPU seconds of ``repeats`` calls after one warm-up call, and a result.

    Garbage collection is paused, as in ``timeit``.
    """
    out = fn()
    walls, cpus = [], []
    gc.disable()
    try:
        for _ in range(repeats):
            wall, cpu = time.perf_counter(), time.process_time()
            fn()
            walls.append(time.perf_counter() - wall)
            cpus.append(time.process_time() - cpu)
    finally:
        gc.enable()
    return (float(np.median(walls)), float(np.median(cpus))), out


def run(eps_values=(0.01, 0.005), repeats: int = REPEATS) -> list[dict]:
    """Time optbound's SIVIA against codac's on the same sets.

    Parameters
    ----------
    eps_values : sequence of float
        Paving precisions.
    repeats : int
        Timed runs of each; the median counts.

    Returns
    -------
    list of dict
        One row per (set, eps) with both wall times, the speed-up and both area brackets;
        ``[{"note": "codac not installed ..."}]`` when codac is missing.
    """
    with round_to_nearest():  # gives the caller's mode back, whatever codac does to it
        try:
            import codac
        except ImportError:
            return [{"note": "codac not installed (pip install -e '.[bench]'): comparison skipped"}]
        return _compare(codac, eps_values, repeats)


def _compare(codac, eps_values, repeats: int) -> list[dict]:
    codac_mode = get_rounding()  # as its import left it
    rows = []
    for case, spec in CASES.items():
        f, y, x0 = _codac_problem(codac, case)
        for eps in eps_values:
            set_rounding(codac_mode)  # what gaol expects
            t_codac, theirs = _median_time(lambda: codac.sivia(x0, f, y, eps), repeats)  # noqa: B023
            set_rounding(FE_TONEAREST)  # optbound would switch itself, inside the timing
            t_ours, ours = _median_time(
                lambda: iv.sivia(spec["f"], spec["Y"], spec["X0"], eps, ratio=CODAC_RATIO),  # noqa: B023
                repeats,
            )
            c_inner = box_volumes(_codac_boxes(codac, theirs, codac.PavingInOut.inner)).sum()
            c_bound = box_volumes(_codac_boxes(codac, theirs, codac.PavingInOut.bound)).sum()
            o_inner, o_outer = ours.volume_bounds()
            (seconds, cpu), (codac_seconds, codac_cpu) = t_ours, t_codac
            rows.append(
                {
                    "name": f"{case} eps={eps}",
                    "seconds": seconds,
                    "codac_seconds": codac_seconds,
                    "ratio": codac_seconds / seconds,
                    "ratio_label": "codac wall time / optbound wall time",
                    "cpu_seconds": cpu,
                    "codac_cpu_seconds": codac_cpu,
                    "cpu_ratio": codac_cpu / cpu,
                    "load_average": os.getloadavg()[0],
                    "true_area": float(spec["area"]),
                    "inner_area": o_inner,
                    "boundary_area": o_outer - o_inner,
                    "codac_inner_area": float(c_inner),
                    "codac_boundary_area": float(c_bound),
                    "max_area_rel_diff": float(
                        max(
                            abs(o_inner - c_inner) / c_inner,
                            abs(o_outer - o_inner - c_bound) / c_bound,
                        )
                    ),
                }
            )
    return rows


def table(rows: list[dict]) -> str:
    """Format :func:`run`'s rows as a Markdown table.

    Parameters
    ----------
    rows : list of dict
        The rows of :func:`run`.

    Returns
    -------
    str
        The table, or the note when codac is missing.
    """
    if rows and "note" in rows[0]:
        return rows[0]["note"]
    lines = [
        "| set | eps | codac wall [ms] | optbound wall [ms] | speed-up wall (cpu) "
        "| inner area codac / optbound | boundary area codac / optbound | max rel. diff |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        case, eps = r["name"].split(" eps=")
        lines.append(
            f"| {case} | {eps} | {1e3 * r['codac_seconds']:.1f} | {1e3 * r['seconds']:.2f} "
            f"| {r['ratio']:.1f}x ({r['cpu_ratio']:.1f}x) "
            f"| {r['codac_inner_area']:.6f} / {r['inner_area']:.6f} "
            f"| {r['codac_boundary_area']:.6f} / {r['boundary_area']:.6f} "
            f"| {r['max_area_rel_diff']:.1e} |"
        )
    load = max(r["load_average"] for r in rows)
    lines.append(
        f"\nMedian of {REPEATS} runs each; 1-min load average during the run <= {load:.1f}."
    )
    return "\n".join(lines)


if __name__ == "__main__":
    print(table(run()))
