"""The papers' results in the bench: every ``papers_repro`` script, one task each.

The scripts are discovered (:func:`optbound.papers_repro._common.scripts`), so a new reproduction
script appears here without any edit. The quick and tiny suites run each script's
``quick=True`` variant, the full suite the full one. A task runs its script in a temporary
folder and returns the script's Markdown (a ``quantity | paper | optbound`` table with the
paper's values labelled as the paper's) and its PNG figures as base64 attachments, so it
works on any executor, a remote Dask worker included; ``optbound.report.save_results``
writes the attachments into the report folder under ``papers/``.
"""

from __future__ import annotations

import base64
import tempfile
from pathlib import Path

from optbound.bench.family import Family
from optbound.problems.generators import task_seeds

NAME = "papers"
ATTACHMENT_DIR = "papers"
#: Rough seconds of one quick script on one core, warm numba cache, its imports included:
#: the longest-first scheduler starts the long ones first. Scripts not listed: DEFAULT_COST.
QUICK_COST = {
    "glh12_visibility": 6.7,
    "kjwm00_outliers": 5.9,
    "alamo05_linear": 4.8,
    "bh_relative_bearing": 3.3,
    "hs96_office": 2.1,
    "ljmw97_triangle": 2.1,
    "hs96_fusion": 1.2,
    "hs96_projection": 0.6,
    "ljmw97_appendix_a": 0.3,
}
DEFAULT_COST = 2.0
#: A full run costs about this many times its quick run.
FULL_FACTOR = 3.0


def tasks(suite: str, seed: int) -> list[dict]:
    """One task per script; ``tiny`` (the smoke test) runs only the first one.

    The scripts fix their own seeds (their tables are the papers' cases), so the task seed
    only identifies the task; it is derived from the script's name, so adding a script
    changes no other task.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run; every suite but ``full`` runs the scripts' quick versions.
    seed : int
        Suite seed.

    Returns
    -------
    list of dict
        One JSON-able task per script: its ``"seed"``, ``"script"``, ``"paper"`` and
        ``"quick"``.
    """
    from optbound.papers_repro._common import scripts

    found = scripts()[:1] if suite == "tiny" else scripts()
    return [
        {
            "seed": task_seeds(seed, f"{NAME}:{script.name}", 1)[0],
            "script": script.name,
            "paper": script.paper,
            "quick": suite != "full",
        }
        for script in found
    ]


def run(task: dict) -> dict:
    """Run one reproduction script in a temporary folder.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    dict
        ``{"records": [record], "attachments": {...}}``: the script's Markdown and the names
        of its figures, which are attached base64-encoded.
    """
    from optbound.papers_repro._common import Script

    script = Script(task["script"], task["paper"])
    with tempfile.TemporaryDirectory() as tmp:
        result = script.run(Path(tmp), quick=task["quick"])
        attachments = {
            f"{ATTACHMENT_DIR}/{script.name}/{Path(p).name}": base64.b64encode(
                Path(p).read_bytes()
            ).decode("ascii")
            for p in result["figures"]
        }
    record = {
        "family": NAME,
        "paper": script.paper,
        "script": script.name,
        "quick": task["quick"],
        "markdown": result["markdown"],
        "figures": sorted(attachments),
    }
    return {"records": [record], "attachments": attachments}


def cost(task: dict) -> float:
    """Estimate the seconds of one script (:data:`QUICK_COST`, :data:`FULL_FACTOR` for full).

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    float
        Estimated seconds on one core.
    """
    quick = QUICK_COST.get(task["script"], DEFAULT_COST)
    return quick if task["quick"] else FULL_FACTOR * quick


FAMILY = Family(
    name=NAME,
    title="The papers' results, reproduced",
    kind="papers",
    requires=("optbound.papers_repro._common:scripts",),
    tasks=tasks,
    run=run,
    cost=cost,
)
