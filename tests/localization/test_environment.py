"""E⁻ ⊂ E ⊂ E⁺ [GLH12, Fig. 2]: the margin helper and the certified inclusion checks."""

import numpy as np
import pytest

from optbound.localization.environment import Environment
from tests.localization import exact_visibility as ex

SQUARE = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]])
TRIANGLE = np.array([[3.0, 3.0], [3.5, 4.0], [4.0, 3.0]])  # clockwise on purpose


def test_from_polygons_margin():
    env = Environment.from_polygons([SQUARE, TRIANGLE], 0.1)
    np.testing.assert_allclose(env.outer[0], [[-0.1, -0.1], [2.1, -0.1], [2.1, 1.1], [-0.1, 1.1]])
    np.testing.assert_allclose(env.inner[0], [[0.1, 0.1], [1.9, 0.1], [1.9, 0.9], [0.1, 0.9]])
    # Points at distance < margin outside E are in E⁺; at depth > margin inside E, in E⁻.
    rng = np.random.default_rng(0)
    assert len(env.inner) == 2  # the triangle's inradius (0.31) exceeds the margin
    pts = rng.uniform(2.5, 4.5, (400, 2))
    tri = ex.rational(TRIANGLE)
    for p, q in zip(pts, ex.rational(pts), strict=True):
        a, b = ex.rational(TRIANGLE[[0, 1, 2]]), ex.rational(TRIANGLE[[1, 2, 0]])
        dist = min(
            _dist(p, np.array(a_, float), np.array(b_, float)) for a_, b_ in zip(a, b, strict=True)
        )
        if not ex.inside(q, tri) and dist < 0.099:
            assert ex.inside(q, ex.rational(env.outer[1]))
        if ex.inside(q, tri) and dist > 0.101:
            assert ex.inside(q, ex.rational(env.inner[1]))


def _dist(p, a, b):
    t = np.clip(np.dot(p - a, b - a) / np.dot(b - a, b - a), 0, 1)
    return float(np.linalg.norm(p - (a + t * (b - a))))


def test_thin_obstacle_leaves_inner_empty():
    env = Environment.from_polygons(
        [np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 0.05], [0.0, 0.05]])], 0.1
    )
    assert env.inner == [] and len(env.outer) == 1


def test_inner_not_in_outer_is_rejected():
    with pytest.raises(ValueError, match="E⁻ ⊄ E⁺"):
        Environment([SQUARE + 5.0], [SQUARE * 1.1])
    with pytest.raises(ValueError, match="E⁻ ⊄ E⁺"):
        Environment([SQUARE], [SQUARE])  # touching boundaries: not in the interior
    with pytest.raises(ValueError, match="E ⊄ E⁺"):
        Environment([], [SQUARE], exact=[SQUARE * 2.0])


@pytest.mark.parametrize(
    ("polys", "margin", "match"),
    [
        ([SQUARE], 0.0, "margin"),
        ([SQUARE], np.inf, "margin"),
        ([np.array([[0, 0], [2, 0], [1, 0.5], [2, 2], [0, 2]])], 0.1, "convex"),
    ],
)
def test_from_polygons_rejects_bad_input(polys, margin, match):
    with pytest.raises(ValueError, match=match):
        Environment.from_polygons(polys, margin)


def test_thin_triangle_is_left_out_of_inner():
    # Its inradius (about 0.05) is below the margin: the erosion is empty, so E⁻ is.
    env = Environment.from_polygons([[[0, 0], [4, 0], [0, 0.1]]], 0.1)
    assert env.inner == [] and len(env.outer) == 1


def _thin_convex_polygon(rng, k):
    """k points in angular order on a random thin ellipse (a strictly convex polygon)."""
    t = np.sort(rng.uniform(0, 2 * np.pi, k))
    a, b, phi = rng.uniform(0.5, 3.0), rng.uniform(0.02, 0.4), rng.uniform(0, np.pi)
    p = np.column_stack([a * np.cos(t), b * np.sin(t)])
    rot = np.array([[np.cos(phi), -np.sin(phi)], [np.sin(phi), np.cos(phi)]])
    return p @ rot.T + rng.uniform(-5, 5, 2)


def _depth(p, poly):
    """Float distance from p to the boundary of the convex CCW-or-CW polygon (inside only)."""
    return min(_dist(p, poly[i], poly[(i + 1) % len(poly)]) for i in range(len(poly)))


@pytest.mark.parametrize("k", [3, 4, 5])
def test_thin_polygons_erode_to_their_deep_points(k):
    """Random thin convex polygons: no refusal; points at depth > margin are in E⁻ (exact)."""
    rng = np.random.default_rng(k)
    margin, kept = 0.1, 0
    for _ in range(60):
        poly = _thin_convex_polygon(rng, k)
        env = Environment.from_polygons([poly], margin)  # E⁻ ⊂ E is checked exactly inside
        kept += len(env.inner)
        lo, hi = poly.min(axis=0), poly.max(axis=0)
        rpoly = ex.rational(poly)
        for p in rng.uniform(lo, hi, (200, 2)):
            q = ex.rational([p])[0]
            if ex.inside(q, rpoly) and _depth(p, poly) > margin * 1.001:
                assert env.inner and ex.inside(q, ex.rational(env.inner[0]))
    assert kept > 0  # the sample also has polygons thick enough to keep
