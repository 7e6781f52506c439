"""Planar geometry shared by every localization model: points, segments, maps and poses.

Each predicate is written **once**, with ordinary arithmetic, and serves two purposes:

- called with float arrays it evaluates on points (simulation, sampling, plotting);
- called with :class:`~optbound.interval.Interval` arrays it is its own natural inclusion
  function: the result encloses the value over every point of the boxes, so its sign (read with
  ``< 0`` / ``> 0``, which return :class:`~optbound.interval.Tri` arrays on intervals) is a
  guaranteed answer for whole boxes [GLH12, Sect. 3], [LJMW97, Sect. 3.2].

A point is a pair ``(x, y)`` of broadcastable coordinate arrays (floats or intervals); a
segment is a pair of points. Point evaluation rounds to nearest (a sign decided on points near
a degenerate configuration may be wrong by rounding); pass point intervals
(``Interval(x, x)``) where a point answer must be certain.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from optbound.interval import Interval, as_interval

Point = tuple[Any, Any]


def det(ux, uy, vx, vy):
    """Determinant ``ux * vy - uy * vx`` of the 2 x 2 matrix with columns ``u`` and ``v``."""
    return ux * vy - uy * vx


def side(p: Point, a: Point, b: Point):
    """``Side(p, Seg(a, b)) = det(p - a, b - a)`` [GLH12, Definition 18, eq. (20)].

    Negative when ``p`` is on the left of the directed line ``a -> b`` (counter-clockwise
    side), positive on the right, zero on the line.
    """
    return det(p[0] - a[0], p[1] - a[1], b[0] - a[0], b[1] - a[1])


def intersect(p1: Point, p2: Point, p3: Point, p4: Point):
    """``Intersect(Seg(p1, p2), Seg(p3, p4))`` [GLH12, Definition 17, eq. (19)].

    ``max(Side(p1, s34) Side(p2, s34), Side(p3, s12) Side(p4, s12)) / 2``: negative when the
    two segments cross (each one's end points lie strictly on both sides of the other's line),
    positive when they certainly do not meet, zero when they touch or are collinear.
    """
    s34 = side(p1, p3, p4) * side(p2, p3, p4)
    s12 = side(p3, p1, p2) * side(p4, p1, p2)
    return np.maximum(s34, s12) / 2


def crosses(p1: Point, p2: Point, p3: Point, p4: Point):
    """Do ``Seg(p1, p2)`` and ``Seg(p3, p4)`` cross? Booleans on points, Tri on boxes.

    TRUE for boxes means every choice of end points in the boxes gives crossing segments
    [GLH12, eq. (6)]; FALSE means none does [GLH12, eq. (7)]. Touching is not crossing.
    """
    return intersect(p1, p2, p3, p4) < 0


def to_world(pose: tuple[Any, Any, Any], local: Point) -> Point:
    """Robot-frame point ``local`` in the world frame for ``pose = (x, y, theta)``.

    ``theta`` is the heading (radians, counter-clockwise from the world x-axis); works on floats
    and on intervals (``np.cos``/``np.sin`` dispatch to their interval versions).
    """
    x, y, theta = pose
    c, s = np.cos(theta), np.sin(theta)
    return x + c * local[0] - s * local[1], y + s * local[0] + c * local[1]


def as_segments(world, name: str = "world") -> np.ndarray:
    """Validate a map of oriented segments ``[[a_x, a_y], [b_x, b_y]]`` as an (s, 2, 2) array.

    A segment's reflecting (visible) face is on its left, i.e. where ``side(p, a, b) < 0``
    [KJWM00, eq. (2)]. Raises ``ValueError`` naming ``name`` for an empty map, a wrong shape,
    non-finite or complex coordinates, or a segment of zero length.
    """
    arr = np.asarray(world)
    if np.iscomplexobj(arr):
        raise ValueError(f"{name} must be real, got complex coordinates")
    try:
        arr = arr.astype(float)
    except (TypeError, ValueError) as err:
        raise ValueError(f"{name} must be an (s, 2, 2) array of numbers: {err}") from None
    if arr.ndim != 3 or arr.shape[1:] != (2, 2):
        raise ValueError(f"{name} must have shape (s, 2, 2) (segments [a, b]), got {arr.shape}")
    if arr.shape[0] == 0:
        raise ValueError(f"{name} is empty: a map needs at least one segment")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite")
    degenerate = np.flatnonzero(np.all(arr[:, 0] == arr[:, 1], axis=1))
    if degenerate.size:
        raise ValueError(f"{name}: segment(s) {degenerate.tolist()} have zero length")
    return arr


def exact(p: Point) -> Point:
    """``p`` with float coordinates as point intervals, so that ``b - a`` etc. round outward."""
    return as_interval(p[0]), as_interval(p[1])


def segment_points(world: np.ndarray) -> tuple[Point, Point]:
    """End points ``(a, b)`` of an (s, 2, 2) map as coordinate pairs, ready for the predicates."""
    return (world[:, 0, 0], world[:, 0, 1]), (world[:, 1, 0], world[:, 1, 1])


def occluded(p: Point, q: Point, world: np.ndarray):
    """Is the sight line ``Seg(p, q)`` crossed by some segment of ``world``? [HS96, Sect. 3].

    ``p`` and ``q`` broadcast against each other; the answer has their broadcast shape
    (booleans on points, Tri on boxes: the disjunction of :func:`crosses` over the map, i.e.
    its maximum in the FALSE < UNKNOWN < TRUE order). A sight line that only touches a segment
    (e.g. ends on the wall that carries the landmark) is not occluded.
    """
    a, b = segment_points(world)
    p, q = (_trailing(p[0]), _trailing(p[1])), (_trailing(q[0]), _trailing(q[1]))
    return np.max(crosses(p, q, a, b), axis=-1)


def _trailing(c):
    """``c`` with a trailing axis for the segments (floats as arrays; intervals as they are)."""
    return (c if isinstance(c, Interval) else np.asarray(c, dtype=float))[..., None]


# ----- predicates of the sonar model [LJMW97, Sect. 2.3], [KJWM00, Sect. 2.1] ---------------


def unit(angle) -> Point:
    """Unit vector ``(cos angle, sin angle)`` (floats or intervals)."""
    return np.cos(angle), np.sin(angle)


def dot(ux, uy, vx, vy):
    """Scalar product ``ux * vx + uy * vy``."""
    return ux * vx + uy * vy


def distance(p: Point, q: Point):
    """Euclidean distance ``|p - q|`` (``sqrt`` of a sum of squares: tight on intervals)."""
    return np.sqrt((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2)


def in_cone(direction: Point, right: Point, left: Point):
    """Margin of ``direction`` inside the cone spanned from unit vector ``right`` to ``left``.

    ``min(det(right, direction), det(direction, left))``: >= 0 iff ``direction`` lies in the
    closed cone turning counter-clockwise from ``right`` to ``left``, a cone narrower than a
    half-turn (an emission cone of half-aperture below 90 degrees [KJWM00, Fig. 3]).
    """
    return np.minimum(
        det(right[0], right[1], direction[0], direction[1]),
        det(direction[0], direction[1], left[0], left[1]),
    )


def cone_candidates(apex: Point, right: Point, left: Point, a: Point, b: Point) -> list:
    """Points of ``Seg(a, b)`` among which lies its nearest point to ``apex`` inside the cone.

    The part of a segment inside a convex cone is a sub-segment; ``|p - apex|`` is convex along
    it, so its minimum is reached at the foot of the perpendicular from ``apex`` or at an end
    of the sub-segment: an end point of ``Seg(a, b)`` or the hit of a cone edge ray
    [LJMW97, Fig. 3: the detected point P*]. Only the reflecting face counts: ``apex`` must be
    strictly on the left of ``a -> b`` [KJWM00, eq. (2)].

    Returns
    -------
    list of (distance, strict, closed)
        One triple per candidate: its distance to ``apex``, the margins that must be ``> 0``
        (the reflecting side ``-side(apex, a, b)`` first) and those that must be ``>= 0`` for
        the candidate to be a point of the segment inside the cone, seen from the front. All
        values are floats on points and intervals on boxes.
    """
    ex, ey = b[0] - a[0], b[1] - a[1]
    front = -side(apex, a, b)  # > 0 on the reflecting side
    length = distance(b, a)
    perp = front_distance(apex, a, b)  # distance from apex to the segment's line
    ax, ay = a[0] - apex[0], a[1] - apex[1]
    bx, by = b[0] - apex[0], b[1] - apex[1]
    inward = (ey / length, -ex / length)  # direction from the reflecting side onto the line
    out = [
        (distance(a, apex), [front], [in_cone((ax, ay), right, left)]),
        (distance(b, apex), [front], [in_cone((bx, by), right, left)]),
        (
            perp,
            [front],
            [dot(-ax, -ay, ex, ey), dot(bx, by, ex, ey), in_cone(inward, right, left)],
        ),
    ]
    for u in (right, left):
        toward = det(u[0], u[1], ex, ey)  # > 0: the ray runs toward the reflecting face
        hit = np.maximum(front / toward, perp)  # ray length to the line; never below perp
        out.append((hit, [front, toward], [det(ax, ay, u[0], u[1]), det(u[0], u[1], bx, by)]))
    return out


def nearest_in_cone(apex: Point, heading, half_aperture, a: Point, b: Point, far: float):
    """Distance from ``apex`` to the nearest point of ``Seg(a, b)`` in an emission cone.

    The cone has its vertex at ``apex``, axis angle ``heading`` and half-aperture
    ``half_aperture`` (below 90 degrees); only the reflecting face counts, and the result is
    ``min(far, d)`` with ``d = +inf`` when no point of the front face is in the cone: the
    inner loop of the simulation function f [LJMW97, eq. (2)].

    Floats give the distance. Intervals (on boxes of apex and heading) give an ``Interval``
    enclosing it over the boxes: its lower bound is the nearest candidate that may be valid,
    its upper bound the nearest candidate that is valid everywhere on the box
    (see :func:`cone_candidates`).
    """
    boxes = any(isinstance(v, Interval) for v in (*apex, heading))
    if boxes:
        a, b = exact(a), exact(b)
    right, left = unit(heading - half_aperture), unit(heading + half_aperture)
    with np.errstate(divide="ignore", invalid="ignore"):
        cands = cone_candidates(apex, right, left, a, b)
    if not boxes:
        best = far
        for value, strict, closed in cands:
            ok = np.logical_and.reduce([m > 0 for m in strict] + [m >= 0 for m in closed])
            best = np.minimum(best, np.where(ok, value, np.inf))
        return best
    lo = hi = far
    for value, strict, closed in cands:
        value = as_interval(value)
        sure = np.logical_and.reduce(
            [as_interval(m).lo > 0 for m in strict] + [as_interval(m).lo >= 0 for m in closed]
        )
        maybe = np.logical_and.reduce(
            [as_interval(m).hi > 0 for m in strict] + [as_interval(m).hi >= 0 for m in closed]
        )
        lo = np.minimum(lo, np.where(maybe, value.lo, np.inf))
        hi = np.minimum(hi, np.where(sure, value.hi, np.inf))
    return Interval._make(np.asarray(lo), np.asarray(hi))


def front_distance(p: Point, a: Point, b: Point):
    """Signed distance from ``p`` to the line of ``Seg(a, b)``, positive on its reflecting side.

    ``-side(p, a, b) / |b - a|`` [KJWM00, eq. (2)]: a point of a convex room whose walls all
    face inward is at least ``r`` from every wall iff this is ``>= r`` for every wall.
    """
    return -side(p, a, b) / distance(b, a)
