"""Set representations: the common interface and the concrete types.

``Ellipsoid``, ``Strip``, ``Halfspace`` and ``Box`` validate their input on construction and
are immutable afterwards, so a set that exists is always a valid set. ``PseudoEllipsoid`` is
an ellipsoid in the lifted space of a ``PolynomialLifting`` [BH, eq. (10)]. ``Zonotope`` and
``ConstrainedZonotope`` (Scott et al. 2016) carry generator representations whose every
operation is guaranteed in floating point.

The set protocol (what a type must define, may add and gets for free) is written down in
``optbound.sets.base``; the base of every bound result in ``optbound.sets.result``. ``Box`` is
defined in :mod:`optbound._core` (every layer, interval arithmetic included, uses boxes) and
exported here unchanged.
"""

from optbound import _fresh  # noqa: F401  (drops stale kernel caches before any is loaded)
from optbound._core import Box
from optbound._lazy import attach
from optbound.sets.base import ConvexSet, QuadraticDescription
from optbound.sets.constrained_zonotope import ConstrainedZonotope
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.lifting import PolynomialLifting
from optbound.sets.pseudo_ellipsoid import PseudoEllipsoid
from optbound.sets.quadratic import QuadraticSet
from optbound.sets.result import BoundResult
from optbound.sets.strip import Halfspace, Strip
from optbound.sets.zonotope import Zonotope

__all__ = [
    "BoundResult",
    "Box",
    "ConstrainedZonotope",
    "ConvexSet",
    "Ellipsoid",
    "Halfspace",
    "PolynomialLifting",
    "PseudoEllipsoid",
    "QuadraticDescription",
    "QuadraticSet",
    "Strip",
    "Zonotope",
]

__getattr__, __dir__ = attach(__name__, public=__all__, submodules=())
