"""Vectorized outward-rounded interval arithmetic, SIVIA pavings and relaxed intersections.

- :class:`Interval`: interval arrays; operators and numpy ufuncs dispatch to interval
  versions, so ``f(x, y)`` written with ``+ - * / **`` and ``np.sqrt``, ``np.sin``, ... is its
  own natural inclusion function when called with intervals.
- :func:`sivia`, :func:`pave`, :func:`constraint`: set inversion [LJMW97, Sect. 3.2],
  breadth-first over whole arrays of boxes, returning a :class:`Paving`.
- :func:`relaxed_test`, :func:`min_outliers`: the relaxed intersection of KJWM00.

Every interval operation and paving runs in round-to-nearest and restores the caller's
rounding mode afterwards (:mod:`optbound.interval.fenv`), so optbound and codac (which sets
round-upward when imported) work in one process; ``codac_interop`` converts between them.
The submodules are imported in round-to-nearest too, so that their constants (and the float
literals Python parses while compiling them) are the intended ones.
"""

from optbound import _fresh  # noqa: F401  (drops stale kernel caches before any is loaded)
from optbound._lazy import attach
from optbound.interval.fenv import round_to_nearest

with round_to_nearest():
    from optbound.interval.functions import (
        absolute,
        add,
        atan2,
        cos,
        divide,
        exp,
        greater,
        greater_equal,
        hull,
        intersection,
        less,
        less_equal,
        log,
        maximum,
        minimum,
        multiply,
        negative,
        power,
        sin,
        sqr,
        sqrt,
        subtract,
    )
    from optbound.interval.interval import Interval, as_interval
    from optbound.interval.paving import Paving
    from optbound.interval.relaxed import min_outliers, relaxed_test
    from optbound.interval.sivia import constraint, pave, sivia
    from optbound.interval.tribool import Tri, as_tri, tri_and, tri_not, tri_or

__all__ = [
    "Interval",
    "Paving",
    "Tri",
    "absolute",
    "add",
    "as_interval",
    "as_tri",
    "atan2",
    "constraint",
    "cos",
    "divide",
    "exp",
    "greater",
    "greater_equal",
    "hull",
    "intersection",
    "less",
    "less_equal",
    "log",
    "maximum",
    "min_outliers",
    "minimum",
    "multiply",
    "negative",
    "pave",
    "power",
    "relaxed_test",
    "sin",
    "sivia",
    "sqr",
    "sqrt",
    "subtract",
    "tri_and",
    "tri_not",
    "tri_or",
]

__getattr__, __dir__ = attach(__name__, public=__all__, submodules=())
