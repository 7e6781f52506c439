"""Sonar localization by set inversion, with outliers [LJMW97], [KJWM00].

A belt of sonars on the robot measures, each, the distance to the nearest point of the map's
reflecting faces inside its emission cone. The simulation function f of [LJMW97, eq. (2)]
maps a pose ``q = (x, y, theta)`` to those t distances (:func:`simulate_ranges`); its
inclusion function on boxes of poses (:func:`range_inclusion`) drives SIVIA, which
characterises the poses consistent with the measured ranges [LJMW97, eq. (3)]
(:func:`localize`). With ``q > 0`` up to ``q`` sonars may be inconsistent (relaxed
intersection [KJWM00]); ``q="auto"`` raises ``q`` until the set is not proven empty (a lower
bound on the number of outliers, see :func:`localize`). Optionally, every box is contracted
by the sonars' upper range bounds before bisection (:func:`sonar_contractors`).

The geometry (cone, reflecting side, nearest point) is :func:`geometry.nearest_in_cone`,
one formula for points and boxes. On SIVIA's boxes the belt is evaluated by a compiled loop
(:mod:`optbound.localization._sonar_kernel`) that computes the same outward-rounded bounds bit
for bit and counts the inconsistent sonars per box, stopping at the first that decides it
(:func:`sonar_tests`); the numpy evaluation stays the reference. The heading ``theta`` is an
angle: an initial box covering a whole turn is widened to contain the true circle, and
components that meet across the seam ``theta = +-pi`` are merged (:meth:`SonarPaving.components`).

A world is an (s, 2, 2) array of oriented segments; :func:`polygon_walls` builds a room's
walls from its vertices and :func:`clearance_test` is a "centre inside the room" prior. Under
the model contract of :mod:`optbound.localization`, :func:`localize` is also
:func:`exact_paving`, :func:`sonar_tests` is :func:`exact_tests` and :func:`simulate_ranges` is
:func:`measure`.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np

from optbound._core import box_array, box_rows
from optbound._core import validate as v
from optbound.interval import (
    Interval,
    Paving,
    Tri,
    constraint,
    min_outliers,
    relaxed_test,
)
from optbound.interval.fenv import nearest
from optbound.interval.relaxed import FusedTests, relaxed_paving
from optbound.localization import _sonar_kernel as kernel
from optbound.localization import geometry as g
from optbound.localization._sonar_contractor import upper_range_contractor
from optbound.sets import Box

#: Default maximal range d_max [m]: what a sonar returns when its cone meets no reflecting
#: face [LJMW97, eq. (2)] (the Polaroid sensors' usual limit).
D_MAX = 10.0
#: SIVIA tests every level of at least this many boxes (:func:`~optbound.interval.pave`'s
#: ``defer_below``): the compiled belt test costs little per call, so pruning from a few
#: hundred boxes on is cheaper than bisecting untested (1024, the default, halves the speed).
DEFER_BELOW = 256


@dataclass(frozen=True)
class Sonar:
    """One sonar of the belt, in the robot frame [KJWM00, Sect. 2.1].

    Parameters
    ----------
    position
        ``(x, y)`` of the cone's vertex in the robot frame [m].
    orientation
        Axis of the cone in the robot frame [rad], counter-clockwise from the robot's heading.
    half_aperture
        Half-angle gamma of the cone [rad], in ``(0, pi/2)`` [LJMW97, Fig. 3: +-12 degrees].
    rel_accuracy
        Relative accuracy alpha in ``[0, 1)``: a reading ``d`` means the true distance lies in
        ``[d (1 - alpha), d (1 + alpha)]`` [KJWM00, Sect. 2.1], [LJMW97, eq. (1)].
    """

    position: tuple[float, float]
    orientation: float
    half_aperture: float
    rel_accuracy: float

    def __post_init__(self):
        pos = v.finite_array("position", self.position)
        if pos.shape != (2,):
            raise ValueError(f"position must be a pair (x, y), got shape {pos.shape}")
        object.__setattr__(self, "position", (float(pos[0]), float(pos[1])))
        object.__setattr__(self, "orientation", v.finite_scalar("orientation", self.orientation))
        gamma = v.finite_scalar("half_aperture", self.half_aperture)
        if not 0.0 < gamma < np.pi / 2:
            raise ValueError(f"half_aperture must lie in (0, pi/2), got {gamma}")
        object.__setattr__(self, "half_aperture", gamma)
        alpha = v.finite_scalar("rel_accuracy", self.rel_accuracy)
        if not 0.0 <= alpha < 1.0:
            raise ValueError(f"rel_accuracy must lie in [0, 1), got {alpha}")
        object.__setattr__(self, "rel_accuracy", alpha)


def _belt(sonars) -> list[Sonar]:
    belt = [sonars] if isinstance(sonars, Sonar) else list(sonars)
    if not belt:
        raise ValueError("sonars must hold at least one Sonar")
    bad = [type(s).__name__ for s in belt if not isinstance(s, Sonar)]
    if bad:
        raise TypeError(f"sonars must be Sonar objects, got {bad[0]}")
    return belt


def _d_max(d_max) -> float:
    d_max = v.finite_scalar("d_max", d_max)
    if d_max <= 0.0:
        raise ValueError(f"d_max must be positive, got {d_max}")
    return d_max


def _ranges(world, sonars, pose, d_max) -> object:
    """f on poses ``(x, y, theta)`` (float arrays or intervals of one shape), shape (..., t, s).

    Sonars go on the second-to-last axis and segments on the last, so that the segments'
    minimum (the loop of [LJMW97, eq. (2)]) is one reduction.
    """
    x, y, theta = (c[..., None, None] for c in pose)
    sx, sy, alpha, gamma = (np.array(c)[:, None] for c in zip(*_params(sonars), strict=True))
    apex = g.to_world((x, y, theta), (sx, sy))
    a, b = g.segment_points(world)
    return g.nearest_in_cone(apex, theta + alpha, gamma, a, b, d_max)


def _params(sonars) -> list[tuple[float, float, float, float]]:
    return [(s.position[0], s.position[1], s.orientation, s.half_aperture) for s in sonars]


def simulate_ranges(world, sonars, pose, d_max: float = D_MAX) -> np.ndarray:
    """The simulation function f of [LJMW97, eq. (2)]: noise-free ranges at poses.

    Parameters
    ----------
    world
        (s, 2, 2) oriented segments ``[a, b]``, reflecting face on the left
        (see :func:`geometry.as_segments`).
    sonars
        A :class:`Sonar` or a sequence of t of them.
    pose
        ``(x, y, theta)`` or an (m, 3) array of poses (theta the heading, radians).
    d_max
        Range returned when no reflecting face is in the cone.

    Returns
    -------
    ndarray
        (t,) ranges for one pose, (m, t) for m poses: per sonar, the distance to the nearest
        point of a reflecting face inside its cone, at most ``d_max``.

    Notes
    -----
    As in [LJMW97, eq. (2)] every segment is considered on its own: a segment seen from
    behind neither echoes nor hides the segments beyond it (there is no occlusion test).
    """
    world = g.as_segments(world)
    belt = _belt(sonars)
    d_max = _d_max(d_max)
    poses = v.finite_array("pose", pose)
    if poses.shape[-1:] != (3,) or poses.ndim not in (1, 2):
        raise ValueError(f"pose must be (x, y, theta) or an (m, 3) array, got {poses.shape}")
    per_segment = _ranges(world, belt, tuple(np.moveaxis(poses, -1, 0)), d_max)
    return per_segment.min(axis=-1)


def _min_over_segments(per_segment: Interval) -> Interval:
    return Interval._make(per_segment.lo.min(axis=-1), per_segment.hi.min(axis=-1))


def range_inclusion(world, sonars, boxes, d_max: float = D_MAX) -> Interval:
    """Inclusion function of f on (m, 3, 2) pose boxes: an (m, t) ``Interval``.

    Every pose of box k gives, for sonar i, a range inside entry ``[k, i]`` (outward-rounded:
    guaranteed for the floats of the map and the boxes read as exact numbers). The bounds of
    :func:`geometry.nearest_in_cone` on intervals, minimised over the segments, evaluated by
    the compiled loop of :mod:`optbound.localization._sonar_kernel` (the same bounds, bit for
    bit).

    Parameters
    ----------
    world : array_like, shape (s, 2, 2)
        Oriented segments ``[a, b]``, reflecting face on the left.
    sonars : Sonar or sequence of Sonar
        The belt of t sonars.
    boxes : array_like, shape (m, 3, 2)
        Pose boxes, rows ``[lo, hi]`` of x, y, theta.
    d_max : float
        Range returned when no reflecting face is in the cone.

    Returns
    -------
    Interval, shape (m, t)
        Entry ``[k, i]`` encloses the range of sonar i at every pose of box k.

    Raises
    ------
    ValueError
        On a malformed world, boxes or ``d_max``.
    TypeError
        If ``sonars`` holds something other than :class:`Sonar`.
    """
    world = g.as_segments(world)
    belt = _belt(sonars)
    arr = box_array("boxes", boxes, 3)
    pose = tuple(Interval._make(arr[:, k, 0].copy(), arr[:, k, 1].copy()) for k in range(3))
    return kernel.range_bounds(kernel.wall_table(world), _param_table(belt), _d_max(d_max), *pose)


def _param_table(belt: list[Sonar]) -> np.ndarray:
    return np.array(_params(belt), dtype=float).reshape(len(belt), 4)


def measurement_box(sonars, ranges) -> np.ndarray:
    """Bound each true range by ``[d (1 - alpha), d (1 + alpha)]``, rounded outward.

    Parameters
    ----------
    sonars : Sonar or sequence of Sonar
        The belt of t sonars (their ``rel_accuracy`` alpha).
    ranges : array_like, shape (t,)
        Positive measured ranges d, one per sonar.

    Returns
    -------
    numpy.ndarray, shape (t, 2)
        Rows ``[lo, hi]`` of the measurement box D.

    Raises
    ------
    ValueError
        If ``ranges`` is not one positive finite range per sonar.

    Notes
    -----
    The box ``D`` of [LJMW97, eq. (3)], from the sensor model of [LJMW97, eq. (1)].
    """
    belt = _belt(sonars)
    d = v.finite_array("ranges", ranges)
    if d.shape != (len(belt),):
        raise ValueError(f"ranges must have shape ({len(belt)},) (one per sonar), got {d.shape}")
    if np.any(d <= 0.0):
        raise ValueError(f"ranges must be positive, got {d.tolist()}")
    alpha = np.array([s.rel_accuracy for s in belt])
    lo = np.nextafter(np.nextafter(d * (1.0 - alpha), -np.inf), -np.inf)
    hi = np.nextafter(np.nextafter(d * (1.0 + alpha), np.inf), np.inf)
    return np.stack([lo, hi], axis=1)


def _initial_box(X0) -> tuple[np.ndarray, bool]:
    """X0 as (3, 2) rows; a heading range of a whole turn becomes one that covers the circle.

    Returns the rows and whether the heading wraps (covers a full turn).
    """
    lo, hi = box_rows("X0", X0, allow_infinite=False)
    if lo.size != 3:
        raise ValueError(f"X0 must have 3 rows (x, y, theta), got {lo.size}")
    if np.any(hi <= lo):
        raise ValueError("X0 must have volume: lo < hi on x, y and theta")
    full = hi[2] - lo[2] >= 2 * np.pi
    if full:
        # The float 2*pi is below the true 2 pi: two ulps more make [lo, hi] cover the circle.
        hi[2] = np.nextafter(np.nextafter(lo[2] + 2 * np.pi, np.inf), np.inf)
    return np.stack([lo, hi], axis=1), bool(full)


def sonar_tests(
    world, sonars, ranges, d_max: float = D_MAX, *, keep_counts: bool = False
) -> FusedTests:
    """One three-valued SIVIA test per sonar: ``f_i(q) in [d_i (1 -+ alpha_i)]``.

    Each test evaluates :func:`geometry.nearest_in_cone` with the interval layer. The list
    also carries their compiled q-relaxed conjunction (:class:`~optbound.interval.relaxed.
    FusedTests`), which :func:`~optbound.interval.relaxed_test` uses on SIVIA's boxes: one
    compiled pass over the boxes that stops, per box, at the first sonar that decides it
    [KJWM00]. With ``keep_counts`` it keeps each box's sonar counts, so the same box tested
    again at another ``q`` (``q = "auto"``) resumes where it stopped (same verdicts as a
    fresh evaluation). ``list(sonar_tests(...))`` drops it (the plain, lazy numpy evaluation).

    Parameters
    ----------
    world : array_like, shape (s, 2, 2)
        Oriented segments ``[a, b]``, reflecting face on the left.
    sonars : Sonar or sequence of Sonar
        The belt of t sonars.
    ranges : array_like, shape (t,)
        Positive measured ranges, one per sonar.
    d_max : float
        Range returned when no reflecting face is in the cone.
    keep_counts : bool
        Memoise each tested box's sonar counts for the tests at other ``q`` (worth it when
        the same boxes are tested at several ``q``; each kept box costs about 150 bytes).

    Returns
    -------
    FusedTests
        The t tests ``test(x, y, theta)`` with their compiled q-relaxed conjunction.

    Raises
    ------
    ValueError
        On a malformed world, ranges or ``d_max``.
    TypeError
        If ``sonars`` holds something other than :class:`Sonar`.
    """
    world = g.as_segments(world)
    belt = _belt(sonars)
    Y = measurement_box(belt, ranges)
    d_max = _d_max(d_max)

    def test_of(i: int):
        def f(x, y, theta):
            return _min_over_segments(_ranges(world, [belt[i]], (x, y, theta), d_max))[..., 0]

        return constraint(f, Y[i : i + 1])

    walls, params = kernel.wall_table(world), _param_table(belt)
    memo = {} if keep_counts else None  # each box's sonar counts, for every q

    def fused(q: int):
        def test(x, y, theta):
            return kernel.relaxed_tri(walls, params, d_max, Y, q, x, y, theta, memo)

        return test

    return FusedTests([test_of(i) for i in range(len(belt))], fused)


def _keep(lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return lo, hi


def sonar_contractors(world, sonars, ranges, d_max: float = D_MAX) -> list:
    """One sound contractor per sonar, for :func:`localize` (contraction before bisection).

    A sonar whose upper range bound is below ``d_max`` contracts ``(x, y)`` by
    :func:`~optbound.localization._sonar_contractor.upper_range_contractor`; one that may read
    ``d_max`` ("no face") removes nothing.

    Parameters
    ----------
    world : array_like, shape (s, 2, 2)
        Oriented segments ``[a, b]``, reflecting face on the left.
    sonars : Sonar or sequence of Sonar
        The belt of t sonars.
    ranges : array_like, shape (t,)
        Positive measured ranges, one per sonar.
    d_max : float
        Range returned when no reflecting face is in the cone.

    Returns
    -------
    list of callable
        One contractor ``c(lo, hi) -> (lo, hi)`` per sonar.

    Raises
    ------
    ValueError
        On a malformed world, ranges or ``d_max``.
    TypeError
        If ``sonars`` holds something other than :class:`Sonar`.
    """
    world = g.as_segments(world)
    belt = _belt(sonars)
    Y = measurement_box(belt, ranges)
    d_max = _d_max(d_max)
    return [
        upper_range_contractor(world, s.position, hi) if hi < d_max else _keep
        for s, hi in zip(belt, Y[:, 1], strict=True)
    ]


class SonarPaving(Paving):
    """A :class:`Paving` of poses with the sonar problem it solves.

    Parameters
    ----------
    paving : Paving
        The paving of poses (x, y, theta).
    problem : dict
        The problem solved: ``world``, ``sonars``, ``Y`` (measurement box), ``d_max``,
        ``tests`` and ``prior``.
    q : int
        Number of sonars allowed to be inconsistent.
    wraps : bool
        Whether the heading range covers a whole turn (components are then merged across
        the seam).
    hypothesis : tuple of tuple of int, optional
        The association hypothesis of a component (see below).

    Attributes
    ----------
    q
        Number of sonars allowed to be inconsistent (reached by ``q="auto"``).
    hypothesis
        For a component (see :meth:`components`): per sonar, the tuple of segment indices
        that sonar may be seeing on the component's boxes [LJMW97, Sect. 4]; one index per
        sonar is a single association hypothesis, an empty tuple means "no face (d_max)"
        or an outlier. ``None`` on the whole paving.
    """

    def __init__(self, paving: Paving, problem: dict, q: int, wraps: bool, hypothesis=None):
        super().__init__(paving.inner, paving.boundary, paving.outside, paving.X0, paving.eps)
        self.problem, self.q, self.wraps, self.hypothesis = problem, q, wraps, hypothesis

    def contains(self, pose) -> bool:
        """Test whether the pose ``(x, y, theta)``, theta read modulo 2 pi, is in inner ∪ boundary.

        Parameters
        ----------
        pose : array_like, shape (3,)
            ``(x, y, theta)``.

        Returns
        -------
        bool
            True if a box of ``inner ∪ boundary`` holds the pose (theta shifted by -2 pi, 0
            or 2 pi).

        Raises
        ------
        ValueError
            If ``pose`` is not three finite numbers.
        """
        p = v.finite_array("pose", pose)
        if p.shape != (3,):
            raise ValueError(f"pose must be (x, y, theta), got shape {p.shape}")
        boxes = self.outer()
        turns = np.array([[0.0, 0.0, 2 * np.pi * k] for k in (-1, 0, 1)])
        q = (p + turns)[:, None, :]  # (3, 1, 3) against (m, 3) bounds
        return bool(np.any(np.all((boxes[:, :, 0] <= q) & (q <= boxes[:, :, 1]), axis=-1)))

    def components(self) -> list[SonarPaving]:
        """Connected components with their association hypotheses, largest first.

        When the heading covers the whole circle, components touching at ``theta = lo`` and
        ``theta = lo + 2 pi`` with overlapping (x, y) are one component; its boxes on the low
        side are shifted by 2 pi so that its hull is an ordinary box (theta may exceed pi).

        Returns
        -------
        list of SonarPaving
            One paving per component, with its ``hypothesis``, by decreasing outer volume.
        """
        parts = Paving.components(self)
        if self.wraps:
            parts = _merge_across_seam(parts, self.X0)
        out = [
            SonarPaving(p, self.problem, self.q, False, self._hypothesis(p.outer())) for p in parts
        ]
        return sorted(out, key=lambda p: -p.volume_bounds()[1])

    def witness(self, per_side: int = 3) -> np.ndarray | None:
        """A float pose of this paving proven consistent with the readings, or ``None``.

        Tries the centre of every box, then a ``per_side``³ grid in each box; a pose is
        proven when the sonar tests (and the prior) are TRUE at the point box of the pose:
        at least ``t - q`` readings are shown, in interval arithmetic, to contain the ranges
        of that exact float pose. A component with a witness holds a point of the true set
        [LJMW97, eq. (3)]; one without may be an artefact of the paving.

        Parameters
        ----------
        per_side : int
            Grid points per axis tried in each box (>= 1).

        Returns
        -------
        numpy.ndarray, shape (3,), or None
            The first proven pose, ``None`` if none is found.

        Raises
        ------
        ValueError
            If ``per_side`` is not a positive integer.
        """
        if not isinstance(per_side, (int, np.integer)) or per_side < 1:
            raise ValueError(f"per_side must be a positive integer, got {per_side!r}")
        boxes = self.outer()
        if not boxes.shape[0]:
            return None
        lo, hi = boxes[:, :, 0], boxes[:, :, 1]
        grid = (np.arange(per_side) + 0.5) / per_side
        frac = np.stack(np.meshgrid(grid, grid, grid, indexing="ij"), -1).reshape(-1, 3)
        for f in (np.full((1, 3), 0.5), frac):
            poses = np.clip(lo[:, None] + f[None] * (hi - lo)[:, None], lo[:, None], hi[:, None])
            poses = poses.reshape(-1, 3)
            proven = np.flatnonzero(self._proven(poses) == Tri.TRUE)
            if proven.size:
                return poses[proven[0]]
        return None

    @nearest
    def _proven(self, poses: np.ndarray) -> np.ndarray:
        coords = [Interval._make(poses[:, k].copy(), poses[:, k].copy()) for k in range(3)]
        tests, prior = self.problem["tests"], self.problem["prior"]
        tri = relaxed_test(tests, self.q)(*coords)
        return tri if prior is None else np.minimum(tri, prior(*coords))

    def _hypothesis(self, boxes: np.ndarray) -> tuple[tuple[int, ...], ...]:
        world, belt, Y, d_max = (self.problem[k] for k in ("world", "sonars", "Y", "d_max"))
        pose = tuple(Interval._make(boxes[:, k, 0], boxes[:, k, 1]) for k in range(3))
        per = _ranges(world, belt, pose, d_max)  # (m, t, s)
        nearest_hi = per.hi.min(axis=-1, keepdims=True)
        can_be = (per.lo <= Y[:, 1, None]) & (per.hi >= Y[:, 0, None]) & (per.lo <= nearest_hi)
        can_be &= per.lo < d_max  # a segment seen only at d_max is "no face"
        seen = can_be.any(axis=0)  # (t, s)
        return tuple(tuple(np.flatnonzero(row).tolist()) for row in seen)


_SHARED: list[dict] = []  # one {inputs: tests} per open :func:`shared_counts` block


@contextmanager
def shared_counts() -> Iterator[None]:
    """Within the block, :func:`localize` calls on the same data share their sonar tests.

    The compiled test keeps each box's sonar counts (:func:`sonar_tests`), so a call at
    another ``q`` on the same world, belt, ranges and ``d_max`` tests no box twice. The
    pavings are those of separate calls; only the work is shared. Outside such a block every
    call starts afresh, so that timing repeated calls measures a full paving. The block keeps
    the tests of the latest data only.

    Examples
    --------
    >>> room = polygon_walls([[0, 0], [4, 0], [4, 3], [0, 3]])
    >>> belt = [Sonar((0.0, 0.0), a, 0.2, 0.02) for a in (0.0, np.pi / 2, np.pi, -np.pi / 2)]
    >>> ranges = simulate_ranges(room, belt, np.array([1.0, 1.0, 0.1]))
    >>> X0 = [[0.5, 1.5], [0.5, 1.5], [-0.2, 0.4]]
    >>> with shared_counts():
    ...     strict = localize(room, belt, ranges, X0, 0.05, q=0)
    ...     relaxed = localize(room, belt, ranges, X0, 0.05, q=1)
    >>> bool(strict.volume_bounds()[1] <= relaxed.volume_bounds()[1])
    True
    """
    _SHARED.append({})
    try:
        yield
    finally:
        _SHARED.pop()


def _tests_for(
    world: np.ndarray, belt: list[Sonar], ranges, d_max: float, several_q: bool
) -> FusedTests:
    """:func:`sonar_tests`, shared with earlier calls on the same data in :func:`shared_counts`.

    They keep their boxes' counts when they will be used at several ``q`` (``q = "auto"``,
    or in a :func:`shared_counts` block).
    """
    if not _SHARED:
        return sonar_tests(world, belt, ranges, d_max, keep_counts=several_q)
    shared = _SHARED[-1]
    inputs = (world.tobytes(), world.shape, tuple(belt), measurement_box(belt, ranges).tobytes())
    inputs += (d_max,)
    if inputs not in shared:
        shared.clear()
        shared[inputs] = sonar_tests(world, belt, ranges, d_max, keep_counts=True)
    return shared[inputs]


def _merge_across_seam(parts: list[Paving], X0: Box) -> list[Paving]:
    lo, hi = X0.lo[2], X0.hi[2]
    n = len(parts)
    group = list(range(n))

    def root(i):
        while group[i] != i:
            i = group[i]
        return i

    low = [p.outer()[p.outer()[:, 2, 0] <= lo] for p in parts]
    high = [p.outer()[p.outer()[:, 2, 1] >= hi] for p in parts]
    for i in range(n):
        for j in range(n):
            if low[i].size and high[j].size and _xy_touch(low[i], high[j]):
                group[root(i)] = root(j)
    merged = {}
    for i in range(n):
        merged.setdefault(root(i), []).append(parts[i])
    return [_shifted_union(members, X0) for members in merged.values()]


def _xy_touch(A: np.ndarray, B: np.ndarray) -> bool:
    a, b = A[:, None, :2], B[None, :, :2]
    return bool(np.any(np.all((a[..., 0] <= b[..., 1]) & (b[..., 0] <= a[..., 1]), axis=-1)))


def _shifted_union(members: list[Paving], X0: Box) -> Paving:
    if len(members) == 1:
        return members[0]
    centre = 0.5 * (X0.lo[2] + X0.hi[2])

    def shift(boxes: np.ndarray, low_side: bool) -> np.ndarray:
        out = boxes.copy()
        if low_side:  # theta + 2 pi, rounded outward: the box keeps all its poses (mod 2 pi)
            out[:, 2, 0] = np.nextafter(np.nextafter(out[:, 2, 0] + 2 * np.pi, -np.inf), -np.inf)
            out[:, 2, 1] = np.nextafter(np.nextafter(out[:, 2, 1] + 2 * np.pi, np.inf), np.inf)
        return out

    low_side = [p.hull().lo[2] + p.hull().hi[2] < 2 * centre for p in members]
    inner = np.concatenate([shift(p.inner, s) for p, s in zip(members, low_side, strict=True)])
    bound = np.concatenate([shift(p.boundary, s) for p, s in zip(members, low_side, strict=True)])
    x0 = Box(X0.lo, np.array([X0.hi[0], X0.hi[1], X0.hi[2] + 2 * np.pi]))
    return Paving(inner, bound, np.empty((0, 3, 2)), x0, members[0].eps)


def localize(
    world,
    sonars,
    ranges,
    X0,
    eps: float,
    q: int | str = 0,
    *,
    d_max: float = D_MAX,
    prior=None,
    contract: bool = False,
    max_boxes: int = 20_000_000,
) -> SonarPaving:
    """Pave the poses consistent with the sonar ranges, in (x, y, theta).

    [LJMW97, eq. (3)]: ``Q = {q in X0 : f(q) in D}`` with ``D`` the product of
    ``[d_i (1 - alpha_i), d_i (1 + alpha_i)]``; with ``q > 0`` the poses where at most ``q``
    sonars disagree (relaxed intersection [KJWM00]).

    Parameters
    ----------
    world, sonars, d_max
        As in :func:`simulate_ranges`.
    ranges
        (t,) positive measured ranges, one per sonar.
    X0
        (3, 2) rows ``[lo, hi]`` of x, y, theta with volume; a theta row spanning a whole turn
        (e.g. ``[-pi, pi]``) is widened by two ulps so that it covers the circle exactly.
    eps
        SIVIA's bisection threshold (> 0, same units on every axis: m and rad).
    q
        Number of sonars that may be outliers, or ``"auto"``: raise ``q`` from 0 until the
        set is not proven empty [KJWM00] (the reached ``q`` is ``result.q``). A fixed ``q``
        at least the true number of outliers is guaranteed to keep every consistent pose.
        ``"auto"`` guarantees only that no ``q' < result.q`` is consistent with the data at
        this ``eps``: ``result.q`` is a lower bound on the number of outliers, not an
        estimate of it. When the wrong readings fit some other pose, the search stops below
        the true count and the set may miss the true pose.
    prior
        Optional three-valued test on ``(x, y, theta)`` that every pose must pass, whatever
        ``q`` (prior information [KJWM00, Sect. 2.2], e.g.
        :func:`clearance_test`). It is tested first; the sonars only on the boxes it leaves.
    contract
        Contract every box by the sonars' :func:`sonar_contractors` before it is tested
        (their q-relaxed union, :func:`~optbound.interval.relaxed.relaxed_contractor`);
        ``False`` (default) is plain SIVIA. Both are guaranteed. The contractors act on
        ``(x, y)`` only and, measured in :mod:`optbound.bench.sonar_codac`, do not pay for
        themselves on our rooms; they are kept as a sound option.
    max_boxes : int
        Refuse to create more boxes than this.

    Returns
    -------
    SonarPaving
        ``inner ⊂ Q ⊂ inner ∪ boundary``; ``.components()`` gives the connected components
        with their association hypotheses [LJMW97, Sect. 4].

    Raises
    ------
    ValueError
        On a malformed world, ranges, ``X0``, ``eps``, ``d_max`` or ``q``, too many boxes,
        or (``q="auto"``) a set proven empty for every ``q``.
    TypeError
        If ``sonars`` holds something other than :class:`Sonar`, or ``prior`` is not
        callable.

    References
    ----------
    .. [LJMW97] O. Lévêque, L. Jaulin, D. Meizel, E. Walter, "Vehicle localization from
       inaccurate telemetric data: a set inversion approach", IFAC SYROCO, 1997.
    .. [KJWM00] M. Kieffer, L. Jaulin, E. Walter, D. Meizel, "Robust autonomous robot
       localization using interval analysis", Reliable Computing, 2000.

    Examples
    --------
    A 4 m x 3 m room and four sonars looking ahead, left, behind and right:

    >>> room = polygon_walls([[0, 0], [4, 0], [4, 3], [0, 3]])
    >>> belt = [Sonar((0.0, 0.0), a, 0.2, 0.02) for a in (0.0, np.pi / 2, np.pi, -np.pi / 2)]
    >>> truth = np.array([1.0, 1.0, 0.1])
    >>> ranges = simulate_ranges(room, belt, truth)
    >>> ranges.tolist()
    [3.0, 2.0, 1.0, 1.0]
    >>> Q = localize(room, belt, ranges, [[0.5, 1.5], [0.5, 1.5], [-0.2, 0.4]], 0.05)
    >>> Q.contains(truth), Q.q
    (True, 0)
    """
    world = g.as_segments(world)
    belt = _belt(sonars)
    d_max = _d_max(d_max)
    tests = _tests_for(world, belt, ranges, d_max, several_q=isinstance(q, str))
    if prior is not None and not callable(prior):
        raise TypeError(f"prior must be a test callable, got {type(prior).__name__}")
    contractors = sonar_contractors(world, belt, ranges, d_max) if contract else None
    box, wraps = _initial_box(X0)
    eps = v.finite_scalar("eps", eps)
    if eps <= 0.0:
        raise ValueError(f"eps must be positive, got {eps}")
    options = dict(
        prior=prior, contractors=contractors, max_boxes=max_boxes, defer_below=DEFER_BELOW
    )
    if isinstance(q, str):
        if q != "auto":
            raise ValueError(f'q must be an integer in [0, {len(belt)}] or "auto", got {q!r}')
        q, paving = min_outliers(tests, box, eps, **options)
    else:
        paving = relaxed_paving(tests, q, box, eps, **options)
    problem = dict(
        world=world,
        sonars=belt,
        Y=measurement_box(belt, ranges),
        d_max=d_max,
        tests=tests,
        prior=prior,
    )
    return SonarPaving(paving, problem, int(q), wraps)


# ------------------------------------------------------------------------------ worlds, priors
def polygon_walls(vertices) -> np.ndarray:
    """Walls of a polygon given counter-clockwise: (s, 2, 2) segments facing its interior.

    Going counter-clockwise the interior is on the left, which is the reflecting face
    [KJWM00, eq. (2)].

    Parameters
    ----------
    vertices : array_like, shape (s, 2)
        The polygon's vertices, counter-clockwise.

    Returns
    -------
    numpy.ndarray, shape (s, 2, 2)
        Segments ``[v_k, v_{k+1}]`` (the last one closing the polygon).

    Raises
    ------
    ValueError
        If ``vertices`` is not a finite (s, 2) array.
    """
    vertices = np.asarray(vertices, dtype=float)
    return g.as_segments(np.stack([vertices, np.roll(vertices, -1, axis=0)], axis=1), "vertices")


def clearance_test(world, clearance: float):
    """Prior test: the robot's centre is inside a convex room, at least ``clearance`` from walls.

    For a convex room whose walls face inward this is ``front_distance >= clearance`` for
    every wall (:func:`geometry.front_distance`): prior knowledge of the robot's body
    [KJWM00, Sect. 2.2]. Pass it as ``prior`` to :func:`localize`.

    Parameters
    ----------
    world : array_like, shape (s, 2, 2)
        Walls of a convex room, facing inward (e.g. :func:`polygon_walls`).
    clearance : float
        Least distance [m] of the centre from every wall, >= 0.

    Returns
    -------
    callable
        The three-valued test ``test(x, y, theta)``.

    Raises
    ------
    ValueError
        On a malformed world or a negative or non-finite ``clearance``.
    """
    world = g.as_segments(world)
    if not np.isfinite(clearance) or clearance < 0:
        raise ValueError(f"clearance must be finite and >= 0, got {clearance}")
    a, b = g.segment_points(world[:, :, :, None])  # (s, 1) columns: one row per wall
    a, b = g.exact(a), g.exact(b)
    n_walls = world.shape[0]
    Y = np.tile([clearance, np.inf], (n_walls, 1))

    def f(x, y, theta):
        dist = g.front_distance((x, y), a, b)
        return [dist[j] for j in range(n_walls)]

    return constraint(f, Y)


# --------------------------------------------------------------- the model contract's verbs
#: The noise-free measurement function of the model (:mod:`optbound.localization` contract).
measure = simulate_ranges
#: :func:`localize` is already the paving of the exact set [LJMW97, eq. (3)].
exact_paving = localize
#: The interval tests whose conjunction is the exact set.
exact_tests = sonar_tests

__all__ = [
    "D_MAX",
    "Sonar",
    "SonarPaving",
    "clearance_test",
    "exact_paving",
    "exact_tests",
    "localize",
    "measure",
    "measurement_box",
    "polygon_walls",
    "range_inclusion",
    "shared_counts",
    "simulate_ranges",
    "sonar_contractors",
    "sonar_tests",
]
