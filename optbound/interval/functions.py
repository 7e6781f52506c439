"""Public interval functions and their registration as numpy ufunc overrides.

Every function accepts ``Interval`` arrays or plain numbers/arrays (read as point intervals)
and returns an ``Interval`` (a :class:`~optbound.interval.Tri` array for comparisons). The
same callables back the arithmetic operators of :class:`Interval` and ``np.sqrt(X)``,
``np.arctan2(Y, X)``, etc., through :data:`~optbound.interval.interval.UFUNC_IMPL`.
"""

from __future__ import annotations

import operator

import numpy as np

from optbound.interval import _arith, _transcendental
from optbound.interval.fenv import nearest
from optbound.interval.interval import INF, UFUNC_IMPL, Interval, as_interval
from optbound.interval.tribool import from_masks


@nearest
def _lift(kernel, *args, may_empty: bool = False, domain=None, **params) -> Interval:
    """Apply a bound-array kernel to intervals, propagating empty and partial entries.

    Runs in round-to-nearest whatever the caller's rounding mode (:mod:`.fenv`).

    ``may_empty`` marks kernels that can return empty entries (domain restrictions); only then
    is the result scanned for them, which keeps the common path to the kernel's own ops.
    ``domain(*bounds)`` (optional) flags inputs reaching outside the function's domain; the
    result is partial there or wherever an operand was partial.
    Floating-point warnings are silenced: overflow to +-inf, 0 * inf and x / 0 are expected
    and the kernels turn them into correct bounds.
    """
    xs = [as_interval(a) for a in args]
    empty = None
    if any(x._maybe_empty for x in xs):
        empty = xs[0].is_empty
        for x in xs[1:]:
            empty = empty | x.is_empty
        # Feed [0, 0] where an operand is empty, then overwrite: the kernel never sees empties.
        bounds = [np.where(empty, 0.0, b) for x in xs for b in (x.lo, x.hi)]
    else:
        bounds = [b for x in xs for b in (x.lo, x.hi)]
    with np.errstate(all="ignore"):
        lo, hi = kernel(*bounds, **params)
    partial = _partial_of(xs, None if domain is None else domain(*bounds))
    if empty is not None:
        return Interval._make(np.where(empty, INF, lo), np.where(empty, -INF, hi), True, partial)
    return Interval._make(lo, hi, may_empty and bool(np.any(lo > hi)), partial)


def _partial_of(xs, new):
    flags = [x._partial for x in xs if x._partial is not None]
    if new is not None and np.any(new):
        flags.append(new)
    if not flags:
        return None
    out = flags[0]
    for flag in flags[1:]:
        out = out | flag
    return out


def add(a, b) -> Interval:
    """Compute ``a + b``, rounded outward.

    Parameters
    ----------
    a, b : Interval or array_like
        Operands, broadcast together (finite points are read as point intervals).

    Returns
    -------
    Interval
        An enclosure of ``{x + y : x in a, y in b}``.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _lift(_arith.add, a, b)


def subtract(a, b) -> Interval:
    """Compute ``a - b``, rounded outward.

    Parameters
    ----------
    a, b : Interval or array_like
        Operands, broadcast together (finite points are read as point intervals).

    Returns
    -------
    Interval
        An enclosure of ``{x - y : x in a, y in b}``.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _lift(_arith.sub, a, b)


def negative(a) -> Interval:
    """Compute ``-a`` (exact).

    Parameters
    ----------
    a : Interval or array_like
        Operand (finite points are read as point intervals).

    Returns
    -------
    Interval
        ``[-hi, -lo]``.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _lift(_arith.neg, a)


def multiply(a, b) -> Interval:
    """Compute ``a * b``, rounded outward; a scalar factor takes a two-product shortcut.

    Parameters
    ----------
    a, b : Interval or array_like
        Operands, broadcast together (finite points are read as point intervals).

    Returns
    -------
    Interval
        An enclosure of ``{x y : x in a, y in b}``.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    if not isinstance(a, Interval) and np.ndim(a) == 0:
        a, b = b, a
    if not isinstance(b, Interval) and np.ndim(b) == 0:
        c = float(as_interval(b, "factor").lo)
        return _lift(lambda lo, hi: _arith.scale(c, lo, hi), a)
    return _lift(_arith.mul, a, b)


def _contains_zero(lo, hi):
    return (lo <= 0.0) & (hi >= 0.0)


def divide(a, b) -> Interval:
    """Compute ``a / b``; see :func:`optbound.interval._arith.div` for divisors containing 0.

    Parameters
    ----------
    a, b : Interval or array_like
        Operands, broadcast together (finite points are read as point intervals).

    Returns
    -------
    Interval
        An enclosure of the quotient set (its hull for a divisor containing 0; empty for a
        divisor ``[0, 0]``).

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _lift(
        _arith.div, a, b, may_empty=True, domain=lambda al, ah, bl, bh: _contains_zero(bl, bh)
    )


def sqr(a) -> Interval:
    """Compute ``a**2`` (tight: ``sqr([-1, 2]) = [0, 4]``, unlike ``a * a = [-2, 4]``).

    Parameters
    ----------
    a : Interval or array_like
        Operand (finite points are read as point intervals).

    Returns
    -------
    Interval
        An enclosure of ``{x^2 : x in a}``.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _lift(_arith.sqr, a)


def _integer_exponent(n) -> int:
    if isinstance(n, (float, np.floating)) and float(n).is_integer():
        return int(n)
    try:
        return operator.index(n)
    except TypeError:
        raise ValueError(
            f"interval power needs an integer exponent, got {n!r}; use exp(y * log(x))"
        ) from None


def power(a, n) -> Interval:
    """Compute the integer power ``a**n``; negative ``n`` gives ``1 / a**|n|``.

    Parameters
    ----------
    a : Interval or array_like
        Operand (finite points are read as point intervals).
    n : int
        The exponent (an integral float is accepted).

    Returns
    -------
    Interval
        An enclosure of ``{x^n : x in a}`` (for ``n < 0`` its hull where ``a`` contains 0).

    Raises
    ------
    ValueError
        If ``n`` is not an integer, or an operand holds a non-finite point.
    """
    k = _integer_exponent(n)
    if k < 0:
        return _lift(_arith.power, a, n=k, may_empty=True, domain=_contains_zero)
    return _lift(_arith.power, a, n=k)


def sqrt(a) -> Interval:
    """Compute the square root on its domain: ``sqrt([-1, 4]) = [0, 2]``; empty where ``a < 0``.

    Parameters
    ----------
    a : Interval or array_like
        Operand (finite points are read as point intervals).

    Returns
    -------
    Interval
        An enclosure of sqrt over ``a ∩ [0, inf)``, flagged partial where ``a`` leaves the domain.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _lift(_transcendental.sqrt, a, may_empty=True, domain=lambda lo, hi: lo < 0.0)


def exp(a) -> Interval:
    """Compute the exponential, rounded outward.

    Parameters
    ----------
    a : Interval or array_like
        Operand (finite points are read as point intervals).

    Returns
    -------
    Interval
        An enclosure of ``{e^x : x in a}``.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _lift(_transcendental.exp, a)


def log(a) -> Interval:
    """Compute the natural log on its domain: ``log([0, 1]) = [-inf, 0]``; empty where ``a <= 0``.

    Parameters
    ----------
    a : Interval or array_like
        Operand (finite points are read as point intervals).

    Returns
    -------
    Interval
        An enclosure of log over ``a ∩ (0, inf)``, flagged partial where ``a`` leaves the domain.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _lift(_transcendental.log, a, may_empty=True, domain=lambda lo, hi: lo <= 0.0)


def sin(a) -> Interval:
    """Compute the sine, rounded outward.

    Parameters
    ----------
    a : Interval or array_like
        Operand (finite points are read as point intervals).

    Returns
    -------
    Interval
        An enclosure of ``{sin x : x in a}``, within ``[-1, 1]``.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _lift(_transcendental.sin, a)


def cos(a) -> Interval:
    """Compute the cosine, rounded outward.

    Parameters
    ----------
    a : Interval or array_like
        Operand (finite points are read as point intervals).

    Returns
    -------
    Interval
        An enclosure of ``{cos x : x in a}``, within ``[-1, 1]``.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _lift(_transcendental.cos, a)


def atan2(y, x) -> Interval:
    """Compute the angle of ``(x, y)`` in ``[-pi, pi]``, rounded outward.

    Boxes meeting the negative x axis give all of ``[-pi, pi]``.

    Parameters
    ----------
    y, x : Interval or array_like
        Coordinates, broadcast together (finite points are read as point intervals).

    Returns
    -------
    Interval
        An enclosure of ``{atan2(v, u) : v in y, u in x}``.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _lift(_transcendental.atan2, y, x)


def absolute(a) -> Interval:
    """Compute ``|a|`` (exact).

    Parameters
    ----------
    a : Interval or array_like
        Operand (finite points are read as point intervals).

    Returns
    -------
    Interval
        ``{|x| : x in a}``.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _lift(_arith.absolute, a)


def minimum(a, b) -> Interval:
    """Compute the elementwise minimum of ``a`` and ``b`` (exact).

    Parameters
    ----------
    a, b : Interval or array_like
        Operands, broadcast together (finite points are read as point intervals).

    Returns
    -------
    Interval
        ``[min(a.lo, b.lo), min(a.hi, b.hi)]``.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _lift(_arith.minimum, a, b)


def maximum(a, b) -> Interval:
    """Compute the elementwise maximum of ``a`` and ``b`` (exact).

    Parameters
    ----------
    a, b : Interval or array_like
        Operands, broadcast together (finite points are read as point intervals).

    Returns
    -------
    Interval
        ``[max(a.lo, b.lo), max(a.hi, b.hi)]``.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _lift(_arith.maximum, a, b)


def hull(a, b) -> Interval:
    """Compute the smallest interval containing both (empty is the neutral element).

    Parameters
    ----------
    a, b : Interval or array_like
        Operands, broadcast together (finite points are read as point intervals).

    Returns
    -------
    Interval
        ``[min(a.lo, b.lo), max(a.hi, b.hi)]``.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    a, b = as_interval(a), as_interval(b)
    # The empty encoding (+inf, -inf) makes plain min/max correct without masking.
    return Interval._make(
        np.minimum(a.lo, b.lo),
        np.maximum(a.hi, b.hi),
        a._maybe_empty and b._maybe_empty,
        _partial_of([a, b], None),
    )


def intersection(a, b) -> Interval:
    """Intersect ``a`` and ``b``; disjoint pairs give empty entries (see :attr:`Interval.is_empty`).

    Parameters
    ----------
    a, b : Interval or array_like
        Operands, broadcast together (finite points are read as point intervals).

    Returns
    -------
    Interval
        ``[max(a.lo, b.lo), min(a.hi, b.hi)]``, empty where that is not an interval.

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    a, b = as_interval(a), as_interval(b)
    lo, hi = np.maximum(a.lo, b.lo), np.minimum(a.hi, b.hi)
    empty = lo > hi
    partial = _partial_of([a, b], None)
    if not np.any(empty):
        return Interval._make(lo, hi, False, partial)
    return Interval._make(np.where(empty, INF, lo), np.where(empty, -INF, hi), True, partial)


def _compare(a, b, strict: bool) -> np.ndarray:
    """Tri value of ``a < b`` (strict) or ``a <= b``; FALSE where either is empty.

    Never TRUE on partial entries (see :attr:`Interval.partial`).
    """
    a, b = as_interval(a), as_interval(b)
    if strict:
        certainly, never = a.hi < b.lo, a.lo >= b.hi
    else:
        certainly, never = a.hi <= b.lo, a.lo > b.hi
    if a._maybe_empty or b._maybe_empty:
        # No point of an empty set satisfies anything.
        empty = a.is_empty | b.is_empty
        certainly, never = certainly & ~empty, never | empty
    if a._partial is not None or b._partial is not None:
        # Where the value is undefined at some points, the comparison is not proven there.
        certainly = certainly & ~(a.partial | b.partial)
    return from_masks(certainly, never)


def less(a, b) -> np.ndarray:
    """Compare ``a < b``: TRUE if every pair satisfies it, FALSE if none does.

    Parameters
    ----------
    a, b : Interval or array_like
        Operands, broadcast together (finite points are read as point intervals).

    Returns
    -------
    numpy.ndarray of int8
        :class:`Tri` per entry (never TRUE on partial entries, FALSE where either is empty).

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _compare(a, b, strict=True)


def less_equal(a, b) -> np.ndarray:
    """Compare ``a <= b``: TRUE if every pair satisfies it, FALSE if none does.

    Parameters
    ----------
    a, b : Interval or array_like
        Operands, broadcast together (finite points are read as point intervals).

    Returns
    -------
    numpy.ndarray of int8
        :class:`Tri` per entry (never TRUE on partial entries, FALSE where either is empty).

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _compare(a, b, strict=False)


def greater(a, b) -> np.ndarray:
    """Compare ``a > b``: TRUE if every pair satisfies it, FALSE if none does.

    Parameters
    ----------
    a, b : Interval or array_like
        Operands, broadcast together (finite points are read as point intervals).

    Returns
    -------
    numpy.ndarray of int8
        :class:`Tri` per entry (never TRUE on partial entries, FALSE where either is empty).

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _compare(b, a, strict=True)


def greater_equal(a, b) -> np.ndarray:
    """Compare ``a >= b``: TRUE if every pair satisfies it, FALSE if none does.

    Parameters
    ----------
    a, b : Interval or array_like
        Operands, broadcast together (finite points are read as point intervals).

    Returns
    -------
    numpy.ndarray of int8
        :class:`Tri` per entry (never TRUE on partial entries, FALSE where either is empty).

    Raises
    ------
    ValueError
        If an operand holds a non-finite point.
    """
    return _compare(b, a, strict=False)


UFUNC_IMPL.update(
    {
        np.add: add,
        np.subtract: subtract,
        np.negative: negative,
        np.positive: as_interval,
        np.multiply: multiply,
        np.divide: divide,
        np.square: sqr,
        np.power: power,
        np.sqrt: sqrt,
        np.exp: exp,
        np.log: log,
        np.sin: sin,
        np.cos: cos,
        np.arctan2: atan2,
        np.absolute: absolute,
        np.minimum: minimum,
        np.maximum: maximum,
        np.less: less,
        np.less_equal: less_equal,
        np.greater: greater,
        np.greater_equal: greater_equal,
    }
)
