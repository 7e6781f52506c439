"""Three-valued membership of boxes in any set: the interval test every proof here builds on.

``tri_test(S)`` returns ``test(*coords) -> Tri array``: with each coordinate an
:class:`~optbound.interval.Interval` over m boxes, TRUE where the whole box lies in ``S``,
FALSE where it misses ``S``, UNKNOWN otherwise, proven in outward-rounded interval arithmetic.
On point intervals (``Interval(x, x)``) it decides the membership of float points: TRUE only
if the point provably lies in ``S``. One test per set type:

- ``Box``: float comparisons, exact;
- ``Strip`` / ``Halfspace``: the interval of ``a^T x - b`` against ``[-1, 1]`` / ``(-inf, 0]``;
- ``Ellipsoid``: the ellipsoid as a pseudo-ellipsoid of the identity lifting, whose test
  bounds the quadratic form without trusting a float inverse [BH, eq. (10)]
  (:meth:`~optbound.sets.PseudoEllipsoid.tri_test`);
- ``PseudoEllipsoid``: its own ``tri_test``;
- ``Paving`` (as a bound it claims ``inner ∪ boundary``): TRUE for a box inside one of those
  boxes, FALSE for a box disjoint from all of them;
- any other object with ``tri_contains(boxes)`` (boxes ``(m, n, 2)``): that method.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import lru_cache

import numpy as np

from optbound.interval import Interval, Paving
from optbound.interval.tribool import as_tri, from_masks
from optbound.sets import Box, Ellipsoid, Halfspace, PolynomialLifting, PseudoEllipsoid, Strip

Test = Callable[..., np.ndarray]
#: Box pairs compared at once by the test of a Paving (bounds memory).
_PAIRS = 2_000_000


def tri_test(S) -> Test:
    """Build the interval membership test of ``S`` on ``Interval`` coordinates.

    See the module docstring for what each type's test proves.

    Parameters
    ----------
    S : set
        An optbound set (``Box``, ``Strip``, ``Halfspace``, ``Ellipsoid``,
        ``PseudoEllipsoid``), a ``Paving``, or an object with ``tri_contains(boxes)``.

    Returns
    -------
    callable
        ``test(*coords)`` returning a :class:`~optbound.interval.Tri` per box: TRUE if the box
        is proven inside ``S``, FALSE if proven disjoint, UNKNOWN otherwise.

    Raises
    ------
    TypeError
        If ``S`` is none of the supported types and has no ``tri_contains`` method.
    """
    if isinstance(S, Box):
        return _box_test(S.lo, S.hi)
    if isinstance(S, Strip):
        return _linear_test(S.a, S.b, -1.0)
    if isinstance(S, Halfspace):
        return _linear_test(S.a, S.b, None)
    if isinstance(S, Ellipsoid):
        return as_pseudo_ellipsoid(S).tri_test
    if isinstance(S, PseudoEllipsoid):
        return S.tri_test
    if isinstance(S, Paving):
        return _paving_test(S)
    if callable(getattr(S, "tri_contains", None)):
        return _boxes_test(S.tri_contains)
    raise TypeError(
        f"no interval membership test for {type(S).__name__}: expected an optbound set, a "
        "Paving or an object with tri_contains(boxes)"
    )


def tri_contains(S, boxes: np.ndarray) -> np.ndarray:
    """Evaluate ``tri_test(S)`` on an ``(m, n, 2)`` array of boxes.

    Parameters
    ----------
    S : set
        As in :func:`tri_test`.
    boxes : array_like, shape (m, n, 2)
        Rows ``[lo, hi]`` of each box.

    Returns
    -------
    numpy.ndarray of int8, shape (m,)
        :class:`~optbound.interval.Tri` per box.

    Raises
    ------
    TypeError
        If ``S`` has no interval membership test.

    Examples
    --------
    >>> from optbound.sets import Ellipsoid
    >>> disc = Ellipsoid(np.zeros(2), np.eye(2))
    >>> boxes = [[[-0.1, 0.1], [-0.1, 0.1]], [[2, 3], [2, 3]], [[0.5, 1.5], [0, 0.1]]]
    >>> from optbound.interval import Tri
    >>> [Tri(t).name for t in tri_contains(disc, boxes)]
    ['TRUE', 'FALSE', 'UNKNOWN']
    """
    B = np.asarray(boxes, dtype=float)
    return as_tri(tri_test(S)(*(Interval(B[:, j, 0], B[:, j, 1]) for j in range(B.shape[1]))))


def point_test(test: Test, X: np.ndarray) -> np.ndarray:
    """Evaluate a box test on the float points ``X``, read as degenerate boxes.

    Parameters
    ----------
    test : callable
        A three-valued test on ``Interval`` coordinates.
    X : array_like, shape (m, n)
        The points.

    Returns
    -------
    numpy.ndarray of int8, shape (m,)
        :class:`~optbound.interval.Tri` per point.
    """
    X = np.asarray(X, dtype=float)
    return as_tri(test(*(Interval(X[:, j]) for j in range(X.shape[1]))))


@lru_cache(maxsize=16)
def _identity(dim: int) -> PolynomialLifting:
    return PolynomialLifting(np.eye(dim, dtype=np.int64), np.eye(dim))


def as_pseudo_ellipsoid(E: Ellipsoid) -> PseudoEllipsoid:
    """Represent ``E`` as the pseudo-ellipsoid of the identity lifting (the same set).

    Parameters
    ----------
    E : Ellipsoid
        The ellipsoid.

    Returns
    -------
    PseudoEllipsoid
        The same set, with the pseudo-ellipsoid's interval tests.
    """
    return PseudoEllipsoid.from_ellipsoid(_identity(E.dim), E)


def _box_test(lo: np.ndarray, hi: np.ndarray) -> Test:
    def test(*coords) -> np.ndarray:
        inside = np.ones(np.shape(coords[0].lo), dtype=bool)
        outside = np.zeros_like(inside)
        for x, l_j, h_j in zip(coords, lo, hi, strict=True):
            inside &= (x.lo >= l_j) & (x.hi <= h_j)
            outside |= (x.hi < l_j) | (x.lo > h_j)
        return from_masks(inside, outside)

    return test


def _linear_test(a: np.ndarray, b: float, floor: float | None) -> Test:
    """``a^T x - b`` in ``[floor, 1]`` (strip) or ``<= 0`` (half-space, ``floor=None``)."""
    top = 0.0 if floor is None else 1.0

    def test(*coords) -> np.ndarray:
        value = None
        for a_j, x in zip(a, coords, strict=True):
            if a_j != 0.0:
                value = a_j * x if value is None else value + a_j * x
        value = value - b
        inside, outside = value.hi <= top, value.lo > top
        if floor is not None:
            inside &= value.lo >= floor
            outside |= value.hi < floor
        return from_masks(inside, outside)

    return test


def _paving_test(P: Paving) -> Test:
    """As a bound, a paving claims ``inner ∪ boundary``: a box inside one of those boxes is
    TRUE, a box disjoint from all of them FALSE (compared in chunks to bound memory)."""
    outer = P.outer()
    chunk = max(1, _PAIRS // max(1, outer.shape[0]))

    def test(*coords) -> np.ndarray:
        lo = np.stack([np.atleast_1d(x.lo) for x in coords], axis=-1)
        hi = np.stack([np.atleast_1d(x.hi) for x in coords], axis=-1)
        inside = np.zeros(lo.shape[0], dtype=bool)
        meets = np.zeros(lo.shape[0], dtype=bool)
        for start in range(0, lo.shape[0], chunk):
            a, b = lo[start : start + chunk, None, :], hi[start : start + chunk, None, :]
            inside[start : start + chunk] = np.any(
                np.all((a >= outer[None, :, :, 0]) & (b <= outer[None, :, :, 1]), axis=2), axis=1
            )
            meets[start : start + chunk] = np.any(
                np.all((b >= outer[None, :, :, 0]) & (a <= outer[None, :, :, 1]), axis=2), axis=1
            )
        return from_masks(inside, ~meets)

    return test


def _boxes_test(tri_contains_method) -> Test:
    def test(*coords) -> np.ndarray:
        boxes = np.stack(
            [np.stack([np.atleast_1d(x.lo), np.atleast_1d(x.hi)], axis=-1) for x in coords],
            axis=1,
        )
        out = as_tri(tri_contains_method(boxes))
        if out.shape != (boxes.shape[0],):
            raise ValueError(
                f"tri_contains must return one Tri value per box, got shape {out.shape}"
            )
        return out

    return test


__all__ = ["as_pseudo_ellipsoid", "point_test", "tri_contains", "tri_test"]
