"""Set representations: the common interface and the concrete types.

``Ellipsoid``, ``Strip``, ``Halfspace`` and ``Box`` validate their input on construction and
are immutable afterwards, so a set that exists is always a valid set. ``PseudoEllipsoid`` is
an ellipsoid in the lifted space of a ``PolynomialLifting`` [BH, eq. (10)]. ``Box`` and the
interface ``ConvexSet`` are defined in :mod:`optbound._core` (every layer, interval arithmetic
included, uses boxes) and exported here unchanged.
"""

from optbound._core import Box, ConvexSet
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.lifting import PolynomialLifting
from optbound.sets.pseudo_ellipsoid import PseudoEllipsoid
from optbound.sets.quadratic import QuadraticSet
from optbound.sets.strip import Halfspace, Strip

__all__ = [
    "Box",
    "ConvexSet",
    "Ellipsoid",
    "Halfspace",
    "PolynomialLifting",
    "PseudoEllipsoid",
    "QuadraticSet",
    "Strip",
]
