"""Family ``linear_estimation``: the exact set ``X_k`` of a 2-D linear system at one step.

A problem is one step ``k`` of a run of ``x_{k+1} = A x_k + w_k``, ``y_k = C x_k + v_k``
(``optbound.estimation``, issue 21): Alamo, Bravo & Camacho's example [ABC05, Sect. 7.1]
(``optbound.scenarios.alamo2005``, no simulated state) and seeded random stable systems with
box noise (``optbound.scenarios.linear_systems.random_system``). The estimator gets
``data = {"system": LinearSystem, "X0": Box, "ys": ys[:k]}`` and must bound ``X_k``; ``truth``
is the simulated ``x_k`` (None for Alamo's example).

The true set is described once, by the exact rational polygon of ``X_k``
(:func:`optbound.estimation.exact_polygon.exact_polygons`: every float of the data read as the
rational it is, no rounding): a box is TRUE when every corner satisfies every edge's
half-plane, FALSE when the whole box violates one, decided exactly (a float filter with a
proven margin, ``Fraction`` arithmetic near an edge). Only
2-D systems for now: the exact polygon is 2-D (higher dimensions would need a certified
H-representation of the constrained zonotope ``X_k``).

References: ``"optimal_ellipsoid"`` is the MVEE (:func:`optbound.optimal.mvee`) of the exact
polygon's vertices rounded to floats (the polygon is at hand, so no LP vertex search of the
constrained zonotope ``X_k`` is needed: that search is one LP per vertex); ``"best_box"``
the hull of the exact paving, which here is the exact polygon's interval hull rounded outward
to floats (:func:`outward_hull`, the paving's domain): tighter than, and as certain as, the LP hull
``references.interval_hull``.
"""

from __future__ import annotations

import numpy as np

from optbound._core import Box
from optbound.estimation.exact_polygon import Point, exact_polygons
from optbound.problems.generators import task_seeds
from optbound.problems.problem import Problem
from optbound.scenarios import alamo2005
from optbound.scenarios.linear_systems import random_system
from optbound.sets.constrained_zonotope_polygon import polygon_box_test, round_down, round_up

NAME = "linear_estimation"
# (steps k of Alamo's example, steps k of the random systems, random systems per k).
SIZES = {
    "tiny": ((5,), (10,), 1),
    "quick": ((5, 10, 20), (5, 10, 20), 2),
    "full": ((2, 5, 10, 15, 20), (5, 10, 20, 30), 5),
}
#: Default paving resolution, as a fraction of the exact set's widest extent.
RELATIVE_EPS = 1 / 128


def tasks(suite: str, seed: int) -> list[dict]:
    """List the instance cells of a suite: Alamo's example per step, then random systems.

    Alamo's cells carry the seed of their position (the data are fixed; the seed only names
    the cell), the random systems their own instance seed.

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
        One cell per problem, keys ``seed``, ``system`` ("alamo" or "random"), ``k`` (the
        step) and ``rep``.

    Raises
    ------
    ValueError
        For an unknown ``suite``.
    """
    if suite not in SIZES:
        raise ValueError(f"suite must be one of {tuple(SIZES)}, got {suite!r}")
    alamo_steps, random_steps, reps = SIZES[suite]
    cells = [("alamo", k, 0) for k in alamo_steps] + [
        ("random", k, rep) for k in random_steps for rep in range(reps)
    ]
    return [
        {"seed": s, "system": name, "k": k, "rep": rep}
        for s, (name, k, rep) in zip(task_seeds(seed, NAME, len(cells)), cells, strict=True)
    ]


def instance(system: str, seed: int, k: int) -> tuple[dict, np.ndarray | None]:
    """Build the estimator's data of one instance and the simulated state.

    Parameters
    ----------
    system : {"alamo", "random"}
        Alamo's example (:mod:`optbound.scenarios.alamo2005`) or a random 2-D system
        (:func:`~optbound.scenarios.linear_systems.random_system`).
    seed : int
        The instance seed (unused for Alamo's example).
    k : int
        The number of steps (measurements).

    Returns
    -------
    data : dict
        ``"system"``, ``"X0"`` and ``"ys"`` (the first ``k`` measurements).
    truth : np.ndarray or None
        The simulated state ``x_k``; None for Alamo's example (no recorded states).

    Raises
    ------
    ValueError
        For an unknown ``system``.
    """
    if system == "alamo":
        data = {"system": alamo2005.system(), "X0": alamo2005.X0, "ys": alamo2005.MEASUREMENTS[:k]}
        return data, None
    if system == "random":
        run = random_system(2, seed, "box", steps=k)
        return {"system": run.system, "X0": run.X0, "ys": run.ys}, run.states[-1]
    raise ValueError(f"system must be 'alamo' or 'random', got {system!r}")


def polygon_test(P: list[Point]):
    """Build the exact three-valued box test of the convex polygon ``P`` (module docstring).

    Parameters
    ----------
    P : list of Point
        The rational vertices of a convex polygon, at least 3.

    Returns
    -------
    callable
        The ``test(x, y) -> Tri array`` of a Problem, on ``Interval`` coordinates
        (``constrained_zonotope_polygon.polygon_box_test``).

    Raises
    ------
    ValueError
        If ``P`` has fewer than 3 vertices (the exact set is flat or empty).
    """
    if len(P) < 3:
        raise ValueError("the exact set is flat or empty: it has no polygon test")
    boxes = polygon_box_test(P)

    def test(x, y) -> np.ndarray:
        shape = np.broadcast(x.lo, y.lo).shape
        B = np.stack(
            [
                np.stack(
                    [np.broadcast_to(x.lo, shape).ravel(), np.broadcast_to(x.hi, shape).ravel()], 1
                ),
                np.stack(
                    [np.broadcast_to(y.lo, shape).ravel(), np.broadcast_to(y.hi, shape).ravel()], 1
                ),
            ],
            axis=1,
        )
        return boxes(B).reshape(shape)

    return test


def outward_hull(P: list[Point]) -> Box:
    """Bound the rational polygon ``P`` by a float box, its bounds rounded outward.

    Parameters
    ----------
    P : list of Point
        Rational vertices (``Fraction`` coordinates).

    Returns
    -------
    Box
        The smallest float box proven to contain ``P``.
    """
    xs, ys = [p[0] for p in P], [p[1] for p in P]
    return Box([round_down(min(xs)), round_down(min(ys))], [round_up(max(xs)), round_up(max(ys))])


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
    data, truth = instance(task["system"], task["seed"], task["k"])
    P = exact_polygons(data["system"], data["X0"], data["ys"])[-1]
    domain = outward_hull(P)

    def optimal_ellipsoid(_):
        from optbound import optimal  # cvxpy: loaded when a reference is asked for

        return optimal.mvee(np.array(P, dtype=float)).ellipsoid

    suffix = "" if task["system"] == "alamo" else f"-r{task['rep']}"
    return Problem(
        family=NAME,
        name=f"{task['system']}-k{task['k']}{suffix}",
        seed=task["seed"],
        dim=2,
        data=data,
        truth=truth,
        test=polygon_test(P),
        domain=domain,
        eps=float(np.max(domain.widths)) * RELATIVE_EPS,
        optimal=optimal_ellipsoid,
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
