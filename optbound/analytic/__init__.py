"""Closed-form ellipsoid calculus [HS96], [BH]: Minkowski sums, strip fusion, bounding updates,
the lifted (pseudo-ellipsoid) update and the noise of transformed measurements.

Every function returns a guaranteed outer bound: each member of the families used (Schweppe's
kappa family [HS96, eq. (14)], the strip family [HS96, eq. (24)], the bounding-ellipsoid filter
[BH, eq. (7)]) contains the true set; the criteria only choose the member. Batched variants take
a leading batch axis and are fully vectorized.
"""

from optbound.analytic import _jit_cache

_jit_cache.refresh()  # before any compiled kernel is loaded from numba's cache

from optbound.analytic.arc_noise import ArcNoise, parabola_arc_ellipse  # noqa: E402
from optbound.analytic.bounding_update import BoundingUpdate, bounding_update  # noqa: E402
from optbound.analytic.lifted import LiftedUpdate, lifted_update  # noqa: E402
from optbound.analytic.minkowski import (  # noqa: E402
    MinkowskiBatch,
    MinkowskiResult,
    minkowski_sum,
    minkowski_sum_batch,
)
from optbound.analytic.strip_fusion import (  # noqa: E402
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
