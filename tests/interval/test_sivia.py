"""SIVIA on the papers' sets: the brackets hold, narrow with eps, and contain sampled truth."""

import numpy as np
import pytest

from optbound import Box
from optbound import interval as iv

# LJMW97 Appendix A: unit disc minus the ellipse 2x^2 + y^2 < 1; area pi (1 - 1/sqrt 2).
APP_A = dict(
    f=lambda x, y: (x**2 + y**2, 2 * x**2 + y**2),
    Y=[[-np.inf, 1.0], [1.0, np.inf]],
    X0=[[-2.5, 2.5], [-2.0, 2.0]],
    area=np.pi * (1 - 1 / np.sqrt(2)),
)
# Ring 1 <= (x-1)^2 + (y-2)^2 <= 4: area 3 pi.
RING = dict(
    f=lambda x, y: (x - 1) ** 2 + (y - 2) ** 2,
    Y=[[1.0, 4.0]],
    X0=[[-5.0, 5.0], [-5.0, 5.0]],
    area=3 * np.pi,
)


def _in_app_a(p, margin):
    r2, e2 = p[:, 0] ** 2 + p[:, 1] ** 2, 2 * p[:, 0] ** 2 + p[:, 1] ** 2
    return (r2 <= 1 + margin) & (e2 >= 1 - margin)


def _in_ring(p, margin):
    d2 = (p[:, 0] - 1) ** 2 + (p[:, 1] - 2) ** 2
    return (d2 >= 1 - margin) & (d2 <= 4 + margin)


def _points_in_boxes(points, boxes):
    if boxes.shape[0] == 0:
        return np.zeros(points.shape[0], dtype=bool)
    inside = (points[:, None, :] >= boxes[None, :, :, 0]) & (
        points[:, None, :] <= boxes[None, :, :, 1]
    )
    return inside.all(axis=2).any(axis=1)


@pytest.mark.parametrize(("case", "member"), [(APP_A, _in_app_a), (RING, _in_ring)])
def test_area_bracket_narrows_and_contains_truth(case, member):
    widths = []
    for eps in (0.1, 0.05, 0.02):
        p = iv.sivia(case["f"], case["Y"], case["X0"], eps)
        inner, outer = p.volume_bounds()
        assert inner <= case["area"] <= outer
        widths.append(outer - inner)
        assert np.all(p.boundary[:, :, 1] - p.boundary[:, :, 0] <= eps)
    assert widths[0] > widths[1] > widths[2]
    # Guaranteed: 10^4 sampled points of the set lie in inner ∪ boundary; points of inner boxes
    # lie in the set (a 1e-12 margin absorbs the float evaluation of the membership test).
    pts = Box.from_array(case["X0"]).sample(10_000, np.random.default_rng(1))
    assert np.all(_points_in_boxes(pts[member(pts, -1e-12)], p.outer()))
    assert np.all(member(pts[_points_in_boxes(pts, p.inner)], 1e-12))
    assert not np.any(member(pts[_points_in_boxes(pts, p.outside)], -1e-12))


def test_test_form_and_conjunction_match_image_form():
    ref = iv.sivia(APP_A["f"], APP_A["Y"], APP_A["X0"], 0.05)

    def disc(x, y):
        return x**2 + y**2 <= 1.0

    def not_ellipse(x, y):
        return 2 * x**2 + y**2 >= 1.0

    both = iv.pave(lambda x, y: iv.tri_and(disc(x, y), not_ellipse(x, y)), APP_A["X0"], 0.05)
    listed = iv.pave([disc, not_ellipse], APP_A["X0"], 0.05)
    for p in (both, listed):
        assert np.allclose(p.volume_bounds(), ref.volume_bounds(), rtol=1e-12)
    # The same test evaluated on points answers booleans.
    assert iv.tri_and(disc(0.8, 0.0), not_ellipse(0.8, 0.0)) == iv.Tri.TRUE
    assert iv.tri_and(disc(0.0, 0.9), not_ellipse(0.0, 0.9)) == iv.Tri.FALSE


def test_box_inputs_and_infinite_y():
    p = iv.sivia(
        APP_A["f"], Box([-np.inf, 1.0], [1.0, np.inf]), Box([-2.5, -2.0], [2.5, 2.0]), 0.05
    )
    q = iv.sivia(APP_A["f"], APP_A["Y"], APP_A["X0"], 0.05)
    assert p.volume_bounds() == q.volume_bounds()


def test_three_dimensional_ball():
    p = iv.sivia(lambda x, y, z: x**2 + y**2 + z**2, [[0.0, 1.0]], [[-1.5, 1.5]] * 3, 0.1)
    inner, outer = p.volume_bounds()
    assert inner <= 4 / 3 * np.pi <= outer
    assert p.inner.shape[1:] == (3, 2)


def test_function_undefined_on_boxes_is_outside():
    # sqrt(x) in [0, 1] on x in [-1, 2]: the set is [0, 1] (y is a dummy coordinate).
    p = iv.sivia(lambda x, y: np.sqrt(x), [[0.0, 1.0]], [[-1.0, 2.0], [0.0, 1.0]], 0.01)
    inner, outer = p.volume_bounds()
    assert inner <= 1.0 <= outer and outer < 1.05
    assert np.all(p.inner[:, 0, 0] >= 0.0)


def test_empty_set_and_full_box():
    empty = iv.sivia(lambda x, y: x**2 + y**2, [[-2.0, -1.0]], [[-1.0, 1.0]] * 2, 0.1)
    assert empty.is_empty and empty.volume_bounds() == (0.0, 0.0) and empty.hull() is None
    assert empty.components() == []
    full = iv.sivia(lambda x, y: x + y, [[-10.0, 10.0]], [[-1.0, 1.0]] * 2, 0.1)
    assert full.volume_bounds() == (4.0, 4.0)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        (dict(X0=[[0.0, np.nan], [0.0, 1.0]]), "X0"),
        (dict(X0=[[0.0, np.inf], [0.0, 1.0]]), "X0 must be a bounded box"),
        (dict(X0=[[1.0, 0.0], [0.0, 1.0]]), "X0"),
        (dict(X0=[0.0, 1.0]), "X0"),
        (dict(Y=[[np.nan, 1.0]]), "Y"),
        (dict(Y=[[0.0, 1.0], [0.0, 1.0], [0.0, 1.0]]), "outputs but Y has 3 rows"),
        (dict(eps=0.0), "eps must be positive"),
        (dict(eps=np.nan), "eps must be finite"),
        (dict(ratio=1.0), "ratio"),
        (dict(X0=[[1e6, 1e6 + 1.0], [0.0, 1.0]], eps=1e-12), "resolution"),
        (dict(max_boxes=100), "max_boxes"),
    ],
)
def test_bad_input_raises(kwargs, match):
    args = dict(f=APP_A["f"], Y=APP_A["Y"], X0=APP_A["X0"], eps=0.05) | kwargs
    with pytest.raises(ValueError, match=match):
        iv.sivia(**args)


def test_bad_tests_raise():
    with pytest.raises(ValueError, match="callable"):
        iv.pave([], APP_A["X0"], 0.1)
    with pytest.raises(ValueError, match="one value per box"):
        iv.pave(lambda x, y: np.zeros(3, dtype=np.int8), APP_A["X0"], 0.1)
