"""Strips ``{x : |a^T x - b| <= 1}`` [HS96, eq. (23)] and half-spaces ``{x : a^T x <= b}``.

References
----------
[HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
on an angle measurement technique", IFAC, 1996.
"""

from __future__ import annotations

import math

import numpy as np

from optbound._core import MAG
from optbound._core import validate as v
from optbound.sets.base import ConvexSet, QuadraticDescription


def _normal(name: str, a) -> np.ndarray:
    a = v.finite_vector(name, a).copy()
    norm = math.hypot(*a.tolist())  # scaled internally: no overflow or underflow
    if norm == 0.0:
        raise ValueError(f"{name} must be a non-zero vector")
    if not 1.0 / MAG <= norm <= MAG:
        raise ValueError(
            f"{name} must have a norm in [{1 / MAG:.0e}, {MAG:.0e}] (the supported domain; the "
            f"width 2 / ||a|| of a strip), got {norm:.3e}"
        )
    a.setflags(write=False)
    return a


class _LinearSet(ConvexSet):
    """Shared part of the sets bounded by hyperplanes with normal ``a`` and offset ``b``."""

    def __init__(self, a, b):
        self._a = _normal("a", a)
        self._b = v.finite_scalar("b", b)
        if abs(self._b) > MAG * MAG:
            raise ValueError(f"b must satisfy |b| <= {MAG * MAG:.0e} (the supported domain)")

    @property
    def a(self) -> np.ndarray:
        return self._a

    @property
    def b(self) -> float:
        return self._b

    @property
    def dim(self) -> int:
        return self._a.shape[0]

    def __repr__(self) -> str:
        return f"{type(self).__name__}(a={self._a.tolist()}, b={self._b})"

    def enclosing_ellipsoid(self) -> None:
        """None: the set is unbounded."""
        return None

    def _along_normal(self, d) -> tuple[np.ndarray, np.ndarray, bool]:
        """Directions as ``s * a``: the factors s, which rows are parallel to a, single flag.

        The support function of such a set is finite only along multiples of its normal.
        """
        dirs, single = v.points("d", d, self.dim)
        s = dirs @ self._a / (self._a @ self._a)
        parallel = np.all(np.isclose(dirs, np.outer(s, self._a), rtol=1e-12, atol=1e-15), axis=1)
        return s, parallel, single

    @staticmethod
    def _finite_where(mask: np.ndarray, values: np.ndarray, single: bool):
        """+inf except where ``mask``, which gets ``values``; a float for a single direction."""
        out = np.full(mask.shape[0], np.inf)
        out[mask] = values
        return float(out[0]) if single else out


class Strip(_LinearSet):
    """The slab between two parallel hyperplanes, ``{x : |a^T x - b| <= 1}`` [HS96, eq. (23)].

    Parameters
    ----------
    a : array_like, shape (n,)
        Non-zero normal; its length sets the width ``2 / ||a||``.
    b : float
        Offset: the strip is ``b - 1 <= a^T x <= b + 1``.

    Raises
    ------
    ValueError
        If ``a`` is zero, non-finite or has a norm outside ``[1e-60, 1e60]``, or ``b`` is
        non-finite or ``|b| > 1e120`` (the supported domain, ``optbound._core.domain``).
    TypeError
        If an argument is complex or not numeric.

    Examples
    --------
    >>> from optbound.sets import Strip
    >>> S = Strip([0.0, 2.0], 1.0)  # 0 <= x_2 <= 1
    >>> S.width
    1.0
    >>> S.contains([[5.0, 0.9], [0.0, 1.1]]).tolist()
    [True, False]
    >>> S.extent([0.0, 1.0])
    (0.0, 1.0)
    """

    @classmethod
    def from_bounds(cls, a, lo: float, hi: float) -> Strip:
        """The strip ``{x : lo <= a^T x <= hi}``; requires ``lo < hi``.

        Parameters
        ----------
        a : array_like, shape (n,)
            Non-zero normal.
        lo, hi : float
            Bounds of ``a^T x``, ``lo < hi``.

        Returns
        -------
        Strip
            The strip with normal ``a / h`` and offset ``m / h`` (``m``, ``h`` the midpoint and
            half-width of ``[lo, hi]``).

        Raises
        ------
        ValueError
            If an argument is non-finite, ``lo >= hi``, or the result leaves the supported domain.
        """
        lo, hi = v.finite_scalar("lo", lo), v.finite_scalar("hi", hi)
        if not lo < hi:
            raise ValueError(f"lo must be smaller than hi, got lo={lo}, hi={hi}")
        a = _normal("a", a)
        half = 0.5 * hi - 0.5 * lo  # no overflow for bounds near the float range
        with np.errstate(over="ignore", under="ignore"):
            return cls(a / half, (0.5 * hi + 0.5 * lo) / half)

    @property
    def width(self) -> float:
        """Euclidean distance between the two boundary planes."""
        return 2.0 / float(np.linalg.norm(self._a))

    def quadratic_description(self) -> QuadraticDescription:
        """One range, ``b - 1 <= a^T x <= b + 1``.

        Returns
        -------
        QuadraticDescription
            The strip exactly, as one linear range.
        """
        return QuadraticDescription(ranges=((self._a, self._b - 1.0, self._b + 1.0),))

    def contains(self, X, tol: float = 1e-9) -> np.ndarray | bool:
        """Float test ``|a^T x - b| <= 1 + tol`` per row of X.

        Parameters
        ----------
        X : array_like, shape (m, n) or (n,)
            Points, one per row; a single point gives a bool.
        tol : float, default 1e-9
            Slack so that boundary points pass.

        Returns
        -------
        ndarray of bool, shape (m,), or bool
            True where the point is inside.

        Raises
        ------
        ValueError
            If the argument is non-finite or its dimension is not ``dim``.
        """
        pts, single = v.points("X", X, self.dim)
        inside = np.abs(pts @ self._a - self._b) <= 1.0 + tol
        return bool(inside[0]) if single else inside

    def support(self, d) -> np.ndarray | float:
        """Support function: finite only along multiples ``d = s a`` of the normal.

        ``d = s a`` gives ``s (b + 1)`` for ``s >= 0`` and ``s (b - 1)`` for ``s < 0``.

        Parameters
        ----------
        d : array_like, shape (m, n) or (n,)
            Directions, one per row; a single direction gives a float.

        Returns
        -------
        ndarray, shape (m,), or float
            ``h(d)`` per direction, ``+inf`` where ``d`` is not parallel to ``a``.

        Raises
        ------
        ValueError
            If the argument is non-finite or its dimension is not ``dim``.
        """
        s, parallel, single = self._along_normal(d)
        sp = s[parallel]
        values = np.where(sp >= 0, sp * (self._b + 1), sp * (self._b - 1))
        return self._finite_where(parallel, values, single)


class Halfspace(_LinearSet):
    """The half-space ``{x : a^T x <= b}``.

    Parameters
    ----------
    a : array_like, shape (n,)
        Non-zero outward normal.
    b : float
        Offset.

    Raises
    ------
    ValueError
        If ``a`` is zero, non-finite or has a norm outside ``[1e-60, 1e60]``, or ``b`` is
        non-finite or ``|b| > 1e120`` (the supported domain, ``optbound._core.domain``).
    TypeError
        If an argument is complex or not numeric.
    """

    def quadratic_description(self) -> QuadraticDescription:
        """One range, ``-inf <= a^T x <= b``.

        Returns
        -------
        QuadraticDescription
            The half-space exactly, as one linear range.
        """
        return QuadraticDescription(ranges=((self._a, -np.inf, self._b),))

    def contains(self, X, tol: float = 1e-9) -> np.ndarray | bool:
        """Float test ``a^T x <= b + tol max(1, |b|)`` per row of X.

        Parameters
        ----------
        X : array_like, shape (m, n) or (n,)
            Points, one per row; a single point gives a bool.
        tol : float, default 1e-9
            Relative slack so that boundary points pass.

        Returns
        -------
        ndarray of bool, shape (m,), or bool
            True where the point is inside.

        Raises
        ------
        ValueError
            If the argument is non-finite or its dimension is not ``dim``.
        """
        pts, single = v.points("X", X, self.dim)
        scale = max(1.0, abs(self._b))
        inside = pts @ self._a <= self._b + tol * scale
        return bool(inside[0]) if single else inside

    def support(self, d) -> np.ndarray | float:
        """Support function: ``s b`` along non-negative multiples ``d = s a``, else ``+inf``.

        Parameters
        ----------
        d : array_like, shape (m, n) or (n,)
            Directions, one per row; a single direction gives a float.

        Returns
        -------
        ndarray, shape (m,), or float
            ``h(d)`` per direction.

        Raises
        ------
        ValueError
            If the argument is non-finite or its dimension is not ``dim``.
        """
        s, parallel, single = self._along_normal(d)
        bounded = parallel & (s >= 0)
        return self._finite_where(bounded, s[bounded] * self._b, single)
