"""Three-valued logic for tests on boxes: FALSE, UNKNOWN, TRUE.

A test evaluated on a box answers TRUE (every point satisfies it), FALSE (no point does) or
UNKNOWN. The values are small integers ordered FALSE < UNKNOWN < TRUE, so conjunction is the
elementwise minimum, disjunction the maximum and negation ``TRUE - t``. Plain boolean arrays
(a test evaluated on points) are accepted everywhere and read as TRUE/FALSE, so one test
function serves both points and boxes.
"""

from __future__ import annotations

from enum import IntEnum

import numpy as np


class Tri(IntEnum):
    """Truth values of a test on a box; stored in ``int8`` arrays.

    Parameters
    ----------
    value : int
        0 (FALSE), 1 (UNKNOWN) or 2 (TRUE): ``Tri(2) is Tri.TRUE``.
    names, module, qualname, type, start, boundary
        The functional API of :class:`enum.Enum` (not used).
    """

    FALSE = 0
    UNKNOWN = 1
    TRUE = 2


TRI_DTYPE = np.int8


def as_tri(t) -> np.ndarray:
    """Return ``t`` as an ``int8`` array of :class:`Tri` values (booleans map to TRUE/FALSE).

    Parameters
    ----------
    t : array_like of bool or int
        Booleans (a test on points) or :class:`Tri` values.

    Returns
    -------
    numpy.ndarray of int8
        The Tri values.

    Raises
    ------
    ValueError
        If ``t`` is neither boolean nor integer, or holds integers outside ``{0, 1, 2}``.
    """
    arr = np.asarray(t)
    if arr.dtype == np.bool_:
        return arr.astype(TRI_DTYPE) * TRI_DTYPE(Tri.TRUE)
    if not np.issubdtype(arr.dtype, np.integer):
        raise ValueError(f"a test must return booleans or Tri values, got dtype {arr.dtype}")
    if arr.size and (arr.min() < Tri.FALSE or arr.max() > Tri.TRUE):
        raise ValueError("Tri values must lie in {0 (FALSE), 1 (UNKNOWN), 2 (TRUE)}")
    return arr.astype(TRI_DTYPE, copy=False)


def from_masks(certainly_true: np.ndarray, certainly_false: np.ndarray) -> np.ndarray:
    """Tri array that is TRUE where ``certainly_true``, FALSE where ``certainly_false``.

    The two masks must be disjoint. ``True + (not False)`` counts 2, 1 or 0: one addition.

    Parameters
    ----------
    certainly_true, certainly_false : numpy.ndarray of bool
        Disjoint masks where the test is proven TRUE, resp. FALSE.

    Returns
    -------
    numpy.ndarray of int8
        TRUE, FALSE or UNKNOWN (neither mask) per entry.
    """
    return np.add(certainly_true, ~certainly_false, dtype=TRI_DTYPE)


def _fold(ufunc, name: str, tests) -> np.ndarray:
    if not tests:
        raise ValueError(f"{name} needs at least one test")
    out = as_tri(tests[0])
    for t in tests[1:]:
        out = ufunc(out, as_tri(t))
    return out


def tri_and(*tests) -> np.ndarray:
    """Conjoin tests: TRUE only if all are TRUE, FALSE if any is FALSE.

    Parameters
    ----------
    *tests : array_like of bool or int
        Booleans or :class:`Tri` values, broadcast together.

    Returns
    -------
    numpy.ndarray of int8
        The elementwise minimum (FALSE < UNKNOWN < TRUE).

    Raises
    ------
    ValueError
        With no test, or a test that is not boolean or Tri.

    Examples
    --------
    >>> [Tri(t).name for t in tri_and([Tri.TRUE, Tri.TRUE, Tri.UNKNOWN], [True, False, True])]
    ['TRUE', 'FALSE', 'UNKNOWN']
    """
    return _fold(np.minimum, "tri_and", tests)


def tri_or(*tests) -> np.ndarray:
    """Disjoin tests: TRUE if any is TRUE, FALSE only if all are FALSE.

    Parameters
    ----------
    *tests : array_like of bool or int
        Booleans or :class:`Tri` values, broadcast together.

    Returns
    -------
    numpy.ndarray of int8
        The elementwise maximum (FALSE < UNKNOWN < TRUE).

    Raises
    ------
    ValueError
        With no test, or a test that is not boolean or Tri.
    """
    return _fold(np.maximum, "tri_or", tests)


def tri_not(t) -> np.ndarray:
    """Negate a test: TRUE <-> FALSE, UNKNOWN stays UNKNOWN.

    Parameters
    ----------
    t : array_like of bool or int
        Booleans (a test on points) or :class:`Tri` values.

    Returns
    -------
    numpy.ndarray of int8
        ``TRUE - t``.

    Raises
    ------
    ValueError
        If ``t`` is not boolean or Tri.
    """
    return TRI_DTYPE(Tri.TRUE) - as_tri(t)
