"""SDP solve time with the cvxpy problem cached (DPP parameters) vs rebuilt for every solve.

The measurement itself lives in :mod:`optbound.bench.sdp_cache` (owned by the SDP module); this
family runs it inside the suite so that its ratio lands in the same report.

Sampling: every time is a median over single calls, each on a fresh instance (:data:`SOLVES`
instances per suite, each solved rebuilt, cached, and once more in a run of cached calls):
200 in the full suite, 20 in the quick one (a call takes milliseconds; a median of 20 moves
by a few per cent between runs), 3 in the tiny smoke test.
"""

from __future__ import annotations

from optbound.bench.family import Family
from optbound.bench.timing import speed_record
from optbound.problems.generators import task_seeds

NAME = "speed_sdp"
SOLVES = {"tiny": 3, "quick": 20, "full": 200}


def tasks(suite: str, seed: int) -> list[dict]:
    """Build the single task of ``suite``: the cached-vs-rebuilt SDP timing.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run.
    seed : int
        Suite seed; the task's seed is derived from it.

    Returns
    -------
    list of dict
        One JSON-able task, with its ``"seed"`` and number of solves ``"n_solves"``.
    """
    return [{"seed": task_seeds(seed, NAME, 1)[0], "n_solves": SOLVES[suite]}]


def run(task: dict) -> dict:
    """Time the SDP call with a cached and with a rebuilt problem.

    Parameters
    ----------
    task : dict
        The task of :func:`tasks`.

    Returns
    -------
    dict
        ``{"records": [...]}``, the records of :func:`cache_records`.
    """
    from optbound.bench import sdp_cache

    timings = sdp_cache.run(n_solves=task["n_solves"], seed=task["seed"])
    return {"records": cache_records(timings)}


def cache_records(timings: dict) -> list[dict]:
    """Build the speed records of the cached and rebuilt SDP timings.

    Parameters
    ----------
    timings : dict
        What :func:`optbound.bench.sdp_cache.run` returns.

    Returns
    -------
    list of dict
        The rebuilt and cached call times (with the speed-up), and the cached call's
        shares inside ``optimal.solver.solve`` and inside Clarabel.
    """
    what = f"{timings['dim']}-D ellipsoid ∩ strip, median of {timings['n_solves']}"
    cached, rebuilt = float(timings["cached_s"]), float(timings["rebuilt_s"])
    return [
        speed_record(NAME, f"SDP call, problem rebuilt each time ({what})", rebuilt),
        speed_record(
            NAME,
            f"SDP call, cached problem, DPP parameters ({what})",
            cached,
            ratio=rebuilt / cached,
            ratio_label="speed-up vs rebuilt",
        ),
        speed_record(
            NAME,
            "of which inside optimal.solver.solve (cached)",
            float(timings["cached_solve_s"]),
            ratio=cached / float(timings["cached_solve_s"]),
            ratio_label="whole call / solve()",
        ),
        speed_record(
            NAME,
            "of which Clarabel's own solve time (cached)",
            float(timings["clarabel_s"]),
            ratio=float(timings["call_over_clarabel"]),
            ratio_label="whole call / Clarabel (median per call)",
        ),
    ]


FAMILY = Family(
    name=NAME,
    title="Speed: SDP solve, cached vs rebuilt",
    kind="speed",
    requires=("optbound.bench.sdp_cache:run",),
    tasks=tasks,
    run=run,
    parallel=False,
)
