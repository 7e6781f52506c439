"""The required part of the set protocol: ``ConvexSet`` and ``QuadraticDescription``.

The whole protocol (what a set type must define, what it may add, what it gets for free) is
written down in :mod:`optbound.sets.base`, which exports these names with it. They are defined
here, in the core, because ``Box`` implements them and every layer, interval arithmetic
included, uses boxes.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass

import numpy as np

#: One linear range ``lo <= a^T x <= hi``: a finite non-zero normal ``a`` (n,) and float ends,
#: of which one may be infinite (``-inf``/``+inf``: a half-space).
LinearRange = tuple[np.ndarray, float, float]


@dataclass(frozen=True)
class QuadraticDescription:
    """A set as the intersection of quadratic inequalities and linear ranges in ``[x; 1]``.

    The set equals ``{x : q(x) <= 0 for q in forms} ∩ {x : lo <= a^T x <= hi for (a, lo, hi)
    in ranges}`` exactly: a description that is only an outer approximation would make the
    SDP layer's bounds contain a larger set than asked for (still outer bounds, but of the
    wrong set), one that is smaller would make them unsound.

    Attributes
    ----------
    forms : tuple of QuadraticSet
        Used by the S-procedure as they are, one multiplier each [Boyd, El Ghaoui, Feron &
        Balakrishnan 1994, Sect. 2.6.3].
    ranges : tuple of LinearRange
        Kept apart from ``forms`` because the SDP layer first clips each range to the bounded
        members of an intersection (``optbound.optimal.lift``), which makes the S-procedure
        tight where the raw product form ``(a^T x - lo)(a^T x - hi) <= 0`` is not
        [HS96, Sect. 4].
    """

    forms: tuple = ()  # of optbound.sets.QuadraticSet (a higher layer: not imported here)
    ranges: tuple[LinearRange, ...] = ()


class ConvexSet(ABC):
    """A closed convex subset of R^n (the required part of the protocol, see optbound.sets.base)."""

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
        """Range ``[min a^T x, max a^T x]`` of the linear functional ``a`` over the set.

        Parameters
        ----------
        a : array_like, shape (n,)
            The direction of the linear functional.

        Returns
        -------
        tuple of float
            ``(-support(-a), support(a))``, as guaranteed as the type's ``support``.
        """
        a = np.asarray(a, dtype=float)
        return -float(self.support(-a)), float(self.support(a))
