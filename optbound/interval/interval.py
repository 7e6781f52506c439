"""``Interval``: an array of closed real intervals ``[lo, hi]`` over numpy.

An ``Interval`` holds two float64 arrays of one (broadcast) shape. Arithmetic operators and
numpy ufuncs (``np.sqrt(X)``, ``np.sin(X)``, ``x * X``, ...) dispatch to outward-rounded
interval versions, so a function written once with ordinary operators evaluates on float
arrays (its value) and on ``Interval`` arrays (its natural inclusion function [LJMW97,
Sect. 3.2]).

**Empty intervals** are stored NaN-free as ``lo = +inf, hi = -inf``; :attr:`Interval.is_empty`
is the mask. They arise from intersections and from functions evaluated outside their domain
(``sqrt([-2, -1])``) and propagate: any operation with an empty operand is empty there.

**Partial values.** ``sqrt([-1, 4]) = [0, 2]`` encloses sqrt over the part of the box where it
is defined. Such entries are flagged (:attr:`Interval.partial`, propagated by every operation,
a simplified IEEE 1788 "defined" decoration) so that a test never proves a constraint TRUE on
a box where the function is undefined somewhere.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

INF = np.inf

#: numpy ufunc -> interval implementation; filled by :mod:`optbound.interval.functions`.
UFUNC_IMPL: dict[np.ufunc, Callable] = {}


class Interval:
    """Array of intervals ``[lo, hi]``; ``lo`` and ``hi`` broadcast to one shape.

    Parameters
    ----------
    lo, hi
        Lower and upper bounds (array-like, broadcastable). ``hi`` defaults to ``lo`` (point
        intervals). Infinite bounds are allowed (``[-inf, 3]``); NaN, ``lo > hi``,
        ``lo = +inf`` and ``hi = -inf`` are errors. Use :meth:`Interval.empty` for empties.

    Notes
    -----
    Division by an interval containing 0 gives the hull of the extended quotient set (e.g.
    ``[1, 2] / [0, 1] = [1, +inf]``, ``[1, 2] / [-1, 1] = [-inf, +inf]``) and is empty for a
    divisor ``[0, 0]``. Comparisons ``<, <=, >, >=`` return :class:`~optbound.interval.Tri`
    arrays (TRUE / FALSE / UNKNOWN); ``==`` is not overloaded.

    Examples
    --------
    Bounds are rounded outward, so the exact range is enclosed with a float to spare:

    >>> X = Interval([1.0, -1.0], [2.0, 4.0])
    >>> Y = X * X
    >>> Y.lo.tolist(), Y.hi.tolist()
    ([0.9999999999999998, -4.000000000000001], [4.000000000000001, 16.000000000000004])
    >>> Z = np.sqrt(Interval(-1.0, 4.0))
    >>> float(Z.lo), float(Z.hi), bool(Z.partial)
    (0.0, 2.0000000000000004, True)
    """

    __slots__ = ("_maybe_empty", "_partial", "hi", "lo")

    def __init__(self, lo, hi=None):
        lo = np.asarray(lo, dtype=float)
        hi = lo if hi is None else np.asarray(hi, dtype=float)
        for name, arr in (("lo", lo), ("hi", hi)):
            if np.any(np.isnan(arr)):
                raise ValueError(f"{name} must not contain NaN")
        try:
            lo, hi = np.broadcast_arrays(lo, hi)
        except ValueError:
            raise ValueError(
                f"lo and hi must broadcast to one shape, got {lo.shape} and {hi.shape}"
            ) from None
        if np.any(lo > hi):
            raise ValueError("lo must be <= hi elementwise (use Interval.empty for empty sets)")
        if np.any(lo == INF) or np.any(hi == -INF):
            raise ValueError("lo must not be +inf and hi must not be -inf")
        self.lo, self.hi, self._maybe_empty, self._partial = lo.copy(), hi.copy(), False, None

    @classmethod
    def _make(
        cls, lo: np.ndarray, hi: np.ndarray, maybe_empty: bool = False, partial=None
    ) -> Interval:
        """Wrap trusted bound arrays without validation (the hot path of SIVIA).

        ``maybe_empty`` False promises no empty entry; ``partial`` None promises no partial one.
        """
        out = object.__new__(cls)
        out.lo, out.hi, out._maybe_empty, out._partial = lo, hi, maybe_empty, partial
        return out

    @classmethod
    def empty(cls, shape=()) -> Interval:
        """An array of empty intervals."""
        return cls._make(np.full(shape, INF), np.full(shape, -INF), True)

    @classmethod
    def entire(cls, shape=()) -> Interval:
        """An array of ``[-inf, +inf]``."""
        return cls._make(np.full(shape, -INF), np.full(shape, INF))

    # ----- array protocol -------------------------------------------------------------------
    @property
    def shape(self) -> tuple[int, ...]:
        return self.lo.shape

    @property
    def ndim(self) -> int:
        return self.lo.ndim

    @property
    def size(self) -> int:
        return self.lo.size

    def __len__(self) -> int:
        return len(self.lo)

    def __getitem__(self, index) -> Interval:
        partial = (
            None if self._partial is None else np.broadcast_to(self._partial, self.shape)[index]
        )
        return Interval._make(self.lo[index], self.hi[index], self._maybe_empty, partial)

    def __repr__(self) -> str:
        return f"Interval(lo={self.lo!r}, hi={self.hi!r})"

    # ----- set properties -------------------------------------------------------------------
    @property
    def is_empty(self) -> np.ndarray:
        """Boolean mask of the empty entries."""
        return self.lo > self.hi

    @property
    def partial(self) -> np.ndarray:
        """Mask of entries computed from inputs partly outside a function's domain (or empty)."""
        flags = np.zeros(self.shape, dtype=bool) if self._partial is None else self._partial
        return np.broadcast_to(flags, self.shape) | self.is_empty

    def width(self) -> np.ndarray:
        """Return ``hi - lo`` rounded up (an upper bound of the true width).

        Returns
        -------
        numpy.ndarray
            The widths, 0 for empty entries.
        """
        with np.errstate(invalid="ignore"):
            w = np.nextafter(self.hi - self.lo, INF)
        return np.where(self.is_empty, 0.0, w)

    def midpoint(self) -> np.ndarray:
        """A point inside each interval near its centre (finite even for unbounded ones).

        Returns
        -------
        numpy.ndarray
            ``(lo + hi) / 2`` clipped to ``[lo, hi]``, infinite bounds replaced by the largest
            float.

        Raises
        ------
        ValueError
            If any entry is empty: an empty set has no midpoint.
        """
        if np.any(self.is_empty):
            raise ValueError("midpoint of an empty interval is undefined")
        big = np.finfo(float).max
        lo, hi = np.maximum(self.lo, -big), np.minimum(self.hi, big)
        return np.clip(0.5 * lo + 0.5 * hi, lo, hi)  # halves first: no overflow

    def contains(self, x) -> np.ndarray:
        """Test whether each point ``x`` lies in the corresponding interval.

        Parameters
        ----------
        x : array_like
            Points, broadcastable to the interval's shape.

        Returns
        -------
        numpy.ndarray of bool
            ``lo <= x <= hi`` elementwise (False on empty entries).
        """
        return (self.lo <= x) & (x <= self.hi)

    def subset_of(self, other) -> np.ndarray:
        """Test whether each interval is included in ``other``.

        Parameters
        ----------
        other : Interval or array_like
            Intervals, or finite points read as point intervals.

        Returns
        -------
        numpy.ndarray of bool
            ``other.lo <= lo`` and ``hi <= other.hi`` elementwise; True on empty entries (empty
            is a subset of everything).

        Raises
        ------
        ValueError
            If ``other`` holds non-finite points.
        """
        other = as_interval(other, "other")
        return self.is_empty | ((other.lo <= self.lo) & (self.hi <= other.hi))

    # ----- numpy dispatch -------------------------------------------------------------------
    def __array_ufunc__(self, ufunc, method, *inputs, **kwargs):
        impl = UFUNC_IMPL.get(ufunc)
        if method != "__call__" or kwargs or impl is None:
            return NotImplemented
        return impl(*inputs)

    def __add__(self, other):
        return UFUNC_IMPL[np.add](self, other)

    def __radd__(self, other):
        return UFUNC_IMPL[np.add](other, self)

    def __sub__(self, other):
        return UFUNC_IMPL[np.subtract](self, other)

    def __rsub__(self, other):
        return UFUNC_IMPL[np.subtract](other, self)

    def __mul__(self, other):
        return UFUNC_IMPL[np.multiply](self, other)

    def __rmul__(self, other):
        return UFUNC_IMPL[np.multiply](other, self)

    def __truediv__(self, other):
        return UFUNC_IMPL[np.divide](self, other)

    def __rtruediv__(self, other):
        return UFUNC_IMPL[np.divide](other, self)

    def __pow__(self, n):
        return UFUNC_IMPL[np.power](self, n)

    def __neg__(self):
        return UFUNC_IMPL[np.negative](self)

    def __pos__(self):
        return self

    def __abs__(self):
        return UFUNC_IMPL[np.absolute](self)

    def __lt__(self, other):
        return UFUNC_IMPL[np.less](self, other)

    def __le__(self, other):
        return UFUNC_IMPL[np.less_equal](self, other)

    def __gt__(self, other):
        return UFUNC_IMPL[np.greater](self, other)

    def __ge__(self, other):
        return UFUNC_IMPL[np.greater_equal](self, other)


def as_interval(x, name: str = "operand") -> Interval:
    """``x`` itself if it is an ``Interval``, else the point intervals ``[x, x]``.

    Points must be finite: ``[inf, inf]`` is not an interval of reals.

    Parameters
    ----------
    x : Interval or array_like
        Intervals, or points.
    name : str
        The argument's name in the error message.

    Returns
    -------
    Interval
        ``x`` unchanged, or the point intervals of ``x``.

    Raises
    ------
    ValueError
        If ``x`` holds a non-finite point.
    """
    if isinstance(x, Interval):
        return x
    arr = np.asarray(x, dtype=float)
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite to act as a point interval, got {x}")
    return Interval._make(arr, arr)
