"""optbound: guaranteed bounding sets for set-membership estimation.

Analytic ellipsoid updates (``optbound.analytic``), certified SDP references
(``optbound.optimal``, needs cvxpy) and interval pavings (``optbound.interval``), compared on
the same instances (``optbound.compare``); public problems and ``optbound.evaluate`` to audit
any estimator on them (``optbound.problems``). The subpackages are attributes of the package
(``import optbound as ob; ob.optimal``), imported on first access (PEP 562), so
``import optbound`` stays light and does not import cvxpy.
"""

from __future__ import annotations

import importlib
import importlib.util

from optbound import _jit_cache

_jit_cache.refresh()  # before any compiled kernel is loaded from numba's cache

from optbound.sets import (  # noqa: E402
    Box,
    ConstrainedZonotope,
    ConvexSet,
    Ellipsoid,
    Halfspace,
    PseudoEllipsoid,
    QuadraticSet,
    Strip,
    Zonotope,
)

__version__ = "0.1.0"

#: Subpackages reachable as attributes, imported on first access.
SUBMODULES = (
    "analytic",
    "compare",
    "estimation",
    "interval",
    "localization",
    "optimal",
    "problems",
    "report",
    "scenarios",
    "sets",
)
#: Functions reachable as attributes, imported from their subpackage on first access.
FUNCTIONS = {"evaluate": "problems"}

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
]


def __getattr__(name: str):
    if name in FUNCTIONS:
        module = importlib.import_module(f"{__name__}.{FUNCTIONS[name]}")
        globals()[name] = function = getattr(module, name)
        return function
    if name in SUBMODULES:
        try:
            # import_module also binds the attribute on the package: this runs once per name.
            return importlib.import_module(f"{__name__}.{name}")
        except ModuleNotFoundError as exc:
            if exc.name != f"{__name__}.{name}":
                raise  # the subpackage exists but something it imports is missing
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    present = [name for name in SUBMODULES if importlib.util.find_spec(f"{__name__}.{name}")]
    return sorted({*globals(), *present, *FUNCTIONS})
