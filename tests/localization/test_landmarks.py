"""HS96 linear landmark solver, its interval bound and the exact pose paving."""

import math

import numpy as np
import pytest

from optbound.localization.landmarks import (
    linear_position,
    linear_position_bound,
    pose_paving,
)


def _bearings(L, pose):
    return np.arctan2(L[:, 1] - pose[1], L[:, 0] - pose[0]) - pose[2]


def _geometry(rng, n):
    """Landmarks on a ring of radius 3-8 around the origin, robot within 1.5 of it."""
    phi = np.sort(rng.uniform(0, 2 * np.pi, n))
    r = rng.uniform(3, 8, n)
    L = np.column_stack([r * np.cos(phi), r * np.sin(phi)])
    pose = np.r_[rng.uniform(-1.5, 1.5, 2), rng.uniform(-np.pi, np.pi)]
    return L, pose


@pytest.mark.parametrize("n", range(3, 13))
def test_exact_on_noise_free_random_geometries(n):
    rng = np.random.default_rng(n)
    solved = 0
    for _ in range(40):
        L, pose = _geometry(rng, n)
        try:
            x, y, psi = linear_position(L, _bearings(L, pose))
        except ValueError:
            continue  # a near-singular draw (robot near the circle through 3 landmarks)
        solved += 1
        assert abs(x - pose[0]) < 1e-8 and abs(y - pose[1]) < 1e-8
        assert abs(math.remainder(psi - pose[2], 2 * np.pi)) < 1e-8
        assert -np.pi < psi <= np.pi
    assert solved >= 38


def test_printed_eq6_has_a_typo():
    """The printed h_i has x_{i+1} where g_i - g_{i+1} gives x_i: the printed one fails."""
    rng = np.random.default_rng(0)
    L, pose = _geometry(rng, 6)
    a = _bearings(L, pose)
    x, y = L[:, 0], L[:, 1]
    i = np.arange(6)
    j, k = (i + 1) % 6, (i + 2) % 6
    c = 1 / np.tan(a[j] - a[i])
    A = x[j] * x[i] + y[j] * y[i] + c * (x[j] * y[i] - y[j] * x[i])
    hx = c * (y[i] - y[j]) + x[j] - c[j] * (y[j] - y[k]) - x[k]
    hy = c * (x[j] - x[i]) + y[j] - c[j] * (x[k] - x[j]) - y[k]
    printed = np.linalg.lstsq(np.c_[hx, hy][:5], (A[i] - A[j])[:5], rcond=None)[0]
    assert np.abs(printed - pose[:2]).max() > 1e-3
    assert np.allclose(linear_position(L, a)[:2], pose[:2], atol=1e-10)


def test_robot_on_the_circle_is_singular():
    phi = np.array([0.3, 1.5, 2.9, 4.0, 5.2])
    L = 5 * np.column_stack([np.cos(phi), np.sin(phi)])
    pose = np.array([5 * math.cos(0.9), 5 * math.sin(0.9), 0.2])
    with pytest.raises(ValueError, match="relative condition number"):
        linear_position(L, _bearings(L, pose))
    # Off the circle the same landmarks are fine.
    assert np.allclose(linear_position(L, _bearings(L, [1.0, 0.5, 0.2]))[:2], [1.0, 0.5])


def test_robot_in_line_with_collinear_landmarks_is_singular():
    L = np.array([[0.0, 0.0], [2.0, 0.0], [5.0, 0.0]])
    with pytest.raises(ValueError, match="equal modulo pi"):
        linear_position(L, _bearings(L, [-3.0, 0.0, 0.1]))


def test_collinear_landmarks_seen_from_off_the_line_are_solved():
    # The "circle" through collinear landmarks is their line: only a robot on it is singular.
    L = np.array([[0.0, 0.0], [2.0, 0.0], [5.0, 0.0]])
    assert np.allclose(linear_position(L, _bearings(L, [1.0, 3.0, 0.4]))[:2], [1.0, 3.0])


@pytest.mark.parametrize(
    ("landmarks", "alphas", "error"),
    [
        ([[0, 1], [1, 0]], [0.1, 0.2], ValueError),
        ([[0, 1], [1, 0], [2, 2]], [0.1, 0.2], ValueError),
        ([[0, 1], [1, 0], [2, np.nan]], [0.1, 0.2, 0.3], ValueError),
        ([[0, 1], [1, 0], [2, 2j]], [0.1, 0.2, 0.3], ValueError),
        ([0, 1, 1, 0, 2, 2], [0.1, 0.2, 0.3], ValueError),
        ([[0, 1], [1, 0], [2, 2]], [0.1, 0.2, np.inf], ValueError),
        ([["a", "b"], [1, 0], [2, 2]], [0.1, 0.2, 0.3], TypeError),
    ],
)
def test_bad_input(landmarks, alphas, error):
    with pytest.raises(error):
        linear_position(landmarks, alphas)


def _noisy_instance(rng, n, delta, radius):
    """Bearings of true landmarks inside their ellipses, errors at most 0.9 of the bounds."""
    L, pose = _geometry(rng, n)
    shapes = []
    for _ in range(n):
        Q = np.linalg.qr(rng.normal(size=(2, 2)))[0]
        shapes.append(Q @ np.diag(rng.uniform(0.3, 1.0, 2) * radius) ** 2 @ Q.T)
    shapes = np.array(shapes)
    u = rng.normal(size=(n, 2))
    u *= (0.9 * rng.uniform(0, 1, n) / np.linalg.norm(u, axis=1))[:, None]
    true_L = L + np.einsum("nij,nj->ni", np.linalg.cholesky(shapes), u)
    alphas = _bearings(true_L, pose) + rng.uniform(-0.9, 0.9, n) * delta
    return L, alphas, shapes, pose


@pytest.mark.parametrize("seed", range(6))
def test_bound_and_paving_contain_the_truth(seed):
    rng = np.random.default_rng(100 + seed)
    delta = math.radians(0.05)
    L, alphas, shapes, pose = _noisy_instance(rng, 4 + seed % 3, delta, 0.02)
    box = linear_position_bound(L, alphas, delta, shapes)
    assert np.all(box.lo <= pose[:2]) and np.all(pose[:2] <= box.hi)
    paving = pose_paving(L, alphas, delta, shapes)
    outer = paving.outer()
    # The true heading may be represented modulo 2 pi: try the representative in the hull.
    hull = paving.hull()
    psi = pose[2] + 2 * np.pi * round((hull.center[2] - pose[2]) / (2 * np.pi))
    truth = np.array([pose[0], pose[1], psi])
    inside = np.all((outer[:, :, 0] <= truth) & (truth <= outer[:, :, 1]), axis=1)
    assert inside.any()


def test_paving_is_tight_where_the_linear_bound_is_loose():
    # An instance where the linear bound (landmark ellipses boxed, correlations between the
    # pair equations ignored) is loose; the area ratio is 9.5 at seed 7, 29 here.
    rng = np.random.default_rng(9)
    delta = math.radians(0.02)
    L, alphas, shapes, _ = _noisy_instance(rng, 8, delta, 0.015)
    box = linear_position_bound(L, alphas, delta, shapes)
    hull = pose_paving(L, alphas, delta, shapes).hull()
    assert np.prod(hull.widths[:2]) * 10 < np.prod(box.widths)


def test_paving_of_inconsistent_bearings_is_empty():
    rng = np.random.default_rng(3)
    L, pose = _geometry(rng, 5)
    alphas = _bearings(L, pose)
    alphas[2] += 0.3
    X0 = [[-2, 2], [-2, 2], [pose[2] - 0.5, pose[2] + 0.5]]
    paving = pose_paving(L, alphas, 1e-4, X0=X0, eps=0.01)
    assert paving.is_empty and paving.hull() is None


def test_paving_components_split_a_two_landmark_ambiguity():
    # Exact landmarks, noise-free bearings, and a prior box in which three bearings admit the
    # truth only: one component containing it.
    L = np.array([[4.0, 0.0], [0.0, 4.0], [-4.0, -1.0]])
    pose = np.array([0.5, 0.2, 0.3])
    alphas = _bearings(L, pose)
    paving = pose_paving(L, alphas, 1e-3, X0=[[-1, 1], [-1, 1], [0, 0.6]], eps=0.005)
    comps = paving.components()
    assert len(comps) >= 1
    first = comps[0].hull()
    assert np.all(first.lo <= pose) and np.all(pose <= first.hi)


def test_bound_refuses_hopeless_errors():
    rng = np.random.default_rng(1)
    L, pose = _geometry(rng, 4)
    with pytest.raises(ValueError, match=r"not provably regular|unbounded"):
        linear_position_bound(L, _bearings(L, pose), 0.3, np.eye(2) * 0.5)


def test_paving_with_a_prior_keeps_the_truth_inside_both():
    from optbound.sets import Ellipsoid

    L = np.array([[4.0, 1.0]])
    pose = np.array([0.2, -0.1, 0.3])
    prior = Ellipsoid([0.25, -0.05, 0.28], np.diag([0.1**2, 0.1**2, 0.05**2]))
    paving = pose_paving(L, _bearings(L, pose), 1e-3, prior=prior)
    outer = paving.outer()
    assert np.any(np.all((outer[:, :, 0] <= pose) & (pose <= outer[:, :, 1]), axis=1))
    # Every box of the paving meets the prior's bounding box; the hull is inside it.
    box = prior.bounding_box()
    hull = paving.hull()
    assert np.all(hull.lo >= box.lo) and np.all(hull.hi <= box.hi)
    # A single bearing leaves a thin slab: much smaller than the prior.
    assert paving.volume_bounds()[1] < 0.2 * prior.volume()


def test_bound_reports_bearings_that_no_position_fits():
    rng = np.random.default_rng(11)
    L, pose = _geometry(rng, 6)
    alphas = _bearings(L, pose)
    alphas[3] += 0.05
    with pytest.raises(ValueError, match="inconsistent"):
        linear_position_bound(L, alphas, 1e-5)


def test_bound_does_not_depend_on_the_landmarks_order():
    """Robot in line with landmarks 0 and 1: that pair is useless, whatever the order."""
    L = np.array([[-4.0, 0.0], [4.0, 0.0], [0.0, 5.0], [1.0, -6.0]])
    pose = np.array([0.3, 0.001, 0.2])
    alphas = _bearings(L, pose)
    boxes = []
    for perm in [[0, 1, 2, 3], [0, 2, 1, 3], [3, 1, 0, 2], [1, 0, 3, 2]]:
        box = linear_position_bound(L[perm], alphas[perm], 1e-3)
        assert np.all(box.lo <= pose[:2]) and np.all(pose[:2] <= box.hi)
        boxes.append(np.r_[box.lo, box.hi])
    np.testing.assert_allclose(boxes, [boxes[0]] * 4, rtol=1e-9)
    assert pose_paving(L[[0, 1, 2, 3]], alphas, 1e-3).hull() is not None


def _generic_instance(rng, lo, hi):
    """N in 3..8 landmarks at random angles (in no particular order), exact, errors <= delta."""
    n = int(rng.integers(3, 9))
    phi = rng.uniform(0, 2 * np.pi, n)
    L = np.column_stack([np.cos(phi), np.sin(phi)]) * rng.uniform(3, 8, n)[:, None]
    pose = np.r_[rng.uniform(-1.5, 1.5, 2), rng.uniform(-np.pi, np.pi)]
    delta = rng.uniform(lo, hi)
    return L, _bearings(L, pose) + rng.uniform(-1, 1, n) * delta, delta, pose


@pytest.mark.parametrize(("lo", "hi", "max_refused"), [(1e-4, 0.03, 12), (0.05, 0.3, 140)])
def test_bound_refuses_few_generic_instances(lo, hi, max_refused):
    """Seeded sample of 200: the regularity proof is not the bottleneck of the bound.

    Measured on this sample: the former ||I - R [H]|| < 1 test on consecutive pairs refused
    53 / 200 and 189 / 200 (now 4 and 107); every returned box contains the truth.
    """
    rng = np.random.default_rng(2026)
    refused = 0
    for _ in range(200):
        L, alphas, delta, pose = _generic_instance(rng, lo, hi)
        try:
            box = linear_position_bound(L, alphas, delta)
        except ValueError:
            refused += 1
            continue
        assert np.all(box.lo <= pose[:2]) and np.all(pose[:2] <= box.hi)
    assert refused <= max_refused
