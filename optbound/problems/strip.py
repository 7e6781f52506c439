"""Family ``strip``: an ellipsoid cut by a strip, ``E ∩ S`` [HS96, Sect. 4].

The instances of the benchmark family of the same name, with its seeds: a random ellipsoid
(dimension 2-6, condition number 1-1e6) cut by a strip that is narrow, wide, off-centre or
partial (only one plane cuts: in effect a half-space) [HS96, Sect. 4]. The estimator gets
``data = {"ellipsoid": E, "strip": S}``: the prior set and the measurement. The true set is
``E ∩ S``, described once by the conjunction of the two sets' interval tests; its volume
has a closed form (:func:`~optbound.compare.size.ellipsoid_strip_volume_bracket`).

References
----------
[HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
on an angle measurement technique", IFAC, 1996.
"""

from __future__ import annotations

import itertools
from functools import partial

import numpy as np

from optbound.compare.size import ellipsoid_strip_volume_bracket
from optbound.compare.tri import as_pseudo_ellipsoid, tri_test
from optbound.interval import tri_and
from optbound.problems.generators import STRIP_KINDS, random_ellipsoid, random_strip, task_seeds
from optbound.problems.problem import Problem
from optbound.sets import Ellipsoid, Strip

NAME = "strip"
# (dims, condition numbers, repetitions per cell), as the benchmark family runs them.
SIZES = {
    "tiny": ((2,), (10.0,), 1),
    "quick": ((2, 3, 4, 5, 6), (1.0, 10.0, 1e2, 1e4, 1e6), 3),
    "full": ((2, 3, 4, 5, 6), (1.0, 10.0, 1e2, 1e3, 1e4, 1e5, 1e6), 10),
}
#: Default paving resolution of the exact set, as a fraction of the prior's widest extent:
#: finer in low dimension, where it is cheap (the box count grows like eps^-(n-1)).
RELATIVE_EPS = {2: 1 / 128, 3: 1 / 32, 4: 1 / 12, 5: 1 / 8, 6: 1 / 6}


def tasks(suite: str, seed: int) -> list[dict]:
    """List the instance cells of a suite: seed, dimension, condition, strip kind, repetition.

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
        One cell per problem, keys ``seed``, ``dim``, ``cond``, ``kind`` and ``rep``.

    Raises
    ------
    ValueError
        For an unknown ``suite``.
    """
    if suite not in SIZES:
        raise ValueError(f"suite must be one of {tuple(SIZES)}, got {suite!r}")
    dims, conds, reps = SIZES[suite]
    cells = list(itertools.product(dims, conds, STRIP_KINDS, range(reps)))
    return [
        {"seed": s, "dim": dim, "cond": cond, "kind": kind, "rep": rep}
        for s, (dim, cond, kind, rep) in zip(task_seeds(seed, NAME, len(cells)), cells, strict=True)
    ]


def instance(seed: int, dim: int, cond: float, kind: str) -> tuple[Ellipsoid, Strip]:
    """Rebuild the ellipsoid and strip of one instance from its seed.

    Parameters
    ----------
    seed : int
        The instance seed (``np.random.default_rng(seed)``).
    dim : int
        The dimension.
    cond : float
        Condition number of the ellipsoid's shape matrix.
    kind : {"narrow", "wide", "off-centre", "partial"}
        Where the strip cuts (:func:`~optbound.problems.generators.strip_bounds`).

    Returns
    -------
    E : Ellipsoid
        The prior.
    S : Strip
        The measurement.
    """
    rng = np.random.default_rng(seed)
    E = random_ellipsoid(rng, dim, cond)
    return E, random_strip(rng, E, kind)


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
    E, S = instance(task["seed"], task["dim"], task["cond"], task["kind"])
    tests = (tri_test(E), tri_test(S))

    def test(*coords):
        return tri_and(*(t(*coords) for t in tests))

    domain = as_pseudo_ellipsoid(E).bounding_box()  # outward-rounded: contains E, hence E ∩ S
    return Problem(
        family=NAME,
        name=f"{task['kind']}-d{task['dim']}-c{task['cond']:g}-r{task['rep']}",
        seed=task["seed"],
        dim=E.dim,
        data={"ellipsoid": E, "strip": S},
        truth=None,
        test=test,
        domain=domain,
        eps=float(np.max(domain.widths)) * RELATIVE_EPS[E.dim],
        intersection=(E, S),
        volume=partial(ellipsoid_strip_volume_bracket, E, S),
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
