"""Tests for optbound.sets.Ellipsoid: validation, geometry and sampling."""

from math import gamma, pi

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound import Box, Ellipsoid
from tests.strategies import ellipsoids


def test_volume_matches_closed_form_in_each_dimension():
    for n in range(1, 7):
        shape = np.diag(np.arange(1.0, n + 1))
        unit_ball = pi ** (n / 2) / gamma(n / 2 + 1)
        expected = unit_ball * np.sqrt(np.prod(np.arange(1.0, n + 1)))
        assert Ellipsoid(np.zeros(n), shape).volume() == pytest.approx(expected, rel=1e-12)


def test_log_volume_is_finite_where_volume_underflows():
    E = Ellipsoid(np.zeros(6), 1e-120 * np.eye(6))
    assert E.volume() == 0.0
    assert np.isfinite(E.log_volume())


def test_contains_single_point_and_batch():
    E = Ellipsoid([1.0, -1.0], [[4.0, 0.0], [0.0, 1.0]])
    assert E.contains([3.0, -1.0])
    assert not E.contains([3.0 + 1e-6, -1.0])
    np.testing.assert_array_equal(E.contains([[1.0, 0.0], [1.0, 0.01]]), [True, False])


@given(ellipsoids(), st.integers(0, 2**32 - 1))
def test_uniform_samples_lie_inside_and_fill_the_volume(E, seed):
    X = E.sample(4000, np.random.default_rng(seed))
    assert E.contains(X).all()
    # A uniform sample has E[level] = E[r^2] = n / (n + 2) in normalized coordinates.
    n = E.dim
    assert np.mean(E.level(X)) == pytest.approx(n / (n + 2), abs=0.05)


@given(ellipsoids(), st.integers(0, 2**32 - 1))
def test_support_is_attained_by_boundary_and_bounds_samples(E, seed):
    rng = np.random.default_rng(seed)
    d = rng.standard_normal((50, E.dim))
    h = E.support(d)
    X = E.sample_boundary(2000, rng)
    assert np.all(X @ d.T <= h + 1e-9 * (1 + np.abs(h)))
    # The maximizer c + C d / sqrt(d^T C d) lies on the boundary and attains h.
    Cd = d @ E.shape
    argmax = E.center + Cd / np.sqrt(np.einsum("ij,ij->i", Cd, d))[:, None]
    np.testing.assert_allclose(np.einsum("ij,ij->i", argmax, d), h, rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(E.level(argmax), 1.0, rtol=1e-9)


@given(ellipsoids(), st.integers(0, 2**32 - 1))
def test_projection_contains_projected_samples(E, seed):
    dims = [0, E.dim - 1]
    P = E.project(dims)
    X = E.sample(2000, np.random.default_rng(seed))
    assert P.contains(X[:, dims]).all()
    # Its support equals the support of E along directions in the subspace.
    d = np.zeros(E.dim)
    d[dims] = [1.0, -2.0]
    assert P.support([1.0, -2.0]) == pytest.approx(E.support(d), rel=1e-12)


@given(ellipsoids(), st.integers(0, 2**32 - 1))
def test_affine_map_maps_samples_inside(E, seed):
    rng = np.random.default_rng(seed)
    A = rng.standard_normal((E.dim, E.dim)) + 3 * np.eye(E.dim)
    t = rng.standard_normal(E.dim)
    F = E.affine_map(A, t)
    X = E.sample(2000, rng)
    assert F.contains(X @ A.T + t, tol=1e-7).all()
    assert F.log_volume() == pytest.approx(
        E.log_volume() + np.log(abs(np.linalg.det(A))), rel=1e-9, abs=1e-9
    )


def test_bounding_box_is_tight():
    E = Ellipsoid([0.0, 1.0], [[4.0, 1.0], [1.0, 1.0]])
    B = E.bounding_box()
    assert isinstance(B, Box)
    np.testing.assert_allclose(B.hi, [2.0, 2.0])
    np.testing.assert_allclose(B.hi, E.support(np.eye(2)))


def test_boundary_points_trace_a_closed_curve_on_the_ellipse():
    E = Ellipsoid([1.0, 2.0], [[2.0, 0.5], [0.5, 1.0]])
    P = E.boundary(100)
    assert P.shape == (100, 2)
    np.testing.assert_allclose(E.level(P), 1.0, rtol=1e-12)
    np.testing.assert_allclose(P[0], P[-1])


def test_scaled_multiplies_semi_axes():
    E = Ellipsoid([0.0, 0.0, 0.0], np.diag([1.0, 4.0, 9.0]))
    np.testing.assert_allclose(E.scaled(2.0).semi_axes(), [2.0, 4.0, 6.0])


def test_tiny_asymmetry_is_symmetrized():
    E = Ellipsoid([0.0, 0.0], [[1.0, 0.2 + 1e-13], [0.2, 1.0]])
    np.testing.assert_array_equal(E.shape, E.shape.T)


def test_the_set_is_immutable():
    E = Ellipsoid([0.0, 0.0], np.eye(2))
    with pytest.raises(ValueError):
        E.center[0] = 1.0


@pytest.mark.parametrize(
    ("center", "shape", "word"),
    [
        ([0.0, np.nan], np.eye(2), "center"),
        ([0.0, 0.0], [[1.0, np.inf], [0.0, 1.0]], "shape"),
        ([0.0, 0.0], np.eye(3), "shape"),
        ([0.0, 0.0], [[1.0, 0.5], [0.0, 1.0]], "symmetric"),
        ([0.0, 0.0], [[1.0, 2.0], [2.0, 1.0]], "positive definite"),
        ([0.0, 0.0], [[1.0, 0.0], [0.0, 0.0]], "positive definite"),
        ([[0.0, 0.0]], np.eye(2), "center"),
    ],
)
def test_bad_input_raises_naming_the_argument(center, shape, word):
    with pytest.raises(ValueError, match=word):
        Ellipsoid(center, shape)


def test_bad_method_arguments():
    E = Ellipsoid([0.0, 0.0], np.eye(2))
    with pytest.raises(ValueError, match="X"):
        E.contains([1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="dims"):
        E.project([0, 0])
    with pytest.raises(ValueError, match="full row rank"):
        E.affine_map([[1.0, 1.0], [2.0, 2.0]])
    with pytest.raises(ValueError, match="rng"):
        E.sample(10, None)
    with pytest.raises(ValueError, match="2-D"):
        Ellipsoid(np.zeros(3), np.eye(3)).boundary()
    with pytest.raises(ValueError, match="factor"):
        E.scaled(-1.0)


@pytest.mark.parametrize(
    ("center", "shape", "err", "word"),
    [
        ([1j, 0.0], np.eye(2), TypeError, "center must be real"),
        ([0.0, 0.0], np.eye(2) * (1 + 1e-3j), TypeError, "shape must be real"),
        ([0.0, 0.0], np.diag([1.0, 1e-13]), ValueError, "ill-conditioned"),
        ([1e12, 0.0], np.eye(2), ValueError, "center is too far"),
        ([1.0, 0.0], 1e-24 * np.eye(2), ValueError, "center is too far"),
        ([0.0, 0.0], 1e-130 * np.eye(2), ValueError, "semi-axes outside"),
        ([0.0, 0.0], 1e130 * np.eye(2), ValueError, "semi-axes outside"),
    ],
)
def test_inputs_outside_the_domain_are_refused(center, shape, err, word):
    with pytest.raises(err, match=word):
        Ellipsoid(center, shape)


def test_domain_edges_are_accepted():
    Ellipsoid([0.0, 0.0], np.diag([1.0, 1e-11]))
    Ellipsoid([1e10, 0.0], np.eye(2))
    Ellipsoid([0.0, 0.0], 1e-118 * np.eye(2))


def test_scaling_out_of_the_domain_is_a_value_error_not_an_overflow():
    E = Ellipsoid([0.0, 0.0], np.eye(2))
    with pytest.raises(ValueError, match="factor=1e\\+200"):
        E.scaled(1e200)


def test_extent_is_the_support_in_both_senses():
    E = Ellipsoid([0.5, -1.0], [[2.0, 0.3], [0.3, 0.5]])
    for a in ([1.0, 0.0], [0.3, -2.0], [-1.0, 4.0]):
        lo, hi = E.extent(a)
        expected = (-E.support(-np.asarray(a)), E.support(a))
        np.testing.assert_allclose((lo, hi), expected, rtol=1e-15, atol=1e-15)
    with pytest.raises(ValueError, match="a must have length 2"):
        E.extent([1.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="a must be finite"):
        E.extent([np.nan, 0.0])


def test_from_floats_checks_like_the_constructor():
    C = np.array([[2.0, 0.3], [0.3 * (1 + 1e-15), 0.5]])  # asymmetric at rounding level
    fast, slow = Ellipsoid._from_floats(np.array([0.1, 0.2]), C), Ellipsoid([0.1, 0.2], C)
    assert np.array_equal(fast.shape, slow.shape) and np.array_equal(fast.chol, slow.chol)
    assert not fast.shape.flags.writeable
    with pytest.raises(ValueError, match="positive definite"):
        Ellipsoid._from_floats(np.zeros(2), np.array([[1.0, 0.0], [0.0, -1.0]]))
