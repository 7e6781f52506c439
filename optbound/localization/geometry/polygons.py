"""Polygonal obstacles [GLH12, Sect. 2.3]: validation and compiled, certified box predicates.

A polygon is a (k, 2) array of vertices (k >= 3), a closed solid set. The box predicates are
compiled (numba) because LUVIA evaluates them on thousands of box pairs per step; they evaluate
the formulas of :func:`~.primitives.side` and :func:`~.primitives.intersect` [GLH12,
eqs. (19)-(20)] with the compiled outward-rounded interval operations of
``optbound.interval.compiled``; tests check that their enclosures lie inside those of
``intersect`` on ``Interval`` arrays and contain the exact values.
"""

from __future__ import annotations

from fractions import Fraction
from functools import lru_cache

import numpy as np

from optbound._core import real_array
from optbound._core.jit import njit
from optbound.interval.compiled import imul, isub
from optbound.localization.geometry.primitives import intersect, side


def as_polygons(polygons, name: str = "obstacles") -> list[np.ndarray]:
    """Validate a list of polygons, each a (k, 2) array of k >= 3 finite real vertices.

    A solid obstacle needs a boundary that does not cross itself and encloses some area. An
    empty list is valid (an environment without obstacles).

    Parameters
    ----------
    polygons : list or tuple of array_like
        The polygons, each (k, 2).
    name : str
        The argument's name in error messages.

    Returns
    -------
    list of numpy.ndarray
        The validated (k, 2) float arrays.

    Raises
    ------
    TypeError
        If ``polygons`` is not a list or tuple.
    ValueError
        Naming ``name``, for a wrong shape, non-finite or complex coordinates, repeated
        consecutive vertices, or a polygon that is not simple (self-intersecting or of zero
        area, decided exactly).
    """
    if isinstance(polygons, np.ndarray) or not isinstance(polygons, list | tuple):
        raise TypeError(f"{name} must be a list of (k, 2) vertex arrays, got {type(polygons)}")
    out = []
    for j, poly in enumerate(polygons):
        arr = real_array(f"{name}[{j}]", poly, "a (k, 2) array")
        if arr.ndim != 2 or arr.shape[1] != 2 or arr.shape[0] < 3:
            raise ValueError(f"{name}[{j}] must have shape (k, 2) with k >= 3, got {arr.shape}")
        if not np.all(np.isfinite(arr)):
            raise ValueError(f"{name}[{j}] must be finite")
        if np.any(np.all(arr == np.roll(arr, -1, axis=0), axis=1)):
            raise ValueError(f"{name}[{j}] has a zero-length edge (repeated vertex)")
        _check_simple(arr, f"{name}[{j}]")
        out.append(arr)
    return out


def _check_simple(poly: np.ndarray, name: str) -> None:
    """Raise unless no two non-adjacent edges meet and the area is not zero, decided exactly
    (:func:`_simplicity_defect`)."""
    defect = _simplicity_defect(poly.tobytes(), poly.shape[0])
    if defect is not None:
        raise ValueError(f"{name} {defect}")


@lru_cache(maxsize=256)
def _simplicity_defect(vertices: bytes, k: int) -> str | None:
    """Why the polygon of ``k`` float64 vertices (C-order bytes) is not simple, or None.

    The compiled interval ``intersect`` [GLH12, eq. (19)] clears most edge pairs at once; the
    pairs it cannot separate (meeting, touching, collinear or close) are decided with
    :func:`~.primitives.intersect` in Fractions. The area is the shoelace sum in Fractions.
    Kept by the vertices' bytes: the same obstacles are validated by every call of the
    public predicates (e.g. once per step of a simulation), and the verdict is exact.
    """
    poly = np.frombuffer(vertices).reshape(k, 2)
    a, b = _edge_boxes(poly)
    lo, _ = intersect_boxes(a, b, a, b)
    i, j = np.triu_indices(k, 2)
    keep = (j - i) % k != k - 1  # edges 0 and k - 1 are adjacent too
    v = [(Fraction(float(x)), Fraction(float(y))) for x, y in poly]
    for e1, e2 in zip(i[keep], j[keep], strict=True):
        if lo[e1, e2] <= 0.0 and _segments_meet(v[e1], v[(e1 + 1) % k], v[e2], v[(e2 + 1) % k]):
            return (
                f"is self-intersecting: its edges {e1} and {e2} meet; an obstacle must "
                "be a simple polygon"
            )
    if sum(v[n][0] * v[n - 1][1] - v[n - 1][0] * v[n][1] for n in range(k)) == 0:
        return "has zero area (its vertices are collinear)"
    return None


def _segments_meet(p1, p2, p3, p4) -> bool:
    """Do the closed segments meet? Exact for Fraction points (collinear: extents overlap)."""
    if intersect(p1, p2, p3, p4) > 0:
        return False
    if side(p1, p3, p4) == 0 and side(p2, p3, p4) == 0:
        return all(
            max(min(p1[c], p2[c]), min(p3[c], p4[c])) <= min(max(p1[c], p2[c]), max(p3[c], p4[c]))
            for c in (0, 1)
        )
    return True


def pack_polygons(polygons: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Flatten validated polygons for the compiled predicates.

    Parameters
    ----------
    polygons : list of numpy.ndarray
        Validated polygons (:func:`as_polygons`).

    Returns
    -------
    vertices : numpy.ndarray, shape (V, 2)
        All vertices stacked.
    starts : numpy.ndarray of int64, shape (n + 1,)
        The index of each polygon's first vertex, with a final sentinel.
    bboxes : numpy.ndarray, shape (n, 2, 2)
        Each polygon's bounding box ``[[x_lo, x_hi], [y_lo, y_hi]]``.
    """
    n = len(polygons)
    starts = np.zeros(n + 1, dtype=np.int64)
    starts[1:] = np.cumsum([len(p) for p in polygons])
    verts = np.concatenate(polygons) if n else np.zeros((0, 2))
    bboxes = np.array(
        [[[p[:, 0].min(), p[:, 0].max()], [p[:, 1].min(), p[:, 1].max()]] for p in polygons]
    )
    return verts, starts, bboxes.reshape(n, 2, 2)


@njit(cache=True)
def _idet(ux, uy, vx, vy):
    """Interval ``det(u, v)``; each argument is a (lo, hi) pair."""
    t1l, t1h = imul(ux[0], ux[1], vy[0], vy[1])
    t2l, t2h = imul(uy[0], uy[1], vx[0], vx[1])
    return isub(t1l, t1h, t2l, t2h)


@njit(cache=True)
def _iside(p, a, b):
    """Interval ``side(p, a, b)`` [GLH12, eq. (20)]; points are (x_lo, x_hi, y_lo, y_hi).

    ``det(p - a, b - a)`` and the equal ``det(p - a, b - p)`` (add ``det(p - a, p - a) = 0``)
    are both enclosures; the first is the exact range when ``p`` is a box and ``a``, ``b``
    points, the second when ``p`` is a point and ``a``, ``b`` boxes (each variable then
    occurs once), so their intersection is tight in both uses of eq. (19).
    """
    ux, uy = isub(p[0], p[1], a[0], a[1]), isub(p[2], p[3], a[2], a[3])
    l1, h1 = _idet(ux, uy, isub(b[0], b[1], a[0], a[1]), isub(b[2], b[3], a[2], a[3]))
    l2, h2 = _idet(ux, uy, isub(b[0], b[1], p[0], p[1]), isub(b[2], b[3], p[2], p[3]))
    return max(l1, l2), min(h1, h2)


@njit(cache=True)
def _iside_product(p1, p2, p3, p4):
    """Interval ``Side(p1, Seg(p3, p4)) Side(p2, Seg(p3, p4))``, one half of eq. (19)."""
    al, ah = _iside(p1, p3, p4)
    bl, bh = _iside(p2, p3, p4)
    return imul(al, ah, bl, bh)


@njit(cache=True)
def _iintersect(p1, p2, p3, p4):
    """Interval ``intersect(p1, p2, p3, p4)`` [GLH12, eq. (19)] as (lo, hi).

    The final halving is exact (no underflow matters for a sign) and is kept for fidelity.
    """
    s34l, s34h = _iside_product(p1, p2, p3, p4)
    s12l, s12h = _iside_product(p3, p4, p1, p2)
    return max(s34l, s12l) / 2.0, max(s34h, s12h) / 2.0


@njit(cache=True)
def _intersect_sign(p1, p2, p3, p4):
    """Sign of :func:`_iintersect`: -1 certainly < 0, 1 certainly > 0, 0 undecided.

    Skips the second product when the first already proves ``> 0`` (the max is then > 0).
    """
    s34l, s34h = _iside_product(p1, p2, p3, p4)
    if s34l > 0.0:
        return 1
    s12l, s12h = _iside_product(p3, p4, p1, p2)
    if s12l > 0.0:
        return 1
    return -1 if s34h < 0.0 and s12h < 0.0 else 0


@njit(cache=True)
def _box(b):
    return (b[0, 0], b[0, 1], b[1, 0], b[1, 1])


@njit(cache=True)
def _vertex(verts, k):
    return (verts[k, 0], verts[k, 0], verts[k, 1], verts[k, 1])


@njit(cache=True)
def _point_in_polygon(x, y, verts, s, e):
    """Certified crossing-number test of the point (x, y): 2 inside, 0 outside, 1 unknown.

    The ray goes from the point towards +x; an edge whose end points straddle ``y`` (exact
    comparisons) crosses it iff the point lies on its left (upward edge) or right (downward
    edge), a sign of ``side`` decided in interval arithmetic, else the answer is unknown.
    """
    p = (x, x, y, y)
    inside = False
    for k in range(s, e):
        k2 = k + 1 if k + 1 < e else s
        ay, by = verts[k, 1], verts[k2, 1]
        if (verts[k, 0] == x and ay == y) or (
            ay == y == by and min(verts[k, 0], verts[k2, 0]) <= x <= max(verts[k, 0], verts[k2, 0])
        ):
            return 1  # on a vertex or a horizontal edge: on the boundary
        up = ay <= y < by
        down = by <= y < ay
        if not (up or down):
            continue
        lo, hi = _iside(p, _vertex(verts, k), _vertex(verts, k2))
        if lo <= 0.0 <= hi:
            return 1
        if (hi < 0.0) == up:
            inside = not inside
    return 2 if inside else 0


@njit(cache=True)
def _box_in_bbox(b, bb):
    return (
        bb[0, 0] <= b[0, 0] and b[0, 1] <= bb[0, 1] and bb[1, 0] <= b[1, 0] and b[1, 1] <= bb[1, 1]
    )


@njit(cache=True)
def _box_inside_polygon(b, verts, s, e, bb):
    """True only if the whole box ``b`` certainly lies in the polygon's interior.

    ``Seg(b, b)`` covers the (convex) box, so ``intersect(Seg(b, b), edge) > 0`` for every
    edge means no point of the box is on the boundary; the box is then inside or outside as
    a whole, decided by one corner.
    """
    if not _box_in_bbox(b, bb):
        return False
    bx = _box(b)
    for k in range(s, e):
        k2 = k + 1 if k + 1 < e else s
        if _intersect_sign(bx, bx, _vertex(verts, k), _vertex(verts, k2)) != 1:
            return False
    return _point_in_polygon(b[0, 0], b[1, 0], verts, s, e) == 2


@njit(cache=True)
def _segments_meet_polygon(b1, b2, verts, s, e, bb):
    """Does ``Seg([b1], [b2])`` meet the solid polygon? 2 every segment, 0 none, 1 unknown.

    For boxes whose hull meets the polygon's bounding box (:func:`segment_pair_meets` tests
    that first, for every polygon):

    - 0 if ``intersect > 0`` on every edge (no segment touches the boundary, [GLH12, eq. (7)])
      and a corner of ``b1`` is certainly outside (so every segment is outside);
    - 2 if ``intersect < 0`` on some edge (every segment crosses it, [GLH12, eq. (6)]), or if
      one of the boxes lies inside the polygon (every segment starts in the obstacle);
    - 1 otherwise.
    """
    p1, p2 = _box(b1), _box(b2)
    clear = True
    for k in range(s, e):
        k2 = k + 1 if k + 1 < e else s
        sign = _intersect_sign(p1, p2, _vertex(verts, k), _vertex(verts, k2))
        if sign < 0:
            return 2
        if sign == 0:
            clear = False
    if clear:
        # No segment touches the boundary: b1 is wholly inside or wholly outside.
        return _point_in_polygon(b1[0, 0], b1[1, 0], verts, s, e)
    if _box_inside_polygon(b1, verts, s, e, bb) or _box_inside_polygon(b2, verts, s, e, bb):
        return 2
    return 1


@njit(cache=True)
def segment_pair_meets(b1, b2, verts, starts, bboxes) -> int:
    """Compiled: does some polygon meet ``Seg([b1], [b2])``? 2 every segment, 0 none, 1 unknown.

    For compiled loops (LUVIA); ``verts, starts, bboxes`` come from :func:`pack_polygons`.
    A polygon whose bounding box the hull of the boxes misses (exact comparisons) meets no
    segment; it is skipped here, before the call, which costs more than this test.
    """
    res = 0
    for j in range(len(starts) - 1):
        if (
            max(b1[0, 1], b2[0, 1]) < bboxes[j, 0, 0]
            or min(b1[0, 0], b2[0, 0]) > bboxes[j, 0, 1]
            or max(b1[1, 1], b2[1, 1]) < bboxes[j, 1, 0]
            or min(b1[1, 0], b2[1, 0]) > bboxes[j, 1, 1]
        ):
            continue
        r = _segments_meet_polygon(b1, b2, verts, starts[j], starts[j + 1], bboxes[j])
        if r == 2:
            return 2
        res = max(res, r)
    return res


@njit(cache=True)
def _segments_meet_polygons(boxes1, boxes2, verts, starts, bboxes, out):
    """Tri of "some obstacle meets Seg([b1], [b2])" for each box pair, written into ``out``."""
    for i in range(len(boxes1)):
        out[i] = segment_pair_meets(boxes1[i], boxes2[i], verts, starts, bboxes)


@njit(cache=True)
def _intersect_boxes(boxes1, boxes2, a, b, lo, hi):
    for i in range(len(boxes1)):
        for k in range(len(a)):
            lo[i, k], hi[i, k] = _iintersect(
                _box(boxes1[i]), _box(boxes2[i]), _box(a[k]), _box(b[k])
            )


def intersect_boxes(boxes1: np.ndarray, boxes2: np.ndarray, a: np.ndarray, b: np.ndarray):
    """Evaluate the interval ``intersect`` [GLH12, eq. (19)] of box segments, compiled.

    Inside the enclosure of :func:`intersect` on ``Interval`` arrays (``side`` is evaluated in
    two equal forms and intersected, which removes most of the dependency effect), without
    per-operation overhead.

    Parameters
    ----------
    boxes1, boxes2 : numpy.ndarray, shape (m, 2, 2)
        End-point boxes ``[[x_lo, x_hi], [y_lo, y_hi]]`` of the first segments.
    a, b : numpy.ndarray, shape (s, 2, 2)
        End-point boxes of the second segments.

    Returns
    -------
    lo, hi : numpy.ndarray, shape (m, s)
        Bounds enclosing ``Intersect(Seg(x1, x2), Seg(x3, x4))`` over all points of the boxes.
    """
    m, s = len(boxes1), len(a)
    lo, hi = np.empty((m, s)), np.empty((m, s))
    _intersect_boxes(
        *(np.ascontiguousarray(v, dtype=float) for v in (boxes1, boxes2, a, b)), lo, hi
    )
    return lo, hi


def segments_meet_polygons(boxes1: np.ndarray, boxes2: np.ndarray, polygons: list[np.ndarray]):
    """Decide, per box pair, whether some polygon meets ``Seg([b1], [b2])`` [GLH12, Def. 7].

    TRUE: for every ``x1`` in ``boxes1[i]`` and ``x2`` in ``boxes2[i]`` the closed segment meets
    a (solid, closed) polygon; FALSE: no segment meets any polygon; UNKNOWN otherwise. Touching
    counts as meeting; a segment lying inside an obstacle meets it. ``boxes1``, ``boxes2`` are
    validated (m, 2, 2) float arrays, ``polygons`` the output of :func:`as_polygons`.
    Degenerate boxes (``lo == hi``) give the answer for points, certified against rounding.

    Parameters
    ----------
    boxes1, boxes2 : numpy.ndarray, shape (m, 2, 2)
        Validated end-point boxes.
    polygons : list of numpy.ndarray
        The obstacles (:func:`as_polygons`).

    Returns
    -------
    numpy.ndarray of int8, shape (m,)
        :class:`~optbound.interval.Tri` values [GLH12, eq. (5)].
    """
    return segments_meet_packed(boxes1, boxes2, pack_polygons(polygons))


def segments_meet_packed(boxes1: np.ndarray, boxes2: np.ndarray, packed) -> np.ndarray:
    """:func:`segments_meet_polygons` with the polygons packed (:func:`pack_polygons`) once
    by a caller that tests the same obstacles many times (e.g. a simulation, every step).

    Parameters
    ----------
    boxes1, boxes2 : numpy.ndarray, shape (m, 2, 2)
        Validated end-point boxes.
    packed : tuple
        ``(verts, starts, bboxes)`` of :func:`pack_polygons`.

    Returns
    -------
    numpy.ndarray of int8, shape (m,)
        As :func:`segments_meet_polygons`.
    """
    out = np.zeros(len(boxes1), dtype=np.int8)
    verts, starts, bboxes = packed
    if len(starts) > 1 and len(out):
        _segments_meet_polygons(
            np.ascontiguousarray(boxes1), np.ascontiguousarray(boxes2), verts, starts, bboxes, out
        )
    return out


def point_in_polygon(points: np.ndarray, polygon: np.ndarray) -> np.ndarray:
    """Certified Tri per point of an (m, 2) array: TRUE inside, FALSE outside the polygon.

    UNKNOWN only where rounding cannot decide (points on or within a few ulps of an edge).

    Parameters
    ----------
    points : array_like, shape (m, 2)
        The points.
    polygon : numpy.ndarray, shape (k, 2)
        A validated polygon.

    Returns
    -------
    numpy.ndarray of int8, shape (m,)
        :class:`~optbound.interval.Tri` values.
    """
    verts, starts, _ = pack_polygons([polygon])
    pts = np.asarray(points, dtype=float)
    return np.array([_point_in_polygon(x, y, verts, 0, starts[1]) for x, y in pts], dtype=np.int8)


def _edge_boxes(polygon: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The polygon's edges as degenerate boxes ``(starts, ends)``, each (k, 2, 2)."""
    a = np.repeat(polygon[:, :, None], 2, axis=2)
    return a, np.roll(a, -1, axis=0)


def polygon_inside(inner: np.ndarray, outer: np.ndarray) -> bool:
    """True only if the polygon ``inner`` certainly lies in the interior of ``outer``.

    No edge of ``inner`` meets an edge of ``outer`` (``intersect > 0`` [GLH12, eq. (19)] in
    interval arithmetic, so touching is excluded) and a vertex of ``inner`` is certainly inside
    ``outer``; then the connected boundary of ``inner``, hence ``inner`` itself, is inside.
    False means "not proven" (rounding near a touching configuration counts as not proven).

    Parameters
    ----------
    inner, outer : numpy.ndarray, shape (k, 2)
        Validated polygons.

    Returns
    -------
    bool
        True if the inclusion is proven.
    """
    a1, b1 = _edge_boxes(inner)
    a2, b2 = _edge_boxes(outer)
    lo, _ = intersect_boxes(a1, b1, a2, b2)  # every edge pair
    return bool(np.all(lo > 0.0) and point_in_polygon(inner[:1], outer)[0] == 2)


__all__ = [
    "as_polygons",
    "intersect_boxes",
    "pack_polygons",
    "point_in_polygon",
    "polygon_inside",
    "segment_pair_meets",
    "segments_meet_packed",
    "segments_meet_polygons",
]
