"""Emission cones of range sensors: the sonar model's predicates [LJMW97], [KJWM00, Sect. 2.1].

One formula each, on float points and on interval boxes (see :mod:`.primitives`).
"""

from __future__ import annotations

import numpy as np

from optbound.interval import Interval, as_interval
from optbound.localization.geometry.primitives import Point, det, exact, side

# ----- predicates of the sonar model [LJMW97, Sect. 2.3], [KJWM00, Sect. 2.1] ---------------


def unit(angle) -> Point:
    """Build the unit vector ``(cos angle, sin angle)`` (floats or intervals).

    Parameters
    ----------
    angle : array_like or Interval
        Angles [rad].

    Returns
    -------
    tuple
        ``(cos angle, sin angle)``.
    """
    return np.cos(angle), np.sin(angle)


def dot(ux, uy, vx, vy):
    """Compute the scalar product ``ux * vx + uy * vy``.

    Parameters
    ----------
    ux, uy, vx, vy : array_like or Interval
        Coordinates of ``u`` and ``v`` (broadcast together).

    Returns
    -------
    numpy.ndarray or Interval
        The scalar product.
    """
    return ux * vx + uy * vy


def distance(p: Point, q: Point):
    """Compute the Euclidean distance ``|p - q|`` (a square root of a sum of squares).

    Parameters
    ----------
    p, q : tuple of (float array or Interval)
        The two points.

    Returns
    -------
    numpy.ndarray or Interval
        The distance (tight on intervals: each coordinate appears in one square).
    """
    return np.sqrt((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2)


def in_cone(direction: Point, right: Point, left: Point):
    """Margin of ``direction`` inside the cone spanned from unit vector ``right`` to ``left``.

    ``min(det(right, direction), det(direction, left))``: >= 0 iff ``direction`` lies in the
    closed cone turning counter-clockwise from ``right`` to ``left``, a cone narrower than a
    half-turn (an emission cone of half-aperture below 90 degrees [KJWM00, Fig. 3]).

    Parameters
    ----------
    direction : tuple of (float array or Interval)
        The direction tested.
    right, left : tuple of (float array or Interval)
        Unit vectors of the cone's edges.

    Returns
    -------
    numpy.ndarray or Interval
        The margin, >= 0 inside the closed cone.
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

    Parameters
    ----------
    apex : tuple of (float array or Interval)
        The cone's vertex.
    right, left : tuple of (float array or Interval)
        Unit vectors of the cone's edges.
    a, b : tuple of (float array or Interval)
        End points of the segment.

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

    Parameters
    ----------
    apex : tuple of (float array or Interval)
        The cone's vertex.
    heading : array_like or Interval
        Angle of the cone's axis [rad].
    half_aperture : float
        Half-angle of the cone [rad], below pi/2.
    a, b : tuple of (float array or Interval)
        End points of the segment (floats; made exact on boxes).
    far : float
        The range returned when no point of the front face is in the cone (``d_max``).

    Returns
    -------
    numpy.ndarray or Interval
        ``min(far, d)`` on points; on boxes an ``Interval`` enclosing it.
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

    Parameters
    ----------
    p : tuple of (float array or Interval)
        The point.
    a, b : tuple of (float array or Interval)
        End points of the segment.

    Returns
    -------
    numpy.ndarray or Interval
        The signed distance.
    """
    return -side(p, a, b) / distance(b, a)


__all__ = [
    "cone_candidates",
    "distance",
    "dot",
    "front_distance",
    "in_cone",
    "nearest_in_cone",
    "unit",
]
