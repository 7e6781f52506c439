"""Certification: exact candidates pass, shrunken ones are inflated minimally, bad ones raise."""

import numpy as np
import pytest

from optbound import Ellipsoid, QuadraticSet
from optbound.optimal import CertificationError
from optbound.optimal.certify import certify_lmi, certify_points


def _ball_form(E):
    B = np.hstack([np.eye(E.dim), -E.center[:, None]])
    return B.T @ np.linalg.inv(E.shape) @ B


def _corner(n):
    G = np.zeros((n + 1, n + 1))
    G[n, n] = 1.0
    return G


def test_containing_candidate_passes_without_inflation():
    inner = QuadraticSet.from_ellipsoid(Ellipsoid([0.0, 0.0], np.eye(2)))
    candidate = Ellipsoid([0.0, 0.0], 1.5 * np.eye(2))
    E, alpha, beta = certify_lmi(candidate, _ball_form, _corner(2), np.array([0.8]), inner.F[None])
    assert E is candidate and alpha == 1.0 and beta == 1.0


def test_too_small_candidate_is_inflated_to_the_smallest_factor():
    # Candidate: ball radius 0.9 for the unit ball, multiplier 1 (the exact certificate for
    # radius 1). The smallest inflation is 1 / 0.9 (up to the float64 margin).
    inner = QuadraticSet.from_ellipsoid(Ellipsoid([0.0, 0.0], np.eye(2)))
    candidate = Ellipsoid([0.0, 0.0], 0.81 * np.eye(2))
    E, alpha, _ = certify_lmi(candidate, _ball_form, _corner(2), np.array([1.0]), inner.F[None])
    assert alpha == pytest.approx(1.0 / 0.9, rel=1e-6)
    X = Ellipsoid([0.0, 0.0], np.eye(2)).sample_boundary(10_000, 0)
    assert np.all(E.contains(X, tol=0.0))


def test_wrong_multipliers_raise():
    inner = QuadraticSet.from_ellipsoid(Ellipsoid([0.0, 0.0], np.eye(2)))
    candidate = Ellipsoid([0.0, 0.0], np.eye(2))
    with pytest.raises(CertificationError):
        certify_lmi(candidate, _ball_form, _corner(2), np.array([-1.0]), inner.F[None])


def test_points_outside_are_brought_inside_minimally():
    X = np.array([[2.0, 0.0], [0.0, 1.0], [-1.0, 0.0]])
    E, alpha = certify_points(Ellipsoid([0.0, 0.0], np.eye(2)), X)
    assert alpha == pytest.approx(2.0, rel=1e-12)
    assert np.all(E.level(X) <= 1.0)


def test_points_inside_pass_unchanged():
    E0 = Ellipsoid([0.0, 0.0], np.eye(2))
    E, alpha = certify_points(E0, np.array([[0.5, 0.0], [0.0, -0.5], [0.1, 0.1]]))
    assert E is E0 and alpha == 1.0
