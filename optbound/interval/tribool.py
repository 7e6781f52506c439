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
    """Truth values of a test on a box; stored in ``int8`` arrays."""

    FALSE = 0
    UNKNOWN = 1
    TRUE = 2


TRI_DTYPE = np.int8


def as_tri(t) -> np.ndarray:
    """Return ``t`` as an ``int8`` array of :class:`Tri` values (booleans map to TRUE/FALSE)."""
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
    """Conjunction: TRUE only if all are TRUE, FALSE if any is FALSE (FALSE < UNKNOWN < TRUE)."""
    return _fold(np.minimum, "tri_and", tests)


def tri_or(*tests) -> np.ndarray:
    """Disjunction: TRUE if any is TRUE, FALSE only if all are FALSE."""
    return _fold(np.maximum, "tri_or", tests)


def tri_not(t) -> np.ndarray:
    """Negation: TRUE <-> FALSE, UNKNOWN stays UNKNOWN."""
    return TRI_DTYPE(Tri.TRUE) - as_tri(t)
