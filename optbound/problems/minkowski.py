"""Family ``minkowski``: the Minkowski sum ``E1 ⊕ E2`` of two ellipsoids [HS96, eqs. (10)-(17)].

The instances of the benchmark family of the same name, with its seeds: two random ellipsoids
(dimension 2-6, condition numbers up to 1e6) whose sizes differ by a factor 1, 1e-1 or 1e-3
(a large prior plus a small odometry error, say). The estimator gets
``data = {"summands": (E1, E2)}``; the true set is their Minkowski sum.

The true set has no closed-form membership test, so it is described once by
:func:`sum_test`, a three-valued interval test on boxes built from two exact facts:

- **FALSE** (support function): ``x ∈ E1 ⊕ E2`` implies
  ``d^T (x - c1 - c2) <= sqrt(d^T C1 d) + sqrt(d^T C2 d)`` for every direction ``d``; a box
  on which one direction violates this (evaluated in outward-rounded interval arithmetic) is
  outside;
- **TRUE** (certified decomposition): a box ``B`` with centre ``m`` is inside when, for a
  point ``y`` and a share ``a ∈ [0, 1]``, the box ``Y = y + a (B - m)`` is proven in ``E1``
  and ``Z = (m - y) + (1 - a)(B - m)`` in ``E2`` (the ellipsoids' own interval tests), since
  every ``x ∈ B`` is ``(y + a (x - m)) + (m - y + (1 - a)(x - m))``.

The direction and the split point of a box come from the κ family (HS96's outer ellipsoids
``E_κ = {C1/(1-κ) + C2/κ}``, whose intersection over κ is the sum): for the box centre
``m``, the member ``E_κ`` in which ``m`` has the largest gauge gives the normal
``d = Q_κ^{-1} (m - c)`` and the split ``y = c1 + C1 d / (1-κ)``, which balance the two
summands' gauges at the optimal κ; the share ``a`` is ``E1``'s part of the support in
direction ``d``, ``h1 / (h1 + h2)``. Both are floating-point guesses; only the interval checks
decide, so a poor guess costs tightness, never soundness.

References
----------
[HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
on an angle measurement technique", IFAC, 1996.
"""

from __future__ import annotations

import itertools

import numpy as np

from optbound.compare.tri import as_pseudo_ellipsoid, tri_test
from optbound.interval import Interval, Tri, sqrt
from optbound.interval.tribool import from_masks, tri_and
from optbound.problems.generators import random_ellipsoid, task_seeds
from optbound.problems.problem import Problem
from optbound.sets import Box, Ellipsoid

NAME = "minkowski"
# (dims, condition numbers, scale of the second summand, repetitions), as the benchmark runs.
SIZES = {
    "tiny": ((2, 3), (10.0,), (1e-1,), 1),
    "quick": ((2, 3, 4, 5, 6), (1.0, 10.0, 1e3, 1e6), (1.0, 1e-1, 1e-3), 3),
    "full": ((2, 3, 4, 5, 6), (1.0, 10.0, 1e2, 1e4, 1e6), (1.0, 1e-1, 1e-2, 1e-3), 8),
}
#: Default paving resolution, as a fraction of the sum's widest extent (see ``strip``).
RELATIVE_EPS = {2: 1 / 128, 3: 1 / 32, 4: 1 / 12, 5: 1 / 8, 6: 1 / 6}
#: κ values searched for a box's direction and split: logit-spaced in (0, 1).
KAPPAS = 1.0 / (1.0 + np.exp(-np.linspace(-14.0, 14.0, 401)))


def tasks(suite: str, seed: int) -> list[dict]:
    """List the instance cells of a suite: seed, dimension, condition number, scale, repetition.

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
        One cell per problem, keys ``seed``, ``dim``, ``cond``, ``scale`` and ``rep``.

    Raises
    ------
    ValueError
        For an unknown ``suite``.
    """
    if suite not in SIZES:
        raise ValueError(f"suite must be one of {tuple(SIZES)}, got {suite!r}")
    dims, conds, scales, reps = SIZES[suite]
    cells = list(itertools.product(dims, conds, scales, range(reps)))
    return [
        {"seed": s, "dim": dim, "cond": cond, "scale": scale, "rep": rep}
        for s, (dim, cond, scale, rep) in zip(
            task_seeds(seed, NAME, len(cells)), cells, strict=True
        )
    ]


def instance(seed: int, dim: int, cond: float, scale: float) -> tuple[Ellipsoid, Ellipsoid]:
    """Rebuild the two summands of one instance from its seed.

    Parameters
    ----------
    seed : int
        The instance seed (``np.random.default_rng(seed)``).
    dim : int
        The dimension.
    cond : float
        Condition number of both shape matrices.
    scale : float
        The largest semi-axis of the second summand (the first's is 1).

    Returns
    -------
    E1 : Ellipsoid
        The first summand (largest semi-axis 1).
    E2 : Ellipsoid
        The second summand (largest semi-axis ``scale``).
    """
    rng = np.random.default_rng(seed)
    E1 = random_ellipsoid(rng, dim, cond)
    return E1, random_ellipsoid(rng, dim, cond, scale=scale)


def _quadratic(d: list, C: np.ndarray) -> Interval:
    """``d^T C d`` in interval arithmetic (``d`` a list of Interval coordinates)."""
    n = len(d)
    return sum((d[j] * C[j, k]) * d[k] for j in range(n) for k in range(n))


def sum_test(E1: Ellipsoid, E2: Ellipsoid):
    """Build the three-valued interval test of ``E1 ⊕ E2`` on boxes (module docstring).

    Parameters
    ----------
    E1, E2 : Ellipsoid
        The summands.

    Returns
    -------
    callable
        ``test(*coords) -> Tri array`` on ``Interval`` coordinates: TRUE only for boxes
        proven inside the sum, FALSE only for boxes proven outside.
    """
    C1, C2 = E1.shape, E2.shape
    c1, c2 = E1.center, E2.center
    Qinv = np.linalg.inv(
        C1[None] / (1.0 - KAPPAS)[:, None, None] + C2[None] / KAPPAS[:, None, None]
    )
    in1, in2 = tri_test(E1), tri_test(E2)

    def test(*coords) -> np.ndarray:
        n = len(coords)
        mid = np.stack([np.asarray(x.midpoint(), dtype=float) for x in coords], axis=-1)
        shape = mid.shape[:-1]
        r = (mid - (c1 + c2)).reshape(-1, n)
        gauges = np.einsum("mi,kij,mj->mk", r, Qinv, r)
        k = np.argmax(gauges, axis=1)
        d = np.einsum("mij,mj->mi", Qinv[k], r)
        # FALSE: the support inequality fails in direction d on the whole box.
        dI = [Interval(d[:, j].reshape(shape)) for j in range(n)]
        reach = sum(dI[j] * ((coords[j] - c1[j]) - c2[j]) for j in range(n))
        support = sqrt(_quadratic(dI, C1)) + sqrt(_quadratic(dI, C2))
        outside = np.asarray(reach.lo > support.hi)
        # TRUE: B = Y + Z with the box Y = y + a (B - m) in E1 and Z = (m - y) + (1 - a)(B - m)
        # in E2; the box's width is shared as the summands' supports in direction d.
        h1, h2 = (np.sqrt(np.maximum(np.einsum("mi,ij,mj->m", d, C, d), 0.0)) for C in (C1, C2))
        with np.errstate(invalid="ignore"):
            a = np.where(h1 + h2 > 0.0, h1 / (h1 + h2), 0.5).reshape(shape)
        y = (c1 + np.einsum("ij,mj->mi", C1, d) / (1.0 - KAPPAS[k])[:, None]).reshape(*shape, n)
        offset = [coords[j] - mid[..., j] for j in range(n)]
        Y = [Interval(y[..., j]) + offset[j] * a for j in range(n)]
        Z = [(Interval(mid[..., j]) - y[..., j]) + offset[j] * (1.0 - a) for j in range(n)]
        inside = np.asarray(tri_and(in1(*Y), in2(*Z)) == Tri.TRUE)
        return from_masks(inside & ~outside, outside)

    return test


def _hull(E1: Ellipsoid, E2: Ellipsoid) -> Box:
    """A box proven to contain ``E1 ⊕ E2``: the interval sum of the summands' boxes."""
    b1, b2 = (as_pseudo_ellipsoid(E).bounding_box() for E in (E1, E2))
    lo = Interval(b1.lo) + Interval(b2.lo)
    hi = Interval(b1.hi) + Interval(b2.hi)
    return Box(np.asarray(lo.lo, dtype=float), np.asarray(hi.hi, dtype=float))


def _sdp(p: Problem) -> Ellipsoid:
    """The benchmark's reference: the certified minimum-volume outer ellipsoid of the sum."""
    from optbound import optimal  # cvxpy only when a reference is asked for

    return optimal.minkowski_outer(*p.data["summands"], objective="volume").ellipsoid


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
    E1, E2 = instance(task["seed"], task["dim"], task["cond"], task["scale"])
    domain = _hull(E1, E2)
    return Problem(
        family=NAME,
        name=f"d{task['dim']}-c{task['cond']:g}-s{task['scale']:g}-r{task['rep']}",
        seed=task["seed"],
        dim=E1.dim,
        data={"summands": (E1, E2)},
        truth=None,
        test=sum_test(E1, E2),
        domain=domain,
        eps=float(np.max(domain.widths)) * RELATIVE_EPS[E1.dim],
        optimal=_sdp,
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
