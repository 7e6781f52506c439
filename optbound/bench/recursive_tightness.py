"""Recursive strip filtering vs the batch SDP over all strips at once.

A random prior ellipsoid (dimension 2-4 in the quick suite, up to 6 in full) and a sequence of
up to 50 strips that all contain one true point, each of normalised width ``width``. The
analytic filter fuses them one at a time with the minimum-volume criterion [HS96, eq. (26)];
the reference is one SDP over ``E ∩ S_1 ∩ ... ∩ S_k``. Their volume ratio as k grows shows how
fast the recursion loses tightness. For k >= 2 strips the S-procedure is only an upper bound
on the smallest outer ellipsoid, so the SDP's certified lower bound is recorded as well.
"""

from __future__ import annotations

import itertools

import numpy as np

from optbound.bench import records
from optbound.bench.family import Family
from optbound.problems.generators import random_ellipsoid, strips_around, task_seeds
from optbound.problems.recursive import NAME, PRIOR_COND, SIZES  # one source of instances

FIGURE_K = 5


def tasks(suite: str, seed: int) -> list[dict]:
    """Build the seeded tasks of ``suite``: a prior and a strip sequence per cell.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run (:data:`SIZES`).
    seed : int
        Suite seed; each task's instance seed is derived from it.

    Returns
    -------
    list of dict
        One JSON-able task per (dimension, strip width, repetition), with its ``"seed"``, the
        recursion depths ``"ks"`` compared and whether it draws a figure.
    """
    dims, widths, ks, reps = SIZES[suite]
    cells = list(itertools.product(dims, widths, range(reps)))
    return [
        {
            "seed": s,
            "dim": dim,
            "width": width,
            "ks": list(ks),
            "figure": dim == 2 and width == widths[0] and rep == 0,
        }
        for s, (dim, width, rep) in zip(task_seeds(seed, NAME, len(cells)), cells, strict=True)
    ]


def instance(task: dict):
    """Rebuild the prior ellipsoid, true point and strip sequence of a task from its seed.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    E0 : Ellipsoid
        The prior.
    point : numpy.ndarray
        The true state, a sample of ``E0``.
    strips : list of Strip
        ``max(task["ks"])`` strips containing ``point``.
    """
    rng = np.random.default_rng(task["seed"])
    E0 = random_ellipsoid(rng, task["dim"], PRIOR_COND)
    point = E0.sample(1, rng)[0]
    return E0, point, strips_around(rng, E0, point, max(task["ks"]), task["width"])


def _batch_sdp(optimal, intersection: list, seed: int):
    """The batch SDP with its sampled lower bound; ``(result, sdp_error, lower_bound_error)``.

    The lower bound (an MVEE of samples) can fail on its own, e.g. when sampling finds too few
    points of a thin set or the MVEE iteration does not converge; the SDP ratio is then still
    recorded, without the lower bound (a bad instance fails again in the plain solve).
    """
    try:
        result = optimal.outer_ellipsoid(
            intersection=intersection, objective="volume", lower_bound=True, rng=seed
        )
        return result, "", ""
    except (RuntimeError, ValueError) as exc:  # a refused solve, or too few samples / no MVEE
        lower_error = f"{type(exc).__name__}: {exc}"
    result, error = records.reference(
        optimal.outer_ellipsoid, intersection=intersection, objective="volume"
    )
    return result, error, lower_error


def run(task: dict) -> dict:
    """Run one task: recursive volume updates against the batch SDP over the first k strips.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    dict
        ``{"records": [...], "figures": [...]}``: one record per depth k in ``task["ks"]`` (volume
        ratio and lower-bound ratio), and a 2-D figure for figure tasks.
    """
    from optbound import analytic, optimal

    E0, _, strips = instance(task)
    ks = set(task["ks"])
    E, out, figures = E0, [], []
    for k, S in enumerate(strips, start=1):
        E = analytic.intersect_strip(E, S, criterion="volume").ellipsoid
        if k not in ks:
            continue
        sdp, error, lower_error = _batch_sdp(optimal, [E0, *strips[:k]], task["seed"])
        out.append(
            {
                "family": NAME,
                "variant": f"width {task['width']:g}",
                "dim": E0.dim,
                "seed": task["seed"],
                "k": k,
                "criterion": "volume",
                "reference": "SDP volume, all k strips",
                "lower_ratio": None if sdp is None else records.lower_ratio(E.volume(), sdp),
                "lower_error": lower_error,
                **records.comparison("volume_ratio", E, sdp, error),
            }
        )
        if task["figure"] and k == FIGURE_K and sdp is not None:
            drawn = {f"analytic recursive (k={k})": E, f"SDP batch (k={k})": sdp.ellipsoid}
            title = f"{k} strips, width {task['width']:g}"
            figures.append(records.figure(title, task["seed"], E0, strips[:k], drawn))
    return {"records": out, "figures": figures}


def cost(task: dict) -> float:
    """Estimate the seconds of one task (quick suite, 2-core VM).

    One SDP with its lower bound per recursion depth, each growing with the dimension.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    float
        Estimated seconds on one core.
    """
    return 0.06 * task["dim"] * len(task["ks"])


FAMILY = Family(
    name=NAME,
    title="Recursive strip updates vs batch SDP",
    kind="recursive",
    requires=(
        "optbound.analytic:intersect_strip",
        "optbound.optimal:outer_ellipsoid",
        "optbound.compare:volume_ratio",
    ),
    tasks=tasks,
    run=run,
    cost=cost,
)
