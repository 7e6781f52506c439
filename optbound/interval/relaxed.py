"""Relaxed intersection: m tests of which at most q may fail [KJWM00].

KJWM00 localize a robot from m sonar tests without data association; some measurements are
outliers. Instead of the intersection of the m feasible sets they characterise the set of
configurations satisfying **at least m - q** tests (the q-relaxed intersection), and raise q
from 0 until that set is non-empty, so q estimates the number of outliers.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from optbound.interval.paving import Paving
from optbound.interval.sivia import DEFAULT_MAX_BOXES, DEFAULT_RATIO, FALSE, TRUE, Test, pave
from optbound.interval.tribool import as_tri, from_masks


def _check_tests(tests) -> list:
    tests = list(tests)
    if not tests or not all(callable(t) for t in tests):
        raise ValueError("tests must be a non-empty sequence of callables")
    return tests


def _check_count(name: str, value, m: int) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not 0 <= value <= m:
        raise ValueError(f"{name} must be an integer in [0, {m}], got {value!r}")
    return int(value)


def relaxed_test(tests: Sequence[Test], q: int) -> Test:
    """The three-valued test "at most ``q`` of ``tests`` fail".

    On a box: TRUE when at least ``m - q`` tests are TRUE (every point then satisfies at
    least ``m - q`` of them); FALSE when more than ``q`` tests are FALSE (every point fails
    more than ``q``); UNKNOWN otherwise. ``q = 0`` is the plain intersection.
    """
    tests = _check_tests(tests)
    m = len(tests)
    q = _check_count("q", q, m)

    def test(*coords) -> np.ndarray:
        tris = np.stack(np.broadcast_arrays(*(as_tri(t(*coords)) for t in tests)))
        n_true = np.count_nonzero(tris == TRUE, axis=0)
        n_false = np.count_nonzero(tris == FALSE, axis=0)
        return from_masks(n_true >= m - q, n_false > q)

    return test


def min_outliers(
    tests: Sequence[Test],
    X0,
    eps: float,
    *,
    q_max: int | None = None,
    ratio: float = DEFAULT_RATIO,
    max_boxes: int = DEFAULT_MAX_BOXES,
) -> tuple[int, Paving]:
    """Raise ``q`` from 0 until the q-relaxed intersection is not proven empty [KJWM00].

    Returns the first such ``q`` and its paving. "Not proven empty" means SIVIA kept some
    inner or boundary box; with boundary boxes only, the set may still be empty at a finer
    ``eps``, so ``q`` is a lower bound on the number of outliers consistent with the data.
    ``q_max`` (default ``m``) caps the search; if every ``q <= q_max`` is proven empty the
    result is ``ValueError``.
    """
    tests = _check_tests(tests)
    q_max = len(tests) if q_max is None else _check_count("q_max", q_max, len(tests))
    for q in range(q_max + 1):
        paving = pave(relaxed_test(tests, q), X0, eps, ratio=ratio, max_boxes=max_boxes)
        if not paving.is_empty:
            return q, paving
    raise ValueError(f"the relaxed intersection is empty for every q <= q_max={q_max}")
