"""Family ``visibility``: one robot's position box at one step of GLH12 team tracking [GLH12].

Our design on the arena of the GLH12 reproduction (:mod:`optbound.scenarios.arena`): a seeded
run of the team (:func:`optbound.scenarios.arena.simulate`) for a few steps; at the last step
every robot's position is known to lie in a 1 m box placed at random around it (the kind of
box interval odometry predicts), and robot ``robot`` measures which team-mates it sees
[GLH12, eq. (18)]. The estimator gets ``data = {"robot": int, "boxes": (m, 2, 2),
"visibility": (m,) bool, "environment": Environment}`` (E⁻ ⊂ E ⊂ E⁺) and ``truth`` is the
robot's true position.

The true set is what the data allow when the map is known through E⁻ and E⁺ only
[GLH12, Props. 15-16], the set LUVIA contracts: the positions ``p`` in the robot's box such
that for every team-mate ``j`` some ``p_j`` in its box has ``Seg(p, p_j)`` free of E⁻ when
``j`` is seen, and meeting E⁺ when it is not. It is described once by :func:`visibility_set_test`,
built on the model's three-valued segment test
(:func:`optbound.localization.geometry.segments_meet_polygons`, which ``visibility_test`` and
LUVIA use): a measurement is refuted on a box when the whole team-mate box refutes it, and
proven when one of WITNESSES × WITNESSES witness points of the team-mate box proves it for
every point of the box. The truth lies in the set, since E⁻ ⊂ E ⊂ E⁺.

References
----------
[GLH12] R. Guyonneau, S. Lagrange, L. Hardouin, "Mobile robots pose tracking: a
set-membership approach using a visibility information", ICINCO, 2012.
"""

from __future__ import annotations

import numpy as np

from optbound.compare.tri import tri_test
from optbound.interval import Tri, tri_and
from optbound.interval.tribool import from_masks
from optbound.localization.geometry import as_polygons, segments_meet_polygons
from optbound.problems.generators import task_seeds
from optbound.problems.problem import Problem
from optbound.scenarios import arena
from optbound.sets import Box

NAME = "visibility"
# Per suite: (robots, obstacles) cells and repetitions.
SIZES = {
    "tiny": (((7, 11),), 1),
    "quick": (((4, 6), (7, 11)), 2),
    "full": (((3, 6), (5, 6), (7, 11), (11, 11)), 3),
}
#: Steps simulated before the problem's step, and the side of the position boxes (m).
STEPS, BOX_SIDE = 3, 1.0
#: Witness points per axis of a team-mate's box (a WITNESSES x WITNESSES grid).
WITNESSES = 5
#: Paving resolution: 1/RELATIVE of the box side.
RELATIVE = 64


def tasks(suite: str, seed: int) -> list[dict]:
    """List the instance cells of a suite: seed, robots, obstacles, repetition.

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
        One cell per problem, keys ``seed``, ``robots``, ``obstacles`` and ``rep``.

    Raises
    ------
    ValueError
        For an unknown ``suite``.
    """
    if suite not in SIZES:
        raise ValueError(f"suite must be one of {tuple(SIZES)}, got {suite!r}")
    cells, reps = SIZES[suite]
    flat = [(m, k, r) for m, k in cells for r in range(reps)]
    return [
        {"seed": s, "robots": m, "obstacles": k, "rep": r}
        for s, (m, k, r) in zip(task_seeds(seed, NAME, len(flat)), flat, strict=True)
    ]


def instance(seed: int, robots: int, obstacles: int) -> dict:
    """Rebuild the environment, boxes, measurements and truth of one instance from its seed.

    Parameters
    ----------
    seed : int
        The instance seed (of the simulation and of the boxes).
    robots : int
        Robots in the team.
    obstacles : int
        Obstacles in the room.

    Returns
    -------
    dict
        ``"robot"`` (the one whose position is sought), ``"boxes"`` (robots, 2, 2) position
        boxes of the team, ``"visibility"`` (the robot's row of the visibility matrix),
        ``"environment"`` and ``"truth"`` (the robot's position).
    """
    run = arena.simulate(robots, obstacles, STEPS, seed)
    rng = np.random.default_rng(seed)
    robot = int(rng.integers(robots))
    truth = run.truth[-1]
    lo = truth - rng.uniform(0.05, 0.95, truth.shape) * BOX_SIDE  # away from the edges
    boxes = np.stack([lo, lo + BOX_SIDE], axis=-1)
    return {
        "robot": robot,
        "boxes": boxes,
        "visibility": run.visibility[-1][robot].copy(),
        "environment": run.env,
        "truth": truth[robot].copy(),
    }


def _pairs(boxes: np.ndarray, others: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Every (box, other) pair: ``boxes`` (m, 2, 2) against ``others`` (w, 2, 2)."""
    m, w = boxes.shape[0], others.shape[0]
    return np.repeat(boxes, w, axis=0), np.tile(others, (m, 1, 1))


def visibility_set_test(robot: int, boxes: np.ndarray, y: np.ndarray, env) -> callable:
    """Build the three-valued test of the true set on boxes of the robot's position.

    See the module docstring for the set and its proofs.

    Parameters
    ----------
    robot : int
        The index of the robot whose position is sought.
    boxes : np.ndarray, shape (m, 2, 2)
        The team's position boxes (``[lo, hi]`` per coordinate).
    y : np.ndarray, shape (m,)
        The robot's visibility measurements: ``y[j]`` whether it sees robot ``j``.
    env : Environment
        The room, with its inner and outer obstacle polygons.

    Returns
    -------
    callable
        ``test(x, y) -> Tri array`` on ``Interval`` coordinates.
    """
    inner, outer = as_polygons(env.inner), as_polygons(env.outer)
    own = tri_test(Box(boxes[robot, :, 0], boxes[robot, :, 1]))
    u = (np.arange(WITNESSES) + 0.5) / WITNESSES
    mates = [j for j in range(boxes.shape[0]) if j != robot]

    def witnesses(j: int) -> np.ndarray:
        b = boxes[j]
        gx, gy = np.meshgrid(b[0, 0] + u * (b[0, 1] - b[0, 0]), b[1, 0] + u * (b[1, 1] - b[1, 0]))
        pts = np.column_stack([gx.ravel(), gy.ravel()])
        return np.repeat(pts[:, :, None], 2, axis=2)

    points = {j: witnesses(j) for j in mates}

    def test(x, yc) -> np.ndarray:
        shape = np.shape(x.lo)
        P = np.ascontiguousarray(
            np.stack(
                [
                    np.stack([np.ravel(x.lo), np.ravel(x.hi)], -1),
                    np.stack([np.ravel(yc.lo), np.ravel(yc.hi)], -1),
                ],
                axis=1,
            ),
            dtype=float,
        )
        m = P.shape[0]
        out = [own(x, yc)]
        for j in mates:
            seen = bool(y[j])
            polygons = inner if seen else outer
            # Meeting E⁻ on every pair refutes "seen"; missing E⁺ on every pair, "not seen".
            whole = segments_meet_polygons(P, np.repeat(boxes[j][None], m, axis=0), polygons)
            refuted = whole == (Tri.TRUE if seen else Tri.FALSE)
            a, b = _pairs(P, points[j])
            at = segments_meet_polygons(a, b, polygons).reshape(m, -1)
            proven = np.any(at == (Tri.FALSE if seen else Tri.TRUE), axis=1)
            out.append(from_masks(proven & ~refuted, refuted).reshape(shape))
        return tri_and(*out)

    return test


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
    """
    inst = instance(task["seed"], task["robots"], task["obstacles"])
    robot, boxes = inst["robot"], inst["boxes"]
    domain = Box(boxes[robot, :, 0], boxes[robot, :, 1])
    return Problem(
        family=NAME,
        name=f"m{task['robots']}-o{task['obstacles']}-r{task['rep']}",
        seed=task["seed"],
        dim=2,
        data={
            "robot": robot,
            "boxes": boxes,
            "visibility": inst["visibility"],
            "environment": inst["environment"],
        },
        truth=inst["truth"],
        test=visibility_set_test(robot, boxes, inst["visibility"], inst["environment"]),
        domain=domain,
        eps=BOX_SIDE / RELATIVE,
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
