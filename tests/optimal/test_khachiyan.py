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


def _clustered(seed: int) -> np.ndarray:
    # Points on an ellipse's boundary, each with near-duplicates: like the polished points at
    # a curved contact, on which separate forward and away steps zigzag between neighbours.
    rng = np.random.default_rng(seed)
    t = rng.uniform(0.0, 2.0 * np.pi, 60)
    base = np.column_stack([np.cos(t), 2.0 * np.sin(t), 0.5 * np.cos(3 * t)])
    return np.repeat(base, 5, axis=0) * (1.0 - rng.uniform(0.0, 1e-4, (300, 1)))


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_exchange_steps_reach_the_same_ellipsoid(seed):
    X = _clustered(seed)
    u, converged = khachiyan_weights(X, tol=1e-7, max_iter=1_000_000)
    v, converged_v = khachiyan_weights(X, tol=1e-7, max_iter=1_000_000, exchange=True)
    assert converged and converged_v
    assert np.all(v >= 0) and np.sum(v) == pytest.approx(1.0)
    logdet = [np.linalg.slogdet(covariance(X, w)[1])[1] for w in (u, v)]
    assert logdet[1] == pytest.approx(logdet[0], abs=1e-5)


# Support points of a polished 3-D lower bound (recursive family, seed 700352055, width 1,
# k = 10): rows 1 and 4 are 1e-6 apart, both at the contact.
_NEAR_TWINS = np.array(
    [
        [1.2048637081160662, 2.3370546507877377, 1.0873148163818263],
        [1.5570465472855137, 2.1290452445374766, 0.9213102581971734],
        [1.2155402229013763, 2.3544401470262866, 1.0082802807018234],
        [1.8128848153062334, 2.561388047248501, 0.9812683913312593],
        [1.5570465329342926, 2.1290461867485644, 0.9213100245812285],
        [1.5157969203308068, 2.123708205454954, 1.1812729258533619],
    ]
)


def test_exchange_steps_converge_where_separate_steps_zigzag():
    # Separate forward and away steps move weight back and forth between the twins by tiny
    # steps (tens of thousands); one exchange step moves it at once.
    assert khachiyan_weights(_NEAR_TWINS, tol=1e-6, max_iter=100, exchange=True)[1]
    assert not khachiyan_weights(_NEAR_TWINS, tol=1e-6, max_iter=10_000)[1]


@pytest.mark.parametrize("exchange", [False, True])
def test_forward_condition_alone_bounds_the_volume_gap(exchange):
    # max w <= (1 + tol) d puts every point within level 1 + tol d / n of the weights'
    # ellipsoid (shape n Sigma): its volume is within that factor^(n/2) of the minimum.
    X, tol = _clustered(4), 1e-5
    n, d = 3, 4
    u, converged = khachiyan_weights(X, tol=tol, away_tol=np.inf, exchange=exchange)
    exact, _ = khachiyan_weights(X, tol=1e-9, max_iter=1_000_000, exchange=True)
    gap = [np.linalg.slogdet(covariance(X, w)[1])[1] for w in (exact, u)]
    assert converged
    assert gap[1] <= gap[0] + 1e-9
    assert gap[1] >= gap[0] - n * np.log1p(tol * d / n) - 1e-9
