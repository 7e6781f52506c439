"""Khachiyan's algorithm: encloses the points, anchors, weights in the simplex."""

import numpy as np
import pytest

from optbound.optimal.khachiyan import core_set, covariance, khachiyan_mvee, khachiyan_weights


def test_square_corners_give_the_circumcircle():
    X = np.array([[1.0, 1.0], [-1.0, 1.0], [-1.0, -1.0], [1.0, -1.0]])
    E = khachiyan_mvee(X)
    np.testing.assert_allclose(E.shape, 2.0 * np.eye(2), rtol=1e-6, atol=1e-9)


def test_weights_are_in_the_simplex_and_enclose_after_scaling():
    X = np.random.default_rng(0).standard_normal((100, 3))
    u, converged = khachiyan_weights(X, tol=1e-6)
    assert converged and np.all(u >= 0) and np.sum(u) == pytest.approx(1.0)
    assert np.all(khachiyan_mvee(X).contains(X, tol=0.0))


def test_covariance_of_uniform_weights():
    X = np.random.default_rng(1).standard_normal((50, 2))
    mean, cov = covariance(X, np.full(50, 1 / 50))
    np.testing.assert_allclose(mean, X.mean(axis=0))
    np.testing.assert_allclose(cov, np.cov(X.T, bias=True), atol=1e-12)


def test_non_convergence_raises():
    X = np.random.default_rng(2).standard_normal((100, 3))
    assert not khachiyan_weights(X, tol=1e-12, max_iter=3)[1]
    with pytest.raises(RuntimeError, match="converge"):
        khachiyan_mvee(X, tol=1e-12, max_iter=3)


def test_core_set_is_small_and_full_dimensional():
    X = np.random.default_rng(3).standard_normal((500, 4))
    core = core_set(X)
    assert core.size <= 8 and np.unique(core).size == core.size
    assert np.linalg.matrix_rank(X[core] - X[core[0]]) == 4


def test_core_set_start_converges_in_fewer_steps_than_points():
    # From uniform weights every interior point's weight must be removed by an away step of
    # its own before the tolerance can hold (> 4000 steps here); from the core set it need
    # never be given one.
    X = np.random.default_rng(4).standard_normal((5000, 3))
    u, converged = khachiyan_weights(X, tol=1e-6, max_iter=2000)
    assert converged and np.count_nonzero(u) < 100


def test_a_converged_start_needs_no_step():
    X = np.random.default_rng(5).standard_normal((300, 3))
    u, _ = khachiyan_weights(X, tol=1e-6)
    again, converged = khachiyan_weights(X, tol=1e-6, max_iter=1, start=u)
    assert converged and np.array_equal(again, u)
