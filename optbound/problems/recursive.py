"""Family ``recursive``: a prior ellipsoid cut by a sequence of strips, ``E0 ∩ S_1 ∩ ... ∩ S_k``.

The instances of the benchmark family of the same name, with its seeds: a random prior
ellipsoid (condition number 10, dimension 2-4 in the quick suite, up to 6 in full), a true
point drawn in it, and up to 50 strips that all contain that point, each of normalised
width ``width`` [HS96, Sect. 4]. One problem per task and depth ``k`` of the benchmark: the
estimator gets ``data = {"prior": E0, "strips": (S_1, ..., S_k)}`` (to fuse in this order,
recursively or at once) and ``truth`` is the point. The true set is the intersection,
described once by the conjunction of the sets' interval tests; its reference ellipsoid is
the S-procedure SDP over all k strips at once (the benchmark's "batch SDP").
"""

from __future__ import annotations

import itertools

import numpy as np

from optbound.compare.tri import as_pseudo_ellipsoid, tri_test
from optbound.interval import tri_and
from optbound.problems._random import random_ellipsoid, strips_around, task_seeds
from optbound.problems.problem import Problem
from optbound.sets import Ellipsoid, Strip

NAME = "recursive"
PRIOR_COND = 10.0
# (dims, normalised strip widths, depths k, repetitions), as the benchmark family runs them.
SIZES = {
    "tiny": ((2,), (0.3,), (1, 3, 5), 1),
    "quick": ((2, 3, 4), (0.2, 1.0), (1, 2, 3, 5, 10, 20, 30, 40, 50), 4),
    "full": ((2, 3, 4, 5, 6), (0.2, 0.5, 1.0), tuple(range(1, 51)), 6),
}
#: Default paving resolution, as a fraction of the prior's widest extent (see ``strip``).
RELATIVE_EPS = {2: 1 / 128, 3: 1 / 32, 4: 1 / 12, 5: 1 / 8, 6: 1 / 6}


def tasks(suite: str, seed: int) -> list[dict]:
    """The instance cells of a suite: seed, dimension, strip width, depths, repetition."""
    if suite not in SIZES:
        raise ValueError(f"suite must be one of {tuple(SIZES)}, got {suite!r}")
    dims, widths, ks, reps = SIZES[suite]
    cells = list(itertools.product(dims, widths, range(reps)))
    return [
        {"seed": s, "dim": dim, "width": width, "ks": list(ks), "rep": rep}
        for s, (dim, width, rep) in zip(task_seeds(seed, NAME, len(cells)), cells, strict=True)
    ]


def instance(
    seed: int, dim: int, width: float, k: int
) -> tuple[Ellipsoid, np.ndarray, list[Strip]]:
    """Prior ellipsoid, true point and ``k`` strips of one instance, rebuilt from its seed."""
    rng = np.random.default_rng(seed)
    E0 = random_ellipsoid(rng, dim, PRIOR_COND)
    point = E0.sample(1, rng)[0]
    return E0, point, strips_around(rng, E0, point, k, width)


def problem(task: dict, k: int, E0: Ellipsoid, point: np.ndarray, strips: list[Strip]) -> Problem:
    """The :class:`Problem` of depth ``k`` of one task (the first ``k`` strips)."""
    sets = (E0, *strips[:k])
    tests = tuple(tri_test(S) for S in sets)

    def test(*coords):
        return tri_and(*(t(*coords) for t in tests))

    domain = as_pseudo_ellipsoid(E0).bounding_box()  # outward-rounded: contains E0
    return Problem(
        family=NAME,
        name=f"d{task['dim']}-w{task['width']:g}-k{k}-r{task['rep']}",
        seed=task["seed"],
        dim=E0.dim,
        data={"prior": E0, "strips": tuple(strips[:k])},
        truth=point.copy(),
        test=test,
        domain=domain,
        eps=float(np.max(domain.widths)) * RELATIVE_EPS[E0.dim],
        intersection=sets,
    )


def problems(suite: str, seed: int = 0) -> list[Problem]:
    """Every problem of the family in a suite, seeded like ``optbound bench``."""
    out = []
    for task in tasks(suite, seed):
        E0, point, strips = instance(task["seed"], task["dim"], task["width"], max(task["ks"]))
        out += [problem(task, k, E0, point, strips) for k in task["ks"]]
    return out
