"""Family ``bh_bearings``: planar position from relative bearings of landmark pairs [BH, Sect. II].

The instances of the benchmark's localization family, with its seeds: the geometry of
[BH, Sect. V] (landmarks ``[0, 1]``, ``[1, 1]``, ``[-1, 0]``, vehicle at the origin, pairs
(3, 1), (1, 2), (2, 3), noise-free bearings, eps = 4°) and seeded random landmark triples and
vehicles (:func:`optbound.scenarios.bh_geometry.random_instance`). The estimator gets
``data = {"landmarks": (N, 2), "pairs": (P, 2), "gammas": (P,), "eps": (P,)}`` (the
relative bearings ``gamma_k`` of the pairs, each within ``eps_k`` of the true one) and
``truth`` is the vehicle's position.

The true set is described once by the model's own interval test,
:func:`optbound.localization.relative_bearing.exact_test` (the angle constraints of
[BH, eq. (2)], the test ``exact_paving`` paves). Its domain and resolution are the
benchmark's: a coarse paving of the prior box (1/40 of its widest side) gives a hull proven
to contain the set, paved at 1/``relative`` of the hull's widest side. The reference ellipse
is the benchmark's: the smaller of the rings' S-procedure SDP and the MVEE of the exact
paving's boxes (``relative_bearing.best_ellipse``, both certified).

References
----------
[BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
bearing measurements", IEEE Transactions on Robotics and Automation, 2004.
"""

from __future__ import annotations

import numpy as np

from optbound.interval import pave
from optbound.localization import relative_bearing as rb
from optbound.problems.generators import task_seeds
from optbound.problems.problem import Problem
from optbound.scenarios import bh_geometry as bh
from optbound.sets import Ellipsoid

NAME = "bh_bearings"
#: The benchmark family whose instances these are (its name enters the instance seeds).
BENCH_NAME = "localization"
# (random instances, paving width relative to the hull) per suite, as the benchmark runs them.
SIZES = {"tiny": (0, 40), "quick": (2, 40), "full": (12, 100)}
#: The coarse paving that finds the domain: 1/COARSE of the prior box's widest side.
COARSE = 40


def tasks(suite: str, seed: int) -> list[dict]:
    """List the instance cells of a suite: the [BH, Sect. V] geometry, then the random ones.

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
        One cell per problem, keys ``seed``, ``variant`` ("BH geometry" or "random"),
        ``relative`` (the paving's resolution, 1/``relative`` of the domain's widest side)
        and ``index``.

    Raises
    ------
    ValueError
        For an unknown ``suite``.

    References
    ----------
    [BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
    bearing measurements", IEEE Transactions on Robotics and Automation, 2004.
    """
    if suite not in SIZES:
        raise ValueError(f"suite must be one of {tuple(SIZES)}, got {suite!r}")
    count, relative = SIZES[suite]
    seeds = task_seeds(seed, BENCH_NAME, count + 1)
    variants = ["BH geometry"] + ["random"] * count
    return [
        {"seed": s, "variant": variant, "relative": relative, "index": i}
        for i, (s, variant) in enumerate(zip(seeds, variants, strict=True))
    ]


def instance(seed: int, variant: str) -> tuple[np.ndarray, list, np.ndarray, float, np.ndarray]:
    """Rebuild the measurements and vehicle position of one instance from its seed.

    Parameters
    ----------
    seed : int
        The instance seed, unused for the BH geometry (``np.random.default_rng(seed)``).
    variant : {"BH geometry", "random"}
        The geometry of [BH, Sect. V], or a random one
        (:func:`~optbound.scenarios.bh_geometry.random_instance`).

    Returns
    -------
    tuple
        ``(landmarks, pairs, gammas, eps, truth)``: landmarks (N, 2), landmark pairs,
        relative bearings (P,), their error bounds and the vehicle's position (2,).

    References
    ----------
    [BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
    bearing measurements", IEEE Transactions on Robotics and Automation, 2004.
    """
    if variant == "BH geometry":
        return bh.sect5_instance()
    return bh.random_instance(np.random.default_rng(seed))


def _best_ellipse(p: Problem) -> Ellipsoid:
    return rb.best_ellipse(p.data["measurements"], p.exact()).best


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
    landmarks, pairs, gammas, eps, truth = instance(task["seed"], task["variant"])
    data = rb.measurements(landmarks, pairs, gammas, eps)
    test = rb.exact_test(data)
    box = rb.prior_box(data)
    domain = pave(test, box, float(np.max(box.widths)) / COARSE).hull()
    return Problem(
        family=NAME,
        name="bh-sect5" if task["variant"] == "BH geometry" else f"random-{task['index']}",
        seed=task["seed"],
        dim=2,
        data={
            "landmarks": data.landmarks,
            "pairs": data.pairs,
            "gammas": data.gammas,
            "eps": data.eps,
            "measurements": data,
        },
        truth=np.asarray(truth, dtype=float),
        test=test,
        domain=domain,
        eps=float(np.max(domain.widths)) / task["relative"],
        optimal=_best_ellipse,
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
