"""Sonar model: f on points, its inclusion on boxes, and the localization guarantees."""

import numpy as np
import pytest

from optbound.interval import Interval
from optbound.localization.sonar import (
    D_MAX,
    Sonar,
    clearance_test,
    localize,
    measurement_box,
    polygon_walls,
    range_inclusion,
    simulate_ranges,
)
from optbound.scenarios import rooms

SQUARE = polygon_walls([[-2, -2], [2, -2], [2, 2], [-2, 2]])
GAMMA = np.deg2rad(12.0)
CROSS = [Sonar((0.0, 0.0), k * np.pi / 2, GAMMA, 0.02) for k in range(4)]


def random_room(rng, n_walls=None):
    """A random convex polygon (counter-clockwise, walls facing inward) around the origin."""
    n = n_walls or int(rng.integers(3, 7))
    angles = np.sort(rng.uniform(0, 2 * np.pi, n))
    while np.max(np.diff(np.r_[angles, angles[0] + 2 * np.pi])) > 0.9 * np.pi:
        angles = np.sort(rng.uniform(0, 2 * np.pi, n))
    radii = rng.uniform(3.0, 6.0, n)
    return polygon_walls(np.column_stack([radii * np.cos(angles), radii * np.sin(angles)]))


def random_belt(rng, n):
    return [
        Sonar(
            rng.uniform(-0.3, 0.3, 2),
            rng.uniform(-np.pi, np.pi),
            rng.uniform(0.05, 0.4),
            0.02,
        )
        for _ in range(n)
    ]


def inside_pose(rng, world, clearance=0.5):
    test = clearance_test(world, clearance)
    while True:
        p = np.r_[rng.uniform(-3, 3, 2), rng.uniform(-np.pi, np.pi)]
        if test(*p) == 2:
            return p


def noisy(rng, truth_ranges, sonars):
    """Readings d with the true range in [d (1 - alpha), d (1 + alpha)] (margin 1 %)."""
    alpha = np.array([s.rel_accuracy for s in sonars])
    return truth_ranges / (1 + 0.99 * alpha * rng.uniform(-1, 1, truth_ranges.shape))


# ----- f on points ----------------------------------------------------------------------------


def test_simulate_known_values():
    """Centre of a 4 m square with a cross of sonars: 2 m each; shifted: the walls' distances."""
    assert np.allclose(simulate_ranges(SQUARE, CROSS, (0.0, 0.0, 0.0)), 2.0)
    assert np.allclose(simulate_ranges(SQUARE, CROSS, (0.5, 0.3, 0.0)), [1.5, 1.7, 2.5, 2.3])
    # Heading pi/2 rotates the belt: sonar 0 now looks up (+y).
    assert np.allclose(simulate_ranges(SQUARE, CROSS, (0.5, 0.3, np.pi / 2)), [1.7, 2.5, 2.3, 1.5])


def test_simulate_oblique_wall_and_cone_edge():
    """Cone axis at 45 deg to a wall: the nearest point in the cone is on the cone's edge."""
    wall = np.array([[[2.0, 1.0], [-2.0, 1.0]]])  # faces -y
    sonar = Sonar((0.0, 0.0), np.pi / 4, GAMMA, 0.02)
    assert np.isclose(simulate_ranges(wall, sonar, (0, 0, 0))[0], 1 / np.sin(np.pi / 4 + GAMMA))
    # Perpendicular axis: the foot of the perpendicular; behind the wall or facing away: d_max.
    up = Sonar((0.0, 0.0), np.pi / 2, GAMMA, 0.02)
    assert simulate_ranges(wall, up, (0, 0, 0))[0] == pytest.approx(1.0)
    assert simulate_ranges(wall, up, (0, 2, 0))[0] == D_MAX
    assert simulate_ranges(wall, up, (0, 0, np.pi))[0] == D_MAX
    assert simulate_ranges(wall, up, (0, 0, 0), d_max=0.5)[0] == 0.5


def test_simulate_segment_end_in_cone():
    """A short wall whose end point is the only part in the cone."""
    wall = np.array([[[3.0, 0.1], [1.0, 0.1]]])  # faces -y, seen from below-left
    sonar = Sonar((0.0, 0.0), 0.0, GAMMA, 0.02)
    assert np.isclose(simulate_ranges(wall, sonar, (0, 0, 0))[0], np.hypot(1.0, 0.1))


def test_simulate_shapes_and_vectorization():
    rng = np.random.default_rng(1)
    poses = np.column_stack([rng.uniform(-1.5, 1.5, (50, 2)), rng.uniform(-4, 4, 50)])
    many = simulate_ranges(SQUARE, CROSS, poses)
    assert many.shape == (50, 4)
    assert simulate_ranges(SQUARE, CROSS, poses[7]).shape == (4,)
    assert np.array_equal(many[7], simulate_ranges(SQUARE, CROSS, poses[7]))
    # theta is an angle: adding 2 pi changes nothing (up to rounding).
    assert np.allclose(many, simulate_ranges(SQUARE, CROSS, poses + np.array([0, 0, 2 * np.pi])))


# ----- inclusion function -------------------------------------------------------------------


@pytest.mark.parametrize("seed", range(6))
def test_range_inclusion_encloses_sampled_poses(seed):
    """Every sampled pose of a box has its ranges inside the box's intervals."""
    rng = np.random.default_rng(seed)
    world = random_room(rng)
    extra = rng.uniform(-3, 3, (2, 2, 2))  # free-standing walls, any orientation
    world = np.concatenate([world, extra[np.any(extra[:, 0] != extra[:, 1], axis=1)]])
    sonars = random_belt(rng, 5)
    m = 300
    centre = np.column_stack([rng.uniform(-4, 4, (m, 2)), rng.uniform(-np.pi, np.pi, m)])
    half = rng.uniform(0, [0.5, 0.5, 0.6], (m, 3)) * (rng.uniform(size=(m, 1)) < 0.9)
    boxes = np.stack([centre - half, centre + half], axis=-1)
    enc = range_inclusion(world, sonars, boxes)
    assert enc.shape == (m, 5)
    for _ in range(40):
        u = rng.uniform(size=(m, 3))
        poses = boxes[:, :, 0] + u * (boxes[:, :, 1] - boxes[:, :, 0])
        r = simulate_ranges(world, sonars, poses)
        assert np.all(enc.lo <= r) and np.all(r <= enc.hi)
    # Corners too (the extreme poses of each box).
    for corner in range(8):
        bits = [(corner >> k) & 1 for k in range(3)]
        poses = boxes[:, [0, 1, 2], bits]
        r = simulate_ranges(world, sonars, poses)
        assert np.all(enc.lo <= r) and np.all(r <= enc.hi)


def test_range_inclusion_is_inclusion_monotonic():
    """Point boxes inside a box get sub-intervals: interval vs interval, no float rounding."""
    rng = np.random.default_rng(8)
    world = random_room(rng)
    sonars = random_belt(rng, 4)
    m = 300
    centre = np.column_stack([rng.uniform(-4, 4, (m, 2)), rng.uniform(-np.pi, np.pi, m)])
    boxes = np.stack([centre - 0.2, centre + 0.2], axis=-1)
    enc = range_inclusion(world, sonars, boxes)
    for _ in range(20):
        lo, hi = boxes[:, :, 0], boxes[:, :, 1]
        p = np.clip(lo + rng.uniform(size=(m, 3)) * (hi - lo), lo, hi)
        point = range_inclusion(world, sonars, np.stack([p, p], axis=-1))
        assert np.all(enc.lo <= point.lo) and np.all(point.hi <= enc.hi)


def test_range_inclusion_is_tight_on_small_boxes():
    """On tiny boxes away from discontinuities the enclosure shrinks to the point value."""
    rng = np.random.default_rng(7)
    poses = np.column_stack([rng.uniform(-1.5, 1.5, (200, 2)), rng.uniform(-np.pi, np.pi, 200)])
    boxes = np.stack([poses - 1e-9, poses + 1e-9], axis=-1)
    enc = range_inclusion(SQUARE, CROSS, boxes)
    width = enc.hi - enc.lo
    assert np.median(width) < 1e-7
    point = simulate_ranges(SQUARE, CROSS, poses)
    assert np.all((enc.lo <= point) & (point <= enc.hi))


def test_range_inclusion_box_across_the_seam():
    """A heading box [3, 3.3] crosses pi: the enclosure covers poses on both sides."""
    box = np.array([[[0.2, 0.3], [0.1, 0.2], [3.0, 3.3]]])
    enc = range_inclusion(SQUARE, CROSS, box)
    for th in np.linspace(3.0, 3.3, 31):
        for th_wrapped in (th, th - 2 * np.pi):
            r = simulate_ranges(SQUARE, CROSS, (0.25, 0.15, th_wrapped))
            assert np.all((enc.lo[0] <= r) & (r <= enc.hi[0]))


# ----- localization ---------------------------------------------------------------------------


@pytest.mark.parametrize("seed", range(8))
def test_truth_in_paving_for_random_rooms(seed):
    """Noisy ranges inside their bounds: the true pose is in inner ∪ boundary [LJMW97, eq. (11)]."""
    rng = np.random.default_rng(100 + seed)
    world = random_room(rng)
    sonars = random_belt(rng, 6)
    truth = inside_pose(rng, world)
    d = noisy(rng, simulate_ranges(world, sonars, truth), sonars)
    X0 = [[-7, 7], [-7, 7], [-np.pi, np.pi]]
    paving = localize(world, sonars, d, X0, 0.1)
    assert paving.contains(truth) and paving.contains(truth + np.array([0, 0, 2 * np.pi]))
    assert not paving.contains(truth + np.array([20.0, 0, 0]))
    assert paving.q == 0
    assert any(c.contains(truth) for c in paving.components())


def test_localize_square_components_and_hypotheses():
    """The cross of sonars in a square: each component's hypothesis names the walls seen."""
    truth = (0.5, 0.3, 0.1)
    d = simulate_ranges(SQUARE, CROSS, truth)
    paving = localize(
        SQUARE,
        CROSS,
        d,
        [[-3, 3], [-3, 3], [-np.pi, np.pi]],
        0.04,
        prior=clearance_test(SQUARE, 0.1),
    )
    comps = paving.components()
    [mine] = [c for c in comps if c.contains(truth)]
    seen = [
        int(np.argmin([simulate_ranges(SQUARE[j : j + 1], s, truth)[0] for j in range(4)]))
        for s in CROSS
    ]
    assert mine.hypothesis == tuple((j,) for j in seen)
    # The square is symmetric: other poses fit the same four readings (other hypotheses).
    assert len(comps) >= 2
    assert all(c.hypothesis is not None for c in comps) and paving.hypothesis is None


@pytest.mark.parametrize("heading", [np.pi - 0.01, -np.pi + 0.01])
def test_heading_seam_keeps_one_component(heading):
    """Truth heading next to +-pi: the set straddles the seam; its two halves are one component."""
    sonars = [Sonar((0.1, 0.0), a, GAMMA, 0.02) for a in (0.0, 1.3, 2.9, -1.7)]
    truth = np.array([0.4, -0.3, heading])
    d = simulate_ranges(SQUARE, sonars, truth)
    paving = localize(
        SQUARE,
        sonars,
        d,
        [[-3, 3], [-3, 3], [-np.pi, np.pi]],
        0.04,
        prior=clearance_test(SQUARE, 0.1),
    )
    assert paving.X0.hi[2] > np.pi and paving.X0.hi[2] - paving.X0.lo[2] >= 2 * np.pi
    [mine] = [c for c in paving.components() if c.contains(truth)]
    hull = mine.hull()
    assert hull.lo[2] < np.pi - 0.1 and np.pi + 0.1 < hull.hi[2]  # both halves, contiguous
    assert hull.hi[2] - hull.lo[2] < 1.0


@pytest.mark.parametrize("seed", range(3))
def test_outliers_relaxed_intersection(seed):
    """With k outliers among the readings the truth stays in the q = k set; auto q <= k."""
    rng = np.random.default_rng(200 + seed)
    world = rooms.BELT_ROOM
    sonars = rooms.belt_sonars(12)
    truth = inside_pose(rng, world)
    d = noisy(rng, simulate_ranges(world, sonars, truth), sonars)
    k = 2
    bad = rng.choice(len(sonars), k, replace=False)
    d[bad] = rng.uniform(0.5, 8.0, k)
    X0 = [[-6, 6], [-5, 5], [-np.pi, np.pi]]
    relaxed = localize(world, sonars, d, X0, 0.15, q=k)
    assert relaxed.contains(truth) and relaxed.q == k
    auto = localize(world, sonars, d, X0, 0.15, q="auto")
    assert auto.q <= k
    if auto.q == k:
        assert auto.contains(truth)


def test_measurement_box_is_outward():
    belt = [Sonar((0, 0), 0.0, GAMMA, 0.1), Sonar((0, 0), 1.0, GAMMA, 0.02)]
    box = measurement_box(belt, [2.0, 3.0])
    assert box[0, 0] < 1.8 < 2.2 < box[0, 1]
    assert box[1, 0] < 2.94 and 3.06 < box[1, 1]


# ----- bad input ------------------------------------------------------------------------------


X0 = [[-3, 3], [-3, 3], [-np.pi, np.pi]]


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (
            dict(position=(0, 0), orientation=0, half_aperture=0.0, rel_accuracy=0.02),
            "half_aperture",
        ),
        (
            dict(position=(0, 0), orientation=0, half_aperture=1.6, rel_accuracy=0.02),
            "half_aperture",
        ),
        (
            dict(position=(0, 0), orientation=np.nan, half_aperture=0.2, rel_accuracy=0.02),
            "orientation",
        ),
        (dict(position=(0, 0, 0), orientation=0, half_aperture=0.2, rel_accuracy=0.02), "position"),
        (
            dict(position=(0, 0), orientation=0, half_aperture=0.2, rel_accuracy=-0.1),
            "rel_accuracy",
        ),
        (dict(position=(0, 0), orientation=0, half_aperture=0.2, rel_accuracy=1.0), "rel_accuracy"),
    ],
)
def test_bad_sonar(kwargs, match):
    with pytest.raises(ValueError, match=match):
        Sonar(**kwargs)


def test_bad_inputs_name_the_argument():
    d = np.array([1.0, 1.0, 1.0, 1.0])
    with pytest.raises(ValueError, match="world is empty"):
        localize(np.empty((0, 2, 2)), CROSS, d, X0, 0.1)
    with pytest.raises(ValueError, match="ranges must be positive"):
        localize(SQUARE, CROSS, [1.0, -1.0, 1.0, 1.0], X0, 0.1)
    with pytest.raises(ValueError, match="ranges must have shape"):
        localize(SQUARE, CROSS, [1.0, 1.0], X0, 0.1)
    with pytest.raises(ValueError, match="ranges must be real"):
        localize(SQUARE, CROSS, d + 1j, X0, 0.1)
    with pytest.raises(ValueError, match="ranges must be finite"):
        localize(SQUARE, CROSS, [1.0, np.inf, 1.0, 1.0], X0, 0.1)
    for eps in (0.0, -0.1, np.nan):
        with pytest.raises(ValueError, match="eps"):
            localize(SQUARE, CROSS, d, X0, eps)
    with pytest.raises(ValueError, match="X0 must have volume"):
        localize(SQUARE, CROSS, d, [[-3, 3], [1, 1], [-1, 1]], 0.1)
    with pytest.raises(ValueError, match="X0 must have 3 rows"):
        localize(SQUARE, CROSS, d, [[-3, 3], [-3, 3]], 0.1)
    with pytest.raises(ValueError, match="X0"):
        localize(SQUARE, CROSS, d, [[-3, 3], [-3, np.inf], [-1, 1]], 0.1)
    for q in (-1, 5, 1.5, "most"):
        with pytest.raises(ValueError, match="q"):
            localize(SQUARE, CROSS, d, X0, 0.1, q=q)
    with pytest.raises(TypeError, match="sonars"):
        localize(SQUARE, [(0, 0, 0, 0.1)], [1.0], X0, 0.1)
    with pytest.raises(ValueError, match="sonars must hold"):
        localize(SQUARE, [], [], X0, 0.1)
    with pytest.raises(ValueError, match="d_max"):
        simulate_ranges(SQUARE, CROSS, (0, 0, 0), d_max=0.0)
    with pytest.raises(ValueError, match="pose"):
        simulate_ranges(SQUARE, CROSS, (0, 0))
    with pytest.raises(ValueError, match="pose must be finite"):
        simulate_ranges(SQUARE, CROSS, (0, np.nan, 0))
    with pytest.raises(ValueError, match="boxes"):
        range_inclusion(SQUARE, CROSS, np.zeros((2, 2, 2)))
    with pytest.raises(ValueError, match="lo <= hi"):
        range_inclusion(SQUARE, CROSS, np.array([[[1, 0], [0, 1], [0, 1]]]))
    with pytest.raises(ValueError, match="pose"):
        localize(SQUARE, CROSS, simulate_ranges(SQUARE, CROSS, (0, 0, 0)), X0, 0.2).contains((0, 0))
    with pytest.raises(TypeError, match="prior"):
        localize(SQUARE, CROSS, d, X0, 0.1, prior=3)


def test_intervals_are_accepted_as_exact_points():
    """range_inclusion returns an Interval whose bounds are plain float arrays."""
    enc = range_inclusion(SQUARE, CROSS, np.array([[[0, 0], [0, 0], [0, 0]]], float))
    assert isinstance(enc, Interval) and enc.lo.dtype == float
    assert np.all(enc.lo <= 2.0) and np.all(2.0 <= enc.hi)


# ----- proven components ----------------------------------------------------------------------


def test_witness_is_a_consistent_pose_of_the_component():
    d = simulate_ranges(rooms.TRIANGLE, rooms.triangle_sonars(), rooms.TRIANGLE_POSE)
    X0 = [[-7, 4], [-1, 8], [-np.pi, np.pi]]
    paving = localize(rooms.TRIANGLE, rooms.triangle_sonars(), d, X0, 0.05)
    [q1] = [c for c in paving.components() if c.contains(rooms.TRIANGLE_POSE)]
    w = q1.witness()
    assert w is not None and q1.contains(w)
    box = measurement_box(rooms.triangle_sonars(), d)
    r = simulate_ranges(rooms.TRIANGLE, rooms.triangle_sonars(), w)
    assert np.all((box[:, 0] <= r) & (r <= box[:, 1]))


def test_no_witness_where_no_pose_is_consistent():
    from optbound.interval import Paving
    from optbound.localization.sonar import SonarPaving
    from optbound.sets import Box

    d = simulate_ranges(rooms.TRIANGLE, rooms.triangle_sonars(), rooms.TRIANGLE_POSE)
    X0 = [[-7, 4], [-1, 8], [-np.pi, np.pi]]
    paving = localize(rooms.TRIANGLE, rooms.triangle_sonars(), d, X0, 0.2)
    far = np.array([[[2.0, 2.1], [6.0, 6.1], [1.0, 1.1]]])  # outside the room
    empty = np.empty((0, 3, 2))
    fake = SonarPaving(
        Paving(empty, far, empty, Box([-7, -1, -4], [4, 8, 4]), 0.2), paving.problem, 0, False
    )
    assert fake.witness() is None
    with pytest.raises(ValueError, match="per_side"):
        fake.witness(per_side=0)
