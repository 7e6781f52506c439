"""GLH12 visibility test, LUVIA and tracking: three-valued answers never contradicted by points,
and the truth never leaves a robot's box."""

import numpy as np
import pytest

from optbound.interval import Tri
from optbound.localization import visibility as v
from optbound.localization.environment import Environment
from optbound.scenarios import arena
from tests.localization import exact_visibility as ex

WALL = np.array([[4.0, 0.0], [6.0, 0.0], [6.0, 10.0], [4.0, 10.0]])
POLYS = [
    np.array([[2.0, 2.0], [3.0, 2.0], [3.0, 4.5], [2.0, 4.5]]),
    np.array([[6.5, 5.0], [8.5, 5.5], [7.0, 7.0]]),
    np.array([[0, 6], [3, 6], [3, 9], [2, 9], [2, 7], [1, 7], [1, 9], [0, 9]], dtype=float),
]


def _random_boxes(rng, m, lo=0.0, hi=9.0, width=1.0):
    low = rng.uniform(lo, hi, (m, 2))
    return np.stack([low, low + rng.uniform(0, width, (m, 2))], -1)


def _sample(rng, box):
    return box[:, 0] + rng.uniform(size=2) * (box[:, 1] - box[:, 0])


def test_visibility_test_interface_and_samples():
    """(m, 2, 2) boxes and a list of (k, 2) polygons -> (m,) Tri, never contradicted."""
    rng = np.random.default_rng(0)
    m = 250
    b1, b2 = _random_boxes(rng, m), _random_boxes(rng, m)
    tri = v.visibility_test(b1, b2, POLYS)
    assert tri.shape == (m,) and tri.dtype == np.int8
    assert {Tri.TRUE, Tri.FALSE, Tri.UNKNOWN} <= set(tri.tolist())
    for i in np.flatnonzero(tri != Tri.UNKNOWN):
        corners = [
            ((b1[i, 0, a], b1[i, 1, c]), (b2[i, 0, c], b2[i, 1, a])) for a in (0, 1) for c in (0, 1)
        ]
        pairs = corners + [(_sample(rng, b1[i]), _sample(rng, b2[i])) for _ in range(6)]
        for p1, p2 in pairs:
            assert ex.visible(p1, p2, POLYS) == (tri[i] == Tri.TRUE)


def test_visibility_inside_obstacle_and_no_obstacles():
    inside = np.array([[[2.2, 2.4], [3.0, 3.2]]])
    outside = np.array([[[2.2, 2.4], [5.0, 5.2]]])  # straight above the block: clear of it
    assert v.visibility_test(inside, outside, POLYS[:1]).tolist() == [Tri.FALSE]
    assert v.visibility_test(outside, outside + 0.1, POLYS[:1]).tolist() == [Tri.TRUE]
    assert v.visibility_test(inside, outside, []).tolist() == [Tri.TRUE]


@pytest.mark.parametrize(
    ("b1", "b2", "obstacles", "error", "match"),
    [
        (np.zeros((2, 2, 2)), np.zeros((3, 2, 2)), [], ValueError, "same shape"),
        (np.zeros((2, 2)), np.zeros((2, 2)), [], ValueError, r"\(m, 2, 2\)"),
        (np.full((1, 2, 2), np.nan), np.zeros((1, 2, 2)), [], ValueError, "finite"),
        (np.array([[[1.0, 0.0], [0.0, 1.0]]]), np.zeros((1, 2, 2)), [], ValueError, "lower bound"),
        (np.zeros((1, 2, 2)), np.zeros((1, 2, 2)), WALL, TypeError, "list"),
    ],
)
def test_visibility_test_rejects_bad_input(b1, b2, obstacles, error, match):
    with pytest.raises(error, match=match):
        v.visibility_test(b1, b2, obstacles)


def _env():
    return Environment.from_polygons([*POLYS[:2], WALL * [1, 0.5]], 0.05)


def test_luvia_keeps_every_truth_and_contracts():
    """Random true positions, boxes around them, exact measurements: the truth is never lost."""
    rng = np.random.default_rng(1)
    env = _env()
    contracted = 0
    for _ in range(40):
        m = 6
        truth = rng.uniform(0.2, 9.8, (m, 2))
        free = v.visibility_test(*([np.repeat(truth[:, :, None], 2, 2)] * 2), env.outer) == Tri.TRUE
        truth = truth[free]
        if len(truth) < 2:
            continue
        boxes = np.stack([truth - rng.uniform(0.05, 0.95, truth.shape), truth], -1)
        boxes[:, :, 1] = boxes[:, :, 0] + 1.0
        y = v.measure(truth, env.exact)
        for i in range(len(truth)):
            out = v.luvia(i, y[i], boxes, env, 0.005)
            assert out is not None
            assert np.all((out[:, 0] <= truth[i]) & (truth[i] <= out[:, 1]))
            assert np.all((out[:, 0] >= boxes[i, :, 0]) & (out[:, 1] <= boxes[i, :, 1]))
            contracted += np.prod(np.diff(out)) < 0.99 * np.prod(np.diff(boxes[i]))
    assert contracted >= 10


def test_luvia_refutes_impossible_measurements():
    env = Environment.from_polygons([WALL], 0.05)
    boxes = np.array([[[1.0, 2.0], [4.0, 5.0]], [[8.0, 9.0], [4.0, 5.0]]])
    # The wall blocks every line of sight, yet the robots claim to see each other.
    assert v.luvia(0, np.array([True, True]), boxes, env, 0.01) is None
    out = v.luvia(0, np.array([True, False]), boxes, env, 0.01)
    np.testing.assert_array_equal(out, boxes[0])


@pytest.mark.parametrize(
    ("robot", "y", "boxes", "env", "error", "match"),
    [
        (0, [True], np.zeros((0, 2, 2)), "env", ValueError, "empty"),
        (
            0,
            [True, True],
            np.array([[[0, 1], [0, 0]], [[0, 1], [0, 1]]]),
            "env",
            ValueError,
            "no volume",
        ),
        (
            0,
            [True],
            np.array([[[0, 1], [0, 1]], [[2, 3], [0, 1]]]),
            "env",
            ValueError,
            "one entry per robot",
        ),
        (0, [1, 0], np.array([[[0, 1], [0, 1]], [[2, 3], [0, 1]]]), "env", TypeError, "booleans"),
        (
            2,
            [True, True],
            np.array([[[0, 1], [0, 1]], [[2, 3], [0, 1]]]),
            "env",
            ValueError,
            "robot",
        ),
        (
            0,
            [True, True],
            np.array([[[0, 1], [0, 1]], [[2, 3], [0, 1]]]),
            None,
            TypeError,
            "Environment",
        ),
    ],
)
def test_luvia_rejects_bad_input(robot, y, boxes, env, error, match):
    env = _env() if env == "env" else env
    with pytest.raises(error, match=match):
        v.luvia(robot, np.array(y), boxes, env, 0.01)


def test_odometry_encloses_every_move():
    rng = np.random.default_rng(2)
    boxes = _random_boxes(rng, 20)
    heading = rng.uniform(-np.pi, np.pi, 20)
    out = v.odometry(boxes, [0.099, 0.101], heading, 0.05)
    for _ in range(200):
        x = np.array([_sample(rng, b) for b in boxes])
        d = rng.uniform(0.099, 0.101, 20)
        th = heading + rng.uniform(-0.05, 0.05, 20)
        moved = x + d[:, None] * np.column_stack([np.cos(th), np.sin(th)])
        assert np.all((out[:, :, 0] <= moved) & (moved <= out[:, :, 1]))


@pytest.mark.parametrize(("n_robots", "n_obstacles", "seed"), [(5, 6, 0), (7, 6, 1), (4, 3, 2)])
def test_track_keeps_the_truth_in_every_box(n_robots, n_obstacles, seed):
    """[GLH12, Algorithm 1] on short seeded runs: truth inside every box at every step."""
    run = arena.simulate(n_robots, n_obstacles, 40, seed)
    common = (run.distance, run.headings, arena.HEADING_ERROR, run.visibility)
    boxes = v.track(run.boxes0, *common, run.env, 0.01)
    assert boxes.shape == (41, n_robots, 2, 2)
    assert np.all((boxes[..., 0] <= run.truth) & (run.truth <= boxes[..., 1]))
    room = np.array([[-50.0, -50.0], [60.0, -50.0], [60.0, 60.0], [-50.0, 60.0]])
    unknown = Environment([], [room])  # E⁻ = ∅, E⁺ = everything: no measurement informs
    alone = v.track(run.boxes0, *common, unknown, 0.01)
    area, area_alone = (np.prod(np.diff(b[-1]), axis=(1, 2)) for b in (boxes, alone))
    assert np.all(area <= area_alone) and area.sum() < area_alone.sum()


def test_track_takes_visibility_in_any_memory_order():
    """The sweep calls LUVIA by address, compiled for C-ordered rows: a visibility array in
    another memory order (here Fortran order) gives the same boxes."""
    run = arena.simulate(4, 3, 10, 3)
    common = (run.distance, run.headings, arena.HEADING_ERROR)
    boxes = v.track(run.boxes0, *common, run.visibility, run.env, 0.01)
    fortran = np.asfortranarray(run.visibility)
    assert not fortran.flags.c_contiguous
    assert np.array_equal(v.track(run.boxes0, *common, fortran, run.env, 0.01), boxes)


def test_track_rejects_bad_input():
    run = arena.simulate(3, 2, 2, 0)
    args = (run.distance, run.headings, arena.HEADING_ERROR, run.visibility, run.env, 0.01)
    with pytest.raises(ValueError, match="empty"):
        v.track(np.zeros((0, 2, 2)), *args)
    with pytest.raises(ValueError, match="headings"):
        v.track(run.boxes0, run.distance, run.headings[:, :2], *args[2:])
    with pytest.raises(ValueError, match="visibility"):
        v.track(run.boxes0, *args[:3], run.visibility[:, :2], *args[4:])
    with pytest.raises(ValueError, match="eps"):
        v.track(run.boxes0, *args[:5], -1.0)


def _algorithm2(i, y, boxes, env, eps, max_depth):
    """[GLH12, Algorithm 2] literally: a list of boxes, every measurement tested on each."""
    stack, kept = [(boxes[i], 0)], []
    while stack:
        box, depth = stack.pop()
        bisect, consistent = False, True
        for j in range(len(boxes)):
            if j == i:
                continue
            obstacles = env.inner if y[j] else env.outer
            t = v.visibility_test(box[None], boxes[j][None], obstacles)[0]
            if t == (Tri.FALSE if y[j] else Tri.TRUE):
                consistent = False
                break
            bisect |= t == Tri.UNKNOWN
        if consistent:
            if bisect and np.prod(np.diff(box)) > eps and depth < max_depth:
                axis = int(np.argmax(np.diff(box)[:, 0]))  # Bisect(): halve the wider side
                mid = 0.5 * (box[axis, 0] + box[axis, 1])
                low, high = box.copy(), box.copy()
                low[axis, 1] = high[axis, 0] = mid
                stack.extend([(low, depth + 1), (high, depth + 1)])
            else:
                kept.append(box)
    if not kept:
        return None
    kept = np.array(kept)
    return np.stack([kept[:, :, 0].min(0), kept[:, :, 1].max(0)], 1)


def test_luvia_is_the_hull_of_algorithm_2():
    """The best-first search returns exactly the hull of the literal Algorithm 2."""
    rng = np.random.default_rng(5)
    env = _env()
    for _ in range(12):
        truth = rng.uniform(0.5, 9.5, (5, 2))
        boxes = np.stack(
            [truth - rng.uniform(0.1, 1.4, (5, 2)), truth + rng.uniform(0.1, 1.4, (5, 2))], -1
        )
        y = rng.uniform(size=5) < 0.5
        for i in range(5):
            ours = v.luvia(i, y, boxes, env, 0.02, max_depth=7)
            ref = _algorithm2(i, y, boxes, env, 0.02, 7)
            assert (ours is None) == (ref is None)
            if ref is not None:
                np.testing.assert_array_equal(ours, ref)


@pytest.mark.parametrize(
    ("distance", "heading", "error", "match"),
    [
        ([0.1, 0.1], [0.0], -0.1, "heading_error"),
        ([0.1, 0.1], [0.0], "a", "heading_error"),
        ([0.2, 0.1], [0.0], 0.1, "lower bound"),
        ([0.1, 0.1], [0.0, 1.0], 0.1, "heading"),
        ([0.1, np.nan], [0.0], 0.1, "finite"),
    ],
)
def test_odometry_rejects_bad_input(distance, heading, error, match):
    with pytest.raises(ValueError, match=match):
        v.odometry(np.array([[[0.0, 1.0], [0.0, 1.0]]]), distance, heading, error)


def test_measure_sees_through_free_space_only():
    pts = np.array([[1.0, 3.0], [4.0, 3.0], [2.5, 1.0]])  # obstacle 0 spans x 2..3, y 2..4.5
    y = v.measure(pts, arena.environment(1).exact)
    assert y.tolist() == [[True, False, True], [False, True, True], [True, True, True]]


def test_measure_of_a_run_is_the_measure_of_each_step():
    run = arena.simulate(4, 6, 5, 1)
    env = run.env.exact
    ys = v.measure(run.truth, env)
    assert ys.shape == (6, 4, 4)
    for k, pts in enumerate(run.truth):
        np.testing.assert_array_equal(ys[k], v.measure(pts, env))
    with pytest.raises(ValueError, match="points"):
        v.measure(run.truth[None], env)


def test_fixpoint_sweeps_keep_the_exact_truth_and_refine_one_sweep():
    """Team contraction to a fixpoint: measurements from exact rational visibility on E, the
    truth stays in every box, and every box lies in the one-sweep box from the same input."""
    rng = np.random.default_rng(7)
    env = _env()
    gained = 0
    for _ in range(15):
        truth = rng.uniform(0.2, 9.8, (6, 2))
        pts = ex.rational(truth)
        truth = truth[[not any(ex.inside(p, ex.rational(q)) for q in env.outer) for p in pts]]
        m = len(truth)
        if m < 3:
            continue
        lo = truth - rng.uniform(0.05, 1.45, truth.shape)
        boxes = np.stack([lo, lo + 1.5], -1)
        y = np.array([[ex.visible(a, b, env.exact) for b in truth] for a in truth])
        args = ([0.0, 0.0], np.zeros((1, m)), 0.0, y[None], env, 0.005)
        one = v.track(boxes, *args)[1]
        fix = v.track(boxes, *args, passes=50)[1]
        assert np.all((fix[..., 0] <= truth) & (truth <= fix[..., 1]))
        assert np.all((one[..., 0] <= fix[..., 0]) & (fix[..., 1] <= one[..., 1]))
        gained += (
            np.prod(np.diff(fix), axis=(1, 2)).sum() < np.prod(np.diff(one), axis=(1, 2)).sum()
        )
    assert gained >= 1


def test_track_region_clips_and_keeps_the_truth():
    run = arena.simulate(4, 6, 60, 2)
    common = (run.distance, run.headings, arena.HEADING_ERROR, run.visibility, run.env, 0.01)
    room = [[0.0, arena.SIZE], [0.0, arena.SIZE]]
    boxes = v.track(run.boxes0, *common, region=room)
    assert np.all((boxes[..., 0] <= run.truth) & (run.truth <= boxes[..., 1]))
    assert np.all((boxes[1:, :, :, 0] >= 0.0) & (boxes[1:, :, :, 1] <= arena.SIZE))
    with pytest.raises(ValueError, match="misses region"):
        v.track(run.boxes0, *common, region=[[20.0, 21.0], [20.0, 21.0]])
    with pytest.raises(ValueError, match="region"):
        v.track(run.boxes0, *common, region=[[0.0, 1.0]])
    for bad in (0, 1.5, True):
        with pytest.raises(ValueError, match="passes"):
            v.track(run.boxes0, *common, passes=bad)
