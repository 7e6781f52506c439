"""The small interface every set type implements (in the spirit of LazySets.jl).

A set knows its dimension, tests membership of many points at once, and evaluates its
support function ``h(d) = max {d^T x : x in set}``. Everything else (bounding boxes,
clipping, comparisons) is built on these three. It lives in the core because ``Box``, which
every layer uses, implements it; the set types of ``optbound.sets`` implement it too.
"""

from __future__ import annotations

from abc import ABC, abstractmethod

import numpy as np


class ConvexSet(ABC):
    """A closed convex subset of R^n."""

    @property
    @abstractmethod
    def dim(self) -> int:
        """Dimension n of the ambient space."""

    @abstractmethod
    def contains(self, X, tol: float = 1e-9) -> np.ndarray | bool:
        """Membership of each row of ``X`` (shape (m, n)); a single point gives a bool.

        ``tol`` is a relative slack on the defining inequality, so boundary points pass.
        """

    @abstractmethod
    def support(self, d) -> np.ndarray | float:
        """Support function ``max {d^T x : x in set}`` for each row of ``d`` (may be +inf)."""

    def extent(self, a) -> tuple[float, float]:
        """Range ``[min a^T x, max a^T x]`` of the linear functional ``a`` over the set."""
        a = np.asarray(a, dtype=float)
        return -float(self.support(-a)), float(self.support(a))
