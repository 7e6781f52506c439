"""Polygon predicates (GLH12): compiled box enclosures against exact rational references."""

import numpy as np
import pytest

from optbound.interval import Interval, Tri
from optbound.localization import geometry as g
from tests.localization import exact_visibility as ex

SQUARE = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
# A non-convex "U" (opening upwards), to exercise the crossing-number and inside cases.
U_SHAPE = np.array([[0, 0], [3, 0], [3, 3], [2, 3], [2, 1], [1, 1], [1, 3], [0, 3]], dtype=float)


def _exact_intersect(p1, p2, p3, p4):
    """[GLH12, eq. (19)] in exact rational arithmetic."""
    p1, p2, p3, p4 = ex.rational([p1, p2, p3, p4])
    return (
        max(
            ex._side(p1, p3, p4) * ex._side(p2, p3, p4), ex._side(p3, p1, p2) * ex._side(p4, p1, p2)
        )
        / 2
    )


def test_intersect_boxes_encloses_exactly_and_tighter_than_interval_formula():
    """The compiled interval eq. (19) contains every exact value and lies inside the
    enclosure of ``intersect`` on ``Interval`` arrays (up to an ulp of rounding scheme)."""
    rng = np.random.default_rng(1)
    m, s = 60, 7
    lo1, lo2 = rng.uniform(-2, 2, (m, 2)), rng.uniform(-2, 2, (m, 2))
    boxes1 = np.stack([lo1, lo1 + rng.uniform(0, 0.5, (m, 2))], -1)
    boxes2 = np.stack([lo2, lo2 + rng.uniform(0, 0.5, (m, 2))], -1)
    a, b = rng.uniform(-2, 2, (s, 2)), rng.uniform(-2, 2, (s, 2))
    lo, hi = g.intersect_boxes(
        boxes1, boxes2, np.repeat(a[:, :, None], 2, 2), np.repeat(b[:, :, None], 2, 2)
    )
    ref = g.intersect(
        (
            Interval(boxes1[:, None, 0, 0], boxes1[:, None, 0, 1]),
            Interval(boxes1[:, None, 1, 0], boxes1[:, None, 1, 1]),
        ),
        (
            Interval(boxes2[:, None, 0, 0], boxes2[:, None, 0, 1]),
            Interval(boxes2[:, None, 1, 0], boxes2[:, None, 1, 1]),
        ),
        (a[:, 0], a[:, 1]),
        (b[:, 0], b[:, 1]),
    )
    slack = 1e-12 * (np.abs(ref.lo) + np.abs(ref.hi))
    assert np.all(lo >= ref.lo - slack) and np.all(hi <= ref.hi + slack)
    assert np.mean(hi - lo) < 0.8 * np.mean(ref.hi - ref.lo)  # the dependency effect is cut
    for i in range(0, m, 6):
        for k in range(s):
            for _ in range(3):
                p1 = boxes1[i, :, 0] + rng.uniform(size=2) * np.ptp(boxes1[i], 1)
                p2 = boxes2[i, :, 0] + rng.uniform(size=2) * np.ptp(boxes2[i], 1)
                assert lo[i, k] <= _exact_intersect(p1, p2, a[k], b[k]) <= hi[i, k]


def test_point_in_polygon_certified():
    pts = np.array(
        [[1.5, 0.5], [1.5, 2.0], [0.5, 2.0], [2.5, 2.9], [4.0, 1.0], [1.5, 1.0], [0.0, 0.0]]
    )
    tri = g.point_in_polygon(pts, U_SHAPE)
    # inside, in the notch (outside), two arms, far outside, on a horizontal edge, a vertex
    assert tri.tolist() == [
        Tri.TRUE,
        Tri.FALSE,
        Tri.TRUE,
        Tri.TRUE,
        Tri.FALSE,
        Tri.UNKNOWN,
        Tri.UNKNOWN,
    ]
    rng = np.random.default_rng(2)
    pts = rng.uniform(-0.5, 3.5, (500, 2))
    tri = g.point_in_polygon(pts, U_SHAPE)
    poly = ex.rational(U_SHAPE)
    truth = np.array([ex.inside(p, poly) for p in ex.rational(pts)])
    assert np.all(truth[tri == Tri.TRUE]) and not np.any(truth[tri == Tri.FALSE])
    assert np.count_nonzero(tri == Tri.UNKNOWN) == 0  # random points are never on the boundary


def _point_boxes(p):
    p = np.asarray(p, dtype=float)
    return np.repeat(p[:, :, None], 2, axis=2)


def test_segments_meet_polygons_special_cases():
    boxes1 = _point_boxes([[-1.0, 0.5], [-1.0, 0.0], [0.2, 0.2], [0.5, 2.0], [0.0, 2.0]])
    boxes2 = _point_boxes([[2.0, 0.5], [2.0, 0.0], [0.8, 0.8], [0.5, 3.0], [2.0, 0.0]])
    tri = g.segments_meet_polygons(boxes1, boxes2, [SQUARE])
    # crossing; inside the obstacle (no edge crossed); far away. Touching (along an edge, at a
    # vertex) meets the obstacle but sign tests see a zero: never FALSE, honestly UNKNOWN.
    assert tri[[0, 2, 3]].tolist() == [Tri.TRUE, Tri.TRUE, Tri.FALSE]
    assert tri[[1, 4]].tolist() == [Tri.UNKNOWN, Tri.UNKNOWN]
    # Boxes wholly inside an obstacle meet it whatever the other end.
    inside_box = np.array([[[0.4, 0.6], [0.4, 0.6]]])
    far = np.array([[[5.0, 6.0], [-3.0, 3.0]]])
    assert g.segments_meet_polygons(inside_box, far, [SQUARE]).tolist() == [Tri.TRUE]
    assert g.segments_meet_polygons(far, inside_box, [SQUARE]).tolist() == [Tri.TRUE]
    assert g.segments_meet_polygons(far, far, []).tolist() == [Tri.FALSE]


def _random_polygons(rng):
    polys = [U_SHAPE * 0.8 + rng.uniform(0, 6, 2)]
    for _ in range(3):
        c, r = rng.uniform(1, 8, 2), rng.uniform(0.3, 1.5)
        ang = np.sort(rng.uniform(0, 2 * np.pi, rng.integers(3, 7)))
        polys.append(c + r * np.column_stack([np.cos(ang), np.sin(ang)]))
    polys.append(np.array([[3.0, 3.0], [7.0, 3.0], [7.0, 7.0], [3.0, 7.0]]))  # big: boxes inside
    return polys


def test_segments_meet_polygons_agree_with_exact_samples():
    """TRUE/FALSE on boxes is never contradicted by exact rational checks of sampled pairs."""
    rng = np.random.default_rng(3)
    polys = _random_polygons(rng)
    m = 300
    lo1, lo2 = rng.uniform(0, 9, (m, 2)), rng.uniform(0, 9, (m, 2))
    boxes1 = np.stack([lo1, lo1 + rng.uniform(0, 1, (m, 2))], -1)
    boxes2 = np.stack([lo2, lo2 + rng.uniform(0, 1, (m, 2))], -1)
    tri = g.segments_meet_polygons(boxes1, boxes2, polys)
    assert {Tri.TRUE, Tri.FALSE, Tri.UNKNOWN} <= set(tri.tolist())
    decided = np.flatnonzero(tri != Tri.UNKNOWN)
    for i in decided:
        corners = [(boxes1[i, 0, a], boxes1[i, 1, b]) for a in (0, 1) for b in (0, 1)]
        ends = [(boxes2[i, 0, a], boxes2[i, 1, b]) for a in (0, 1) for b in (0, 1)]
        samples = [
            (boxes1[i, :, 0] + rng.uniform(size=2) * np.ptp(boxes1[i], 1),
             boxes2[i, :, 0] + rng.uniform(size=2) * np.ptp(boxes2[i], 1))
            for _ in range(4)
        ]  # fmt: skip
        for p1, p2 in [*zip(corners, ends, strict=True), *samples]:
            assert ex.visible(p1, p2, polys) == (tri[i] == Tri.FALSE)


def test_polygon_inside():
    assert g.polygon_inside(SQUARE * 0.5 + 0.25, SQUARE)
    assert not g.polygon_inside(SQUARE, SQUARE * 0.5 + 0.25)
    assert not g.polygon_inside(SQUARE, SQUARE)  # touching is not "in the interior"
    assert not g.polygon_inside(SQUARE + 2.0, SQUARE)


@pytest.mark.parametrize(
    ("polys", "error", "match"),
    [
        (np.zeros((3, 2)), TypeError, "list"),
        ([np.zeros((2, 2))], ValueError, "k >= 3"),
        ([[[0, 0], [1, 0], [np.nan, 1]]], ValueError, "finite"),
        ([[[0, 0], [1, 0], [1j, 1]]], ValueError, "complex"),
        ([[[0, 0], [0, 0], [1, 1]]], ValueError, "zero-length"),
    ],
)
def test_as_polygons_rejects_bad_input(polys, error, match):
    with pytest.raises(error, match=match):
        g.as_polygons(polys, "obstacles")
