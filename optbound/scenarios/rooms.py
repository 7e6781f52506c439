"""Room scenarios for the sonar reproductions [LJMW97, Sect. 4], [KJWM00, Sect. 6].

The figures of [LJMW97, Fig. 4(a)] and [KJWM00, Sect. 6] are lost: the rooms and sonar
belts here are **our own designs**, consistent with the surviving text (a triangular room
and four sonars; a room with a belt of sonars), not reconstructions of the papers' figures.
The model they feed is :mod:`optbound.localization.sonar` (which also holds the wall builder
:func:`~optbound.localization.sonar.polygon_walls` and the "robot inside the room" prior
:func:`~optbound.localization.sonar.clearance_test`).

References
----------
[LJMW97] O. Lévêque, L. Jaulin, D. Meizel, E. Walter, "Vehicle localization from
inaccurate telemetric data: a set inversion approach", IFAC SYROCO, 1997.
[KJWM00] M. Kieffer, L. Jaulin, E. Walter, D. Meizel, "Robust autonomous robot
localization using interval analysis", Reliable Computing, 2000.
"""

from __future__ import annotations

import numpy as np

from optbound.localization.sonar import Sonar, polygon_walls

#: Our triangle for [LJMW97, Sect. 4] (its Fig. 4(a) is lost), counter-clockwise [m].
TRIANGLE = polygon_walls([[-6.0, 0.0], [3.0, 1.0], [-4.0, 7.0]])

#: q* of [LJMW97, Sect. 4]: (-2 m, 3 m, 0 deg).
TRIANGLE_POSE = (-2.0, 3.0, 0.0)


#: The sonars of [LJMW97, Sect. 4]: +-12 degree cones, 2 % relative accuracy.
HALF_APERTURE, REL_ACCURACY = np.deg2rad(12.0), 0.02


def triangle_sonars(
    half_aperture: float = HALF_APERTURE, rel_accuracy: float = REL_ACCURACY
) -> list[Sonar]:
    """Build four sonars on a 0.2 m radius belt pointing forward, left, backward and right (ours).

    Parameters
    ----------
    half_aperture : float, default HALF_APERTURE
        Half-angle of each sonar's emission cone [rad] (12° [LJMW97, Sect. 4]).
    rel_accuracy : float, default REL_ACCURACY
        Relative range accuracy (2 % [LJMW97, Sect. 4]).

    Returns
    -------
    list of Sonar
        The four sonars, in the robot's frame.

    References
    ----------
    [LJMW97] O. Lévêque, L. Jaulin, D. Meizel, E. Walter, "Vehicle localization from
    inaccurate telemetric data: a set inversion approach", IFAC SYROCO, 1997.
    """
    return [
        Sonar((0.2 * np.cos(a), 0.2 * np.sin(a)), a, half_aperture, rel_accuracy)
        for a in np.deg2rad([0.0, 90.0, 180.0, -90.0])
    ]


#: A 10 m x 8 m room with one chamfered corner (ours, for [KJWM00]); convex, walls facing inward.
BELT_ROOM = polygon_walls([[-5.0, -4.0], [5.0, -4.0], [5.0, 2.0], [3.0, 4.0], [-5.0, 4.0]])


def belt_sonars(
    n: int = 16,
    radius: float = 0.3,
    half_aperture: float = HALF_APERTURE,
    rel_accuracy: float = REL_ACCURACY,
) -> list[Sonar]:
    """Build ``n`` sonars evenly spread on a circular belt, each pointing outward [KJWM00, Fig. 1].

    Parameters
    ----------
    n : int, default 16
        The number of sonars; the first points forward.
    radius : float, default 0.3
        The belt's radius [m].
    half_aperture : float, default HALF_APERTURE
        Half-angle of each sonar's emission cone [rad].
    rel_accuracy : float, default REL_ACCURACY
        Relative range accuracy.

    Returns
    -------
    list of Sonar
        The sonars, in the robot's frame.

    References
    ----------
    [KJWM00] M. Kieffer, L. Jaulin, E. Walter, D. Meizel, "Robust autonomous robot
    localization using interval analysis", Reliable Computing, 2000.
    """
    angles = 2 * np.pi * np.arange(n) / n
    return [
        Sonar((radius * np.cos(a), radius * np.sin(a)), a, half_aperture, rel_accuracy)
        for a in angles
    ]


__all__ = [
    "BELT_ROOM",
    "HALF_APERTURE",
    "REL_ACCURACY",
    "TRIANGLE",
    "TRIANGLE_POSE",
    "belt_sonars",
    "triangle_sonars",
]
