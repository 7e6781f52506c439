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

Every function here, the one-line helpers ``fmin`` ... ``up1`` included, is a compiled
function that kernels call, not inlined by numba: numba inlines a callee by copying its IR into
every call site and typing it there again, which made the sonar kernel's compile ~4 times
longer, and the helpers' branches, copied into each operation, half of ``idiv``'s. LLVM inlines
the calls anyway (no call is left in the kernels' machine code), so the kernels run as fast
(measured in ``benchmarks/compile_cost.md``).
"""

from __future__ import annotations

import numpy as np

from optbound._core.jit import njit
from optbound.interval._rounding import _CAP, _EPS, _TINY, BASIC_ULPS

_MAX = _CAP[BASIC_ULPS]


@njit(cache=True)
def fmin(a, b):
    """``np.fmin``: NaN only if both are NaN."""
    if a != a:
        return b
    if b != b:
        return a
    return a if a <= b else b


@njit(cache=True)
def fmax(a, b):
    """``np.fmax`` (negation is exact)."""
    return -fmin(-a, -b)


@njit(cache=True)
def down1(x):
    """``x`` moved at least one float towards -inf."""
    return fmin(x * (1.0 - np.copysign(_EPS, x)) - _TINY, _MAX)


@njit(cache=True)
def up1(x):
    """``x`` moved at least one float towards +inf."""
    return fmax(x * (1.0 + np.copysign(_EPS, x)) + _TINY, -_MAX)


@njit(cache=True)
def isub(al, ah, bl, bh):
    """``[al, ah] - [bl, bh]``, rounded outward."""
    return down1(al - bh), up1(ah - bl)


@njit(cache=True)
def iadd(al, ah, bl, bh):
    """``[al, ah] + [bl, bh]``, rounded outward."""
    return down1(al + bl), up1(ah + bh)


@njit(cache=True)
def imul(al, ah, bl, bh):
    """``[al, ah] * [bl, bh]`` for finite bounds, rounded outward.

    The min and max of the four corner products, found from the operands' signs (two
    products instead of four, except when both straddle 0). Rounding is monotone, so these
    are bit for bit the min and max of the four rounded products.
    """
    if al >= 0.0:
        if bl >= 0.0:
            lo, hi = al * bl, ah * bh
        elif bh <= 0.0:
            lo, hi = ah * bl, al * bh
        else:
            lo, hi = ah * bl, ah * bh
    elif ah <= 0.0:
        if bl >= 0.0:
            lo, hi = al * bh, ah * bl
        elif bh <= 0.0:
            lo, hi = ah * bh, al * bl
        else:
            lo, hi = al * bh, al * bl
    elif bl >= 0.0:
        lo, hi = al * bh, ah * bh
    elif bh <= 0.0:
        lo, hi = ah * bl, al * bl
    else:
        lo, hi = min(al * bh, ah * bl), max(al * bl, ah * bh)
    return down1(lo), up1(hi)


@njit(cache=True)
def isqr(al, ah):
    """``[al, ah] ** 2`` (tight: the smallest and largest absolute values squared)."""
    mig = max(max(al, -ah), 0.0)
    mag = max(-al, ah)
    return max(fmin(mig * mig * (1.0 - _EPS) - _TINY, _MAX), 0.0), mag * mag * (1.0 + _EPS) + _TINY


@njit(cache=True)
def isqrt(al, ah):
    """Square root on its domain (``_transcendental.sqrt``); empty ``(inf, -inf)`` if ``ah < 0``."""
    if ah < 0.0:
        return np.inf, -np.inf
    return max(down1(np.sqrt(max(al, 0.0))), 0.0), up1(np.sqrt(max(ah, 0.0)))


@njit(cache=True, error_model="numpy")
def idiv(al, ah, bl, bh):
    """``[al, ah] / [bl, bh]`` as ``_arith.div``: hull of the extended quotient where ``b`` holds 0.

    Empty ``(inf, -inf)`` for ``b = [0, 0]``.
    """
    p1, p2, p3, p4 = al / bl, al / bh, ah / bl, ah / bh
    lo, hi = fmin(fmin(p1, p2), fmin(p3, p4)), fmax(fmax(p1, p2), fmax(p3, p4))
    lo, hi = down1(0.0 if lo != lo else lo), up1(0.0 if hi != hi else hi)
    if bl > 0.0 or bh < 0.0:
        return lo, hi
    if bl == 0.0 and bh == 0.0:
        return np.inf, -np.inf
    b_right, b_left = bl == 0.0 and bh > 0.0, bl < 0.0 and bh == 0.0
    new_lo, new_hi = -np.inf, np.inf
    if b_right and al > 0.0:
        new_lo = down1(al / bh)
    elif b_left and ah < 0.0:
        new_lo = down1(ah / bl)
    if b_right and ah < 0.0:
        new_hi = up1(ah / bh)
    elif b_left and al > 0.0:
        new_hi = up1(al / bl)
    return new_lo, new_hi
