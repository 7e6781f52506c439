"""optbound: guaranteed bounding sets for set-membership estimation.

Analytic ellipsoid updates (``optbound.analytic``), certified SDP references
(``optbound.optimal``, needs cvxpy) and interval pavings (``optbound.interval``), compared on
the same instances (``optbound.compare``). Importing this package does not import cvxpy.
"""

from optbound.sets import (
    Box,
    ConvexSet,
    Ellipsoid,
    Halfspace,
    PseudoEllipsoid,
    QuadraticSet,
    Strip,
)

__version__ = "0.1.0"

__all__ = [
    "Box",
    "ConvexSet",
    "Ellipsoid",
    "Halfspace",
    "PseudoEllipsoid",
    "QuadraticSet",
    "Strip",
    "__version__",
]
