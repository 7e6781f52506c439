"""Geometry primitives: point answers, and box answers that agree with every sampled point."""

import numpy as np
import pytest

from optbound.interval import Interval, Tri
from optbound.localization import geometry as g


def test_side_sign_convention():
    a, b = (0.0, 0.0), (1.0, 0.0)
    assert g.side((0.0, 1.0), a, b) < 0  # left of a -> b
    assert g.side((0.0, -1.0), a, b) > 0
    assert g.side((2.0, 0.0), a, b) == 0


def test_crosses_points():
    assert g.crosses((0.0, -1.0), (0.0, 1.0), (-1.0, 0.0), (1.0, 0.0))
    assert not g.crosses((0.0, 1.0), (0.0, 2.0), (-1.0, 0.0), (1.0, 0.0))
    # touching at an end point is not crossing
    assert not g.crosses((0.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (1.0, 0.0))


def _box(rng, m):
    lo = rng.uniform(-2, 2, size=(m, 2))
    return lo, lo + rng.uniform(0.0, 0.6, size=(m, 2))


def _as_intervals(box):
    lo, hi = box
    return Interval(lo[:, 0], hi[:, 0]), Interval(lo[:, 1], hi[:, 1])


def _sample(rng, box):
    lo, hi = box
    u = lo + rng.uniform(size=lo.shape) * (hi - lo)
    return u[:, 0], u[:, 1]


def test_crosses_boxes_agree_with_points():
    """A TRUE/FALSE answer on boxes holds for every sampled point of the boxes."""
    rng = np.random.default_rng(0)
    m = 400
    box1, box2 = _box(rng, m), _box(rng, m)
    a, b = g.segment_points(rng.uniform(-2, 2, size=(m, 2, 2)))
    tri = g.crosses(_as_intervals(box1), _as_intervals(box2), a, b)
    assert {Tri.TRUE, Tri.FALSE} <= set(np.unique(tri).tolist())
    for _ in range(50):
        point = g.crosses(_sample(rng, box1), _sample(rng, box2), a, b)
        assert np.all(point[tri == Tri.TRUE])
        assert not np.any(point[tri == Tri.FALSE])


def test_to_world_points_and_intervals():
    x, y = g.to_world((1.0, 2.0, np.pi / 2), (1.0, 0.0))
    assert np.isclose(x, 1.0) and np.isclose(y, 3.0)
    theta = Interval(0.1, 0.2)
    X, Y = g.to_world((Interval(1.0, 1.5), Interval(2.0, 2.0), theta), (1.0, 0.5))
    for t in np.linspace(0.1, 0.2, 11):
        for x0 in (1.0, 1.25, 1.5):
            px, py = g.to_world((x0, 2.0, t), (1.0, 0.5))
            assert X.lo <= px <= X.hi and Y.lo <= py <= Y.hi


@pytest.mark.parametrize(
    ("world", "match"),
    [
        (np.zeros((0, 2, 2)), "empty"),
        (np.zeros((2, 2)), "shape"),
        ([[[0, 0], [np.inf, 1]]], "finite"),
        ([[[1, 1], [1, 1]]], "zero length"),
        ([[[1j, 1], [1, 2]]], "complex"),
    ],
)
def test_as_segments_rejects_bad_maps(world, match):
    with pytest.raises(ValueError, match=match):
        g.as_segments(world, "world")


def test_occluded_on_points_and_boxes():
    walls = np.array([[[2.0, -1.0], [2.0, 1.0]], [[5.0, 5.0], [6.0, 5.0]]])
    hidden = g.occluded((np.array([0.0, 3.0]), np.array([0.0, 0.0])), (4.0, 0.0), walls)
    assert hidden.tolist() == [True, False]
    # A sight line ending on a wall only touches it: not occluded.
    assert not g.occluded((0.0, 0.0), (2.0, 0.5), walls)
    # Boxes: certainly hidden, certainly seen, undecided.
    box_x, box_y = Interval([0.0, 3.0, 1.0], [0.5, 3.5, 3.0]), Interval([-0.2] * 3, [0.2] * 3)
    tri = g.occluded((box_x, box_y), (4.0, 0.0), walls)
    assert tri.tolist() == [Tri.TRUE, Tri.FALSE, Tri.UNKNOWN]
