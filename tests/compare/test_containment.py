"""Exact ellipsoid-in-ellipsoid containment against boundary sampling."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound import Ellipsoid, Strip, analytic
from optbound.compare import contains, max_level


def _random(rng, n, scale):
    A = rng.standard_normal((n, n)) * scale
    return Ellipsoid(rng.standard_normal(n) * 0.3, A @ A.T + 0.01 * np.eye(n))


@given(st.integers(0, 10_000), st.integers(2, 4))
def test_max_level_matches_dense_boundary_sampling(seed, n):
    rng = np.random.default_rng(seed)
    outer, inner = _random(rng, n, 1.0), _random(rng, n, 0.4)
    exact = max_level(outer, inner)
    sampled = float(np.max(outer.level(inner.sample_boundary(20_000, rng))))
    assert sampled <= exact * (1 + 1e-9)  # exact is a true maximum (upper bound)
    assert sampled >= exact * (1 - 0.05)  # and the samples come close to it


def test_tangent_inner_ellipse_is_contained():
    outer = Ellipsoid([0.0, 0.0], np.eye(2))
    inner = Ellipsoid([0.5, 0.0], np.diag([0.25, 0.5]))  # touches at (1, 0)
    assert max_level(outer, inner) == pytest.approx(1.0, abs=1e-12)
    assert contains(outer, inner)
    assert not contains(inner, outer)


def test_concentric_and_scaled():
    E = Ellipsoid([1.0, -1.0, 2.0], np.diag([1.0, 2.0, 3.0]))
    assert max_level(E.scaled(2.0), E) == pytest.approx(0.25)
    assert contains(E, E)
    assert not contains(E, E.scaled(1.0 + 1e-6))


def test_hard_case_center_offset_orthogonal_to_the_long_axis():
    outer = Ellipsoid([0.0, 0.0], np.eye(2))
    inner = Ellipsoid([0.0, 0.1], np.diag([0.81, 0.01]))
    # max over inner of x^2 + y^2 with x = 0.9 cos t, y = 0.1 + 0.1 sin t.
    t = np.linspace(0, 2 * np.pi, 200_001)
    brute = np.max((0.9 * np.cos(t)) ** 2 + (0.1 + 0.1 * np.sin(t)) ** 2)
    assert max_level(outer, inner) == pytest.approx(brute, rel=1e-8)


def test_tolerance_is_a_relative_slack_on_the_level():
    outer = Ellipsoid([0.0, 0.0], np.eye(2))
    slightly = Ellipsoid([0.0, 0.0], (1.0 + 1e-6) * np.eye(2))  # level 1 + 1e-6
    assert not contains(outer, slightly)
    assert contains(outer, slightly, tol=2e-6)
    for bad in (-1e-9, float("nan")):
        with pytest.raises(ValueError, match="tol must be"):
            contains(outer, slightly, tol=bad)


def test_nearly_equal_ellipsoids_do_not_break_the_root_bracket():
    # An analytic bound and its SDP twin: equal up to ~1e-9, the secular bracket's upper end
    # can round to a positive slope.
    E = Ellipsoid([0.0, 0.0], np.diag([4.0, 1.0]))
    a = analytic.intersect_strip(E, Strip.from_bounds([1.0, 1.0], -0.5, 1.5)).ellipsoid
    twin = Ellipsoid(a.center * (1 + 1e-12) + 1e-13, a.shape * (1 - 1e-10))
    assert max_level(a, twin) == pytest.approx(1.0, abs=1e-8)
    assert contains(a, twin)


def test_an_analytic_bound_equal_to_the_sdp_optimum_contains_it_by_default():
    """HS96 on one ellipse ∩ one strip is the optimum; the SDP finds it to solver accuracy."""
    from optbound import optimal

    E = Ellipsoid([0.0, 0.0], np.diag([4.0, 1.0]))
    S = Strip.from_bounds([1.0, 1.0], -0.5, 1.5)
    a = analytic.intersect_strip(E, S)
    sdp = optimal.outer_ellipsoid([E, S])
    assert contains(a, sdp) and contains(sdp, a)  # equal, to the reference's accuracy
    assert not contains(a.ellipsoid.scaled(1 - 1e-3), sdp)  # a smaller bound is not equal
    assert not contains(E, E.scaled(1.0 + 1e-6))  # two plain ellipsoids: rounding only
