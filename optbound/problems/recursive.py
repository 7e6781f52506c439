"""Family ``recursive``: a prior ellipsoid cut by a sequence of strips, ``E0 ∩ S_1 ∩ … ∩ S_k``.

The instances of the benchmark family of the same name, with its seeds: a random prior
ellipsoid (condition number 10, dimension 2-4 in the quick suite, up to 6 in full), a true
point drawn in it, and up to 50 strips that all contain that point, each of normalised
width ``width`` [HS96, Sect. 4]. One problem per task and depth ``k`` of the benchmark: the
estimator gets ``data = {"prior": E0, "strips": (S_1, ..., S_k)}`` (to fuse in this order,
recursively or at once) and ``truth`` is the point. The true set is the intersection,
described once by the conjunction of the sets' interval tests; its reference ellipsoid is
the S-procedure SDP over all k strips at once (the benchmark's "batch SDP").

References
----------
[HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
on an angle measurement technique", IFAC, 1996.
"""

from __future__ import annotations

import itertools

import numpy as np

from optbound.compare.tri import as_pseudo_ellipsoid, tri_test
from optbound.interval import Interval, tri_and
from optbound.problems.generators import random_ellipsoid, strips_around, task_seeds
from optbound.problems.problem import Problem
from optbound.sets import Box, Ellipsoid, Strip

NAME = "recursive"
PRIOR_COND = 10.0
# (dims, normalised strip widths, depths k, repetitions), as the benchmark family runs them.
SIZES = {
    "tiny": ((2,), (0.3,), (1, 3, 5), 1),
    "quick": ((2, 3, 4), (0.2, 1.0), (1, 2, 3, 5, 10, 20, 30, 40, 50), 4),
    "full": ((2, 3, 4, 5, 6), (0.2, 0.5, 1.0), tuple(range(1, 51)), 6),
}
#: Default paving resolution, as a fraction of the domain's widest extent (see ``strip``).
RELATIVE_EPS = {2: 1 / 128, 3: 1 / 32, 4: 1 / 12, 5: 1 / 8, 6: 1 / 6}


def tasks(suite: str, seed: int) -> list[dict]:
    """List the instance cells of a suite: seed, dimension, strip width, depths, repetition.

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
        One cell per problem sequence (one problem per depth of ``ks``), keys ``seed``,
        ``dim``, ``width``, ``ks`` (the depths) and ``rep``.

    Raises
    ------
    ValueError
        For an unknown ``suite``.
    """
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
    """Rebuild the prior ellipsoid, true point and ``k`` strips of one instance from its seed.

    Parameters
    ----------
    seed : int
        The instance seed (``np.random.default_rng(seed)``).
    dim : int
        The dimension.
    width : float
        Normalised strip width (:func:`~optbound.problems.generators.strips_around`).
    k : int
        The number of strips.

    Returns
    -------
    E0 : Ellipsoid
        The prior.
    point : np.ndarray, shape (dim,)
        The true state, drawn in ``E0``.
    strips : list of Strip
        ``k`` strips, each containing ``point``.
    """
    rng = np.random.default_rng(seed)
    E0 = random_ellipsoid(rng, dim, PRIOR_COND)
    point = E0.sample(1, rng)[0]
    return E0, point, strips_around(rng, E0, point, k, width)


def domain_boxes(E0: Ellipsoid, strips: list[Strip], ks: list[int]) -> list[Box]:
    """Bound ``E0 ∩ S_1 ∩ ... ∩ S_k`` by a proven box, for each depth ``k`` of ``ks``.

    ``E0``'s box contracted by one pass over the strips in order, the box of a depth carried
    to the next (see Notes).

    Parameters
    ----------
    E0 : Ellipsoid
        The prior.
    strips : list of Strip
        The measurement sequence.
    ks : list of int
        Increasing depths, each at most ``len(strips)``.

    Returns
    -------
    list of Box
        One box per depth, each proven to contain the intersection of ``E0`` and the first
        ``k`` strips.

    Notes
    -----
    Each strip ``|a^T x - b| <= 1`` contracts the box ``X`` coordinate by coordinate: for
    every ``i`` with ``a_i != 0``::

        x_i ∈ X_i ∩ (b + [-1, 1] - sum_{j != i} a_j X_j) / a_i

    in outward-rounded interval arithmetic (forward-backward propagation, all coordinates at
    once from the same ``X``).
    """
    prior = as_pseudo_ellipsoid(E0).bounding_box()  # outward-rounded: contains E0
    X, n, done, out = Interval(prior.lo, prior.hi), E0.dim, 0, []
    for k in ks:
        for S in strips[done:k]:
            rest = Interval(S.b) + Interval(-1.0, 1.0)
            for j in range(n):
                others = np.where(np.arange(n) == j, 0.0, S.a[j])  # a_j, except in row j
                rest = rest - Interval(others) * X[j]
            cut = S.a != 0.0
            solved = rest[cut] / Interval(S.a[cut])
            lo, hi = X.lo.copy(), X.hi.copy()
            lo[cut], hi[cut] = np.maximum(lo[cut], solved.lo), np.minimum(hi[cut], solved.hi)
            X = Interval(lo, hi)
        done = max(done, k)
        out.append(Box(np.asarray(X.lo, dtype=float), np.asarray(X.hi, dtype=float)))
    return out


def problem(
    task: dict, k: int, E0: Ellipsoid, point: np.ndarray, strips: list[Strip], domain: Box
) -> Problem:
    """Build the :class:`Problem` of depth ``k`` of one task: ``E0`` and the first ``k`` strips.

    Parameters
    ----------
    task : dict
        A cell of :func:`tasks`.
    k : int
        The depth: how many of ``strips`` the problem has.
    E0 : Ellipsoid
        The prior, from :func:`instance`.
    point : np.ndarray
        The true state, from :func:`instance`.
    strips : list of Strip
        The task's strips, from :func:`instance` (at least ``k``).
    domain : Box
        A box proven to contain the true set, from :func:`domain_boxes`: where it is paved.

    Returns
    -------
    Problem
        The problem of depth ``k``.
    """
    sets = (E0, *strips[:k])
    tests = tuple(tri_test(S) for S in sets)

    def test(*coords):
        return tri_and(*(t(*coords) for t in tests))

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
        One problem per cell of :func:`tasks`, one per depth of its ``ks``.

    Raises
    ------
    ValueError
        For an unknown ``suite``.
    """
    out = []
    for task in tasks(suite, seed):
        E0, point, strips = instance(task["seed"], task["dim"], task["width"], max(task["ks"]))
        boxes = domain_boxes(E0, strips, task["ks"])
        out += [
            problem(task, k, E0, point, strips, box)
            for k, box in zip(task["ks"], boxes, strict=True)
        ]
    return out
