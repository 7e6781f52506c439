"""Contraction before bisection for the sonar model: it never removes a consistent pose."""

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from optbound.interval import Interval, Tri
from optbound.interval.relaxed import relaxed_contractor
from optbound.localization._sonar_contractor import upper_range_contractor
from optbound.localization.sonar import (
    D_MAX,
    localize,
    simulate_ranges,
    sonar_contractors,
    sonar_tests,
)
from optbound.scenarios import rooms
from tests.localization.test_sonar import inside_pose, random_belt, random_room


def _proven(world, sonar, reading, pose) -> bool:
    """The pose's range is shown inside the reading's interval at its point box."""
    [test] = sonar_tests(world, [sonar], [reading])
    return test(*(Interval(np.array([c]), np.array([c])) for c in pose))[0] == Tri.TRUE


def _boundary_reading(world, sonar, pose):
    """A reading whose upper bound d (1 + alpha) is as close to the pose's range as can be
    shown: the pose is then on the boundary of the constraint the contractor uses."""
    r = float(simulate_ranges(world, [sonar], pose)[0])
    for scale in (1.0, 1 + 1e-14, 1 + 1e-12, 1 + 1e-9, 1 + 1e-6):
        d = r / (1 + sonar.rel_accuracy) * scale
        if _proven(world, sonar, d, pose):
            return d
    return None


@settings(max_examples=80, deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_upper_range_contractor_keeps_checked_poses_on_the_boundary(seed):
    rng = np.random.default_rng(seed)
    world = random_room(rng)
    pose = inside_pose(rng, world, clearance=0.4)
    if rng.random() < 0.5:  # a free-standing two-faced partition inside the room
        a, b = rng.uniform(-1.5, 1.5, 2), rng.uniform(-1.5, 1.5, 2)
        assume(np.linalg.norm(a - b) > 0.1)
        world = np.concatenate([world, [[a, b], [b, a]]])
    [sonar] = random_belt(rng, 1)
    d = _boundary_reading(world, sonar, pose)
    assume(d is not None and d * (1 + sonar.rel_accuracy) < D_MAX)
    [contract] = sonar_contractors(world, [sonar], [d])
    m = 50
    widths = np.column_stack([rng.uniform(0, 1.5, (m, 2)), rng.uniform(0, 1.5, m)])
    widths[:5] = 0.0  # point boxes too
    share = rng.uniform(0, 1, (m, 3))
    lo = (pose - share * widths).T
    hi = (pose + (1 - share) * widths).T
    lo, hi = np.minimum(lo, pose[:, None]), np.maximum(hi, pose[:, None])
    c_lo, c_hi = contract(lo.copy(), hi.copy())
    assert np.all(c_lo <= pose[:, None]) and np.all(pose[:, None] <= c_hi)
    assert np.all(c_lo >= lo) and np.all(c_hi <= hi)


def test_upper_range_contractor_removes_boxes_far_from_walls():
    world = rooms.BELT_ROOM
    c = upper_range_contractor(world, (0.3, 0.0), 1.0)
    lo = np.array([[-0.5], [-0.5], [-0.1]])
    hi = np.array([[0.5], [0.5], [0.1]])
    c_lo, c_hi = c(lo, hi)  # the room's centre is >= 3.5 m from every wall
    assert np.any(c_lo > c_hi)
    lo = np.array([[-1.0], [-3.8], [-0.1]])  # a box touching the strip along the wall y = -4
    hi = np.array([[1.0], [0.0], [0.1]])
    c_lo, c_hi = c(lo, hi)
    assert c_lo[1, 0] == -3.8 and c_hi[1, 0] < -2.5  # y contracted to within ~1.3 m of it


@settings(max_examples=100, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), m=st.integers(1, 6), data=st.data())
def test_relaxed_contractor_keeps_points_in_enough_boxes(seed, m, data):
    """A point kept by at least m - q contractors is kept by their q-relaxed union."""
    q = data.draw(st.integers(0, m))
    rng = np.random.default_rng(seed)
    k = 40
    boxes = np.sort(rng.uniform(-1, 1, (m, 2, 2, k)), axis=1)  # (m, lo/hi, dims, boxes)

    emptied = rng.random((m, k)) < 0.2  # some contractors remove whole boxes

    def make(i):
        def contract(lo, hi):
            c_lo, c_hi = np.maximum(lo, boxes[i, 0]), np.minimum(hi, boxes[i, 1])
            c_lo[0, emptied[i]], c_hi[0, emptied[i]] = np.inf, -np.inf
            return c_lo, c_hi

        return contract

    contract = relaxed_contractor([make(i) for i in range(m)], q)
    lo, hi = np.full((2, k), -1.0), np.full((2, k), 1.0)
    c_lo, c_hi = contract(lo, hi)
    points = rng.uniform(-1, 1, (200, 2, 1))
    inside = np.all((boxes[:, None, 0] <= points) & (points <= boxes[:, None, 1]), axis=2)
    inside &= ~emptied[:, None, :]
    enough = inside.sum(axis=0) >= m - q  # (200, k)
    kept = np.all((c_lo <= points) & (points <= c_hi), axis=1)
    assert np.all(kept[enough])


def test_pave_with_contractor_still_tiles_x0():
    """Removed parts become outside boxes: random points of X0 are covered exactly once."""
    world, sonars = rooms.TRIANGLE, rooms.triangle_sonars()
    d = simulate_ranges(world, sonars, rooms.TRIANGLE_POSE)
    paving = localize(world, sonars, d, [[-7, 4], [-1, 8], [-np.pi, np.pi]], 0.1, contract=True)
    boxes = np.concatenate([paving.inner, paving.boundary, paving.outside])
    rng = np.random.default_rng(0)
    pts = rng.uniform([-7, -1, -np.pi], [4, 8, np.pi], (300, 3))
    lo, hi = boxes[None, :, :, 0], boxes[None, :, :, 1]
    inside = np.all((lo < pts[:, None]) & (pts[:, None] < hi), axis=-1)
    assert np.all(inside.sum(axis=1) == 1)


@pytest.mark.parametrize("seed", range(4))
def test_contraction_keeps_the_truth_and_every_proven_pose(seed):
    """Same readings, with and without contraction: the truth and every witness of the
    plain paving's components stay in the contracted one (q = 1, one outlier)."""
    rng = np.random.default_rng(seed)
    world = random_room(rng)
    belt = random_belt(rng, 5)
    truth = inside_pose(rng, world)
    d = simulate_ranges(world, belt, truth)
    d[0] = rng.uniform(0.5, 4.0)
    X0 = [[-6, 6], [-6, 6], [-np.pi, np.pi]]
    plain = localize(world, belt, d, X0, 0.15, q=1)
    tight = localize(world, belt, d, X0, 0.15, q=1, contract=True)
    assert tight.contains(truth)
    for comp in plain.components():
        w = comp.witness()
        if w is not None:
            assert tight.contains(w)
    assert tight.volume_bounds()[1] <= plain.volume_bounds()[1] * 1.5
