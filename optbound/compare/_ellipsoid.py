"""Accept an ``Ellipsoid``, a ``BoundResult`` whose ``set`` is one, or any object carrying one
in ``.ellipsoid``."""

from __future__ import annotations

from optbound.sets import Ellipsoid
from optbound.sets.result import BoundResult


def bound_set(bound):
    """The set of a result (``BoundResult.set``, else ``.ellipsoid``), or ``bound`` itself."""
    if isinstance(bound, BoundResult):
        return bound.set
    return getattr(bound, "ellipsoid", bound)


def as_ellipsoid(name: str, bound) -> Ellipsoid:
    """The ellipsoid of ``bound`` (an Ellipsoid, OuterResult, analytic result ...)."""
    ellipsoid = bound_set(bound)
    if not isinstance(ellipsoid, Ellipsoid):
        raise ValueError(f"{name} must be an Ellipsoid or carry one in .ellipsoid, got {bound!r}")
    return ellipsoid


def same_dim(A: Ellipsoid, B: Ellipsoid) -> None:
    if A.dim != B.dim:
        raise ValueError(f"the two bounds have different dimensions, {A.dim} and {B.dim}")
