"""Public set-membership problems and the evaluation of any estimator on them.

Usage::

    from optbound import problems, evaluate
    suite = problems.suite("tiny")                  # list[Problem], seeded like `optbound bench`
    p = suite[0]
    p.family, p.name, p.seed, p.dim, p.data, p.truth
    p.member(X)        # Tri per float point: proven in the true set?
    p.exact(eps=None)  # Paving: inner ⊂ true set ⊂ inner ∪ boundary
    p.references()     # {"optimal_ellipsoid": ..., "best_box": ...}, certified outer bounds
    result = evaluate(my_estimator, suite)          # size brackets, ratios, soundness per problem

Families (one module each, defining ``problems(suite, seed) -> list[Problem]``): ``strip``
(ellipsoid ∩ strip), ``minkowski`` (sum of two ellipsoids), ``recursive`` (ellipsoid ∩ a
sequence of strips), ``bh_bearings`` (BH relative bearings), ``hs96_pose`` (HS96 landmark
bearings, pose x, y, psi), ``sonar`` (LJMW97/KJWM00 sonar scan, pose x, y, theta),
``visibility`` (GLH12: one robot's box at one step), ``linear_estimation`` (the exact set
of a 2-D linear system at one step, issue 21).
"""

from __future__ import annotations

import importlib

from optbound._lazy import attach
from optbound.problems.audit import evaluate
from optbound.problems.evaluation import Evaluation
from optbound.problems.problem import Problem

SUITES = ("tiny", "quick", "full")
#: Family name -> its module (imported when a suite asks for it: the localization families
#: pull in their models and worlds).
_FAMILIES = {
    name: f"optbound.problems.{name}"
    for name in (
        "strip",
        "minkowski",
        "recursive",
        "bh_bearings",
        "hs96_pose",
        "sonar",
        "visibility",
        "linear_estimation",
    )
}


def families() -> list[str]:
    """List the names of the problem families, in suite order.

    Returns
    -------
    list of str
        The family names, each also a module ``optbound.problems.<name>``.

    Examples
    --------
    >>> from optbound import problems
    >>> problems.families()[:3]
    ['strip', 'minkowski', 'recursive']
    """
    return list(_FAMILIES)


def suite(name: str, families: list[str] | None = None, seed: int = 0) -> list[Problem]:
    """Build the problems of suite ``name``, of every family or of ``families``.

    Parameters
    ----------
    name : {"tiny", "quick", "full"}
        The suite size, as in ``optbound bench --suite``.
    families : list of str, optional
        Family names (see :func:`families`); every family if None.
    seed : int, default 0
        The suite seed of ``optbound bench --seed``: the same seed gives the same instances
        as the benchmark.

    Returns
    -------
    list of Problem
        The problems, family by family in the order of ``families``.

    Raises
    ------
    ValueError
        For an unknown suite or family name.

    Examples
    --------
    >>> from optbound import problems
    >>> suite = problems.suite("tiny", families=["strip"])
    >>> p = suite[0]
    >>> (p.family, p.dim)
    ('strip', 2)
    """
    if name not in SUITES:
        raise ValueError(f"name must be one of {SUITES}, got {name!r}")
    chosen = list(_FAMILIES) if families is None else list(families)
    unknown = [f for f in chosen if f not in _FAMILIES]
    if unknown:
        raise ValueError(f"families: unknown {unknown}; known: {list(_FAMILIES)}")
    return [
        p
        for family in chosen
        for p in importlib.import_module(_FAMILIES[family]).problems(name, seed)
    ]


__all__ = ["SUITES", "Evaluation", "Problem", "evaluate", "families", "suite"]

__getattr__, __dir__ = attach(__name__, public=__all__, submodules=tuple(_FAMILIES))
