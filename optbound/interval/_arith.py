"""Outward-rounded kernels for the algebraic operations, on raw bound arrays.

Kernels run under ``np.errstate(all="ignore")`` (set by the caller): overflow and x / 0 are
expected. Each kernel takes the bounds of non-empty intervals (``lo <= hi``, ``lo < +inf``,
``hi > -inf``; broadcastable arrays) and returns ``(lo, hi)`` of an enclosure. Emptiness is
handled one level up, in :mod:`optbound.interval.functions`, so the kernels stay short; a
kernel that can produce an empty result (division by [0, 0]) returns the canonical empty
bounds ``(+inf, -inf)`` there.
"""

from __future__ import annotations

import numpy as np
from numba import vectorize

from optbound._core.jit import njit
from optbound.interval._rounding import (
    TRANSCENDENTAL_ULPS,
    down,
    down_nonneg,
    up,
    up_nonneg,
)
from optbound.interval.compiled import down1, fmax, fmin, up1

INF = np.inf


# Compiled ufuncs for +, - and * (numpy broadcasts their operands without copies): the same
# IEEE operations as ``_rounding.down``/``up`` with one ulp (bit for bit, see ``compiled``),
# fused into one pass instead of ~20 numpy temporaries per product on SIVIA's box arrays.
_F2 = ["float64(float64, float64)"]
_F4 = ["float64(float64, float64, float64, float64)"]


@vectorize(_F2, cache=True)
def _sum_down(a, b):
    return down1(a + b)


@vectorize(_F2, cache=True)
def _sum_up(a, b):
    return up1(a + b)


@vectorize(_F2, cache=True)
def _diff_down(a, b):
    return down1(a - b)


@vectorize(_F2, cache=True)
def _diff_up(a, b):
    return up1(a - b)


@njit(cache=True, inline="always")
def _nan_to_zero(x):
    # All four products NaN only for [0, 0] times an interval unbounded on both sides: 0.
    return 0.0 if x != x else x


@vectorize(_F4, cache=True)
def _product_down(al, ah, bl, bh):
    low = fmin(fmin(al * bl, al * bh), fmin(ah * bl, ah * bh))
    return down1(_nan_to_zero(low))


@vectorize(_F4, cache=True)
def _product_up(al, ah, bl, bh):
    high = fmax(fmax(al * bl, al * bh), fmax(ah * bl, ah * bh))
    return up1(_nan_to_zero(high))


def add(al, ah, bl, bh):
    return _sum_down(al, bl), _sum_up(ah, bh)


def sub(al, ah, bl, bh):
    return _diff_down(al, bh), _diff_up(ah, bl)


def neg(al, ah):
    return -ah, -al


def _hull_of_products(p1, p2, p3, p4):
    """Min and max of four endpoint products/quotients, ignoring NaN.

    NaN comes only from 0 * inf or inf / inf at a corner; the true set there is covered by the
    other corners (0 * inf contributes 0, which another corner or the all-NaN fix supplies).
    """
    lo = np.fmin(np.fmin(p1, p2), np.fmin(p3, p4))
    hi = np.fmax(np.fmax(p1, p2), np.fmax(p3, p4))
    # All four NaN only for [0, 0] times an interval unbounded on both sides: the product is 0.
    # (np.where, not np.nan_to_num: the same values at a fifth of the cost on large arrays.)
    return np.where(np.isnan(lo), 0.0, lo), np.where(np.isnan(hi), 0.0, hi)


def mul(al, ah, bl, bh):
    return _product_down(al, ah, bl, bh), _product_up(al, ah, bl, bh)


def scale(c: float, al, ah):
    """Product with a finite point ``c``: one product per bound instead of four."""
    if c == 0.0:
        zero = np.zeros(np.broadcast(al, ah).shape)
        return zero, zero.copy()
    if c > 0.0:
        return down(c * al), up(c * ah)
    return down(c * ah), up(c * al)


def div(al, ah, bl, bh):
    """Quotient; where ``b`` contains 0 the result is the hull of the extended division.

    With ``b = [0, d]`` (d > 0) the quotient set is ``[a_lo/d, +inf]`` when ``a > 0`` and
    ``[-inf, a_hi/d]`` when ``a < 0``; symmetrically for ``b = [c, 0]``; it is ``[-inf, +inf]``
    when both contain 0 in their interior or ``a`` contains 0; and **empty** for
    ``b = [0, 0]`` (no quotient exists).
    """
    lo, hi = _hull_of_products(al / bl, al / bh, ah / bl, ah / bh)
    lo, hi = down(lo), up(hi)
    b_has_zero = (bl <= 0.0) & (bh >= 0.0)
    if not np.any(b_has_zero):
        return lo, hi
    return _div_by_zero_set(al, ah, bl, bh, b_has_zero, lo, hi)


def _div_by_zero_set(al, ah, bl, bh, b_has_zero, lo, hi):
    al, ah, bl, bh, b_has_zero, lo, hi = np.broadcast_arrays(al, ah, bl, bh, b_has_zero, lo, hi)
    a_pos, a_neg = al > 0.0, ah < 0.0
    b_zero = (bl == 0.0) & (bh == 0.0)
    b_right = (bl == 0.0) & (bh > 0.0)  # b = [0, d]
    b_left = (bl < 0.0) & (bh == 0.0)  # b = [c, 0]
    new_lo = np.select(
        [b_zero, b_right & a_pos, b_left & a_neg], [INF, down(al / bh), down(ah / bl)], -INF
    )
    new_hi = np.select(
        [b_zero, b_right & a_neg, b_left & a_pos], [-INF, up(ah / bh), up(al / bl)], INF
    )
    return np.where(b_has_zero, new_lo, lo), np.where(b_has_zero, new_hi, hi)


def mig_mag(al, ah):
    """Smallest and largest absolute value over ``[al, ah]`` (exact)."""
    mig = np.maximum(np.maximum(al, -ah), 0.0)
    mag = np.maximum(-al, ah)
    return mig, mag


def sqr(al, ah):
    mig, mag = mig_mag(al, ah)
    return down_nonneg(mig * mig), up_nonneg(mag * mag)


def power(al, ah, n: int):
    """Integer power ``x**n`` (``n`` may be negative: ``1 / x**|n|``)."""
    if n < 0:
        pl, ph = power(al, ah, -n)
        one = np.ones(())
        return div(one, one, pl, ph)
    if n == 0:
        one = np.ones(np.broadcast(al, ah).shape)
        return one, one.copy()
    if n == 1:
        return al, ah
    if n == 2:
        return sqr(al, ah)
    k = TRANSCENDENTAL_ULPS  # np.power is libm pow, not correctly rounded
    if n % 2:
        return down(np.power(al, n), k), up(np.power(ah, n), k)
    mig, mag = mig_mag(al, ah)
    return down_nonneg(np.power(mig, n), k), up_nonneg(np.power(mag, n), k)


def minimum(al, ah, bl, bh):
    return np.minimum(al, bl), np.minimum(ah, bh)


def maximum(al, ah, bl, bh):
    return np.maximum(al, bl), np.maximum(ah, bh)


def absolute(al, ah):
    return mig_mag(al, ah)
