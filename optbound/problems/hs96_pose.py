"""Family ``hs96_pose``: a robot's pose ``(x, y, psi)`` from one scan of landmark bearings [HS96].

Our design on the office world of the HS96 reproduction (:mod:`optbound.scenarios.office`,
22 landmarks with error ellipses along the walls): a pose drawn uniformly along the course,
``count`` landmarks drawn among those in sight, and their bearings relative to the heading,
measured to a landmark drawn in its error ellipse, with a uniform error within
``delta_alpha`` [HS96, eqs. (1)-(2)]. The estimator gets ``data = {"landmarks": (N, 2),
"landmark_shapes": (N, 2, 2), "alphas": (N,), "delta_alpha": float}`` (nominal landmarks,
their error ellipses ``{L + e : e^T C^{-1} e <= 1}``, bearings, error bound) and ``truth`` is
the pose (its heading taken within pi of the domain's centre).

The true set is the exact error propagation of [HS96, Sect. 3]: the poses for which every
bearing is consistent with some landmark in its ellipse and some error within
``delta_alpha``. It is described once by the interval test that
:func:`optbound.localization.landmarks.pose_paving` paves (``landmarks.pose_test``); its
domain is the hull of that paving's adaptive refinement from the office box times every
heading (guaranteed, and defined also where HS96's linear position bound is not), paved at
1/RELATIVE of the hull's widest side.

References
----------
[HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
on an angle measurement technique", IFAC, 1996.
"""

from __future__ import annotations

import math

import numpy as np

from optbound.localization.landmarks import pose_paving, pose_test
from optbound.problems.generators import task_seeds
from optbound.problems.problem import Problem
from optbound.scenarios import office

NAME = "hs96_pose"
# Per suite: (landmarks per scan, bearing error bounds in degrees, repetitions).
SIZES = {
    "tiny": ((6,), (math.degrees(office.DELTA_ALPHA),), 1),
    "quick": ((3, 5), (math.degrees(office.DELTA_ALPHA), 0.5), 2),
    "full": ((3, 4, 6, 8), (math.degrees(office.DELTA_ALPHA), 0.2, 1.0), 4),
}
#: The initial box of the domain's refinement: the office and every heading.
ROOM = np.array([[0.0, office.ROOM[0]], [0.0, office.ROOM[1]], [-np.pi, np.pi]])
#: Paving resolution: 1/RELATIVE of the domain's widest side (as ``pose_paving`` refines).
RELATIVE = 120


def tasks(suite: str, seed: int) -> list[dict]:
    """List the instance cells of a suite: seed, landmark count, error bound (degrees), repetition.

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
        One cell per problem, keys ``seed``, ``count`` (landmarks), ``delta_deg`` and ``rep``.

    Raises
    ------
    ValueError
        For an unknown ``suite``.
    """
    if suite not in SIZES:
        raise ValueError(f"suite must be one of {tuple(SIZES)}, got {suite!r}")
    counts, deltas, reps = SIZES[suite]
    cells = [(n, d, r) for n in counts for d in deltas for r in range(reps)]
    return [
        {"seed": s, "count": n, "delta_deg": d, "rep": r}
        for s, (n, d, r) in zip(task_seeds(seed, NAME, len(cells)), cells, strict=True)
    ]


def instance(seed: int, count: int, delta_alpha: float) -> dict:
    """Rebuild the landmarks, shapes, bearings and true pose of one instance from its seed.

    Parameters
    ----------
    seed : int
        The instance seed (``np.random.default_rng(seed)``).
    count : int
        Landmarks in the scan, drawn among those in sight (at most their number).
    delta_alpha : float
        The bearing error bound [rad] [HS96, eq. (2)].

    Returns
    -------
    dict
        ``"landmarks"`` (count, 2), ``"landmark_shapes"`` (count, 2, 2), ``"alphas"``
        (count,) in [0, 2 pi) and ``"truth"``, the pose (x, y, psi).

    References
    ----------
    [HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
    on an angle measurement technique", IFAC, 1996.
    """
    rng = np.random.default_rng(seed)
    omap = office.office_map()
    pose = office.course_pose(rng.uniform(0.0, office.lap_length()))[0]
    seen = np.flatnonzero(omap.visible(pose[0], pose[1]))
    keep = np.sort(rng.choice(seen, count, replace=False))
    L, C = omap.landmarks[keep], omap.shapes[keep]
    # A true landmark uniform in its ellipse: L + chol(C) u with u uniform in the unit disc.
    u = rng.standard_normal((count, 2))
    u *= (np.sqrt(rng.uniform(size=count)) / np.linalg.norm(u, axis=1))[:, None]
    true_L = L + np.einsum("kij,kj->ki", np.linalg.cholesky(C), u)
    alphas = np.arctan2(true_L[:, 1] - pose[1], true_L[:, 0] - pose[0]) - pose[2]
    alphas += rng.uniform(-1.0, 1.0, count) * delta_alpha * (1 - 1e-9)
    alphas = np.mod(alphas, 2 * np.pi)
    return {"landmarks": L, "landmark_shapes": C, "alphas": alphas, "truth": pose}


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
    delta = math.radians(task["delta_deg"])
    inst = instance(task["seed"], task["count"], delta)
    L, C, alphas = inst["landmarks"], inst["landmark_shapes"], inst["alphas"]
    domain = pose_paving(L, alphas, delta, C, X0=ROOM).hull()
    test = pose_test(L, alphas, delta, C, (domain.lo[2], domain.hi[2]))
    truth = inst["truth"].copy()
    truth[2] -= 2 * np.pi * round((truth[2] - domain.center[2]) / (2 * np.pi))
    return Problem(
        family=NAME,
        name=f"n{task['count']}-delta{task['delta_deg']:g}-r{task['rep']}",
        seed=task["seed"],
        dim=3,
        data={"landmarks": L, "landmark_shapes": C, "alphas": alphas, "delta_alpha": delta},
        truth=truth,
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
