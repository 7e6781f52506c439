"""optbound: guaranteed bounding sets for set-membership estimation.

Analytic ellipsoid updates (``optbound.analytic``), certified SDP references
(``optbound.optimal``, needs cvxpy) and interval pavings (``optbound.interval``), compared on
the same instances (``optbound.compare``). The set types and the subpackages are attributes of
the package (``import optbound as ob; ob.Ellipsoid, ob.optimal``), imported on first access
(PEP 562): ``import optbound`` imports neither numpy nor numba nor cvxpy and writes no file.
"""

from optbound._lazy import attach

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

__getattr__, __dir__ = attach(
    __name__,
    public=__all__,
    submodules=(
        "analytic",
        "bench",
        "compare",
        "interval",
        "localization",
        "optimal",
        "report",
        "sets",
    ),
    attributes={name: "optbound.sets" for name in __all__ if name != "__version__"},
)
