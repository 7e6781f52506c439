"""Relaxed intersection: m tests of which at most q may fail [KJWM00].

KJWM00 localize a robot from m sonar tests without data association; some measurements are
outliers. Instead of the intersection of the m feasible sets they characterise the set of
configurations satisfying **at least m - q** tests (the q-relaxed intersection), and raise q
from 0 until that set is not proven empty. (Reading that q as an estimate of the number of
outliers is ours: it is a lower bound only, see :func:`min_outliers`.)

Contractors combine the same way: a part of a box may be removed only if more than q of the
m contractors remove it (:func:`relaxed_contractor`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from optbound.interval.interval import Interval
from optbound.interval.paving import Paving
from optbound.interval.sivia import (
    DEFAULT_MAX_BOXES,
    DEFAULT_RATIO,
    DEFER_BELOW,
    FALSE,
    TRUE,
    UNKNOWN,
    Contractor,
    Test,
    pave,
)
from optbound.interval.tribool import as_tri


class FusedTests(list):
    """A list of tests that also evaluates its q-relaxed conjunction in one call.

    ``fused(q)`` returns a test of one box per entry (1-D coordinate intervals of one shape,
    SIVIA's case) answering exactly as :func:`relaxed_test` ``(list(tests), q)`` does; a model
    whose tests share most of their work (the sonar belt) provides it, compiled.
    :func:`relaxed_test`, :func:`relaxed_paving` and :func:`min_outliers` use it when given one.

    Parameters
    ----------
    tests : sequence of callable
        The m three-valued tests, kept as the list's items.
    fused : callable
        ``fused(q)`` returns the compiled test of the q-relaxed conjunction of ``tests``.
    """

    def __init__(self, tests: Sequence[Test], fused: Callable[[int], Test]):
        super().__init__(tests)
        self.fused = fused


def _check_tests(tests) -> list:
    checked = list(tests)
    if not checked or not all(callable(t) for t in checked):
        raise ValueError("tests must be a non-empty sequence of callables")
    return tests if isinstance(tests, FusedTests) else checked


def _check_count(name: str, value, m: int) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not 0 <= value <= m:
        raise ValueError(f"{name} must be an integer in [0, {m}], got {value!r}")
    return int(value)


def relaxed_test(tests: Sequence[Test], q: int) -> Test:
    """The three-valued test "at most ``q`` of ``tests`` fail".

    On a box: TRUE when at least ``m - q`` tests are TRUE (every point then satisfies at
    least ``m - q`` of them); FALSE when more than ``q`` tests are FALSE (every point fails
    more than ``q``); UNKNOWN otherwise. ``q = 0`` is the plain intersection.

    Parameters
    ----------
    tests : sequence of callable
        The m three-valued tests ``t(*coords)``; a :class:`FusedTests` is evaluated by its
        compiled ``fused(q)`` on SIVIA's boxes.
    q : int
        How many tests may fail, in ``[0, m]``.

    Returns
    -------
    callable
        The test ``test(*coords)`` returning TRUE / FALSE / UNKNOWN per box.

    Raises
    ------
    ValueError
        If ``tests`` is empty or holds a non-callable, or ``q`` is not an integer in ``[0, m]``.

    Notes
    -----
    With ``n_T`` and ``n_F`` the numbers of tests TRUE and FALSE on a box, the verdict is
    TRUE if ``n_T >= m - q``, FALSE if ``n_F > q``, UNKNOWN otherwise: the three-valued form of
    the q-relaxed intersection of [KJWM00, Sect. 4].
    """
    tests = _check_tests(tests)
    m = len(tests)
    q = _check_count("q", q, m)
    fused = tests.fused(q) if isinstance(tests, FusedTests) else None

    def test(*coords) -> np.ndarray:
        shapes = {np.shape(c.lo if isinstance(c, Interval) else c) for c in coords}
        if len(shapes) == 1 and len(next(iter(shapes))) == 1:  # SIVIA's case: one box each
            if fused is not None:
                return fused(*coords)
            return _lazy(tests, coords, m, q)
        tris = np.stack(np.broadcast_arrays(*(as_tri(t(*coords)) for t in tests)))
        n_true, n_false = (np.count_nonzero(tris == v, axis=0) for v in (TRUE, FALSE))
        return _verdict(n_true, n_false, m, q, 0)

    return test


def _verdict(n_true, n_false, m: int, q: int, left) -> np.ndarray:
    """TRUE / FALSE when decided; UNKNOWN where ``left`` remaining tests cannot decide."""
    out = np.full(np.shape(n_true), -1, dtype=np.int8)
    out[n_true >= m - q] = TRUE
    out[n_false > q] = FALSE
    stuck = (out < 0) & (n_true + left < m - q) & (n_false + left <= q)
    out[stuck] = UNKNOWN
    return out


def _lazy(tests, coords, m: int, q: int) -> np.ndarray:
    """Evaluate the tests one by one, each on the boxes the previous ones left undecided.

    Same answer as evaluating every test on every box; ``coords`` are 1-D, one entry per box.
    """
    size = len(coords[0])
    n_true, n_false = np.zeros(size, dtype=np.intp), np.zeros(size, dtype=np.intp)
    out = np.full(size, -1, dtype=np.int8)
    live = np.arange(size)
    for k, t in enumerate(tests):
        sub = [c[live] for c in coords]
        tri = np.broadcast_to(as_tri(t(*sub)), live.shape)
        n_true[live] += tri == TRUE
        n_false[live] += tri == FALSE
        out[live] = _verdict(n_true[live], n_false[live], m, q, m - k - 1)
        live = live[out[live] < 0]
        if not live.size:
            break
    return out


def min_outliers(
    tests: Sequence[Test],
    X0,
    eps: float,
    *,
    q_max: int | None = None,
    prior: Test | None = None,
    contractors: Sequence[Contractor] | None = None,
    ratio: float = DEFAULT_RATIO,
    max_boxes: int = DEFAULT_MAX_BOXES,
    defer_below: int = DEFER_BELOW,
) -> tuple[int, Paving]:
    """Raise ``q`` from 0 until the q-relaxed intersection is not proven empty [KJWM00].

    Returns the first such ``q`` and its paving. "Not proven empty" means SIVIA kept some
    inner or boundary box; with boundary boxes only, the set may still be empty at a finer
    ``eps``, so ``q`` is a lower bound on the number of outliers consistent with the data.
    ``q_max`` (default ``m``) caps the search; if every ``q <= q_max`` is proven empty the
    result is ``ValueError``.

    What this does **not** guarantee: that ``q`` is the number of outliers. If the wrong
    readings happen to agree with some other pose of the map, the set is not empty at a ``q``
    below the true count, the search stops there, and the returned set need not contain the
    true configuration. Only a fixed ``q`` at least the true number of outliers is
    guaranteed to keep it.

    Parameters
    ----------
    tests : sequence of callable
        The m three-valued tests (one per measurement).
    X0 : array_like, shape (n, 2), or Box
        The bounded initial box.
    eps : float
        A box is not split once its widest side is at most ``eps``.
    q_max : int, optional
        Largest ``q`` tried, in ``[0, m]``; default ``m``.
    prior : callable, optional
        A test every point must pass, whatever ``q`` (tested first).
    contractors : sequence of callable, optional
        One contractor per test, combined by :func:`relaxed_contractor` at each ``q``.
    ratio : float
        Where the widest side is cut (codac's rule, 0.49).
    max_boxes : int
        Refuse to create more boxes than this.
    defer_below : int
        Passed to :func:`~optbound.interval.sivia.pave`.

    Returns
    -------
    q : int
        The smallest ``q`` whose relaxed intersection is not proven empty.
    paving : Paving
        The paving of that relaxed intersection.

    Raises
    ------
    ValueError
        If the relaxed intersection is proven empty for every ``q <= q_max``, on invalid
        ``tests``, ``q_max`` or ``contractors``, or on the errors of :func:`relaxed_paving`.

    References
    ----------
    .. [KJWM00] M. Kieffer, L. Jaulin, E. Walter, D. Meizel, "Robust autonomous robot
       localization using interval analysis", Reliable Computing, 2000.

    Examples
    --------
    Three constraints on ``x`` in ``[0, 10]``: ``x <= 2``, ``x >= 5`` and ``x >= 6``; no
    point satisfies all three, some satisfy two (``x >= 6``):

    >>> from optbound.interval.sivia import constraint
    >>> tests = [constraint(lambda x: x, [[-np.inf, 2]]),
    ...          constraint(lambda x: x, [[5, np.inf]]),
    ...          constraint(lambda x: x, [[6, np.inf]])]
    >>> q, paving = min_outliers(tests, [[0, 10]], 0.01)
    >>> q
    1
    >>> hull = paving.hull()
    >>> bool(hull.lo[0] <= 6 and hull.hi[0] == 10)
    True
    """
    tests = _check_tests(tests)
    q_max = len(tests) if q_max is None else _check_count("q_max", q_max, len(tests))
    for q in range(q_max + 1):
        paving = relaxed_paving(
            tests,
            q,
            X0,
            eps,
            prior=prior,
            contractors=contractors,
            ratio=ratio,
            max_boxes=max_boxes,
            defer_below=defer_below,
        )
        if not paving.is_empty:
            return q, paving
    raise ValueError(f"the relaxed intersection is empty for every q <= q_max={q_max}")


def relaxed_paving(
    tests: Sequence[Test],
    q: int,
    X0,
    eps: float,
    *,
    prior: Test | None = None,
    contractors: Sequence[Contractor] | None = None,
    ratio: float = DEFAULT_RATIO,
    max_boxes: int = DEFAULT_MAX_BOXES,
    defer_below: int = DEFER_BELOW,
) -> Paving:
    """Pave the q-relaxed intersection of ``tests`` (and ``prior``, tested first) in ``X0``.

    With ``contractors`` (one per test), every tested box is first contracted by their
    q-relaxed union (:func:`relaxed_contractor`). Other parameters as in :func:`pave`.

    Parameters
    ----------
    tests : sequence of callable
        The m three-valued tests (one per measurement).
    q : int
        How many tests may fail, in ``[0, m]``.
    X0 : array_like, shape (n, 2), or Box
        The bounded initial box.
    eps : float
        A box is not split once its widest side is at most ``eps``.
    prior : callable, optional
        A test every point must pass, whatever ``q`` (tested first).
    contractors : sequence of callable, optional
        One contractor per test, combined by :func:`relaxed_contractor`.
    ratio : float
        Where the widest side is cut (codac's rule, 0.49).
    max_boxes : int
        Refuse to create more boxes than this.
    defer_below : int
        Passed to :func:`~optbound.interval.sivia.pave`.

    Returns
    -------
    Paving
        Inner, boundary and outside boxes of the set of points of ``X0`` that pass ``prior``
        and at least ``m - q`` of ``tests``.

    Raises
    ------
    ValueError
        On invalid ``tests`` or ``q``, if ``contractors`` does not hold one per test, or on
        the errors of :func:`~optbound.interval.sivia.pave` (bad box, ``eps``, too many boxes).

    Notes
    -----
    The set paved is ``{x in X0 : prior(x), #{i : t_i(x)} >= m - q}``, the q-relaxed
    intersection of [KJWM00, Sect. 4].

    Examples
    --------
    >>> from optbound.interval.sivia import constraint
    >>> tests = [constraint(lambda x: x, [[-np.inf, 2]]),
    ...          constraint(lambda x: x, [[1, np.inf]]),
    ...          constraint(lambda x: x, [[8, np.inf]])]
    >>> relaxed_paving(tests, 0, [[0, 10]], 0.01).is_empty
    True
    >>> inner, outer = relaxed_paving(tests, 1, [[0, 10]], 0.01).volume_bounds()
    >>> bool(inner <= 1 + 2 <= outer)
    True
    """
    tests = _check_tests(tests)
    q = _check_count("q", q, len(tests))
    contractor = None
    if contractors is not None:
        contractor = relaxed_contractor(contractors, q)
        if len(contractors) != len(tests):
            raise ValueError(
                f"contractors must hold one per test ({len(tests)}), got {len(contractors)}"
            )
    relaxed = relaxed_test(tests, q)
    test = relaxed if prior is None else [prior, relaxed]
    return pave(
        test,
        X0,
        eps,
        ratio=ratio,
        max_boxes=max_boxes,
        contractor=contractor,
        defer_below=defer_below,
    )


def relaxed_contractor(contractors: Sequence[Contractor], q: int) -> Contractor:
    """The q-relaxed union of m contractors: keep what at least ``m - q`` of them keep.

    A point satisfying at least ``m - q`` constraints lies in at least ``m - q`` of the
    contracted boxes, so on every axis it is at least the ``(m - q)``-th smallest of their
    lower bounds and at most the ``(m - q)``-th largest of their upper bounds (an emptied box
    counts as ``[+inf, -inf]``). That box is returned: an outer bound of the union, sound for
    any q. ``q = 0`` is the intersection of the contracted boxes.

    Parameters
    ----------
    contractors : sequence of callable
        The m contractors ``c(lo, hi) -> (lo, hi)`` on ``(n, k)`` bound arrays.
    q : int
        How many contractors may be wrong, in ``[0, m]``.

    Returns
    -------
    callable
        The contractor ``contract(lo, hi) -> (lo, hi)`` of the q-relaxed union.

    Raises
    ------
    ValueError
        If a contractor is not callable or ``q`` is not an integer in ``[0, m]``.

    Notes
    -----
    The q-relaxed union of [KJWM00, Sect. 4]: with ``a_i <= b_i`` the contracted bounds of
    one axis, the new bounds are the ``(m - q)``-th smallest ``a_i`` and the ``(m - q)``-th
    largest ``b_i``.
    """
    contractors = list(contractors)
    if not all(callable(c) for c in contractors):
        raise ValueError("contractors must be callables")
    m = len(contractors)
    q = _check_count("q", q, m)

    def contract(lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        if q == m:
            return lo, hi
        los, his = [], []
        for c in contractors:
            c_lo, c_hi = c(lo, hi)
            c_lo, c_hi = np.maximum(c_lo, lo), np.minimum(c_hi, hi)
            empty = np.any(c_lo > c_hi, axis=0)
            los.append(np.where(empty, np.inf, c_lo))
            his.append(np.where(empty, -np.inf, c_hi))
        k = m - q - 1  # 0-based rank of the (m - q)-th
        new_lo = np.sort(np.stack(los), axis=0)[k]
        new_hi = -np.sort(-np.stack(his), axis=0)[k]
        return new_lo, new_hi

    return contract
