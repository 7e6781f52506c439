"""tri_test: interval membership per set type, checked against exact arithmetic."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound import Box, Ellipsoid, Halfspace, Strip
from optbound.compare import exact, tri_contains
from optbound.compare.tri import point_test, tri_test
from optbound.interval import Tri
from tests.strategies import ellipsoids


def _sets(E: Ellipsoid):
    d = np.ones(E.dim) / np.sqrt(E.dim)
    lo, hi = E.extent(d)
    return [
        E,
        E.bounding_box(),
        Strip.from_bounds(d, lo + 0.3 * (hi - lo), lo + 0.6 * (hi - lo)),
        Halfspace(d, lo + 0.5 * (hi - lo)),
    ]


@given(ellipsoids(max_dim=4), st.integers(0, 2**32 - 1))
def test_points_are_decided_as_exact_arithmetic_decides_them(E, seed):
    rng = np.random.default_rng(seed)
    X = E.scaled(1.3).sample(60, rng)
    for S in _sets(E):
        tri = point_test(tri_test(S), X)
        for x, t in zip(X, tri, strict=True):
            if t != Tri.UNKNOWN:
                assert exact.member(S, x) == (t == Tri.TRUE), (S, x)
        assert np.mean(tri == Tri.UNKNOWN) < 0.1


@given(ellipsoids(max_dim=3), st.integers(0, 2**32 - 1))
def test_boxes_proven_inside_have_every_corner_inside(E, seed):
    rng = np.random.default_rng(seed)
    centres = E.sample(30, rng)
    width = 0.05 * E.semi_axes()[-1]
    boxes = np.stack([centres - width, centres + width], axis=-1)
    for S in _sets(E):
        tri = tri_contains(S, boxes)
        for box, t in zip(boxes, tri, strict=True):
            corners = [box[:, 0], box[:, 1], np.where(np.arange(E.dim) % 2, box[:, 0], box[:, 1])]
            if t == Tri.TRUE:
                assert all(exact.member(S, c) for c in corners)
            elif t == Tri.FALSE:
                assert not any(exact.member(S, c) for c in corners)


def test_user_tri_contains_is_checked():
    class Bad:
        dim = 2

        def tri_contains(self, boxes):
            return np.array([2, 2, 2], dtype=np.int8)

    with pytest.raises(ValueError, match="one Tri value per box"):
        tri_contains(Bad(), np.zeros((2, 2, 2)))
    with pytest.raises(TypeError, match="no interval membership test"):
        tri_test(object())
    assert tri_contains(Box([0.0, 0.0], [1.0, 1.0]), [[[0.2, 0.3], [0.2, 0.3]]])[0] == Tri.TRUE
