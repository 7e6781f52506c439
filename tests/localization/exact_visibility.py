"""Exact rational reference for segment-polygon meeting (tests only): Fractions, no rounding."""

from fractions import Fraction

import numpy as np


def _side(p, a, b):
    return (p[0] - a[0]) * (b[1] - a[1]) - (p[1] - a[1]) * (b[0] - a[0])


def _on_segment(p, a, b):
    return (
        _side(p, a, b) == 0
        and min(a[0], b[0]) <= p[0] <= max(a[0], b[0])
        and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])
    )


def segments_meet(p1, p2, p3, p4) -> bool:
    """Do the closed segments meet (crossing, touching or overlapping)?"""
    d1, d2 = _side(p1, p3, p4), _side(p2, p3, p4)
    d3, d4 = _side(p3, p1, p2), _side(p4, p1, p2)
    if ((d1 > 0 and d2 < 0) or (d1 < 0 and d2 > 0)) and (
        (d3 > 0 and d4 < 0) or (d3 < 0 and d4 > 0)
    ):
        return True
    return (
        _on_segment(p1, p3, p4)
        or _on_segment(p2, p3, p4)
        or _on_segment(p3, p1, p2)
        or _on_segment(p4, p1, p2)
    )


def inside(p, poly) -> bool:
    """Point in the closed polygon (boundary included)."""
    k = len(poly)
    if any(_on_segment(p, poly[i], poly[(i + 1) % k]) for i in range(k)):
        return True
    result = False
    for i in range(k):
        a, b = poly[i], poly[(i + 1) % k]
        if (a[1] > p[1]) != (b[1] > p[1]):
            x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            if p[0] < x:
                result = not result
    return result


def rational(points) -> list[tuple[Fraction, Fraction]]:
    return [(Fraction(float(x)), Fraction(float(y))) for x, y in np.asarray(points)]


def segment_meets_polygon(p1, p2, poly) -> bool:
    """Exact: does the closed segment meet the closed solid polygon?"""
    p1, p2 = rational([p1])[0], rational([p2])[0]
    poly = rational(poly)
    if inside(p1, poly):
        return True
    k = len(poly)
    return any(segments_meet(p1, p2, poly[i], poly[(i + 1) % k]) for i in range(k))


def visible(p1, p2, polygons) -> bool:
    """Exact visibility [GLH12, Def. 1]: no polygon meets Seg(p1, p2)."""
    return not any(segment_meets_polygon(p1, p2, poly) for poly in polygons)
