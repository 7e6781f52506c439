"""minkowski_outer: closed-form anchors, containment of sampled sums, errors."""

import numpy as np
import pytest

from optbound import Ellipsoid, Strip
from optbound.optimal import minkowski_outer
from tests.optimal.sampling import MIN_POINTS


@pytest.mark.parametrize("objective", ["volume", "trace"])
def test_balls_add_radii(objective):
    r = minkowski_outer(
        Ellipsoid([1.0, 0.0, 0.0], np.eye(3)),
        Ellipsoid([0.0, 2.0, 0.0], 4.0 * np.eye(3)),
        objective=objective,
    )
    np.testing.assert_allclose(r.ellipsoid.center, [1.0, 2.0, 0.0])
    np.testing.assert_allclose(r.ellipsoid.shape, 9.0 * np.eye(3), atol=1e-4)
    np.testing.assert_allclose(r.multipliers, [1 / 3, 2 / 3], atol=1e-4)  # kappa = r2/(r1+r2)


def test_known_volume_optimum():
    # Known facts: C1 = diag(4, 1), C2 = I: C = diag(9.2720018727, 4.1075011704).
    r = minkowski_outer(Ellipsoid([0, 0], np.diag([4.0, 1.0])), Ellipsoid([0, 0], np.eye(2)))
    expected = np.pi * np.sqrt(9.2720018727 * 4.1075011704)
    assert r.objective == pytest.approx(expected, rel=1e-7)


def test_known_trace_optimum():
    r = minkowski_outer(
        Ellipsoid([0, 0], np.diag([4.0, 1.0])), Ellipsoid([0, 0], np.eye(2)), objective="trace"
    )
    assert r.objective == pytest.approx(7.0 + 2.0 * np.sqrt(10.0), rel=1e-7)


@pytest.mark.parametrize("objective", ["volume", "trace"])
def test_certified_sum_contains_sampled_sums(objective):
    rng = np.random.default_rng(5)
    summands = []
    for _ in range(3):
        A = rng.standard_normal((3, 3))
        summands.append(Ellipsoid(rng.standard_normal(3), A @ A.T + 0.05 * np.eye(3)))
    r = minkowski_outer(*summands, objective=objective)
    assert r.certified and 1.0 <= r.inflation < 1.0 + 1e-5
    assert np.sum(r.multipliers) <= 1.0 and np.all(r.multipliers >= 0)
    # Boundary-heavy samples of the sum: sums of boundary points of each summand.
    X = sum(E.sample_boundary(MIN_POINTS, rng) for E in summands)
    assert np.all(r.ellipsoid.contains(X, tol=0.0))


def test_bad_input():
    E = Ellipsoid([0.0, 0.0], np.eye(2))
    with pytest.raises(ValueError, match="at least one"):
        minkowski_outer()
    with pytest.raises(ValueError, match="Ellipsoid"):
        minkowski_outer(E, Strip([1.0, 0.0], 0.0))
    with pytest.raises(ValueError, match="dimension"):
        minkowski_outer(E, Ellipsoid([0.0], [[1.0]]))
    with pytest.raises(ValueError, match="objective"):
        minkowski_outer(E, E, objective="projection")
