"""Sonar localization speed: the KJWM00 workload against the interval-layer reference, and codac.

Two tasks:

- ``kjwm00`` (full suite): the pavings the KJWM00 reproduction's quick plan computes
  per trial (q = 0, 1, ... up to the first not proven empty, which is q = "auto", and q = 2 on
  the 16-sonar belt), on its first seeded trials of each group, timed with
  ``sonar.localize`` (compiled belt test) and with the named reference
  :func:`optbound.bench.sonar_codac.interval_layer_localize` (the same SIVIA with the sonar
  tests evaluated on numpy ``Interval`` arrays, as ``localize`` was before). CPU seconds of
  this process, both in the same run, case by case; ``ratio`` = reference / ours.
- ``codac`` (full suite): :mod:`optbound.bench.sonar_codac` (the LJMW97 triangle, eps = 0.04;
  codac runs in a child process of its own, about 4 minutes).

The family runs isolated in a child process, like ``speed_sivia``, since codac leaves the FPU
rounding mode set to upward. Without codac the report prints its note.
"""

from __future__ import annotations

import math
import os
import time

import numpy as np

from optbound.bench.family import Family
from optbound.bench.speed_sivia import sivia_records
from optbound.bench.timing import speed_record
from optbound.problems.generators import task_seeds

NAME = "speed_sonar"


#: Seeded trials per group of the KJWM00 quick plan timed in the full suite (the reference
#: takes about 2 s CPU per 16-sonar trial on a quiet machine).
KJWM00_TRIALS = 10


def tasks(suite: str, seed: int) -> list[dict]:
    """Build the tasks of ``suite``: the KJWM00 workload and the codac comparison (full only).

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run; only ``full`` has tasks (each takes minutes).
    seed : int
        Suite seed; the tasks' seeds are derived from it.

    Returns
    -------
    list of dict
        The ``"kjwm00"`` task (with its ``"trials"``) and the ``"codac"`` task, or none.
    """
    seeds = task_seeds(seed, NAME, 2)
    out = []
    if suite == "full":
        out.append({"seed": seeds[0], "kind": "kjwm00", "trials": KJWM00_TRIALS})
        out.append({"seed": seeds[1], "kind": "codac"})
    return out


def kjwm00_cases(trials: int) -> tuple[list[dict], float]:
    """Build the first ``trials`` seeded cases of each group of the KJWM00 quick plan.

    Parameters
    ----------
    trials : int
        Cases per group.

    Returns
    -------
    cases : list of dict
        The scenarios (``world``, ``sonars``, ``ranges``, ...).
    eps : float
        The plan's range error bound.
    """
    from optbound.papers_repro import kjwm00_outliers as kj
    from optbound.scenarios import rooms

    plan, _, eps = kj._plan(quick=True)
    cases = []
    for g, (_, kind, k, n_sonars) in enumerate(plan):
        for i in range(trials):
            sonars = rooms.belt_sonars(n_sonars if n_sonars else 3 + i % 5)
            cases.append(kj.scenario(np.random.default_rng([0, g, i]), kind, k, sonars))
    return cases, eps


def _trial_pavings(pave_q, n_sonars: int) -> list:
    """A KJWM00 trial's pavings: q = 0, 1, ... up to q = "auto", and q = 2 on 16 sonars."""
    done = {}
    for q in range(n_sonars + 1):
        done[q] = pave_q(q)
        if not done[q].is_empty:
            break
    if n_sonars >= 8 and 2 not in done:
        done[2] = pave_q(2)
    return [done[q] for q in sorted(done)]


def kjwm00_records(trials: int) -> list[dict]:
    """Time the KJWM00 workload with the reference and with ``localize``, case by case.

    Parameters
    ----------
    trials : int
        Cases per group of the KJWM00 quick plan (:func:`kjwm00_cases`).

    Returns
    -------
    list of dict
        Two speed records: the CPU seconds of the interval-layer reference and of
        ``sonar.localize``, with the ratio.

    Raises
    ------
    RuntimeError
        If the two pave a case differently (outer volumes not equal).
    """
    from optbound.bench.sonar_codac import interval_layer_localize
    from optbound.localization.sonar import localize

    cases, eps = kjwm00_cases(trials)
    X0 = [[-5.5, 5.5], [-4.5, 4.5], [-np.pi, np.pi]]
    totals = {"reference": 0.0, "ours": 0.0}
    for case in cases:
        args = (case["world"], case["sonars"], case["ranges"], X0, eps)
        runs = {
            "reference": lambda q, a=args: interval_layer_localize(*a, q)[1],
            "ours": lambda q, a=args: localize(*a, q=q),
        }
        outer = {}
        for name, pave_q in runs.items():
            start = time.process_time()
            pavings = _trial_pavings(pave_q, len(case["sonars"]))
            totals[name] += time.process_time() - start
            outer[name] = [p.volume_bounds()[1] for p in pavings]
        if outer["ours"] != outer["reference"]:
            raise RuntimeError("the compiled belt paved a KJWM00 case unlike the reference")
    label = f"KJWM00 quick workload, {len(cases)} trials ({trials} per group), CPU"
    return [
        speed_record(NAME, f"interval-layer localize (reference), {label}", totals["reference"]),
        speed_record(
            NAME,
            f"sonar.localize (compiled belt test), {label}",
            totals["ours"],
            ratio=totals["reference"] / totals["ours"],
            ratio_label="CPU time of the interval-layer reference / ours (same run)",
            load_average=os.getloadavg()[0],
        ),
    ]


def sonar_records(rows: list[dict]) -> tuple[list[dict], list[str]]:
    """Build the records and notes of :func:`optbound.bench.sonar_codac.run`'s rows.

    A row without a finite codac time (codac missing, or stopped at the timeout) gives our
    time alone and its note.

    Parameters
    ----------
    rows : list of dict
        The rows of :func:`optbound.bench.sonar_codac.run`.

    Returns
    -------
    records : list of dict
        The speed records.
    notes : list of str
        Why a codac time is missing.
    """
    records, notes = [], []
    for row in rows:
        if math.isfinite(row.get("codac_seconds", math.inf)):
            records += sivia_records([row], NAME, "sonar localize")
        else:
            extra = {k: v for k, v in row.items() if k not in ("name", "seconds", "ratio")}
            extra.pop("ratio_label", None)
            name = f"optbound sonar localize, {row['name']}"
            records.append(speed_record(NAME, name, row["seconds"], **extra))
            notes.append(row.get("note") or f"codac {row.get('codac_note', 'gave no time')}")
    return records, notes


def run(task: dict) -> dict:
    """Run one task: the KJWM00 workload or the codac comparison.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    dict
        ``{"records": [...], "notes": [...]}``.
    """
    if task.get("kind") == "kjwm00":
        return {"records": kjwm00_records(task["trials"]), "notes": []}
    from optbound.bench import sonar_codac

    records, notes = sonar_records(sonar_codac.run())
    return {"records": records, "notes": notes}


def cost(task: dict) -> float:
    """Estimate the seconds of one task: 3 s per KJWM00 trial, 260 s for the codac one.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    float
        Estimated seconds on one core.
    """
    return 3.0 * task["trials"] if task.get("kind") == "kjwm00" else 260.0


FAMILY = Family(
    name=NAME,
    title="Speed: sonar localization vs codac",
    kind="speed",
    requires=("optbound.localization.sonar:localize", "optbound.bench.sonar_codac:run"),
    tasks=tasks,
    run=run,
    parallel=False,
    isolated=True,  # codac leaves the FPU rounding mode set to upward
    cost=cost,
)
