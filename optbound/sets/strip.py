"""Strips ``{x : |a^T x - b| <= 1}`` [HS96, eq. (23)] and half-spaces ``{x : a^T x <= b}``."""

from __future__ import annotations

import numpy as np

from optbound.sets import _validate as v
from optbound.sets.base import ConvexSet


def _normal(name: str, a) -> np.ndarray:
    a = v.finite_vector(name, a)
    if not np.any(a):
        raise ValueError(f"{name} must be a non-zero vector")
    a.setflags(write=False)
    return a


class Strip(ConvexSet):
    """The slab between two parallel hyperplanes, ``{x : |a^T x - b| <= 1}`` [HS96, eq. (23)].

    Parameters
    ----------
    a : array_like, shape (n,)
        Non-zero normal; its length sets the width ``2 / ||a||``.
    b : float
        Offset: the strip is ``b - 1 <= a^T x <= b + 1``.
    """

    def __init__(self, a, b):
        self._a = _normal("a", a)
        self._b = v.finite_scalar("b", b)

    @classmethod
    def from_bounds(cls, a, lo: float, hi: float) -> Strip:
        """The strip ``{x : lo <= a^T x <= hi}``; requires ``lo < hi``."""
        lo, hi = v.finite_scalar("lo", lo), v.finite_scalar("hi", hi)
        if not lo < hi:
            raise ValueError(f"lo must be smaller than hi, got lo={lo}, hi={hi}")
        a = _normal("a", a)
        half = 0.5 * (hi - lo)
        return cls(a / half, 0.5 * (hi + lo) / half)

    @property
    def a(self) -> np.ndarray:
        return self._a

    @property
    def b(self) -> float:
        return self._b

    @property
    def dim(self) -> int:
        return self._a.shape[0]

    @property
    def width(self) -> float:
        """Euclidean distance between the two boundary planes."""
        return 2.0 / float(np.linalg.norm(self._a))

    def __repr__(self) -> str:
        return f"Strip(a={self._a.tolist()}, b={self._b})"

    def contains(self, X, tol: float = 1e-9) -> np.ndarray | bool:
        pts, single = v.points("X", X, self.dim)
        inside = np.abs(pts @ self._a - self._b) <= 1.0 + tol
        return bool(inside[0]) if single else inside

    def support(self, d) -> np.ndarray | float:
        dirs, single = v.points("d", d, self.dim)
        h = np.full(dirs.shape[0], np.inf)
        # Bounded only along +-a: d = s a gives s (b + 1) for s > 0 and s (b - 1) for s < 0.
        s = dirs @ self._a / (self._a @ self._a)
        parallel = np.all(np.isclose(dirs, np.outer(s, self._a), rtol=1e-12, atol=1e-15), axis=1)
        h[parallel] = np.where(
            s[parallel] >= 0, s[parallel] * (self._b + 1), s[parallel] * (self._b - 1)
        )
        return float(h[0]) if single else h


class Halfspace(ConvexSet):
    """The half-space ``{x : a^T x <= b}``."""

    def __init__(self, a, b):
        self._a = _normal("a", a)
        self._b = v.finite_scalar("b", b)

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
        return f"Halfspace(a={self._a.tolist()}, b={self._b})"

    def contains(self, X, tol: float = 1e-9) -> np.ndarray | bool:
        pts, single = v.points("X", X, self.dim)
        scale = max(1.0, abs(self._b))
        inside = pts @ self._a <= self._b + tol * scale
        return bool(inside[0]) if single else inside

    def support(self, d) -> np.ndarray | float:
        dirs, single = v.points("d", d, self.dim)
        h = np.full(dirs.shape[0], np.inf)
        s = dirs @ self._a / (self._a @ self._a)
        parallel = np.all(np.isclose(dirs, np.outer(s, self._a), rtol=1e-12, atol=1e-15), axis=1)
        bounded = parallel & (s >= 0)
        h[bounded] = s[bounded] * self._b
        return float(h[0]) if single else h
