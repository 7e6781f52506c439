"""Room scenarios for the sonar reproductions, and the "robot inside the room" prior.

The figures of [LJMW97, Fig. 4(a)] and [KJWM00, Sect. 6] are lost: the rooms and sonar
belts here are **our own designs**, consistent with the surviving text (a triangular room
and four sonars; a room with a belt of sonars), not reconstructions of the papers' figures.
"""

from __future__ import annotations

import numpy as np

from optbound.interval import constraint
from optbound.localization import geometry as g
from optbound.localization.sonar import Sonar


def polygon(vertices) -> np.ndarray:
    """Walls of a polygon given counter-clockwise: (s, 2, 2) segments facing its interior.

    Going counter-clockwise the interior is on the left, which is the reflecting face
    [KJWM00, eq. (2)].
    """
    v = np.asarray(vertices, dtype=float)
    return g.as_segments(np.stack([v, np.roll(v, -1, axis=0)], axis=1), "vertices")


#: Our triangle for [LJMW97, Sect. 4] (its Fig. 4(a) is lost), counter-clockwise [m].
TRIANGLE = polygon([[-6.0, 0.0], [3.0, 1.0], [-4.0, 7.0]])

#: q* of [LJMW97, Sect. 4]: (-2 m, 3 m, 0 deg).
TRIANGLE_POSE = (-2.0, 3.0, 0.0)


#: The sonars of [LJMW97, Sect. 4]: +-12 degree cones, 2 % relative accuracy.
HALF_APERTURE, REL_ACCURACY = np.deg2rad(12.0), 0.02


def triangle_sonars(half_aperture: float = HALF_APERTURE, rel_accuracy: float = REL_ACCURACY):
    """Four sonars on a 0.2 m radius belt pointing forward, left, backward and right (ours)."""
    return [
        Sonar((0.2 * np.cos(a), 0.2 * np.sin(a)), a, half_aperture, rel_accuracy)
        for a in np.deg2rad([0.0, 90.0, 180.0, -90.0])
    ]


#: A 10 m x 8 m room with one chamfered corner (ours, for [KJWM00]); convex, walls facing inward.
BELT_ROOM = polygon([[-5.0, -4.0], [5.0, -4.0], [5.0, 2.0], [3.0, 4.0], [-5.0, 4.0]])


def belt_sonars(
    n: int = 16,
    radius: float = 0.3,
    half_aperture: float = HALF_APERTURE,
    rel_accuracy: float = REL_ACCURACY,
):
    """``n`` sonars evenly spread on a circular belt, each pointing outward [KJWM00, Fig. 1]."""
    angles = 2 * np.pi * np.arange(n) / n
    return [
        Sonar((radius * np.cos(a), radius * np.sin(a)), a, half_aperture, rel_accuracy)
        for a in angles
    ]


def clearance_test(world, clearance: float):
    """Prior test: the robot's centre is inside a convex room, at least ``clearance`` from walls.

    For a convex room whose walls face inward this is ``front_distance >= clearance`` for
    every wall (:func:`geometry.front_distance`): prior knowledge of the robot's body
    [KJWM00, Sect. 2.2].
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
