"""QuadraticSet: conversions agree with the source sets; support function; bad input."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound import Ellipsoid, Halfspace, QuadraticSet, Strip


def _ellipsoid(seed: int, n: int = 3) -> Ellipsoid:
    rng = np.random.default_rng(seed)
    A = rng.standard_normal((n, n))
    return Ellipsoid(rng.standard_normal(n), A @ A.T + 0.1 * np.eye(n))


@given(st.integers(0, 10_000))
def test_from_ellipsoid_membership_and_support_agree(seed):
    E = _ellipsoid(seed)
    Q = QuadraticSet.from_ellipsoid(E)
    rng = np.random.default_rng(seed)
    X = E.center + 3.0 * rng.standard_normal((500, 3))
    level = E.level(X)
    clear = np.abs(level - 1.0) > 1e-6  # away from the boundary, both must agree exactly
    assert np.array_equal(Q.contains(X)[clear], E.contains(X)[clear])
    D = rng.standard_normal((20, 3))
    np.testing.assert_allclose(Q.support(D), E.support(D), rtol=1e-10, atol=1e-10)


def test_as_ellipsoid_round_trip():
    E = _ellipsoid(1)
    assert QuadraticSet.from_ellipsoid(E).as_ellipsoid() is E  # the validated original
    back = QuadraticSet(QuadraticSet.from_ellipsoid(E).F).as_ellipsoid()  # computed from F
    np.testing.assert_allclose(back.center, E.center, atol=1e-12)
    np.testing.assert_allclose(back.shape, E.shape, rtol=1e-10, atol=1e-12)


def test_empty_bounded_quadratic_gives_none_and_minus_inf():
    Q = QuadraticSet.from_parts(np.eye(2), [0.0, 0.0], 1.0)  # |x|^2 + 1 <= 0
    assert Q.is_bounded
    assert Q.as_ellipsoid() is None
    assert Q.support([1.0, 0.0]) == -np.inf


def test_strip_product_form_is_the_squared_form():
    S = Strip([1.0, 2.0], 0.5)
    F = QuadraticSet.from_strip(S).F
    a, b = S.a, S.b
    squared = QuadraticSet.from_parts(np.outer(a, a), -b * a, b * b - 1.0).F
    np.testing.assert_allclose(F, squared, atol=1e-15)


def test_strip_and_halfspace_support_and_membership():
    S = Strip([1.0, 1.0], 0.5)
    QS = QuadraticSet.from_strip(S)
    assert QS.support([1.0, 1.0]) == pytest.approx(1.5)
    assert QS.support([-2.0, -2.0]) == pytest.approx(1.0)
    assert QS.support([1.0, 0.0]) == np.inf
    H = Halfspace([1.0, 2.0], 3.0)
    QH = QuadraticSet.from_halfspace(H)
    D = np.array([[1.0, 2.0], [2.0, 4.0], [-1.0, -2.0], [1.0, 0.0]])
    np.testing.assert_array_equal(QH.support(D), H.support(D))
    X = np.random.default_rng(0).standard_normal((200, 2)) * 3
    np.testing.assert_array_equal(QH.contains(X, tol=0.0), H.contains(X, tol=0.0))
    np.testing.assert_array_equal(QS.contains(X, tol=0.0), S.contains(X, tol=0.0))


def test_paraboloid_support_closed_form():
    P = QuadraticSet([[1.0, 0.0, 0.0], [0.0, 0.0, -0.5], [0.0, -0.5, 0.0]])  # y >= x^2
    # max -y = 0; max x - y = 1/4 at x = 1/2; max x unbounded.
    np.testing.assert_allclose(P.support([[0.0, -1.0], [1.0, -1.0]]), [0.0, 0.25], atol=1e-12)
    assert P.support([1.0, 0.0]) == np.inf
    assert P.extent([1.0, -1.0]) == (-np.inf, pytest.approx(0.25))


def test_outside_of_ball_is_unbounded_and_nonconvex():
    R = QuadraticSet.from_parts(-np.eye(2), [0.0, 0.0], 1.0)  # |x| >= 1
    assert not R.is_bounded
    assert R.support([0.3, -1.0]) == np.inf
    assert R.contains([[2.0, 0.0], [-2.0, 0.0], [0.0, 0.0]]).tolist() == [True, True, False]


@pytest.mark.parametrize(
    "F, word",
    [
        (np.ones((2, 3)), "square"),
        (np.ones((1, 1)), "square"),
        (np.array([[1.0, 2.0], [0.0, 1.0]]), "symmetric"),
        (np.zeros((3, 3)), "zero"),
        (np.array([[np.nan, 0.0], [0.0, 1.0]]), "finite"),
    ],
)
def test_bad_matrix_is_rejected_naming_F(F, word):
    with pytest.raises(ValueError, match="F") as err:
        QuadraticSet(F)
    assert word in str(err.value)


def test_as_ellipsoid_refuses_unbounded():
    with pytest.raises(ValueError, match="positive definite"):
        QuadraticSet.from_strip(Strip([1.0, 0.0], 0.0)).as_ellipsoid()


def test_trusted_constructors_build_what_the_checking_ones_build():
    E = _ellipsoid(2)
    Q = QuadraticSet.from_ellipsoid(E)
    assert np.array_equal(Q.F, QuadraticSet(Q.F).F) and np.array_equal(Q.F, Q.F.T)
    assert not Q.F.flags.writeable
    a, lo, hi = np.array([0.3, -1.2, 2.0]), -0.7, 1.9
    F = QuadraticSet.from_bounds(a, lo, hi).F
    expected = QuadraticSet.from_parts(np.outer(a, a), -0.5 * (lo + hi) * a, lo * hi).F
    assert np.array_equal(F, expected) and not F.flags.writeable


def test_bounds_whose_product_overflows_are_refused():
    with pytest.raises(ValueError, match="F must be finite"):
        QuadraticSet.from_bounds([1.0, 0.0], -1e200, 1e200)


@given(st.integers(0, 10_000), st.integers(1, 5))
def test_from_ellipsoid_form_is_the_inverse_shape_formula(seed, n):
    E = _ellipsoid(seed, n)
    F = QuadraticSet.from_ellipsoid(E).F
    P = np.linalg.inv(E.shape)
    expected = np.empty((n + 1, n + 1))
    expected[:n, :n], expected[:n, n], expected[n, :n] = P, -P @ E.center, -P @ E.center
    expected[n, n] = E.center @ P @ E.center - 1.0
    scale = np.max(np.abs(expected))
    np.testing.assert_allclose(F, expected, rtol=0, atol=1e-10 * scale)
    assert np.array_equal(F, F.T)


@given(st.integers(0, 10_000), st.integers(1, 5), st.floats(-2.0, 2.0))
def test_is_bounded_is_the_eigenvalue_test_of_the_quadratic_part(seed, n, shift):
    rng = np.random.default_rng(seed)
    F = rng.standard_normal((n + 1, n + 1))
    F = F + F.T
    F[:n, :n] += shift * n * np.eye(n)
    lowest, scale = np.linalg.eigvalsh(F[:n, :n])[0], 1e-12 * np.max(np.abs(F))
    if abs(lowest - scale) > 1e-9 * np.max(np.abs(F)):  # away from the threshold
        assert QuadraticSet(F).is_bounded == (lowest > scale)
