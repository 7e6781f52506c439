"""Compiled (numba) scalar interval operations with the outward rounding of ``_rounding``.

For kernels that evaluate interval formulas on thousands of boxes inside one compiled loop
(e.g. the polygon predicates of :mod:`optbound.localization.geometry.polygons`), where the
array-level :class:`~optbound.interval.Interval` would pay its per-operation overhead. Each
operation is one correctly rounded IEEE operation followed by one ulp outward, exactly the
scheme of :func:`optbound.interval._rounding.down` / ``up`` (``BASIC_ULPS = 1``), including
its cap: an overflowed ``+inf`` lower bound becomes the largest float (and ``-inf`` upper
bounds the most negative). Intervals are passed as ``(lo, hi)`` pairs of finite floats.
"""

from __future__ import annotations

import numpy as np
from numba import njit

_EPS = 2.0**-52
_TINY = 2.0**-1074
_MAX = np.finfo(np.float64).max


@njit(cache=True, inline="always")
def down(x):
    """``x`` moved at least one float towards -inf."""
    return min(x * (1.0 - np.copysign(_EPS, x)) - _TINY, _MAX)


@njit(cache=True, inline="always")
def up(x):
    """``x`` moved at least one float towards +inf."""
    return max(x * (1.0 + np.copysign(_EPS, x)) + _TINY, -_MAX)


@njit(cache=True, inline="always")
def isub(al, ah, bl, bh):
    """``[al, ah] - [bl, bh]``, rounded outward."""
    return down(al - bh), up(ah - bl)


@njit(cache=True, inline="always")
def imul(al, ah, bl, bh):
    """``[al, ah] * [bl, bh]``, rounded outward."""
    p1, p2, p3, p4 = al * bl, al * bh, ah * bl, ah * bh
    return down(min(min(p1, p2), min(p3, p4))), up(max(max(p1, p2), max(p3, p4)))
