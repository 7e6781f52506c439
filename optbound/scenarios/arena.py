"""The 10 x 10 m world of [GLH12, Sect. 5] for visibility-only pose tracking (our design).

[GLH12, Fig. 7] (11 obstacles, 11 initial boxes, the robots' move limits) is lost. This
module **designs** a substitute, fixed before any result was seen and never tuned to the
paper's findings: 11 convex obstacles of various shapes spread over the room (the sweep over
1...11 obstacles uses the first n, so the sets are nested), and 11 start positions in free
space. Robots wander (10 cm steps, a random-walk heading) anywhere in the room at least
``CLEARANCE`` away from the obstacles in use; the paper's per-robot move limits are not known
and are not imitated. The robots' sensing follows the paper: the displacement per step is
known within ±0.1 cm, the heading within ±2.5° (compass), the initial box is 1 m x 1 m and
contains the truth at a random offset. The visibility measurements come from the model's
:func:`optbound.localization.visibility.measure` on the exact obstacles.

One designed room is one sample of a world. :class:`Setting` names the factors a study can vary
one at a time, each with stated alternatives: ``layout="random"`` draws 11 convex obstacles
and 11 start positions from the run's seed (a different room per seed, same rules as the
designed one), ``turn`` the motion (0: straight lines, a new random heading when blocked),
``heading_error`` the compass bound and ``box_offset`` where the truth sits in its initial box.

References
----------
[GLH12] R. Guyonneau, S. Lagrange, L. Hardouin, "Mobile robots pose tracking: a
set-membership approach using a visibility information", ICINCO, 2012.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from optbound.localization.environment import Environment
from optbound.localization.geometry import pack_polygons, segments_meet_packed
from optbound.localization.visibility import measure

SIZE = 10.0
STEP = 0.10
STEP_ERROR = 0.001
HEADING_ERROR = np.deg2rad(2.5)
MARGIN = 0.05  # E⁻ and E⁺: the exact obstacles shrunk and grown by 5 cm
CLEARANCE = 0.15
TURN = 0.2  # standard deviation of the heading's random walk per step (radians)

#: 11 designed convex obstacles (metres), counter-clockwise.
OBSTACLES = tuple(
    np.array(p, dtype=float)
    for p in (
        [[2.0, 2.0], [3.0, 2.0], [3.0, 4.5], [2.0, 4.5]],
        [[5.5, 1.5], [8.0, 1.5], [8.0, 2.3], [5.5, 2.3]],
        [[6.5, 5.0], [8.5, 5.5], [7.0, 7.0]],
        [[1.5, 7.0], [3.5, 7.0], [3.5, 7.6], [1.5, 7.6]],
        [[4.3, 4.3], [5.3, 4.8], [5.0, 5.6], [4.0, 5.1]],
        [[8.3, 7.8], [8.9, 7.8], [8.9, 9.5], [8.3, 9.5]],
        [[0.8, 4.8], [1.6, 5.3], [0.9, 6.0]],
        [[4.0, 0.5], [4.6, 0.5], [4.6, 2.5], [4.0, 2.5]],
        [[4.5, 7.8], [6.0, 7.6], [6.2, 8.6], [4.7, 8.7]],
        [[8.8, 3.0], [9.5, 3.0], [9.5, 4.2], [8.8, 4.2]],
        [[2.5, 0.5], [3.3, 0.7], [2.8, 1.4]],
    )
)
#: 11 designed start positions, free of every obstacle.
STARTS = np.array(
    [
        [1.0, 1.0], [9.0, 1.0], [1.0, 9.0], [9.0, 6.0], [5.0, 3.5], [3.5, 5.5],
        [6.0, 9.3], [7.0, 3.5], [1.2, 3.0], [3.0, 8.8], [5.8, 6.3],
    ]
)  # fmt: skip


@dataclass(frozen=True)
class Setting:
    """The factors of a simulated run; the defaults are the designed room and the paper's sensing.

    Parameters
    ----------
    layout : {"designed", "random"}, default "designed"
        ``"designed"`` (:data:`OBSTACLES`, :data:`STARTS`) or ``"random"`` (drawn from the
        seed by :func:`random_layout`).
    turn : float, default TURN
        Standard deviation (radians) of the heading's random walk per step; 0 gives straight
        lines with a new random heading when blocked.
    heading_error : float, default HEADING_ERROR
        Compass error bound (radians); the paper's is 2.5°.
    box_offset : {"random", "centre"}, default "random"
        ``"random"`` (the truth anywhere at least 5 cm inside its 1 m box) or ``"centre"``.

    Raises
    ------
    ValueError
        For an unknown ``layout`` or ``box_offset``, or a negative or non-finite ``turn`` or
        ``heading_error``.
    """

    layout: str = "designed"
    turn: float = TURN
    heading_error: float = float(HEADING_ERROR)
    box_offset: str = "random"

    def __post_init__(self) -> None:
        if self.layout not in ("designed", "random"):
            raise ValueError(f"layout must be 'designed' or 'random', got {self.layout!r}")
        if self.box_offset not in ("random", "centre"):
            raise ValueError(f"box_offset must be 'random' or 'centre', got {self.box_offset!r}")
        for name in ("turn", "heading_error"):
            value = getattr(self, name)
            if not isinstance(value, int | float) or not np.isfinite(value) or value < 0:
                raise ValueError(f"{name} must be a finite number >= 0, got {value!r}")


@dataclass(frozen=True)
class Run:
    """One simulated run of ``m`` robots over ``K`` steps: the truth and what the robots measure.

    Parameters
    ----------
    env : Environment
        The room: E⁻ ⊂ E ⊂ E⁺ of the obstacles in use.
    truth : np.ndarray, shape (K + 1, m, 2)
        True positions.
    boxes0 : np.ndarray, shape (m, 2, 2)
        Initial 1 m boxes containing ``truth[0]``.
    distance : np.ndarray, shape (2,)
        Known interval of each step's travel.
    headings : np.ndarray, shape (K, m)
        Compass readings.
    visibility : np.ndarray, shape (K, m, m)
        Measurements ``y_il`` after each step (whether robot ``i`` sees robot ``l``).
    heading_error : float, default HEADING_ERROR
        The compass bound of ``headings`` (radians).
    """

    env: Environment
    truth: np.ndarray  # (K + 1, m, 2) true positions
    boxes0: np.ndarray  # (m, 2, 2) initial boxes containing truth[0]
    distance: np.ndarray  # (2,) known interval of each step's travel
    headings: np.ndarray  # (K, m) compass readings
    visibility: np.ndarray  # (K, m, m) measurements y_il after each step
    heading_error: float = float(HEADING_ERROR)  # the compass bound of ``headings``


def environment(n_obstacles: int, obstacles=OBSTACLES) -> Environment:
    """Build E⁻ ⊂ E ⊂ E⁺ made of the first ``n_obstacles`` obstacles (margin 5 cm).

    Parameters
    ----------
    n_obstacles : int
        How many of ``obstacles`` are in the room, from 0 to ``len(obstacles)``.
    obstacles : sequence of np.ndarray, default OBSTACLES
        Convex polygons (counter-clockwise vertices): the designed :data:`OBSTACLES` or a
        :func:`random_layout`'s.

    Returns
    -------
    Environment
        The exact obstacles and their shrunk and grown versions (by :data:`MARGIN`).

    Raises
    ------
    ValueError
        If ``n_obstacles`` is out of range.
    """
    if not 0 <= n_obstacles <= len(obstacles):
        raise ValueError(f"n_obstacles must be in [0, {len(obstacles)}], got {n_obstacles}")
    return Environment.from_polygons(list(obstacles[:n_obstacles]), MARGIN)


def _random_obstacle(rng: np.random.Generator) -> np.ndarray:
    """A convex obstacle about the size of the designed ones: a rectangle or a triangle."""
    centre = rng.uniform(1.0, SIZE - 1.0, 2)
    if rng.uniform() < 0.5:
        a, b = rng.uniform(0.5, 2.0) / 2, rng.uniform(0.3, 0.8) / 2
        poly = np.array([[-a, -b], [a, -b], [a, b], [-a, b]])
    else:
        gaps = rng.uniform(0.7, 1.0, 3)  # angles between vertices, at least ~40° each
        angles = np.cumsum(2 * np.pi * gaps / gaps.sum())
        poly = rng.uniform(0.5, 0.9) * np.column_stack([np.cos(angles), np.sin(angles)])
    phi = rng.uniform(0.0, np.pi)
    rot = np.array([[np.cos(phi), -np.sin(phi)], [np.sin(phi), np.cos(phi)]])
    return centre + poly @ rot.T  # a rotation keeps the counter-clockwise order


def random_layout(seed: int) -> tuple[tuple[np.ndarray, ...], np.ndarray]:
    """11 convex obstacles and 11 free start positions drawn from ``seed`` (our design).

    The rules, fixed before any result was seen: obstacles as :func:`_random_obstacle` draws
    them, inside ``[0.4, 9.6]²`` and with bounding boxes at least 0.6 m apart (robots pass
    between any two); starts at least 0.3 m (sup norm) from every obstacle and the walls.
    The stream is independent of the one :func:`simulate` draws the paths from.

    Parameters
    ----------
    seed : int
        The run's seed.

    Returns
    -------
    obstacles : tuple of np.ndarray
        11 convex polygons (counter-clockwise vertices).
    starts : np.ndarray, shape (11, 2)
        Start positions in free space.
    """
    rng = np.random.default_rng([seed, 1])
    placed: list[np.ndarray] = []
    while len(placed) < len(OBSTACLES):
        poly = _random_obstacle(rng)
        lo, hi = poly.min(axis=0), poly.max(axis=0)
        if np.any(lo < 0.4) or np.any(hi > SIZE - 0.4):
            continue
        if all(np.any((lo > q.max(axis=0) + 0.6) | (hi < q.min(axis=0) - 0.6)) for q in placed):
            placed.append(poly)
    packed = pack_polygons(placed)
    starts: list[np.ndarray] = []
    while len(starts) < len(STARTS):
        p = rng.uniform(0.3, SIZE - 0.3, (1, 2))
        if _free(p, packed, 0.3)[0]:
            starts.append(p[0])
    return tuple(placed), np.array(starts)


def _free(points: np.ndarray, packed, clearance: float = CLEARANCE) -> np.ndarray:
    """Points at least ``clearance`` (in the sup norm) inside the room and off the obstacles
    (packed once by the caller, :func:`~optbound.localization.geometry.pack_polygons`)."""
    inside = np.all((points > clearance) & (points < SIZE - clearance), axis=1)
    boxes = np.stack([points - clearance, points + clearance], axis=-1)
    return inside & (segments_meet_packed(boxes, boxes, packed) == 0)


def simulate(
    n_robots: int, n_obstacles: int, steps: int, seed: int, setting: Setting | None = None
) -> Run:
    """Simulate a seeded run of ``n_robots`` robots among the first ``n_obstacles`` obstacles.

    Parameters
    ----------
    n_robots : int
        Robots in the team, from 1 to 11 (each starts at one of the layout's starts).
    n_obstacles : int
        Obstacles in use, from 0 to 11.
    steps : int
        Simulated steps (>= 0).
    seed : int
        Fixes the paths, the measurement noise and the initial boxes (and the room, with
        ``layout="random"``).
    setting : Setting, optional
        The factors; default ``Setting()``: the designed room, the paper's sensing.

    Returns
    -------
    Run
        The truth and the measurements.

    Raises
    ------
    TypeError
        If ``setting`` is not a :class:`Setting`.
    ValueError
        If ``n_robots``, ``n_obstacles`` or ``steps`` is out of range.
    RuntimeError
        If a robot finds no free heading in 50 draws.

    References
    ----------
    [GLH12] R. Guyonneau, S. Lagrange, L. Hardouin, "Mobile robots pose tracking: a
    set-membership approach using a visibility information", ICINCO, 2012.

    Examples
    --------
    >>> from optbound.scenarios import arena
    >>> run = arena.simulate(n_robots=3, n_obstacles=6, steps=4, seed=0)
    >>> run.truth.shape, run.visibility.shape
    ((5, 3, 2), (4, 3, 3))
    """
    setting = Setting() if setting is None else setting
    if not isinstance(setting, Setting):
        raise TypeError(f"setting must be an arena.Setting, got {type(setting).__name__}")
    if not 1 <= n_robots <= len(STARTS):
        raise ValueError(f"n_robots must be in [1, {len(STARTS)}], got {n_robots}")
    if steps < 0:
        raise ValueError(f"steps must be >= 0, got {steps}")
    obstacles, starts = (OBSTACLES, STARTS) if setting.layout == "designed" else random_layout(seed)
    env = environment(n_obstacles, obstacles)
    rng = np.random.default_rng(seed)
    packed = pack_polygons(env.exact)
    truth = np.empty((steps + 1, n_robots, 2))
    truth[0] = starts[:n_robots]
    theta = rng.uniform(-np.pi, np.pi, n_robots)
    true_heading = np.empty((steps, n_robots))
    for k in range(steps):
        theta = theta + rng.normal(0.0, setting.turn, n_robots)
        d = rng.uniform(STEP - STEP_ERROR, STEP + STEP_ERROR, n_robots)
        nxt = truth[k] + d[:, None] * np.column_stack([np.cos(theta), np.sin(theta)])
        for _ in range(50):  # blocked robots draw a new heading
            bad = ~_free(nxt, packed)
            if not bad.any():
                break
            theta[bad] = rng.uniform(-np.pi, np.pi, bad.sum())
            nxt[bad] = truth[k, bad] + d[bad, None] * np.column_stack(
                [np.cos(theta[bad]), np.sin(theta[bad])]
            )
        else:
            raise RuntimeError("a robot found no free heading in 50 draws")
        truth[k + 1] = nxt
        true_heading[k] = theta
    # The compass error is drawn a relative 1e-9 inside ±2.5°: the reading's rounding (half
    # an ulp) then stays inside the announced bound.
    noise = rng.uniform(-1.0, 1.0, (steps, n_robots)) * setting.heading_error * (1 - 1e-9)
    offset = rng.uniform(0.05, 0.95, (n_robots, 2))  # away from the edges: no rounding issue
    if setting.box_offset == "centre":
        offset[:] = 0.5
    lo = truth[0] - offset
    boxes0 = np.stack([lo, lo + 1.0], axis=-1)
    vis = measure(truth[1:], env.exact)
    distance = np.array([STEP - STEP_ERROR, STEP + STEP_ERROR])
    heading = true_heading + noise
    return Run(env, truth, boxes0, distance, heading, vis, setting.heading_error)


__all__ = [
    "CLEARANCE",
    "HEADING_ERROR",
    "MARGIN",
    "OBSTACLES",
    "SIZE",
    "STARTS",
    "STEP",
    "STEP_ERROR",
    "TURN",
    "Run",
    "Setting",
    "environment",
    "random_layout",
    "simulate",
]
