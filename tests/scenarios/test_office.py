"""The office scenario of the HS96 reproduction: map, course, error model."""

import math

import numpy as np
import pytest

from optbound.localization import geometry
from optbound.localization.geometry import wrap_angle
from optbound.scenarios import office
from optbound.sets import Ellipsoid


def test_map_has_22_landmarks_and_partitions():
    omap = office.office_map()
    assert omap.size == 22 and omap.walls.shape[0] == 4 + len(office.WALLS)


def test_visible_landmarks_appear_in_counter_clockwise_index_order_along_the_course():
    """The ordering assumption of [HS96, Sect. 2] that the association search relies on."""
    omap = office.office_map()
    for pose in office.course_pose(np.linspace(0, office.lap_length(), 97)):
        seen = np.flatnonzero(omap.visible(pose[0], pose[1]))
        L = omap.landmarks[seen]
        bearing = np.mod(np.arctan2(L[:, 1] - pose[1], L[:, 0] - pose[0]), 2 * np.pi)
        order = seen[np.argsort(bearing)]
        descents = np.sum(np.diff(np.r_[order, order[0]]) < 0)
        assert descents == 1


def test_course_is_closed_and_does_not_cross_walls():
    omap = office.office_map()
    s = np.linspace(0, office.lap_length(), 2001)
    poses = office.course_pose(s)
    assert np.allclose(poses[0, :2], poses[-1, :2], atol=1e-9)
    assert np.isclose(poses[-1, 2] - poses[0, 2], 2 * np.pi)
    steps = np.hypot(*np.diff(poses[:, :2], axis=0).T)
    assert np.allclose(steps, s[1], rtol=1e-3)  # arc-length parametrised, no jumps
    hit = geometry.occluded(
        (poses[:-1, 0], poses[:-1, 1]), (poses[1:, 0], poses[1:, 1]), omap.walls
    )
    assert not hit.any()


def test_odometry_errors_lie_in_the_dead_reckoning_sets():
    data = office.simulate(laps=0.3, seed=4)
    for k, (step, shape) in enumerate(zip(data.odometry, data.odometry_shapes, strict=True)):
        a, b = data.poses[k], data.poses[k + 1]
        c, s = np.cos(a[2]), np.sin(a[2])
        true = np.array(
            [
                c * (b[0] - a[0]) + s * (b[1] - a[1]),
                -s * (b[0] - a[0]) + c * (b[1] - a[1]),
                b[2] - a[2],
            ]
        )
        d = true - step
        assert d @ np.linalg.solve(shape, d) <= 1.0


def test_scans_hold_the_visible_landmarks_within_the_noise_bound():
    data = office.simulate(laps=0.1, seed=5)
    for pose, (alphas, seen) in zip(data.poses, data.scans, strict=True):
        L = data.true_landmarks[seen]
        exact = np.arctan2(L[:, 1] - pose[1], L[:, 0] - pose[0]) - pose[2]
        assert np.all(np.abs(wrap_angle(alphas - exact)) <= office.DELTA_ALPHA)
        assert seen.size >= 3


def test_dead_reckoning_drifts():
    data = office.simulate(laps=2, seed=6)
    dr = office.dead_reckoning(data, data.poses[0])
    drift = np.hypot(*(dr[-1, :2] - data.poses[-1, :2]))
    assert drift > 0.05


def test_containment_rate_in_a_seeded_short_office_run():
    data = office.simulate(laps=0.5, seed=3)
    start = Ellipsoid(
        data.poses[0] + [0.01, -0.01, 0.002], np.diag([0.05**2, 0.05**2, math.radians(1) ** 2])
    )
    result = office.track(data, start, "projection")
    rate = float(np.mean(result.levels <= 1.0))
    assert rate >= 0.95
    assert result.updates > 1000 and result.wrong_associations == 0


def test_corrupt_scan_injects_at_the_stated_rates():
    data = office.simulate(laps=0.05, seed=3)
    alphas, truth = data.scans[0]
    rng = np.random.default_rng(0)
    same = office.corrupt_scan(alphas, truth, 0.0, 0.0, rng)
    assert np.array_equal(same[0], alphas) and np.array_equal(same[1], truth)
    none_left, labels = office.corrupt_scan(alphas, truth, 0.0, 1.0, rng)
    assert none_left.size == 0 and labels.size == 0
    # Over many scans the injected fractions approach the rates.
    kept = spurious = total = 0
    for _ in range(400):
        a, lab = office.corrupt_scan(alphas, truth, 0.2, 0.1, rng)
        true = lab >= 0
        label_of = dict(zip(alphas.tolist(), truth.tolist(), strict=True))
        assert [label_of[x] for x in a[true].tolist()] == lab[true].tolist()
        assert np.all((a[~true] >= 0) & (a[~true] < 2 * np.pi))
        kept, spurious, total = kept + true.sum(), spurious + (~true).sum(), total + alphas.size
    assert abs(kept / total - 0.9) < 0.02 and abs(spurious / total - 0.2) < 0.02


def test_corrupt_scan_refuses_bad_rates():
    with pytest.raises(ValueError, match="spurious_rate"):
        office.corrupt_scan([0.1], [0], 1.5, 0.0, np.random.default_rng(0))
    with pytest.raises(ValueError, match="equal length"):
        office.corrupt_scan([0.1, 0.2], [0], 0.0, 0.0, np.random.default_rng(0))
