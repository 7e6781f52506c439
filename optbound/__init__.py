"""optbound: guaranteed bounding sets for set-membership estimation.

Analytic ellipsoid updates (``optbound.analytic``), certified SDP references
(``optbound.optimal``, needs cvxpy) and interval pavings (``optbound.interval``), compared on
the same instances (``optbound.compare``); public problems and ``optbound.evaluate`` to audit
any estimator on them (``optbound.problems``). The set types, ``evaluate`` and the subpackages
are attributes of the package (``import optbound as ob; ob.Ellipsoid, ob.optimal``), imported
on first access (PEP 562): ``import optbound`` imports neither numpy nor numba nor cvxpy and
writes no file.
"""

from optbound._lazy import attach

__version__ = "0.1.0"

__all__ = [
    "Box",
    "ConstrainedZonotope",
    "ConvexSet",
    "Ellipsoid",
    "Halfspace",
    "PseudoEllipsoid",
    "QuadraticSet",
    "Strip",
    "Zonotope",
    "__version__",
    "evaluate",
]

#: Set types and functions reachable as attributes, imported from their module on first access.
_ATTRIBUTES = {
    **{name: "optbound.sets" for name in __all__ if name[0].isupper()},
    "evaluate": "optbound.problems",
}

__getattr__, __dir__ = attach(
    __name__,
    public=__all__,
    submodules=(
        "analytic",
        "bench",
        "compare",
        "estimation",
        "interval",
        "localization",
        "optimal",
        "problems",
        "report",
        "scenarios",
        "sets",
    ),
    attributes=_ATTRIBUTES,
)
