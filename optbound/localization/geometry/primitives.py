"""Points, segments, maps and poses: the predicates every model shares [GLH12, Appendix].

Written once for float points and interval boxes (see :mod:`optbound.localization.geometry`).
A point is a pair ``(x, y)`` of broadcastable coordinate arrays (floats or intervals); a
segment is a pair of points. Point evaluation rounds to nearest (a sign decided on points near
a degenerate configuration may be wrong by rounding); pass point intervals
(``Interval(x, x)``) where a point answer must be certain.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from optbound._core import real_array
from optbound.interval import Interval, as_interval

Point = tuple[Any, Any]


def det(ux, uy, vx, vy):
    """Compute the determinant ``ux * vy - uy * vx`` of the 2 x 2 matrix with columns u, v.

    Parameters
    ----------
    ux, uy, vx, vy : array_like or Interval
        Coordinates of ``u`` and ``v`` (broadcast together).

    Returns
    -------
    numpy.ndarray or Interval
        The determinant (outward-rounded on intervals).
    """
    return ux * vy - uy * vx


def side(p: Point, a: Point, b: Point):
    """``Side(p, Seg(a, b)) = det(p - a, b - a)`` [GLH12, Definition 18, eq. (20)].

    Negative when ``p`` is on the left of the directed line ``a -> b`` (counter-clockwise
    side), positive on the right, zero on the line.

    Parameters
    ----------
    p, a, b : tuple of (float array or Interval)
        The point and the segment's end points, as ``(x, y)`` pairs.

    Returns
    -------
    numpy.ndarray or Interval
        ``det(p - a, b - a)``.
    """
    return det(p[0] - a[0], p[1] - a[1], b[0] - a[0], b[1] - a[1])


def intersect(p1: Point, p2: Point, p3: Point, p4: Point):
    """``Intersect(Seg(p1, p2), Seg(p3, p4))`` [GLH12, Definition 17, eq. (19)].

    ``max(Side(p1, s34) Side(p2, s34), Side(p3, s12) Side(p4, s12)) / 2``: negative when the
    two segments cross (each one's end points lie strictly on both sides of the other's line),
    positive when they certainly do not meet, zero when they touch or are collinear.

    Parameters
    ----------
    p1, p2, p3, p4 : tuple of (float array or Interval)
        End points of the two segments, as ``(x, y)`` pairs.

    Returns
    -------
    numpy.ndarray or Interval
        The value of [GLH12, eq. (19)].
    """
    s34 = side(p1, p3, p4) * side(p2, p3, p4)
    s12 = side(p3, p1, p2) * side(p4, p1, p2)
    return np.maximum(s34, s12) / 2


def crosses(p1: Point, p2: Point, p3: Point, p4: Point):
    """Do ``Seg(p1, p2)`` and ``Seg(p3, p4)`` cross? Booleans on points, Tri on boxes.

    TRUE for boxes means every choice of end points in the boxes gives crossing segments
    [GLH12, eq. (6)]; FALSE means none does [GLH12, eq. (7)]. Touching is not crossing.

    Parameters
    ----------
    p1, p2, p3, p4 : tuple of (float array or Interval)
        End points of the two segments, as ``(x, y)`` pairs.

    Returns
    -------
    numpy.ndarray of bool or Tri
        ``intersect(p1, p2, p3, p4) < 0``.
    """
    return intersect(p1, p2, p3, p4) < 0


def to_world(pose: tuple[Any, Any, Any], local: Point) -> Point:
    """Robot-frame point ``local`` in the world frame for ``pose = (x, y, theta)``.

    ``theta`` is the heading (radians, counter-clockwise from the world x-axis); works on floats
    and on intervals (``np.cos``/``np.sin`` dispatch to their interval versions).

    Parameters
    ----------
    pose : tuple
        ``(x, y, theta)`` (floats or intervals).
    local : tuple of (float array or Interval)
        The point in the robot frame.

    Returns
    -------
    tuple
        ``(x + cos(theta) u - sin(theta) v, y + sin(theta) u + cos(theta) v)`` for
        ``local = (u, v)``.
    """
    x, y, theta = pose
    c, s = np.cos(theta), np.sin(theta)
    return x + c * local[0] - s * local[1], y + s * local[0] + c * local[1]


def as_segments(world, name: str = "world") -> np.ndarray:
    """Validate a map of oriented segments ``[[a_x, a_y], [b_x, b_y]]`` as an (s, 2, 2) array.

    A segment's reflecting (visible) face is on its left, i.e. where ``side(p, a, b) < 0``
    [KJWM00, eq. (2)].

    Parameters
    ----------
    world : array_like, shape (s, 2, 2)
        The segments ``[a, b]``.
    name : str
        The argument's name in error messages.

    Returns
    -------
    numpy.ndarray, shape (s, 2, 2)
        The validated float array.

    Raises
    ------
    ValueError
        Naming ``name``, for an empty map, a wrong shape, non-finite or complex coordinates,
        or a segment of zero length.
    """
    arr = real_array(name, world, "an (s, 2, 2) array")
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
    """Make ``p``'s float coordinates point intervals, so that ``b - a`` etc. round outward.

    Parameters
    ----------
    p : tuple of (float array or Interval)
        A point ``(x, y)``.

    Returns
    -------
    tuple of Interval
        ``(as_interval(x), as_interval(y))``.

    Raises
    ------
    ValueError
        If a coordinate is not finite.
    """
    return as_interval(p[0]), as_interval(p[1])


def segment_points(world: np.ndarray) -> tuple[Point, Point]:
    """Return the end points ``(a, b)`` of an (s, 2, 2) map as coordinate pairs.

    Parameters
    ----------
    world : numpy.ndarray, shape (s, 2, 2)
        The segments.

    Returns
    -------
    a, b : tuple of numpy.ndarray
        ``(x, y)`` pairs of arrays of shape (s,), ready for the predicates.
    """
    return (world[:, 0, 0], world[:, 0, 1]), (world[:, 1, 0], world[:, 1, 1])


def occluded(p: Point, q: Point, world: np.ndarray):
    """Is the sight line ``Seg(p, q)`` crossed by some segment of ``world``? [HS96, Sect. 3].

    ``p`` and ``q`` broadcast against each other; the answer has their broadcast shape
    (booleans on points, Tri on boxes: the disjunction of :func:`crosses` over the map, i.e.
    its maximum in the FALSE < UNKNOWN < TRUE order). A sight line that only touches a segment
    (e.g. ends on the wall that carries the landmark) is not occluded.

    Parameters
    ----------
    p, q : tuple of (float array or Interval)
        The sight line's end points.
    world : numpy.ndarray, shape (s, 2, 2)
        The occluding segments.

    Returns
    -------
    numpy.ndarray of bool or Tri
        Whether some segment crosses ``Seg(p, q)``, in the broadcast shape of ``p`` and ``q``.
    """
    a, b = segment_points(world)
    p, q = (_trailing(p[0]), _trailing(p[1])), (_trailing(q[0]), _trailing(q[1]))
    return np.max(crosses(p, q, a, b), axis=-1)


def _trailing(c):
    """``c`` with a trailing axis for the segments (floats as arrays; intervals as they are)."""
    return (c if isinstance(c, Interval) else np.asarray(c, dtype=float))[..., None]


__all__ = [
    "Point",
    "as_segments",
    "crosses",
    "det",
    "exact",
    "intersect",
    "occluded",
    "segment_points",
    "side",
    "to_world",
]
