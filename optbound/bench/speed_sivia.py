"""SIVIA speed: optbound's vectorised paving vs codac (an optional extra).

The measurement lives in :mod:`optbound.bench.sivia_codac` (owned by the interval module); when
codac is not installed it returns a note, and the report prints that note instead of a ratio.
The task runs in a child process: codac leaves the FPU rounding mode set to upward, which
would otherwise skew every later float operation of the run (and of a test session).
"""

from __future__ import annotations

from optbound.bench.family import Family
from optbound.bench.timing import speed_record
from optbound.problems.generators import task_seeds

NAME = "speed_sivia"
# (eps values, repeats) per suite.
SIZES = {"tiny": ((0.05,), 1), "quick": ((0.01, 0.005), 5), "full": ((0.01, 0.005, 0.002), 7)}


def tasks(suite: str, seed: int) -> list[dict]:
    """Build the single task of ``suite``: SIVIA against codac.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run.
    seed : int
        Suite seed; the task's seed is derived from it.

    Returns
    -------
    list of dict
        One JSON-able task, with its ``"seed"``, the paving precisions ``"eps"`` and ``"repeats"``.
    """
    eps, repeats = SIZES[suite]
    return [{"seed": task_seeds(seed, NAME, 1)[0], "eps": list(eps), "repeats": repeats}]


def sivia_records(rows: list[dict], family: str = NAME, what: str = "sivia") -> list[dict]:
    """Build speed records from timing rows: codac's time, then ours with the ratio.

    Parameters
    ----------
    rows : list of dict
        Rows of :func:`optbound.bench.sivia_codac.run` (or of a run with the same keys,
        e.g. :func:`optbound.bench.sonar_codac.run`), without note rows.
    family : str
        The family named in the records.
    what : str
        What was timed, in the records' names.

    Returns
    -------
    list of dict
        Two speed records per row.
    """
    out = []
    for row in rows:
        extra = {k: v for k, v in row.items() if k not in ("name", "seconds", "codac_seconds")}
        extra["ratio_label"] = "faster than codac (wall time)"
        out.append(speed_record(family, f"codac {what}, {row['name']}", row["codac_seconds"]))
        out.append(speed_record(family, f"optbound {what}, {row['name']}", row["seconds"], **extra))
    return out


def run(task: dict) -> dict:
    """Time optbound's SIVIA against codac's.

    Parameters
    ----------
    task : dict
        The task of :func:`tasks`.

    Returns
    -------
    dict
        ``{"records": [...], "notes": [...]}``: the records of :func:`sivia_records`, and the
        rows' notes (e.g. codac not installed).
    """
    from optbound.bench import sivia_codac

    rows = sivia_codac.run(eps_values=tuple(task["eps"]), repeats=task["repeats"])
    notes = [row["note"] for row in rows if "note" in row]
    return {"records": sivia_records([row for row in rows if "note" not in row]), "notes": notes}


FAMILY = Family(
    name=NAME,
    title="Speed: SIVIA vs codac",
    kind="speed",
    requires=("optbound.interval:sivia", "optbound.bench.sivia_codac:run"),
    tasks=tasks,
    run=run,
    parallel=False,
    isolated=True,  # codac leaves the FPU rounding mode set to upward
)
