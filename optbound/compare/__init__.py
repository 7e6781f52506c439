"""Gap metrics between two bounds of one set: size measures, size ratios and containment.

Every optbound set type has a size measure with a certified bracket (:func:`size_bracket`),
and :func:`prove_contains` proves or refutes (with a counterexample) that a bound contains a
set. Pure numpy/scipy/mpmath (no cvxpy), so reports can compare bounds without the SDP stack.
"""

from optbound._lazy import attach
from optbound.compare._ellipsoid import bound_set
from optbound.compare.containment import contains, max_level
from optbound.compare.metrics import (
    log_volume_ratio,
    projection_volume_ratio,
    ratio_bracket,
    trace_ratio,
    volume_ratio,
    volume_ratio_bracket,
)
from optbound.compare.proof import Containment, prove_contains
from optbound.compare.size import size_bracket
from optbound.compare.tri import tri_contains, tri_test

__all__ = [
    "Containment",
    "bound_set",
    "contains",
    "log_volume_ratio",
    "max_level",
    "projection_volume_ratio",
    "prove_contains",
    "ratio_bracket",
    "size_bracket",
    "trace_ratio",
    "tri_contains",
    "tri_test",
    "volume_ratio",
    "volume_ratio_bracket",
]

__getattr__, __dir__ = attach(__name__, public=__all__, submodules=())
