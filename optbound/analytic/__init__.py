"""Closed-form ellipsoid calculus [HS96], [BH]: Minkowski sums, strip fusion, bounding updates,
the lifted (pseudo-ellipsoid) update and the noise of transformed measurements.

Every function returns a guaranteed outer bound: each member of the families used (Schweppe's
kappa family [HS96, eq. (14)], the strip family [HS96, eq. (24)], the bounding-ellipsoid filter
[BH, eq. (7)]) contains the true set; the criteria only choose the member. Batched variants take
a leading batch axis and are fully vectorized.

The formulas are also written plainly, one instance and no certification, in
:mod:`optbound.analytic.reference` (the tests' oracle); the compiled kernels that evaluate them
fast and certified are fenced in the private package ``optbound.analytic._kernels``, whose
docstring states the rules a kernel follows.
"""

from optbound import _fresh  # noqa: F401  (drops stale kernel caches before any is loaded)
from optbound._lazy import attach
from optbound.analytic.arc_noise import ArcNoise, parabola_arc_ellipse
from optbound.analytic.bounding_update import BoundingUpdate, bounding_update
from optbound.analytic.lifted import LiftedUpdate, lifted_update
from optbound.analytic.minkowski import (
    MinkowskiBatch,
    MinkowskiResult,
    minkowski_sum,
    minkowski_sum_batch,
)
from optbound.analytic.strip_fusion import (
    CASES,
    StripFusion,
    StripFusionBatch,
    intersect_strip,
    intersect_strip_batch,
)

__all__ = [
    "CASES",
    "ArcNoise",
    "BoundingUpdate",
    "LiftedUpdate",
    "MinkowskiBatch",
    "MinkowskiResult",
    "StripFusion",
    "StripFusionBatch",
    "bounding_update",
    "intersect_strip",
    "intersect_strip_batch",
    "lifted_update",
    "minkowski_sum",
    "minkowski_sum_batch",
    "parabola_arc_ellipse",
]

__getattr__, __dir__ = attach(__name__, public=__all__, submodules=())
