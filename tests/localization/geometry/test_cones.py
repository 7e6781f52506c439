"""Cone predicates of the sonar model (appended to geometry.py): points vs brute force, boxes."""

import numpy as np
import pytest

from optbound.interval import Interval
from optbound.localization import geometry as g


def test_in_cone_points():
    right, left = g.unit(-0.2), g.unit(0.2)
    assert g.in_cone((1.0, 0.0), right, left) > 0
    assert g.in_cone((1.0, 0.5), right, left) < 0  # atan(0.5) > 0.2
    assert g.in_cone((-1.0, 0.0), right, left) < 0  # opposite cone excluded
    assert g.in_cone(g.unit(0.2), right, left) == pytest.approx(0.0, abs=1e-15)


def test_front_distance_sign_and_value():
    a, b = (0.0, 0.0), (2.0, 0.0)  # reflecting face up (left of a -> b)
    assert g.front_distance((1.0, 3.0), a, b) == pytest.approx(3.0)
    assert g.front_distance((1.0, -0.5), a, b) == pytest.approx(-0.5)


def _brute_force(apex, heading, gamma, a, b, far, n=20001):
    """Nearest of n points along the segment that are in the cone, seen from the front."""
    t = np.linspace(0, 1, n)
    px, py = a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])
    ang = np.arctan2(py - apex[1], px - apex[0]) - heading
    inside = np.abs(np.angle(np.exp(1j * ang))) <= gamma
    front = g.side(apex, a, b) < 0
    d = np.hypot(px - apex[0], py - apex[1])
    return min(far, d[inside].min()) if front and inside.any() else far


def test_nearest_in_cone_matches_brute_force():
    rng = np.random.default_rng(5)
    seen = 0
    for _ in range(300):
        apex = tuple(rng.uniform(-1, 1, 2))
        heading, gamma = rng.uniform(-np.pi, np.pi), rng.uniform(0.05, 1.2)
        a, b = tuple(rng.uniform(-4, 4, 2)), tuple(rng.uniform(-4, 4, 2))
        exact = float(g.nearest_in_cone(apex, heading, gamma, a, b, 20.0))
        brute = _brute_force(apex, heading, gamma, a, b, 20.0)
        # The sampled points are in the set, so brute >= exact; the gap is the sampling step.
        step = np.hypot(b[0] - a[0], b[1] - a[1]) / 20000
        if brute < 20.0 or exact < 20.0:
            seen += 1
            assert exact <= brute + 1e-12
            assert brute - exact <= step + 1e-9
    assert seen > 50


def test_nearest_in_cone_boxes_enclose_points():
    rng = np.random.default_rng(6)
    m = 500
    lo = rng.uniform(-1, 1, (m, 3))
    hi = lo + rng.uniform(0, [0.3, 0.3, 0.4], (m, 3))
    a, b = (np.array([3.0]), np.array([-2.0])), (np.array([-1.0]), np.array([3.0]))
    box = (Interval(lo[:, 0], hi[:, 0]), Interval(lo[:, 1], hi[:, 1]))
    enc = g.nearest_in_cone(box, Interval(lo[:, 2], hi[:, 2]), 0.3, a, b, 10.0)
    assert np.any(enc.hi < 10.0) and np.any(enc.lo == 10.0)
    for _ in range(50):
        u = lo + rng.uniform(size=(m, 3)) * (hi - lo)
        d = g.nearest_in_cone((u[:, 0], u[:, 1]), u[:, 2], 0.3, a, b, 10.0)
        assert np.all((enc.lo <= d) & (d <= enc.hi))


def test_exact_makes_point_intervals():
    x, y = g.exact((np.array([0.1, 0.2]), 0.3))
    assert isinstance(x, Interval) and np.array_equal(x.lo, x.hi) and float(y.lo) == 0.3
