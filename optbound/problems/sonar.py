"""Family ``sonar``: a robot's pose ``(x, y, theta)`` from one sonar scan [LJMW97], [KJWM00].

Our design on the rooms of the sonar reproductions (:mod:`optbound.scenarios.rooms`, whose
rooms and belts are ours too): the triangle room with four sonars at the pose ``q*`` of
[LJMW97, Sect. 4] (noise-free ranges), and seeded random poses in the triangle and in the
belt room (eight sonars, after [KJWM00, Fig. 1]) with ranges drawn inside the sonars' relative
accuracy [LJMW97, eq. (1)]. The robot is known to lie in a prior box ``X0`` (0.5 m and 0.3 rad
either side, the truth placed at random in it): prior information in the sense of
[KJWM00, Sect. 2.2], which keeps the set to one neighbourhood. The estimator gets
``data = {"world": (s, 2, 2) walls, "sonars": [Sonar], "ranges": (t,), "d_max": float,
"prior_box": Box}`` and ``truth`` is the pose.

The true set is ``{q ∈ X0 : f(q) ∈ D}`` [LJMW97, eq. (3)], described once by the model's
own tests (:func:`optbound.localization.sonar.sonar_tests`, the ones ``sonar.localize``
paves) and ``X0``'s. Its domain is the hull of a coarse paving of ``X0`` (1/COARSE of its
widest side), paved at 1/RELATIVE of the hull's widest side.

References
----------
[LJMW97] O. Lévêque, L. Jaulin, D. Meizel, E. Walter, "Vehicle localization from
inaccurate telemetric data: a set inversion approach", IFAC SYROCO, 1997.
[KJWM00] M. Kieffer, L. Jaulin, E. Walter, D. Meizel, "Robust autonomous robot
localization using interval analysis", Reliable Computing, 2000.
"""

from __future__ import annotations

import numpy as np

from optbound.compare.tri import point_test, tri_test
from optbound.interval import Tri, pave, tri_and
from optbound.localization import sonar
from optbound.problems.generators import task_seeds
from optbound.problems.problem import Problem
from optbound.scenarios import rooms
from optbound.sets import Box

NAME = "sonar"
# Per suite: random poses in the triangle, random poses in the belt room (after q*).
SIZES = {"tiny": (0, 0), "quick": (2, 1), "full": (8, 4)}
#: Half-widths of the prior box X0 in x, y (m) and theta (rad).
PRIOR_HALF = np.array([0.5, 0.5, 0.3])
#: Coarse paving of X0 that finds the domain, and the exact paving's resolution.
COARSE, RELATIVE = 20, 40
#: Clearance of random poses from the walls (m), and the belt's number of sonars.
CLEARANCE, BELT_SONARS = 0.6, 8


def tasks(suite: str, seed: int) -> list[dict]:
    """List the instance cells of a suite: ``q*`` of [LJMW97, Sect. 4], then random poses per room.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        The suite size.
    seed : int
        The suite seed (``optbound bench --seed``); the instance seeds come from
        :func:`~optbound.problems.generators.task_seeds`.

    Returns
    -------
    list of dict
        One cell per problem, keys ``seed``, ``room`` ("triangle" or "belt"), ``paper_pose``
        and ``index``.

    Raises
    ------
    ValueError
        For an unknown ``suite``.

    References
    ----------
    [LJMW97] O. Lévêque, L. Jaulin, D. Meizel, E. Walter, "Vehicle localization from
    inaccurate telemetric data: a set inversion approach", IFAC SYROCO, 1997.
    """
    if suite not in SIZES:
        raise ValueError(f"suite must be one of {tuple(SIZES)}, got {suite!r}")
    n_triangle, n_belt = SIZES[suite]
    cells = [("triangle", True)] + [("triangle", False)] * n_triangle + [("belt", False)] * n_belt
    return [
        {"seed": s, "room": room, "paper_pose": paper, "index": i}
        for i, (s, (room, paper)) in enumerate(
            zip(task_seeds(seed, NAME, len(cells)), cells, strict=True)
        )
    ]


def _room(name: str) -> tuple[np.ndarray, list]:
    if name == "triangle":
        return rooms.TRIANGLE, rooms.triangle_sonars()
    return rooms.BELT_ROOM, rooms.belt_sonars(BELT_SONARS)


def _random_pose(rng: np.random.Generator, world: np.ndarray) -> np.ndarray:
    """A pose uniform in the room's bounding box, redrawn until CLEARANCE from every wall."""
    inside = sonar.clearance_test(world, CLEARANCE)
    pts = world.reshape(-1, 2)
    while True:
        pose = np.r_[rng.uniform(pts.min(axis=0), pts.max(axis=0)), rng.uniform(-np.pi, np.pi)]
        if point_test(inside, pose[None])[0] == Tri.TRUE:
            return pose


def instance(seed: int, room: str, paper_pose: bool) -> dict:
    """Rebuild the world, sonars, ranges, prior box and true pose of one instance from its seed.

    Parameters
    ----------
    seed : int
        The instance seed (``np.random.default_rng(seed)``).
    room : {"triangle", "belt"}
        The room (:mod:`optbound.scenarios.rooms`).
    paper_pose : bool
        True for the pose ``q*`` of [LJMW97, Sect. 4] with noise-free ranges, False for a
        random pose with ranges drawn within the sonars' relative accuracy.

    Returns
    -------
    dict
        ``"world"`` (s, 2, 2) walls, ``"sonars"``, ``"ranges"`` (t,), ``"prior_box"`` and
        ``"truth"``, the pose (x, y, theta).

    References
    ----------
    [LJMW97] O. Lévêque, L. Jaulin, D. Meizel, E. Walter, "Vehicle localization from
    inaccurate telemetric data: a set inversion approach", IFAC SYROCO, 1997.
    """
    rng = np.random.default_rng(seed)
    world, belt = _room(room)
    pose = np.array(rooms.TRIANGLE_POSE) if paper_pose else _random_pose(rng, world)
    ranges = sonar.simulate_ranges(world, belt, pose)
    if not paper_pose:  # a reading d with the true range in [d (1 - a), d (1 + a)]
        alpha = np.array([s.rel_accuracy for s in belt])
        ranges = ranges / (1.0 + 0.5 * alpha * rng.uniform(-1.0, 1.0, ranges.shape))
    lo = pose - PRIOR_HALF * 2.0 * rng.uniform(0.2, 0.8, 3)
    return {
        "world": world,
        "sonars": belt,
        "ranges": ranges,
        "prior_box": Box(lo, lo + 2.0 * PRIOR_HALF),
        "truth": pose,
    }


def problem(task: dict) -> Problem:
    """Build the :class:`Problem` of one task of :func:`tasks`.

    Parameters
    ----------
    task : dict
        A cell of :func:`tasks`.

    Returns
    -------
    Problem
        The problem, its data rebuilt from the task's seed.

    Raises
    ------
    RuntimeError
        If the true set is proven empty (a simulation bug: the truth is in it).
    """
    inst = instance(task["seed"], task["room"], task["paper_pose"])
    tests = (
        *sonar.sonar_tests(inst["world"], inst["sonars"], inst["ranges"]),
        tri_test(inst["prior_box"]),
    )

    def test(*coords):
        return tri_and(*(t(*coords) for t in tests))

    X0 = inst["prior_box"]
    domain = pave(test, X0, float(np.max(X0.widths)) / COARSE).hull()
    if domain is None:
        raise RuntimeError(f"sonar instance {task}: the true set was proven empty")
    name = "ljmw97-q*" if task["paper_pose"] else f"{task['room']}-{task['index']}"
    return Problem(
        family=NAME,
        name=name,
        seed=task["seed"],
        dim=3,
        data={
            "world": inst["world"],
            "sonars": inst["sonars"],
            "ranges": inst["ranges"],
            "d_max": sonar.D_MAX,
            "prior_box": X0,
        },
        truth=inst["truth"],
        test=test,
        domain=domain,
        eps=float(np.max(domain.widths)) / RELATIVE,
    )


def problems(suite: str, seed: int = 0) -> list[Problem]:
    """Build every problem of the family in a suite, seeded like ``optbound bench``.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        The suite size.
    seed : int, default 0
        The suite seed (``optbound bench --seed``).

    Returns
    -------
    list of Problem
        One problem per cell of :func:`tasks`.

    Raises
    ------
    ValueError
        For an unknown ``suite``.
    """
    return [problem(task) for task in tasks(suite, seed)]
