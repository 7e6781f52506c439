"""Sonar localization speed: optbound's ``sonar.localize`` vs codac 2 separators (full suite).

The measurement lives in :mod:`optbound.bench.sonar_codac` (the LJMW97 triangle, eps = 0.04; codac
runs in a child process of its own). codac takes about 4 minutes, so the family has a task in
the full suite only; like ``speed_sivia`` it runs isolated in a child process, since codac
leaves the FPU rounding mode set to upward. Without codac the report prints its note.
"""

from __future__ import annotations

import math

from optbound.bench.family import Family
from optbound.bench.speed_sivia import sivia_records
from optbound.bench.timing import speed_record
from optbound.problems.generators import task_seeds

NAME = "speed_sonar"


def tasks(suite: str, seed: int) -> list[dict]:
    return [{"seed": task_seeds(seed, NAME, 1)[0]}] if suite == "full" else []


def sonar_records(rows: list[dict]) -> tuple[list[dict], list[str]]:
    """Records and notes from :func:`optbound.bench.sonar_codac.run`'s rows.

    A row without a finite codac time (codac missing, or stopped at the timeout) gives our
    time alone and its note.
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
    from optbound.bench import sonar_codac

    records, notes = sonar_records(sonar_codac.run())
    return {"records": records, "notes": notes}


def cost(task: dict) -> float:
    return 260.0


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
