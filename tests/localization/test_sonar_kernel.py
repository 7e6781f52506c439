"""The compiled sonar belt: the interval layer's bounds bit for bit, and the same pavings."""

import numpy as np
import pytest

from optbound.interval import Interval, relaxed_test
from optbound.interval.relaxed import FusedTests, relaxed_paving
from optbound.localization import sonar
from optbound.localization.sonar import (
    D_MAX,
    Sonar,
    localize,
    range_inclusion,
    shared_counts,
    simulate_ranges,
    sonar_tests,
)
from optbound.scenarios import rooms
from tests.localization.test_sonar import inside_pose, noisy, random_belt, random_room


def _world(rng, room=None):
    """A random room plus free-standing walls facing either way."""
    extra = rng.uniform(-3, 3, (3, 2, 2))
    extra = extra[np.any(extra[:, 0] != extra[:, 1], axis=1)]
    return np.concatenate([random_room(rng) if room is None else room, extra, extra[:, ::-1]])


def _boxes(rng, m):
    """Boxes of every size: points, thin, wide; headings up to a whole turn."""
    centre = np.column_stack([rng.uniform(-6, 6, (m, 2)), rng.uniform(-4, 4, m)])
    scale = rng.choice([0.0, 1e-9, 0.01, 0.3, 2.0], (m, 1))
    half = rng.uniform(0, 1, (m, 3)) * scale * np.array([1.0, 1.0, 1.6])
    return np.stack([centre - half, centre + half], axis=-1)


def _interval_layer(world, belt, boxes) -> Interval:
    """The same enclosure evaluated with numpy Interval arrays (geometry.nearest_in_cone)."""
    pose = tuple(Interval(boxes[:, k, 0], boxes[:, k, 1]) for k in range(3))
    return sonar._min_over_segments(sonar._ranges(world, belt, pose, D_MAX))


@pytest.mark.parametrize("seed", range(4))
def test_compiled_enclosure_equals_the_interval_layer(seed):
    rng = np.random.default_rng(seed)
    world, belt = _world(rng), random_belt(rng, 5)
    boxes = _boxes(rng, 400)
    got, ref = range_inclusion(world, belt, boxes), _interval_layer(world, belt, boxes)
    assert np.array_equal(got.lo, ref.lo) and np.array_equal(got.hi, ref.hi)


def test_compiled_enclosure_equals_the_interval_layer_on_the_belt_room():
    rng = np.random.default_rng(9)
    belt = rooms.belt_sonars(16)
    boxes = _boxes(rng, 300)
    got, ref = (
        range_inclusion(rooms.BELT_ROOM, belt, boxes),
        _interval_layer(rooms.BELT_ROOM, belt, boxes),
    )
    assert np.array_equal(got.lo, ref.lo) and np.array_equal(got.hi, ref.hi)


def test_boxes_sharing_headings_get_the_interval_layers_bounds():
    """A few headings for many boxes (as in SIVIA): the per-heading values serve every box."""
    rng = np.random.default_rng(11)
    world, belt = _world(rng), random_belt(rng, 5)
    boxes = _boxes(rng, 400)
    boxes[:, 2] = boxes[rng.integers(0, 4, 400), 2]  # four distinct headings
    got, ref = range_inclusion(world, belt, boxes), _interval_layer(world, belt, boxes)
    assert np.array_equal(got.lo, ref.lo) and np.array_equal(got.hi, ref.hi)


@pytest.mark.parametrize("seed", range(3))
def test_fused_relaxed_test_equals_the_plain_one(seed):
    """Every q: the compiled verdicts (with their skipped walls) are the numpy ones."""
    rng = np.random.default_rng(30 + seed)
    room = random_room(rng)
    world, belt = _world(rng, room), random_belt(rng, 6)
    truth = inside_pose(rng, room)
    d = noisy(rng, simulate_ranges(world, belt, truth), belt)
    d[rng.integers(6)] = rng.uniform(0.5, 8.0)
    boxes = _boxes(rng, 500)
    boxes[:100] = truth[:, None] + np.array([-1.0, 1.0]) * rng.uniform(0, 0.3, (100, 3, 1))
    coords = [Interval(boxes[:, k, 0], boxes[:, k, 1]) for k in range(3)]
    for keep_counts in (False, True):  # with kept counts, every q after the first resumes
        tests = sonar_tests(world, belt, d, keep_counts=keep_counts)
        assert isinstance(tests, FusedTests) and len(tests) == 6
        for q in range(7):
            fused, plain = relaxed_test(tests, q)(*coords), relaxed_test(list(tests), q)(*coords)
            assert np.array_equal(fused, plain)


def test_localize_paves_as_the_interval_layer():
    """Same boxes as the numpy tests at the same deferral; the truth kept with q = outliers."""
    rng = np.random.default_rng(5)
    belt = rooms.belt_sonars(12)
    truth = inside_pose(rng, rooms.BELT_ROOM)
    d = noisy(rng, simulate_ranges(rooms.BELT_ROOM, belt, truth), belt)
    d[[2, 7]] = [1.0, 6.5]
    X0 = [[-5.5, 5.5], [-4.5, 4.5], [-np.pi, np.pi]]
    ours = localize(rooms.BELT_ROOM, belt, d, X0, 0.2, q=2)
    _assert_paved_as_numpy(ours, belt, d, X0, 2, 0.2)
    assert ours.contains(truth)


def test_shared_counts_resume_at_another_q_and_pave_as_a_fresh_run():
    """In shared_counts the second call reuses the first's tests (per-box counts), same boxes."""
    rng = np.random.default_rng(6)
    belt = rooms.belt_sonars(8)
    truth = inside_pose(rng, rooms.BELT_ROOM)
    d = noisy(rng, simulate_ranges(rooms.BELT_ROOM, belt, truth), belt)
    d[3] = 1.0
    X0 = [[-5.5, 5.5], [-4.5, 4.5], [-np.pi, np.pi]]
    with shared_counts():
        localize(rooms.BELT_ROOM, belt, d, X0, 0.3, q=0)
        (tests,) = sonar._SHARED[-1].values()
        ours = localize(rooms.BELT_ROOM, belt, d, X0, 0.3, q=1)
        assert list(sonar._SHARED[-1].values()) == [tests]
    assert not sonar._SHARED  # outside the block every call starts afresh
    _assert_paved_as_numpy(ours, belt, d, X0, 1, 0.3)
    assert ours.contains(truth)


def _assert_paved_as_numpy(ours, belt, d, X0, q: int, eps: float) -> None:
    """``ours`` has the inner and boundary boxes of the numpy interval layer's q-relaxed paving."""
    box, _ = sonar._initial_box(X0)
    plain = list(sonar_tests(rooms.BELT_ROOM, belt, d))
    ref = relaxed_paving(plain, q, box, eps, defer_below=sonar.DEFER_BELOW)
    for mine, theirs in ((ours.inner, ref.inner), (ours.boundary, ref.boundary)):
        assert np.array_equal(mine, theirs)


def test_a_too_short_wall_is_refused():
    world = np.array([[[0.0, 0.0], [1e-170, 0.0]], [[0.0, 1.0], [1.0, 1.0]]])
    with pytest.raises(ValueError, match="too short"):
        range_inclusion(world, [Sonar((0, 0), 0.0, 0.2, 0.02)], np.zeros((1, 3, 2)))
