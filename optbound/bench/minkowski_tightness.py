"""Minkowski sum of two ellipsoids: the κ family [HS96, eqs. (10)-(17)] vs the SDP optimum.

Instances: two random ellipsoids (dimension 2-6, condition numbers up to 1e6) whose sizes
differ by a factor 1, 1e-1 or 1e-3 (a large prior plus a small odometry error, say). For two
summands the best member of the family C1/(1-κ) + C2/κ is the true minimum for volume and
trace (Durieu, Walter & Polyak 2001), so these ratios should sit at 1 up to solver accuracy.
``size_xy_psi`` minimises HS96's tr(proj_xy)·proj_ψ, which no SDP objective matches; it is
shown by its volume ratio to the minimum-volume SDP, i.e. what that choice costs in volume.
"""

from __future__ import annotations

import itertools

import numpy as np

from optbound.bench import records
from optbound.bench.family import Family
from optbound.problems.generators import random_ellipsoid, task_seeds
from optbound.problems.minkowski import NAME, SIZES  # one source of instances

# 2-D instances drawn in the report: this condition number, summands of these relative scales.
FIGURE_COND, FIGURE_SCALES = 10.0, (1.0, 1e-1)
# HS96's pose (x, y, ψ): the size measure needs a position block and a heading coordinate.
XY_PSI_DIMS = ([0, 1], [2])


def tasks(suite: str, seed: int) -> list[dict]:
    """Build the seeded tasks of ``suite``: two summands per cell.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run (:data:`SIZES`).
    seed : int
        Suite seed; each task's instance seed is derived from it.

    Returns
    -------
    list of dict
        One JSON-able task per (dimension, condition number, scale ratio, repetition), with its
        ``"seed"`` and whether it draws a figure.
    """
    dims, conds, scales, reps = SIZES[suite]
    cells = list(itertools.product(dims, conds, scales, range(reps)))
    return [
        {
            "seed": s,
            "dim": dim,
            "cond": cond,
            "scale": scale,
            "figure": dim == 2 and cond == FIGURE_COND and scale in FIGURE_SCALES and rep == 0,
        }
        for s, (dim, cond, scale, rep) in zip(
            task_seeds(seed, NAME, len(cells)), cells, strict=True
        )
    ]


def instance(task: dict):
    """Rebuild the two summands of a task from its seed.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    E1 : Ellipsoid
        The first summand.
    E2 : Ellipsoid
        The second summand, scaled by ``task["scale"]``.
    """
    rng = np.random.default_rng(task["seed"])
    E1 = random_ellipsoid(rng, task["dim"], task["cond"])
    E2 = random_ellipsoid(rng, task["dim"], task["cond"], scale=task["scale"])
    return E1, E2


def run(task: dict) -> dict:
    """Run one task: each κ criterion of the Minkowski sum against the SDP optimum.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    dict
        ``{"records": [...], "figures": [...]}``: one record per criterion (size ratio and κ), and a
        2-D figure for figure tasks.
    """
    from optbound import analytic, optimal

    E1, E2 = instance(task)
    sdp = {
        obj: records.reference(optimal.minkowski_outer, E1, E2, objective=obj)
        for obj in ("volume", "trace")
    }
    criteria = ["volume", "trace"] + (["size_xy_psi"] if E1.dim >= 3 else [])
    out, drawn = [], {}
    for criterion in criteria:
        dims = XY_PSI_DIMS if criterion == "size_xy_psi" else None
        result = analytic.minkowski_sum(E1, E2, criterion=criterion, dims=dims)
        drawn[f"analytic {criterion} κ"] = result.ellipsoid
        objective = "trace" if criterion == "trace" else "volume"
        metric = records.METRIC_OF[objective]
        out.append(
            {
                "family": NAME,
                "variant": f"scale {task['scale']:g}",
                "dim": E1.dim,
                "cond": task["cond"],
                "seed": task["seed"],
                "criterion": criterion,
                "reference": f"SDP {objective}",
                "matched": criterion != "size_xy_psi",
                "kappa": float(result.kappa),
                **records.comparison(metric, result.ellipsoid, *sdp[objective]),
            }
        )
    figures = []
    if task["figure"] and sdp["volume"][0] is not None:
        drawn["SDP volume optimum"] = sdp["volume"][0].ellipsoid
        title = f"sum, scales 1 : {task['scale']:g}"
        figures.append(records.sum_figure(title, task["seed"], [E1, E2], drawn))
    return {"records": out, "figures": figures}


def cost(task: dict) -> float:
    """Estimate the seconds of one task (quick suite, 2-core VM).

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    float
        Estimated seconds on one core.
    """
    return 0.003 * task["dim"]


FAMILY = Family(
    name=NAME,
    title="Minkowski sum: κ criteria vs SDP optimum",
    kind="tightness",
    requires=(
        "optbound.analytic:minkowski_sum",
        "optbound.optimal:minkowski_outer",
        "optbound.compare:volume_ratio",
    ),
    tasks=tasks,
    run=run,
    cost=cost,
)
