"""Input that the adversarial run of issue 22 found accepted silently or met by a raw error.

Each case must now raise a ValueError or TypeError whose message names the argument.
"""

import math

import numpy as np
import pytest

from optbound.localization import relative_bearing as rb
from optbound.localization import visibility as v
from optbound.localization.landmark_map import LandmarkMap
from optbound.localization.landmarks import linear_position, pose_paving
from optbound.localization.tracker import SetTracker
from optbound.scenarios import arena
from optbound.sets import Ellipsoid

L4 = np.array([[4.0, 0.0], [0.0, 4.0], [-4.0, -1.0], [1.0, -5.0]])
ALPHAS = np.arctan2(L4[:, 1] - 0.2, L4[:, 0] - 0.5) - 0.3
BOX = np.array([[[0.0, 1.0], [0.0, 1.0]]])
SQUARE = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]


@pytest.mark.parametrize(
    "X0",
    [
        [[0.0, 1.0], [0.0, 1.0], [0.3, 0.3]],  # zero width in psi
        [[0.5, 0.5], [0.2, 0.2], [0.3, 0.3]],  # a point
    ],
)
def test_pose_paving_refuses_a_zero_size_X0(X0):
    with pytest.raises(ValueError, match="X0"):
        pose_paving(L4, ALPHAS, 1e-3, X0=X0, eps=0.05)


@pytest.mark.parametrize(
    ("polygon", "match"),
    [
        ([[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]], "self-intersecting"),  # a bow tie
        ([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]], "zero area"),  # collinear vertices
        ([[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [1.0, 1.0]], "self-intersecting"),  # a spike
    ],
)
def test_visibility_test_refuses_degenerate_obstacles(polygon, match):
    with pytest.raises(ValueError, match=rf"obstacles\[1\].*{match}"):
        v.visibility_test(BOX, BOX + 3.0, [np.array(SQUARE) + 5.0, polygon])


def test_visibility_test_still_accepts_simple_non_convex_obstacles():
    notch = [[0.0, 0.0], [2.0, 0.0], [1.0, 0.5], [2.0, 2.0], [0.0, 2.0]]
    assert v.visibility_test(BOX + 3.0, BOX + 3.0, [notch]).shape == (1,)


def test_odometry_refuses_a_negative_travel():
    with pytest.raises(ValueError, match="distance"):
        v.odometry(BOX, [-0.2, 0.1], [0.0], 0.1)


@pytest.mark.parametrize("distance", [[0.1, 0.2, 0.3], np.ones((2, 3)), [[0.1, 0.2]] * 3])
def test_track_and_odometry_name_a_misshapen_distance(distance):
    run = arena.simulate(2, 1, 2, 0)
    with pytest.raises(ValueError, match="distance must have shape"):
        v.track(
            run.boxes0,
            distance,
            run.headings,
            arena.HEADING_ERROR,
            run.visibility,
            run.env,
            0.01,
        )
    with pytest.raises(ValueError, match="distance must have shape"):
        v.odometry(run.boxes0, distance, run.headings[0], 0.1)


@pytest.mark.parametrize("name", ["bound", "data", "paving"])
def test_certify_contains_names_a_wrong_type(name):
    L = np.array([[0.0, 1.0], [1.0, 1.0], [-1.0, 0.0]])
    pairs, eps = [(2, 0), (0, 1), (1, 2)], math.radians(4.0)
    g = rb.bearings(np.zeros(2), L, pairs)
    data = rb.measurements(L, pairs, g, eps)
    box = rb.prior_box(data)
    good = {
        "bound": rb.localize(L, pairs, g, eps, order=1).bound,
        "data": data,
        "paving": rb.exact_paving(L, pairs, g, eps, np.stack([box.lo, box.hi], 1), 0.2),
    }
    wrong = {"bound": Ellipsoid(np.zeros(2), np.eye(2)), "data": L, "paving": box}
    kwargs = {**good, name: wrong[name]}
    with pytest.raises(TypeError, match=name):
        rb.certify_contains(**kwargs)


@pytest.mark.parametrize(
    "landmarks", [[[0.0, 1.0], [1.0]], [[0.0, 1.0], [1.0, 2.0, 3.0], [2.0, 0.0]]]
)
def test_ragged_landmarks_are_named(landmarks):
    with pytest.raises(ValueError, match="landmarks must be an \\(N, 2\\) array"):
        linear_position(landmarks, np.zeros(len(landmarks)))
    with pytest.raises(ValueError, match="landmarks must be an \\(N, 2\\) array"):
        LandmarkMap(landmarks)


@pytest.mark.parametrize(
    ("landmark", "error"), [("one", TypeError), (None, TypeError), (math.nan, ValueError)]
)
def test_tracker_update_names_a_non_integer_landmark(landmark, error):
    tracker = SetTracker(
        Ellipsoid([0.0, 0.0, 0.0], np.diag([0.1, 0.1, 0.01])), LandmarkMap(L4), 1e-3
    )
    with pytest.raises(error, match="landmark must be an"):
        tracker.update(0.1, landmark)
