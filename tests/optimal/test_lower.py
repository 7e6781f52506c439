"""Lower bounds: valid for any weights, tight for known sets, points lie in the set."""

from math import pi

import numpy as np
import pytest

from optbound import Ellipsoid, QuadraticSet, Strip
from optbound.optimal.lift import lift
from optbound.optimal.lower import (
    _first_exit,
    sample_set,
    trace_lower_bound,
    volume_lower_bound,
)


def _circle(m=400):
    t = np.linspace(0, 2 * pi, m, endpoint=False)
    return np.column_stack([np.cos(t), 2.0 * np.sin(t)])


def test_volume_bound_is_tight_on_an_ellipse_boundary():
    bound = volume_lower_bound(_circle())
    assert bound <= 2.0 * pi * (1 + 1e-12)
    assert bound == pytest.approx(2.0 * pi, rel=1e-4)


def test_trace_bound_is_tight_on_an_ellipse_boundary():
    # The smallest-trace ellipse around the ellipse x^2 + y^2/4 <= 1 is itself (trace 5).
    bound = trace_lower_bound(_circle())
    assert bound <= 5.0 * (1 + 1e-12)
    assert bound == pytest.approx(5.0, rel=1e-3)


def test_sampled_points_are_in_the_set_and_reach_its_boundary():
    E = Ellipsoid([0.0, 0.0], np.diag([4.0, 1.0]))
    ring = QuadraticSet.from_parts(-np.eye(2), [0.0, 0.0], 0.25)  # |x| >= 0.5
    sets = [E, Strip.from_bounds([0.0, 1.0], 0.0, 2.0), ring]
    quadratics = lift(sets)
    X = sample_set(quadratics, E, rng=0)
    assert X.shape[0] > 1000
    assert np.all([s.contains(X, tol=1e-12) for s in sets])
    assert np.max(E.level(X)) > 1.0 - 1e-6  # boundary points reach the ellipse


def test_first_exit_of_a_ball_is_its_radius():
    q = QuadraticSet.from_ellipsoid(Ellipsoid([0.0, 0.0], 4.0 * np.eye(2)))
    D = np.array([[1.0, 0.0], [0.0, -3.0]])
    np.testing.assert_allclose(_first_exit([q], np.zeros(2), D), [2.0, 2.0 / 3.0])
