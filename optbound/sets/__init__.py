"""Set representations: the common interface and the concrete types.

``Ellipsoid``, ``Strip``, ``Halfspace`` and ``Box`` validate their input on construction and
are immutable afterwards, so a set that exists is always a valid set. ``PseudoEllipsoid`` is
an ellipsoid in the lifted space of a ``PolynomialLifting`` [BH, eq. (10)].

The set protocol (what a type must define, may add and gets for free) is written down in
``optbound.sets.base``; the base of every bound result in ``optbound.sets.result``. ``Box`` is
defined in :mod:`optbound._core` (every layer, interval arithmetic included, uses boxes) and
exported here unchanged.
"""

from optbound._core import Box
from optbound.sets.base import ConvexSet, QuadraticDescription
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.lifting import PolynomialLifting
from optbound.sets.pseudo_ellipsoid import PseudoEllipsoid
from optbound.sets.quadratic import QuadraticSet
from optbound.sets.result import BoundResult
from optbound.sets.strip import Halfspace, Strip

__all__ = [
    "BoundResult",
    "Box",
    "ConvexSet",
    "Ellipsoid",
    "Halfspace",
    "PolynomialLifting",
    "PseudoEllipsoid",
    "QuadraticDescription",
    "QuadraticSet",
    "Strip",
]
