"""The relative-bearing geometry of [BH, Sect. V] and seeded random instances like it.

[BH, Sect. V]: vehicle at ``[0, 0]``, landmarks ``L1 = [0, 1]``, ``L2 = [1, 1]``,
``L3 = [-1, 0]``, relative bearings of the pairs (3, 1), (1, 2), (2, 3) (noise-free values
90°, 45°, -135°). The noise bound eps = 4° is the value of [BH, Fig. 1]; Sect. V does not
restate it. The paper's figures are lost, so nothing beyond these numbers is reproduced.
:func:`random_instance` is **our design**: random landmark triples and vehicles with the
same pairs, for sweeps. The model they feed is :mod:`optbound.localization.relative_bearing`.

References
----------
[BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
bearing measurements", IEEE Transactions on Robotics and Automation, 2004.
"""

from __future__ import annotations

import numpy as np

from optbound.localization.geometry import wrap_angle
from optbound.localization.relative_bearing import bearings

#: Landmarks ``L1, L2, L3`` of [BH, Sect. V] (0-based rows).
LANDMARKS = np.array([[0.0, 1.0], [1.0, 1.0], [-1.0, 0.0]])
#: The vehicle's true position [BH, Sect. V].
VEHICLE = np.zeros(2)
#: The measured pairs of [BH, Sect. V]: (3, 1), (1, 2), (2, 3) in the paper's 1-based names.
PAIRS = ((2, 0), (0, 1), (1, 2))
#: Noise bound in degrees ([BH, Fig. 1]; not restated in Sect. V).
EPS_DEG = 4.0


def sect5_instance() -> tuple[np.ndarray, list, np.ndarray, float, np.ndarray]:
    """Build the noise-free instance of [BH, Sect. V].

    Returns
    -------
    landmarks : np.ndarray, shape (3, 2)
        :data:`LANDMARKS`.
    pairs : list of tuple of int
        :data:`PAIRS` (0-based landmark indices).
    gammas : np.ndarray, shape (3,)
        The noise-free relative bearings of the pairs [rad] (90°, 45°, -135°).
    eps : float
        The noise bound [rad] (:data:`EPS_DEG`).
    vehicle : np.ndarray, shape (2,)
        :data:`VEHICLE`.

    References
    ----------
    [BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
    bearing measurements", IEEE Transactions on Robotics and Automation, 2004.

    Examples
    --------
    >>> import numpy as np
    >>> from optbound.scenarios import bh_geometry
    >>> landmarks, pairs, gammas, eps, vehicle = bh_geometry.sect5_instance()
    >>> np.degrees(gammas).round(6).tolist()
    [90.0, 45.0, -135.0]
    """
    gammas = bearings(VEHICLE, LANDMARKS, PAIRS)
    return LANDMARKS.copy(), list(PAIRS), gammas, float(np.radians(EPS_DEG)), VEHICLE.copy()


def random_instance(
    rng: np.random.Generator, pairs=PAIRS
) -> tuple[np.ndarray, list, np.ndarray, float, np.ndarray]:
    """Draw a random landmark triple and vehicle, eps in [1°, 8°], noise uniform in [-eps, eps].

    Geometries are redrawn until every measured bearing is a crescent with some margin
    (``eps + 3° < |gamma| < 180° - eps - 3°``) and no landmark is within 0.3 of another or of
    the vehicle: the rings of [BH, Sect. IV] need the crescent shape.

    Parameters
    ----------
    rng : np.random.Generator
        The instance's generator.
    pairs : sequence of (int, int), default PAIRS
        The measured landmark pairs (0-based indices into the triple).

    Returns
    -------
    landmarks : np.ndarray, shape (3, 2)
        Landmarks uniform in ``[-3, 3]^2``.
    pairs : list of tuple of int
        ``pairs``, as tuples.
    gammas : np.ndarray, shape (len(pairs),)
        The measured relative bearings [rad], wrapped to ``(-pi, pi]``.
    eps : float
        The noise bound [rad].
    vehicle : np.ndarray, shape (2,)
        The vehicle, uniform in ``[-1, 1]^2``.

    References
    ----------
    [BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
    bearing measurements", IEEE Transactions on Robotics and Automation, 2004.
    """
    pairs = [tuple(p) for p in pairs]
    margin = np.radians(3.0)
    while True:
        L = rng.uniform(-3.0, 3.0, (3, 2))
        x = rng.uniform(-1.0, 1.0, 2)
        eps = np.radians(rng.uniform(1.0, 8.0))
        gam = bearings(x, L, pairs) + rng.uniform(-eps, eps, len(pairs))
        dists = [np.linalg.norm(L[i] - L[j]) for i, j in pairs] + list(
            np.linalg.norm(L - x, axis=1)
        )
        if min(dists) > 0.3 and np.all(
            (np.abs(gam) > eps + margin) & (np.abs(gam) < np.pi - eps - margin)
        ):
            return L, pairs, wrap_angle(gam), eps, x


__all__ = [
    "EPS_DEG",
    "LANDMARKS",
    "PAIRS",
    "VEHICLE",
    "random_instance",
    "sect5_instance",
]
