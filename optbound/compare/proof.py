"""Does a bound contain a set? ``prove_contains`` answers proven, refuted or undecided.

A proof is never drawn from samples. It is one of

- a closed-form containment checked in exact arithmetic (an ellipsoid or a box inside an
  ellipsoid or a box; an ellipsoid cut by strips and half-spaces inside an ellipsoid, by the
  S-procedure with rational multipliers: :mod:`optbound.compare.exact`);
- for a set known through a paving (``inner ⊂ X ⊂ inner ∪ boundary`` [LJMW97, eq. (11)]):
  every inner and boundary box proven inside the bound by its interval test
  (:mod:`optbound.compare.tri`). Boxes not proven at once are bisected; a sub-box is dropped
  when the set's own test (``member``) proves it disjoint from the set, as in
  ``PseudoEllipsoid.prove_covers``.

A refutation is a **counterexample**: a float point ``x`` that the set's test proves to be in
the set (``member(x) == TRUE``, or a point of an inner box) and that the bound excludes, in
exact arithmetic for optbound's set types, by the bound's own ``contains`` for other objects.
Otherwise the answer is undecided.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from optbound.compare import exact
from optbound.compare._ellipsoid import bound_set
from optbound.compare.tri import point_test, tri_contains, tri_test
from optbound.interval import Interval, Paving, Tri
from optbound.sets import Box, Ellipsoid, Halfspace, PseudoEllipsoid, Strip
from optbound.sets.pseudo_ellipsoid import _bisect

#: Bisection rounds spent on boxes not proven inside at once.
ROUNDS = 8
#: Most boxes the bisection tests (beyond, the answer is undecided).
MAX_TESTED = 100_000
#: Random points drawn in undecided boxes when looking for a counterexample.
SAMPLES = 4096
#: Candidate points checked exactly for a counterexample (after a float pre-filter).
MAX_EXACT_CHECKS = 32

OWN_TYPES = (Box, Ellipsoid, Strip, Halfspace, PseudoEllipsoid, Paving)
STATUSES = ("proven", "refuted", "undecided")


@dataclass(frozen=True)
class Containment:
    """Outcome of :func:`prove_contains`.

    Parameters
    ----------
    status : {"proven", "refuted", "undecided"}
        The answer.
    counterexample : np.ndarray or None
        For "refuted": a float point of the set that the bound excludes.
    method : str
        How the answer was reached (e.g. "exact", "paving", "points").
    """

    status: str
    counterexample: np.ndarray | None
    method: str


def prove_contains(outer, inner, *, member: Callable | None = None) -> Containment:
    """Prove or refute ``inner ⊂ outer``.

    Parameters
    ----------
    outer
        The bound: an optbound set, a ``Paving`` (its ``inner ∪ boundary``), or an object with
        ``dim`` and ``tri_contains(boxes)`` and/or a vectorized ``contains(X)``.
    inner
        The set: an optbound ``Box`` / ``Ellipsoid``, a list of sets meaning their intersection
        (closed-form proofs checked exactly, :func:`optbound.compare.exact.contains_intersection`),
        or a ``Paving`` of it.
    member : callable, optional
        The set's three-valued test on ``Interval`` coordinates (e.g. ``Problem.test``); with
        a paving it lets boundary boxes be trimmed and their points serve as counterexamples.

    Returns
    -------
    Containment
        ``"proven"`` (with the floats read as exact numbers), ``"refuted"`` (with a
        counterexample) or ``"undecided"``, and the method that decided.

    Raises
    ------
    TypeError
        If ``inner`` is neither a Box, an Ellipsoid, a list of sets nor a Paving, or
        ``outer`` has neither an interval test nor ``contains``.
    ValueError
        If the dimensions differ.

    Examples
    --------
    >>> from optbound.interval import sivia
    >>> disc = sivia(lambda x, y: (x**2 + y**2,), [[-np.inf, 1]], [[-2, 2], [-2, 2]], 0.05)
    >>> prove_contains(Box([-1.1, -1.1], [1.1, 1.1]), disc).status
    'proven'
    >>> prove_contains(Box([-0.9, -0.9], [0.9, 0.9]), disc).status
    'refuted'
    """
    outer = bound_set(outer)
    dim = getattr(outer, "dim", None)
    inner_dim = inner[0].dim if isinstance(inner, (list, tuple)) and inner else inner.dim
    if dim != inner_dim:
        raise ValueError(f"outer has dimension {dim}, inner has {inner_dim}")
    if isinstance(inner, (Box, Ellipsoid, list, tuple)):
        proven = exact.contains_intersection(outer, inner)
        return Containment("proven" if proven else "undecided", None, "exact")
    if not isinstance(inner, Paving):
        raise TypeError(f"inner must be a Box, an Ellipsoid or a Paving, got {type(inner)}")
    if inner.is_empty:
        return Containment("proven", None, "paving")
    provable = isinstance(outer, OWN_TYPES) or callable(getattr(outer, "tri_contains", None))
    if not provable and not callable(getattr(outer, "contains", None)):
        raise TypeError(f"outer has neither tri_contains nor contains: {type(outer).__name__}")
    if not provable:
        x = _counterexample(outer, inner.inner, inner.boundary, member)
        return Containment("undecided", None, "points") if x is None else _refuted(x, "points")
    boxes = inner.outer()
    t = tri_contains(outer, boxes)
    pending = boxes[t != Tri.TRUE]
    if pending.shape[0] == 0:
        return Containment("proven", None, "paving")
    # Cheap first: points of the set (inner boxes, boundary centres) that the bound excludes.
    x = _counterexample(outer, inner.inner, inner.boundary, member)
    if x is not None:
        return _refuted(x, "points")
    found = _bisection(outer, pending, member)
    if isinstance(found, Containment):
        return found
    x = _counterexample(outer, found[:0], found, member)
    return Containment("undecided", None, "paving") if x is None else _refuted(x, "paving")


def _refuted(x: np.ndarray, method: str) -> Containment:
    return Containment("refuted", x, method)


def _bisection(outer, pending: np.ndarray, member) -> Containment | np.ndarray:
    """Bisect the boxes not proven inside ``outer``, dropping sub-boxes ``member`` proves
    disjoint from the set; a sub-box proven in the set and outside ``outer`` refutes. Returns
    a Containment when decided, else the boxes left (within :data:`MAX_TESTED` box tests)."""
    test = tri_test(outer)
    tested = 0
    for _ in range(ROUNDS):
        if pending.shape[0] == 0 or member is None or tested + 2 * pending.shape[0] > MAX_TESTED:
            break
        pending = _bisect(pending)
        tested += pending.shape[0]
        coords = [Interval(pending[:, j, 0], pending[:, j, 1]) for j in range(pending.shape[1])]
        inside = np.asarray(test(*coords))
        in_set = np.asarray(member(*coords))
        for i in np.flatnonzero((in_set == Tri.TRUE) & (inside == Tri.FALSE))[:MAX_EXACT_CHECKS]:
            x = _midpoint(pending[i])
            if _is_member(member, x) and _excluded(outer, x[None, :])[0]:
                return _refuted(x, "paving")
        pending = pending[(in_set != Tri.FALSE) & (inside != Tri.TRUE)]
    if pending.shape[0] == 0:
        return Containment("proven", None, "paving")
    return pending


def _counterexample(outer, inner: np.ndarray, other: np.ndarray, member) -> np.ndarray | None:
    """A point of the set that ``outer`` excludes, or None.

    Candidates: the centres and corners of ``inner`` boxes (proven in the set) and, given
    ``member``, the centres of ``other`` boxes and :data:`SAMPLES` seeded random points in
    them (a refutation may come from samples; a proof never does). A candidate counts only if
    ``member`` proves it in the set (when given) and ``outer`` excludes it (exactly for
    optbound's types).
    """
    candidates = [0.5 * (inner[:, :, 0] + inner[:, :, 1]), inner[:, :, 0], inner[:, :, 1]]
    if member is not None and other.shape[0]:
        rng = np.random.default_rng(0)
        picked = other[rng.integers(0, other.shape[0], SAMPLES)]
        u = rng.random(picked.shape[:2])
        candidates += [
            0.5 * (other[:, :, 0] + other[:, :, 1]),
            picked[:, :, 0] + u * (picked[:, :, 1] - picked[:, :, 0]),
        ]
    X = np.concatenate(candidates)
    X = X[_excluded(outer, X, prefilter_only=True)]
    if member is not None:
        X = X[point_test(member, X) == Tri.TRUE]
    for x in X[:MAX_EXACT_CHECKS]:
        if _excluded(outer, x[None, :])[0]:
            return x
    return None


def _is_member(member, x: np.ndarray) -> bool:
    return bool(point_test(member, x[None, :])[0] == Tri.TRUE)


def _excluded(outer, X: np.ndarray, prefilter_only: bool = False) -> np.ndarray:
    """Whether each point is outside ``outer``: exactly for optbound's types (an interval
    pre-filter, then rational arithmetic unless ``prefilter_only``), else by ``contains``."""
    if isinstance(outer, OWN_TYPES):
        out = point_test(tri_test(outer), X) != Tri.TRUE
        if prefilter_only:
            return out
        return np.array(
            [bool(o) and not exact.member(outer, x) for o, x in zip(out, X, strict=True)]
        )
    if callable(getattr(outer, "contains", None)):
        return ~checked_contains(outer, X)
    return point_test(tri_test(outer), X) == Tri.FALSE


def checked_contains(S, X: np.ndarray) -> np.ndarray:
    """Call ``S.contains(X)`` for a user object and check it gives one boolean per point.

    Parameters
    ----------
    S : object
        A user set with a vectorized ``contains(X)``.
    X : numpy.ndarray, shape (m, n)
        The points.

    Returns
    -------
    numpy.ndarray of bool, shape (m,)
        ``S.contains(X)``.

    Raises
    ------
    ValueError
        If ``contains`` returns anything but ``m`` booleans (NaN included).
    """
    got = np.asarray(S.contains(X))
    if got.shape != (X.shape[0],) or got.dtype != np.bool_:
        raise ValueError(
            f"contains(X) must return {X.shape[0]} booleans for X of shape {X.shape}, got "
            f"dtype {got.dtype} and shape {got.shape}"
        )
    return got


def _midpoint(box: np.ndarray) -> np.ndarray:
    return 0.5 * (box[:, 0] + box[:, 1])
