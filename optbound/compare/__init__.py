"""Gap metrics between two bounds of one set: size ratios and containment.

Pure numpy/scipy (no cvxpy), so reports can compare bounds without the SDP stack.
"""

from optbound._lazy import attach
from optbound.compare.containment import contains, max_level
from optbound.compare.metrics import (
    log_volume_ratio,
    projection_volume_ratio,
    trace_ratio,
    volume_ratio,
)

__all__ = [
    "contains",
    "log_volume_ratio",
    "max_level",
    "projection_volume_ratio",
    "trace_ratio",
    "volume_ratio",
]

__getattr__, __dir__ = attach(__name__, public=__all__, submodules=())
