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
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from optbound.localization.environment import Environment
from optbound.localization.geometry import segments_meet_polygons
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
class Run:
    """One simulated run: the truth and what the robots measure."""

    env: Environment
    truth: np.ndarray  # (K + 1, m, 2) true positions
    boxes0: np.ndarray  # (m, 2, 2) initial boxes containing truth[0]
    distance: np.ndarray  # (2,) known interval of each step's travel
    headings: np.ndarray  # (K, m) compass readings
    visibility: np.ndarray  # (K, m, m) measurements y_il after each step


def environment(n_obstacles: int) -> Environment:
    """E⁻ ⊂ E ⊂ E⁺ made of the first ``n_obstacles`` designed obstacles (margin 5 cm)."""
    if not 0 <= n_obstacles <= len(OBSTACLES):
        raise ValueError(f"n_obstacles must be in [0, {len(OBSTACLES)}], got {n_obstacles}")
    return Environment.from_polygons(list(OBSTACLES[:n_obstacles]), MARGIN)


def _free(points: np.ndarray, obstacles) -> np.ndarray:
    """Points at least ``CLEARANCE`` (in the sup norm) inside the room and off the obstacles."""
    inside = np.all((points > CLEARANCE) & (points < SIZE - CLEARANCE), axis=1)
    boxes = np.stack([points - CLEARANCE, points + CLEARANCE], axis=-1)
    return inside & (segments_meet_polygons(boxes, boxes, obstacles) == 0)


def simulate(n_robots: int, n_obstacles: int, steps: int, seed: int) -> Run:
    """Seeded run of ``n_robots`` robots among the first ``n_obstacles`` obstacles."""
    if not 1 <= n_robots <= len(STARTS):
        raise ValueError(f"n_robots must be in [1, {len(STARTS)}], got {n_robots}")
    if steps < 0:
        raise ValueError(f"steps must be >= 0, got {steps}")
    env = environment(n_obstacles)
    rng = np.random.default_rng(seed)
    truth = np.empty((steps + 1, n_robots, 2))
    truth[0] = STARTS[:n_robots]
    theta = rng.uniform(-np.pi, np.pi, n_robots)
    true_heading = np.empty((steps, n_robots))
    for k in range(steps):
        theta = theta + rng.normal(0.0, TURN, n_robots)
        d = rng.uniform(STEP - STEP_ERROR, STEP + STEP_ERROR, n_robots)
        nxt = truth[k] + d[:, None] * np.column_stack([np.cos(theta), np.sin(theta)])
        for _ in range(50):  # blocked robots draw a new heading
            bad = ~_free(nxt, env.exact)
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
    noise = rng.uniform(-1.0, 1.0, (steps, n_robots)) * HEADING_ERROR * (1 - 1e-9)
    offset = rng.uniform(0.05, 0.95, (n_robots, 2))  # away from the edges: no rounding issue
    lo = truth[0] - offset
    boxes0 = np.stack([lo, lo + 1.0], axis=-1)
    vis = np.array([measure(truth[k + 1], env.exact) for k in range(steps)])
    vis = vis.reshape(steps, n_robots, n_robots)
    distance = np.array([STEP - STEP_ERROR, STEP + STEP_ERROR])
    return Run(env, truth, boxes0, distance, true_heading + noise, vis)


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
    "environment",
    "simulate",
]
