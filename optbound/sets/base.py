"""The set protocol: what a set type must define, what it may add, and what it gets for free.

Written down in the spirit of LazySets.jl's interface files and cvxpy's atoms: a new set type
is one class in its own module; the layers above (the SDP references, the comparisons, the
paver, the plots) find what they need through the methods named here, never by ``isinstance``
on concrete types. ``docs/extending.md`` walks through adding a type.

Required (abstract in :class:`ConvexSet`)
-----------------------------------------
``dim -> int`` (property)
    Dimension n of the ambient space.
``contains(X, tol=1e-9) -> ndarray of bool | bool``
    Membership of each row of ``X`` (m, n); one point (n,) gives a bool. ``tol`` is a relative
    slack on the defining inequality (so boundary points pass); a float64 test, not a proof.
``support(d) -> ndarray | float``
    ``h(d) = max {d^T x : x in set}`` per row of ``d`` (may be ``+inf``; ``-inf`` when empty).

Free (defined here from the required methods; override when a type knows better)
--------------------------------------------------------------------------------
``extent(a) -> (float, float)``
    The range ``[min a^T x, max a^T x]``, from two support evaluations.

Optional capabilities (a type implements those its users need)
--------------------------------------------------------------
Each is a ``typing.Protocol`` below (``isinstance`` works with them; a consumer on a hot path
may test for the methods directly instead, as ``isinstance`` with a runtime protocol inspects
every member of the protocol on each call). ``optbound.optimal`` refuses a member without
the two methods of :class:`QuadraticallyDescribed` by a ``ValueError`` naming them.

:class:`QuadraticallyDescribed` - the SDP layer (``optbound.optimal``)
    ``quadratic_description() -> QuadraticDescription``: the set written *exactly* as
    quadratic inequalities ``[x; 1]^T F [x; 1] <= 0`` and linear ranges ``lo <= a^T x <= hi``
    (the S-procedure's currency). ``enclosing_ellipsoid() -> Ellipsoid | None``: an ellipsoid
    known to contain the set, or None; the SDP layer clips the other members' linear ranges to
    it (raise :class:`EmptySetError` if the set is found empty). With both, the type works in
    ``optimal.outer_ellipsoid`` and everything built on it.
:class:`BoxProver` - soundness proofs and pavings of the set
    For ``optimal.optimal_pseudo_ellipsoid``, ``localization.relative_bearing`` and
    ``interval.sivia`` on its box test. ``tri_contains(boxes) -> ndarray of int8``: for
    boxes (m, n, 2) of ``[lo, hi]`` rows,
    ``Tri.TRUE`` where the box is proven inside the set, ``Tri.FALSE`` where proven disjoint,
    ``Tri.UNKNOWN`` otherwise; proven with outward-rounded interval arithmetic
    (``optbound.interval``), so a TRUE is a proof for the floats read as exact numbers.
:class:`VolumeBracket` - size comparisons and reports
    ``volume_bounds(eps, ...) -> (lower, upper)``: a certified bracket of the n-volume (for
    types whose volume has no exact float formula, e.g. by a paving of width ``eps``).
:class:`Outlined` - the plots (``optbound.report.figures``)
    ``boundary(resolution) -> ndarray (m, 2) | list of ndarray``: ordered points tracing the
    boundary of a 2-D set (one array per closed curve).

Registration
------------
A type becomes public by one line in ``optbound/sets/__init__.py`` (import and ``__all__``);
nothing in ``optimal`` or ``compare`` names concrete set types for dispatch.

:class:`ConvexSet`, :class:`QuadraticDescription` and ``LinearRange`` are defined in
:mod:`optbound._core.convex` (``Box``, a core type every layer uses, implements them) and
exported here with the rest of the protocol.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol, runtime_checkable

import numpy as np

from optbound._core.convex import ConvexSet, LinearRange, QuadraticDescription

if TYPE_CHECKING:
    from optbound.sets.ellipsoid import Ellipsoid

__all__ = [
    "BoxProver",
    "ConvexSet",
    "EmptySetError",
    "LinearRange",
    "Outlined",
    "QuadraticDescription",
    "QuadraticallyDescribed",
    "VolumeBracket",
]


class EmptySetError(ValueError):
    """A set was found to be empty where a non-empty one is needed (e.g. to clip to it)."""


@runtime_checkable
class QuadraticallyDescribed(Protocol):
    """A set the SDP layer can bound: exact quadratic description, optional enclosing ellipsoid."""

    @property
    def dim(self) -> int: ...

    def quadratic_description(self) -> QuadraticDescription:
        """The set exactly, as quadratic forms and linear ranges (:class:`QuadraticDescription`)."""
        ...

    def enclosing_ellipsoid(self) -> Ellipsoid | None:
        """An ellipsoid containing the set, or None; raises :class:`EmptySetError` if empty."""
        ...


@runtime_checkable
class BoxProver(Protocol):
    """A set that proves membership of whole boxes with interval arithmetic."""

    def tri_contains(self, boxes) -> np.ndarray:
        """``Tri`` per box of ``boxes`` (m, n, 2): TRUE inside, FALSE disjoint, else UNKNOWN.

        Parameters
        ----------
        boxes : array_like, shape (m, n, 2)
            Boxes as ``[lo, hi]`` rows per coordinate.

        Returns
        -------
        np.ndarray of int8, shape (m,)
            ``Tri`` value per box.
        """
        ...


@runtime_checkable
class VolumeBracket(Protocol):
    """A set with a certified bracket of its volume."""

    def volume_bounds(self, eps: float) -> tuple[float, float]:
        """``(lower, upper)`` with ``lower <= volume <= upper``, resolution ``eps``.

        Parameters
        ----------
        eps : float
            Resolution of the bracket (e.g. the width of a paving's boxes).

        Returns
        -------
        tuple of float
            ``(lower, upper)``.
        """
        ...


@runtime_checkable
class Outlined(Protocol):
    """A 2-D set that can trace its boundary for plots."""

    def boundary(self, resolution: int) -> np.ndarray | list[np.ndarray]:
        """Ordered boundary points, one (m, 2) array per closed curve.

        Parameters
        ----------
        resolution : int
            Resolution of the trace (types with an exact polygon ignore it).

        Returns
        -------
        np.ndarray or list of np.ndarray
            The closed curve(s), shape (m, 2) each.
        """
        ...
