"""``optbound bench --estimator``: the user's estimators on the suite's problems, for the report.

The problems are those of :func:`optbound.problems.suite` with the bench's suite and seed (the
instances of the built-in families, bitwise), restricted to the families the bench run selects
(``--family``): the problem families whose instances are those of a selected bench family
(:func:`problem_families`). Each estimator is audited by
:func:`optbound.evaluate` in this process; the exact paving and the references of a problem are
computed once and shared by every estimator. The rows go into ``results["estimators"]``::

    [{"estimator": name, "counts": {...}, "rows": [row, ...]}, ...]

(rows as :meth:`Evaluation.to_json` writes them: non-finite floats as null).
"""

from __future__ import annotations

import importlib
import json
import time
from collections.abc import Callable
from typing import Any


def problem_families(selected: list[str] | None) -> list[str]:
    """List the problem families a bench run over ``selected`` bench families covers.

    Those whose instances are a selected family's (a family module's ``BENCH_NAME``, e.g.
    ``bh_bearings`` for ``localization``; by default its own name).

    Parameters
    ----------
    selected : list of str or None
        Bench family names; None (or empty) selects all.

    Returns
    -------
    list of str
        Names of :func:`optbound.problems.families`, in their order.

    Examples
    --------
    >>> from optbound.bench.user_estimators import problem_families
    >>> problem_families(["localization", "strip"])
    ['strip', 'bh_bearings']
    """
    from optbound import problems

    known = problems.families()
    if not selected:
        return known
    bench_name = {
        f: getattr(importlib.import_module(f"optbound.problems.{f}"), "BENCH_NAME", f)
        for f in known
    }
    return [f for f in known if bench_name[f] in selected]


def run_estimators(
    estimators: dict[str, Callable[[Any], Any]],
    suite: str,
    seed: int,
    families: list[str] | None = None,
) -> list[dict]:
    """Evaluate each named estimator on the problem suite of the selected families.

    The problems are ``problems.suite(suite, problem_families(families), seed)``.

    Parameters
    ----------
    estimators : dict of str to callable
        Name -> ``estimator(problem) -> set``, as :func:`optbound.evaluate` takes.
    suite : {"tiny", "quick", "full"}
        Size of the problem suite.
    seed : int
        Seed of the problems.
    families : list of str, optional
        Bench family names (:func:`problem_families`); default all.

    Returns
    -------
    list of dict
        One results entry per estimator (module docstring), in the given order: its counts,
        wall time and per-problem rows.
    """
    from optbound import evaluate, problems

    chosen = problem_families(families)
    todo = problems.suite(suite, families=chosen, seed=seed) if chosen else []
    out = []
    for name, estimator in estimators.items():
        start = time.perf_counter()
        evaluation = evaluate(estimator, todo, name=name)
        out.append(
            {
                "estimator": name,
                "suite": suite,
                "seed": seed,
                "families": chosen,
                "counts": evaluation.counts(),
                "wall_time_s": time.perf_counter() - start,
                "rows": json.loads(evaluation.to_json())["rows"],
            }
        )
    return out
