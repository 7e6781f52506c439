"""What a benchmark family is: seeded tasks plus a function that runs one task.

A family turns ``(suite, seed)`` into a list of small JSON-able task dicts (each carrying its
own instance seed), and ``run(task)`` turns one task into a :class:`TaskOutput`-shaped dict:

``{"records": [...], "figures": [...], "notes": [...]}``

Records are flat dicts (one measured ratio or time each) that :mod:`optbound.report` turns
into tables, histograms and CSV; figures are drawable 2-D instances; notes are sentences the
report prints verbatim (e.g. "codac is not installed").
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass

SUITES = ("tiny", "quick", "full")
KINDS = ("tightness", "recursive", "speed", "papers", "estimation")


def _unit_cost(task: dict) -> float:
    """Give every task the same rough cost, the default of :attr:`Family.cost`.

    Parameters
    ----------
    task : dict
        A task of the family (ignored).

    Returns
    -------
    float
        1.0: one second on one core.
    """
    return 1.0


@dataclass(frozen=True)
class Family:
    """One benchmark family.

    Parameters
    ----------
    name : str
        Short identifier used in results.json, CSV and file names.
    title : str
        Human-readable heading for the report.
    kind : {"tightness", "recursive", "speed", "papers", "estimation"}
        Decides how the report presents the records (``papers``: each record's Markdown
        and its attached figures; ``estimation``: observers of linear systems per step,
        :mod:`optbound.bench.linear_estimation`).
    requires : tuple of str
        ``"module:attribute"`` names the family needs; a family whose requirement is missing
        is reported as skipped (with the reason) instead of failing the run.
    tasks : callable
        ``tasks(suite, seed) -> list[dict]``; every task has an integer ``"seed"``.
    run : callable
        ``run(task) -> dict`` with ``"records"`` and optionally ``"figures"``, ``"notes"``.
    parallel : bool
        Tightness tasks are spread over ``--jobs`` processes; speed tasks run one at a time
        in the main process after the pool has finished, so timings do not compete for cores.
    isolated : bool
        Run each (serial) task in a fresh child process, for code that changes process-wide
        state; codac, for one, leaves the FPU rounding mode set to upward.
    cost : callable
        ``cost(task) -> float``, the task's rough cost in seconds on one core. Parallel tasks
        start longest first, and the progress bar's ETA weighs tasks by it; results.json
        records the measured ``task_seconds`` to check it against. Default: 1 per task.

    Raises
    ------
    ValueError
        If ``kind`` is not one of :data:`KINDS`.

    Examples
    --------
    >>> from optbound.bench.family import Family
    >>> family = Family(
    ...     name="demo",
    ...     title="A demo family",
    ...     kind="speed",
    ...     requires=("math:sqrt", "no_such_module"),
    ...     tasks=lambda suite, seed: [{"seed": seed}],
    ...     run=lambda task: {"records": [{"family": "demo", "value": task["seed"]}]},
    ... )
    >>> family.missing(), family.cost({"seed": 0})
    (['no_such_module'], 1.0)
    >>> [family.run(task) for task in family.tasks("tiny", 3)]
    [{'records': [{'family': 'demo', 'value': 3}]}]
    """

    name: str
    title: str
    kind: str
    requires: tuple[str, ...]
    tasks: Callable[[str, int], list[dict]]
    run: Callable[[dict], dict]
    parallel: bool = True
    isolated: bool = False
    cost: Callable[[dict], float] = _unit_cost

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"kind must be one of {KINDS}, got {self.kind!r}")

    def missing(self) -> list[str]:
        """List the requirements that cannot be imported right now.

        Returns
        -------
        list of str
            The ``"module:attribute"`` entries of :attr:`requires` whose module does not
            import or lacks the attribute; empty when the family can run.
        """
        return [req for req in self.requires if not _available(req)]


def _available(requirement: str) -> bool:
    module, _, attr = requirement.partition(":")
    try:
        mod = importlib.import_module(module)
    except ImportError:
        return False
    return not attr or hasattr(mod, attr)
