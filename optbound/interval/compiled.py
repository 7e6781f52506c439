"""Compiled (numba) scalar interval operations with exactly the outward rounding of ``_rounding``.

The interval package's API for compiled code, in this package and above it: kernels that
evaluate interval formulas inside one compiled loop or ufunc call these, e.g. the fused
``+ - *`` of :mod:`optbound.interval._arith` (one pass instead of ~20 numpy temporaries on
SIVIA's box arrays) and the polygon predicates of
:mod:`optbound.localization.geometry.polygons`. ``down1`` / ``up1`` are
:func:`optbound.interval._rounding.down` / ``up`` with one ulp (``BASIC_ULPS``), bit for bit:
the same IEEE operations, NaN-ignoring min/max and the same overflow cap (an overflowed
``+inf`` lower bound becomes the float below the largest one). Intervals are passed as
``(lo, hi)`` pairs.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from optbound.interval._rounding import _CAP, _EPS, _TINY, BASIC_ULPS

_MAX = _CAP[BASIC_ULPS]


@njit(cache=True, inline="always")
def fmin(a, b):
    """``np.fmin``: NaN only if both are NaN."""
    if a != a:
        return b
    if b != b:
        return a
    return a if a <= b else b


@njit(cache=True, inline="always")
def fmax(a, b):
    """``np.fmax`` (negation is exact)."""
    return -fmin(-a, -b)


@njit(cache=True, inline="always")
def down1(x):
    """``x`` moved at least one float towards -inf."""
    return fmin(x * (1.0 - np.copysign(_EPS, x)) - _TINY, _MAX)


@njit(cache=True, inline="always")
def up1(x):
    """``x`` moved at least one float towards +inf."""
    return fmax(x * (1.0 + np.copysign(_EPS, x)) + _TINY, -_MAX)


@njit(cache=True, inline="always")
def isub(al, ah, bl, bh):
    """``[al, ah] - [bl, bh]``, rounded outward."""
    return down1(al - bh), up1(ah - bl)


@njit(cache=True, inline="always")
def imul(al, ah, bl, bh):
    """``[al, ah] * [bl, bh]`` for finite bounds, rounded outward."""
    p1, p2, p3, p4 = al * bl, al * bh, ah * bl, ah * bh
    return down1(min(min(p1, p2), min(p3, p4))), up1(max(max(p1, p2), max(p3, p4)))
