"""``evaluate(estimator, problems)``: how tight is a user's bound, and is it really a bound?

For each problem the estimator is called once (timed; any exception, ``None``, non-set,
wrong dimension or NaN is an error row and the run goes on). Its set is then measured and
audited against the exact set of the problem:

- **size**: a certified bracket of its volume (:func:`optbound.compare.size_bracket`),
  the exact set's bracket (:meth:`Problem.volume_bracket`: a closed form where the family
  has one, else the paving's inner and outer volumes [LJMW97, eq. (11)]), their
  ratio bracket ``[size_lo / exact_hi, size_hi / exact_lo]`` and the ratio bracket to each
  reference bound of :meth:`Problem.references`;
- **soundness**: ``"proven"`` (a closed-form exact proof that the set contains the
  intersection describing the true set, e.g. the prior inside it, or an S-procedure
  certificate checked in rational arithmetic; or every box of the exact paving proven inside
  by interval arithmetic), ``"refuted"`` with a counterexample (a float point ``x`` with
  ``p.member(x) == TRUE`` that the set excludes, exactly for optbound's set types, by the
  set's own ``contains`` otherwise) or ``"undecided"``. Never "proven" on samples.

References
----------
[LJMW97] O. Lévêque, L. Jaulin, D. Meizel, E. Walter, "Vehicle localization from
inaccurate telemetric data: a set inversion approach", IFAC SYROCO, 1997.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Iterable
from typing import Any

import numpy as np

from optbound.compare import bound_set
from optbound.compare.metrics import ratio_bracket
from optbound.compare.proof import OWN_TYPES, prove_contains
from optbound.compare.size import size_bracket
from optbound.problems.evaluation import Evaluation
from optbound.problems.problem import Problem
from optbound.sets import Box

#: A user set given only by ``tri_contains`` is paved over the problem's domain enlarged by
#: this factor about its centre (a set reaching the border gets an infinite upper size).
DOMAIN_FACTOR = 3.0
#: ... with boxes this many times the problem's own paving resolution.
EPS_FACTOR = 2.0
REFERENCE_NAMES = ("optimal_ellipsoid", "best_box")


class EstimatorError(Exception):
    """What was wrong with an estimator's answer (becomes the row's ``error``)."""


def evaluate(
    estimator: Callable[[Problem], Any],
    problems: Problem | Iterable[Problem],
    name: str | None = None,
) -> Evaluation:
    """Run ``estimator`` on every problem and audit its sets (module docstring).

    Parameters
    ----------
    estimator : callable
        ``estimator(problem) -> set``: any optbound set (``Ellipsoid``, ``Box``,
        ``PseudoEllipsoid``, a ``Paving``), a result carrying one in ``.ellipsoid``, or an
        object with an integer ``dim`` and a vectorized ``contains(X)`` (X of shape (m, n),
        returning m booleans); with ``tri_contains(boxes)`` (boxes (m, n, 2), returning Tri
        values) its size is certified and its soundness can be proven.
    problems : Problem or iterable of Problem
        E.g. ``problems.suite("tiny")``.
    name : str, optional
        The estimator's name in the tables (default: its ``__name__``).

    Returns
    -------
    Evaluation
        ``.rows``: one dict per problem (keys in :data:`optbound.problems.evaluation.COLUMNS`).

    Raises
    ------
    TypeError
        If ``estimator`` is not callable or a problem is not a ``Problem``.

    Examples
    --------
    >>> from optbound import analytic, evaluate, problems
    >>> suite = problems.suite("tiny", families=["strip"])
    >>> def fused(p):
    ...     return analytic.intersect_strip(p.data["ellipsoid"], p.data["strip"]).ellipsoid
    >>> result = evaluate(fused, suite)
    >>> len(result.rows) == len(suite)
    True
    """
    if not callable(estimator):
        raise TypeError(f"estimator must be callable, got {type(estimator).__name__}")
    todo = [problems] if isinstance(problems, Problem) else list(problems)
    for p in todo:
        if not isinstance(p, Problem):
            raise TypeError(f"problems must hold Problem objects, got {type(p).__name__}")
    label = name or getattr(estimator, "__name__", None) or repr(estimator)
    rows, sets = [], []
    for p in todo:
        row, found = _evaluate_one(estimator, p)
        rows.append({"estimator": label, **row})
        sets.append(found)
    return Evaluation(label, rows, todo, sets)


def _evaluate_one(estimator, p: Problem) -> tuple[dict, Any]:
    row = {"family": p.family, "name": p.name, "seed": p.seed, "dim": p.dim}
    blank = dict.fromkeys(_result_keys())
    start = time.perf_counter()
    try:
        answer = estimator(p)
    except Exception as exc:  # the estimator's failure is the row's outcome
        seconds = time.perf_counter() - start
        return {**row, **blank, "seconds": seconds, "error": _message(exc)}, None
    seconds = time.perf_counter() - start
    start = time.perf_counter()
    # The problem's side first (cached per problem, shared by every estimator): a failure
    # here is the library's, and is raised.
    paving, exact, references = p.exact(), p.volume_bracket(), p.references()
    try:
        S = _as_set(answer, p.dim)
        audit = _audit(S, p, paving, exact, references)
    except Exception as exc:  # a bad set (NaN, broken contains) is the row's outcome
        return {**row, **blank, "seconds": seconds, "error": _message(exc)}, None
    audit["audit_seconds"] = time.perf_counter() - start
    return {**row, **blank, **audit, "seconds": seconds, "error": None}, S


def _result_keys() -> list[str]:
    keys = ["size_lo", "size_hi", "exact_lo", "exact_hi", "ratio_lo", "ratio_hi"]
    for ref in REFERENCE_NAMES:
        keys += [f"ratio_{ref}_lo", f"ratio_{ref}_hi"]
    return [*keys, "soundness", "counterexample", "method", "audit_seconds"]


def _message(exc: BaseException) -> str:
    return f"{type(exc).__name__}: {exc}"


def _as_set(answer, dim: int):
    """The estimator's answer as a set of dimension ``dim``, or an EstimatorError."""
    if answer is None:
        raise EstimatorError("the estimator returned None, not a set")
    S = bound_set(answer)
    if S is None:
        raise EstimatorError(f"the estimator returned a {type(answer).__name__} holding no set")
    is_set = isinstance(S, OWN_TYPES) or (
        callable(getattr(S, "contains", None)) or callable(getattr(S, "tri_contains", None))
    )
    got_dim = getattr(S, "dim", None)
    if not is_set or not isinstance(got_dim, (int, np.integer)):
        raise EstimatorError(
            f"the estimator returned a {type(S).__name__}, which is not a set: a set needs an "
            "integer dim and contains(X) or tri_contains(boxes)"
        )
    if got_dim != dim:
        raise EstimatorError(f"the estimator returned a set of dimension {got_dim}, expected {dim}")
    return S


def _audit(S, p: Problem, paving, exact: tuple[float, float], references: dict) -> dict:
    """Size brackets, ratio brackets and soundness of ``S`` on ``p``."""
    out: dict[str, Any] = {"exact_lo": exact[0], "exact_hi": exact[1]}
    size = _size(S, p)
    if size is not None:
        out["size_lo"], out["size_hi"] = size
        out["ratio_lo"], out["ratio_hi"] = ratio_bracket(size, exact)
        for ref, bound in references.items():
            lo, hi = ratio_bracket(size, size_bracket(bound))
            out[f"ratio_{ref}_lo"], out[f"ratio_{ref}_hi"] = lo, hi
    verdict = prove_contains(S, p.intersection) if p.intersection else None
    if verdict is None or verdict.status != "proven":
        verdict = prove_contains(S, paving, member=p.test)
    out["soundness"], out["method"] = verdict.status, verdict.method
    x = verdict.counterexample
    out["counterexample"] = None if x is None else [float(c) for c in x]
    return out


def _size(S, p: Problem) -> tuple[float, float] | None:
    """Certified size bracket of ``S``; None for an object with only ``contains``."""
    measured = ("volume_bounds", "tri_contains")
    if not isinstance(S, OWN_TYPES) and not any(callable(getattr(S, m, None)) for m in measured):
        return None
    domain = None
    if not isinstance(S, OWN_TYPES):  # optbound's own types know their extent
        centre, half = p.domain.center, 0.5 * DOMAIN_FACTOR * p.domain.widths
        domain = Box(centre - half, centre + half)
    lo, hi = size_bracket(S, domain=domain, eps=EPS_FACTOR * p.eps)
    if math.isnan(lo) or math.isnan(hi):
        raise EstimatorError("the set's size is NaN")
    return lo, hi
