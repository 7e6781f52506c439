"""Planar geometry shared by every localization model: points, segments, maps, poses, bearings,
emission cones and polygonal obstacles.

Each predicate is written **once**, with ordinary arithmetic, and serves two purposes:

- called with float arrays it evaluates on points (simulation, sampling, plotting);
- called with :class:`~optbound.interval.Interval` arrays it is its own natural inclusion
  function: the result encloses the value over every point of the boxes, so its sign (read with
  ``< 0`` / ``> 0``, which return :class:`~optbound.interval.Tri` arrays on intervals) is a
  guaranteed answer for whole boxes [GLH12, Sect. 3], [LJMW97, Sect. 3.2].

Modules: :mod:`.primitives` (side, intersect, segments, poses [GLH12, eqs. (19)-(20)]),
:mod:`.bearings` (angle wrapping, relative bearings [BH, eq. (2)]), :mod:`.cones` (emission
cones of the sonar model [LJMW97], [KJWM00]) and :mod:`.polygons` (obstacles, with compiled
certified box predicates for LUVIA [GLH12]).
"""

from optbound._lazy import attach
from optbound.localization.geometry.bearings import (
    bearing_gradient,
    bearing_residual,
    bearing_sides,
    wrap_angle,
)
from optbound.localization.geometry.cones import (
    cone_candidates,
    distance,
    dot,
    front_distance,
    in_cone,
    nearest_in_cone,
    unit,
)
from optbound.localization.geometry.polygons import (
    as_polygons,
    intersect_boxes,
    pack_polygons,
    point_in_polygon,
    polygon_inside,
    segment_pair_meets,
    segments_meet_packed,
    segments_meet_polygons,
)
from optbound.localization.geometry.primitives import (
    Point,
    as_segments,
    crosses,
    det,
    exact,
    intersect,
    occluded,
    segment_points,
    side,
    to_world,
)

__all__ = [
    "Point",
    "as_polygons",
    "as_segments",
    "bearing_gradient",
    "bearing_residual",
    "bearing_sides",
    "cone_candidates",
    "crosses",
    "det",
    "distance",
    "dot",
    "exact",
    "front_distance",
    "in_cone",
    "intersect",
    "intersect_boxes",
    "nearest_in_cone",
    "occluded",
    "pack_polygons",
    "point_in_polygon",
    "polygon_inside",
    "segment_pair_meets",
    "segment_points",
    "segments_meet_packed",
    "segments_meet_polygons",
    "side",
    "to_world",
    "unit",
    "wrap_angle",
]

__getattr__, __dir__ = attach(__name__, public=__all__, submodules=())
