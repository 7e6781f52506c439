"""HS96 set-theoretic tracker: prediction, linearized strip, fusion criteria."""

import math

import numpy as np
import pytest

from optbound.localization.landmark_map import LandmarkMap
from optbound.localization.tracker import SetTracker, nearest_landmark, pose_level
from optbound.sets import Ellipsoid

MAP = LandmarkMap([[5.0, 0.0], [0.0, 5.0], [-5.0, 0.0], [0.0, -5.0]], shapes=np.eye(2) * 0.02**2)
DELTA = math.radians(0.05)


def _tracker(criterion="projection", **kw):
    start = Ellipsoid([0.1, -0.1, 0.05], np.diag([0.1**2, 0.1**2, math.radians(3) ** 2]))
    return SetTracker(start, MAP, DELTA, criterion=criterion, **kw)


def test_prediction_centre_and_linear_model_containment():
    t = _tracker()
    before = t.set
    step = np.array([0.1, 0.02, 0.05])
    C_delta = np.diag([1e-4, 1e-4, 1e-5])
    predicted = t.predict(step, C_delta)
    c = before.center
    B = np.array([[math.cos(c[2]), -math.sin(c[2])], [math.sin(c[2]), math.cos(c[2])]])
    assert np.allclose(predicted.center, np.r_[c[:2] + B @ step[:2], c[2] + step[2]])
    # The linearized model J z + B dz of [HS96, eq. (11)] is bounded by the Minkowski step.
    rng = np.random.default_rng(0)
    z = before.sample(2000, rng) - c
    dz = Ellipsoid(step, C_delta).sample(2000, rng) - step
    move = B @ step[:2]
    J = np.array([[1, 0, -move[1]], [0, 1, move[0]], [0, 0, 1]])
    B3 = np.eye(3)
    B3[:2, :2] = B
    pts = predicted.center + z @ J.T + dz @ B3.T
    assert np.all(predicted.level(pts) <= 1.0)


def test_strip_at_the_true_pose_contains_it():
    rng = np.random.default_rng(1)
    t = _tracker()
    for _ in range(50):
        pose = np.r_[rng.uniform(-1, 1, 2), rng.uniform(-np.pi, np.pi)]
        j = int(rng.integers(4))
        true_lm = MAP.landmarks[j] + rng.uniform(-0.013, 0.013, 2)
        alpha = math.atan2(true_lm[1] - pose[1], true_lm[0] - pose[0]) - pose[2]
        alpha += rng.uniform(-0.9, 0.9) * DELTA
        strip = t.strip(alpha, j, about=pose)
        assert abs(strip.a @ pose - strip.b) <= 1.0


def _bearing(pose, j):
    lm = MAP.landmarks[j]
    return math.atan2(lm[1] - pose[1], lm[0] - pose[0]) - pose[2]


def test_projection_criterion_gives_the_smallest_xy_area():
    areas = {}
    for criterion in ("projection", "volume", "robust"):
        t = _tracker(criterion)
        info = t.update(_bearing([0.12, -0.08, 0.06], 1), 1)
        assert info.case in ("consistent", "partial")
        areas[criterion] = t.set.project([0, 1]).volume()
    assert areas["projection"] <= areas["volume"] * (1 + 1e-9)
    assert areas["projection"] <= areas["robust"] * (1 + 1e-9)


def test_relinearization_changes_the_set_and_keeps_the_pose():
    pose = np.array([0.15, -0.02, 0.02])
    one, two = _tracker(), _tracker(relinearize=2)
    for t in (one, two):
        for j in range(4):
            t.update(_bearing(pose, j), j)
    assert two.set.level(pose) <= 1.0 and one.set.level(pose) <= 1.0
    assert not np.allclose(two.set.center, one.set.center, rtol=0, atol=1e-9)


def test_inconsistent_strip_is_rejected_and_the_set_kept():
    t = _tracker()
    before = t.set
    info = t.update(_bearing([0.1, -0.1, 0.05], 0) + 0.5, 0)
    assert info.case == "inconsistent"
    assert t.set is before


@pytest.mark.parametrize(
    ("kwargs", "error"),
    [
        ({"criterion": "trace"}, ValueError),
        ({"relinearize": -1}, ValueError),
        ({"delta_alpha": -1.0}, ValueError),
    ],
)
def test_bad_construction(kwargs, error):
    args = {"criterion": "projection", "delta_alpha": DELTA, **kwargs}
    start = Ellipsoid([0, 0, 0], np.eye(3))
    with pytest.raises(error):
        SetTracker(start, MAP, args.pop("delta_alpha"), **args)


def test_bad_calls():
    t = _tracker()
    with pytest.raises(TypeError):
        SetTracker(Ellipsoid([0, 0], np.eye(2)), MAP, DELTA)
    with pytest.raises(ValueError, match="landmark"):
        t.update(0.1, 7)
    with pytest.raises(ValueError, match="alpha"):
        t.update(np.nan, 1)
    with pytest.raises(ValueError, match="odometry"):
        t.predict([0.1, 0.0], np.eye(3))
    with pytest.raises(ValueError, match="odometry_shape"):
        t.predict([0.1, 0.0, 0.0], -np.eye(3))


def test_pose_level_takes_the_heading_modulo_two_pi():
    E = Ellipsoid([1.0, 2.0, 0.1], np.diag([0.1**2, 0.2**2, 0.05**2]))
    assert pose_level(E, [1.0, 2.0, 0.1 + 4 * np.pi]) == pytest.approx(0.0, abs=1e-20)
    assert pose_level(E, [1.1, 2.0, 0.1 - 2 * np.pi]) == pytest.approx(1.0)
    assert pose_level(E, [1.0, 2.0, 0.15]) == pytest.approx(1.0)
    with pytest.raises(ValueError, match="pose"):
        pose_level(E, [1.0, np.nan, 0.0])


def test_nearest_landmark_gates_and_refuses_ambiguity():
    t = _tracker()  # centre (0.1, -0.1, 0.05): landmark 0 near bearing -psi, landmark 1 near pi/2
    seen = np.arange(MAP.size)
    x, y, psi = t.set.center
    to_1 = math.atan2(5.0 - y, 0.0 - x) - psi
    assert nearest_landmark(t, to_1 + 0.001, 0.01, seen) == 1
    assert nearest_landmark(t, to_1 + 0.02, 0.01, seen) is None  # outside the gate
    assert nearest_landmark(t, to_1, 0.01, np.array([0, 2, 3])) is None  # 1 not visible
    assert nearest_landmark(t, to_1, 0.01, np.array([], dtype=int)) is None
    assert nearest_landmark(t, to_1, 1.0, seen) is None  # runner-up within twice the gate
