"""HS96 association search: visibility matrix and pruned interpretation tree."""

import math

import numpy as np
import pytest

from optbound.localization.association import SPURIOUS, associate, score, visibility_matrix
from optbound.localization.landmark_map import LandmarkMap
from optbound.scenarios import office
from optbound.sets import Ellipsoid

MAP = office.office_map()
DELTA = office.DELTA_ALPHA
HEADING = math.radians(10)


def _scan(pose, rng, keep=None):
    seen = np.flatnonzero(MAP.visible(pose[0], pose[1]))
    if keep is not None:
        seen = np.sort(rng.choice(seen, keep, replace=False))
    L = MAP.landmarks[seen]
    alphas = np.arctan2(L[:, 1] - pose[1], L[:, 0] - pose[0]) - pose[2]
    return np.mod(alphas + rng.uniform(-1, 1, seen.size) * DELTA, 2 * np.pi), seen


def _prior(pose, offset=(0.2, -0.15, 0.05), radius=0.5, heading=HEADING):
    return Ellipsoid(np.asarray(pose) + offset, np.diag([radius**2, radius**2, heading**2]))


@pytest.mark.parametrize("seed", range(4))
def test_finds_the_true_association_with_one_false_angle(seed):
    rng = np.random.default_rng(seed)
    pose = office.course_pose(rng.uniform(0, office.lap_length()))[0]
    every, _ = _scan(pose, rng)
    alphas, seen = _scan(pose, rng, keep=7)
    # The false angle: in the middle of the widest gap between all visible landmarks' bearings.
    b = np.sort(every)
    gaps = np.diff(np.r_[b, b[0] + 2 * np.pi])
    false = np.mod(b[np.argmax(gaps)] + gaps.max() / 2, 2 * np.pi)
    alphas = np.r_[alphas, false]
    result = associate(_prior(pose), alphas, MAP, DELTA)
    assert result.spurious == 1
    truth = np.r_[seen, SPURIOUS]
    matches = [a for a in result.associations if np.array_equal(a.pairs, truth)]
    assert len(matches) == 1
    assert np.hypot(*(np.array(matches[0].pose[:2]) - pose[:2])) < 0.05
    assert result.nodes_expanded < result.nodes_unpruned


def test_reports_none_when_no_association_fits():
    rng = np.random.default_rng(5)
    here, there = office.course_pose([1.0, 9.0])
    alphas, _ = _scan(there, rng, keep=6)
    result = associate(_prior(here, radius=0.3), alphas, MAP, DELTA)
    assert result.associations == []


def test_visibility_matrix_contains_the_true_pairs_and_hides_occluded_landmarks():
    rng = np.random.default_rng(2)
    pose = office.course_pose(5.0)[0]
    alphas, seen = _scan(pose, rng)
    V = visibility_matrix(_prior(pose), alphas, MAP, delta_alpha=DELTA)
    assert V.shape == (seen.size, MAP.size)
    assert V[np.arange(seen.size), seen].all()
    hidden = np.flatnonzero(~MAP.visible(pose[0], pose[1]))
    assert hidden.size
    tiny = Ellipsoid(pose, np.diag([1e-6, 1e-6, 1e-6]))
    assert not visibility_matrix(tiny, alphas, MAP, delta_alpha=DELTA)[:, hidden].any()


def test_a_false_angle_outside_every_landmark_direction_is_an_empty_row():
    lm = LandmarkMap([[5.0, 0.0], [0.0, 5.0], [-5.0, 0.0], [0.0, -5.0]])
    prior = Ellipsoid([0.0, 0.0, 0.0], np.diag([0.01, 0.01, 1e-4]))
    alphas = np.array([0.0, np.pi / 2, np.pi, 3 * np.pi / 2, np.pi / 4])
    V = visibility_matrix(prior, alphas, lm, grid=(3, 8))
    assert not V[4].any() and V[:4].any(axis=1).all()
    result = associate(prior, alphas, lm, 1e-3)
    assert result.spurious == 1
    assert [list(a.pairs) for a in result.associations] == [[0, 1, 2, 3, SPURIOUS]]


def test_bad_input():
    with pytest.raises(TypeError, match="prior"):
        visibility_matrix("prior", [0.1], MAP)
    with pytest.raises(ValueError, match="3-D"):
        visibility_matrix(Ellipsoid([0, 0], np.eye(2)), [0.1], MAP)
    with pytest.raises(TypeError, match="landmark_map"):
        visibility_matrix(Ellipsoid([0, 0, 0], np.eye(3)), [0.1], MAP.landmarks)
    with pytest.raises(ValueError, match="grid"):
        visibility_matrix(Ellipsoid([0, 0, 0], np.eye(3)), [0.1], MAP, grid=(0, 3))
    with pytest.raises(ValueError, match="alphas"):
        associate(Ellipsoid([0, 0, 0], np.eye(3)), [0.1, np.nan, 0.3], MAP, DELTA)


def test_score_counts_pairs_and_discards_bearing_by_bearing():
    # bearing 0 correctly paired, 1 spurious and discarded, 2 paired with the wrong landmark,
    # 3 a true bearing declared spurious, 4 spurious but paired.
    s = score([3, SPURIOUS, 5, SPURIOUS, 7], [3, SPURIOUS, 4, 2, SPURIOUS])
    assert (s.paired, s.true_bearings, s.discarded, s.spurious) == (1, 3, 1, 2)
    assert s.accuracy == pytest.approx(2 / 5)
    assert score([1, 2], [1, 2]).accuracy == 1.0


def test_score_refuses_mismatched_or_empty_input():
    with pytest.raises(ValueError, match="equal length"):
        score([1, 2], [1])
    with pytest.raises(ValueError, match="empty"):
        score([], [])


def test_injected_spurious_and_missing_bearings_are_scored_correctly():
    # A tiny injected case: 5 of the visible landmarks, one dropped, one far-off false bearing.
    rng = np.random.default_rng(11)
    pose = office.course_pose(3.0)[0]
    alphas, seen = _scan(pose, rng, keep=6)
    b = np.sort(_scan(pose, rng)[0])
    gaps = np.diff(np.r_[b, b[0] + 2 * np.pi])
    false = np.mod(b[np.argmax(gaps)] + gaps.max() / 2, 2 * np.pi)
    alphas = np.r_[np.delete(alphas, 2), false]
    labels = np.r_[np.delete(seen, 2), SPURIOUS]
    best = min(
        associate(_prior(pose), alphas, MAP, DELTA).associations, key=lambda a: a.max_residual
    )
    s = score(best.pairs, labels)
    assert (s.paired, s.true_bearings, s.discarded, s.spurious) == (5, 5, 1, 1)
    assert s.accuracy == 1.0
    # A wrong association is scored as such: pair the false bearing with a landmark instead.
    wrong = best.pairs.copy()
    wrong[-1] = seen[2]
    assert score(wrong, labels).accuracy == pytest.approx(5 / 6)
