"""Ellipsoid ∩ strip: every analytic fusion criterion against its matching SDP optimum.

Instances: a random ellipsoid (dimension 2-6, condition number 1-1e6) cut by a strip that is
narrow, wide, off-centre or partial (only one plane cuts) [HS96, Sect. 4]. Criteria:

- ``volume`` and ``robust`` (HS96 eqs. 26 and 30) against the minimum-volume SDP;
- ``projection`` (HS96 eq. 27) against the minimum projected-volume SDP;
- ``trace`` (the trace-minimising member of the same family) against the minimum-trace SDP;
- ``bh_volume`` and ``bh_trace``: the BH bounding filter with the strip as the scalar
  measurement ``b = a^T x + v``, ``|v| <= 1`` [BH, eq. (7)], which does not clip the strip.

With the strip clipped to the ellipsoid (the SDP's ``clip=True``), the S-procedure is tight
for one ellipsoid and one strip, so ratios below 1 would mean an analytic bound that is not
an outer bound, and ratios above 1 are the analytic method's loss.
"""

from __future__ import annotations

import itertools

import numpy as np

from optbound.bench import records
from optbound.bench.family import Family
from optbound.problems.generators import STRIP_KINDS, random_ellipsoid, random_strip, task_seeds
from optbound.problems.strip import NAME, SIZES  # one source of instances

FIGURE_COND = 10.0
SAMPLES = 20_000  # points of E tested against each bound (those in S are points of E ∩ S)


def projection_dims(dim: int) -> list[int]:
    """Choose the coordinates the projection criterion targets.

    Parameters
    ----------
    dim : int
        The state dimension.

    Returns
    -------
    list of int
        ``[0, 1]`` (x-y, the position), or ``[0]`` (x alone) in 2-D.
    """
    return [0] if dim == 2 else [0, 1]


def tasks(suite: str, seed: int) -> list[dict]:
    """Build the seeded tasks of ``suite``: one ellipsoid and strip per cell.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run (:data:`SIZES`).
    seed : int
        Suite seed; each task's instance seed is derived from it.

    Returns
    -------
    list of dict
        One JSON-able task per (dimension, condition number, strip kind, repetition), with its
        ``"seed"`` and whether it draws a figure.
    """
    dims, conds, reps = SIZES[suite]
    cells = list(itertools.product(dims, conds, STRIP_KINDS, range(reps)))
    return [
        {
            "seed": s,
            "dim": dim,
            "cond": cond,
            "kind": kind,
            "figure": dim == 2 and cond == FIGURE_COND and rep == 0,
        }
        for s, (dim, cond, kind, rep) in zip(task_seeds(seed, NAME, len(cells)), cells, strict=True)
    ]


def instance(task: dict):
    """Rebuild the ellipsoid and strip of a task from its seed.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    E : Ellipsoid
        The prior ellipsoid.
    S : Strip
        The measurement strip.
    """
    rng = np.random.default_rng(task["seed"])
    E = random_ellipsoid(rng, task["dim"], task["cond"])
    return E, random_strip(rng, E, task["kind"])


def run(task: dict) -> dict:
    """Run one task: every analytic criterion of ``E ∩ S`` against the SDP optimum of its metric.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    dict
        ``{"records": [...], "figures": [...]}``: one record per criterion (its size ratio, the
        sampled points of the exact set it misses), and a 2-D figure for figure tasks.
    """
    from optbound import analytic, optimal

    E, S = instance(task)
    dims = projection_dims(E.dim)
    sdp = {
        objective: records.reference(
            optimal.outer_ellipsoid,
            intersection=[E, S],
            objective=objective,
            dims=dims if objective == "projection" else None,
        )
        for objective in ("volume", "trace", "projection")
    }
    bounds = {
        criterion: analytic.intersect_strip(
            E, S, criterion=criterion, dims=dims if criterion == "projection" else None
        )
        for criterion in ("volume", "trace", "projection", "robust")
    }
    for criterion in ("volume", "trace"):
        bounds[f"bh_{criterion}"] = analytic.bounding_update(
            E, S.a, [S.b], 1.0, criterion=criterion
        )
    pts = E.sample(SAMPLES, np.random.default_rng([task["seed"], 1]))
    pts = pts[S.contains(pts)]
    out = []
    for criterion, result in bounds.items():
        metric = records.METRIC_OF[criterion]
        objective = records.OBJECTIVE_OF[metric]
        out.append(
            {
                "family": NAME,
                "variant": task["kind"],
                "dim": E.dim,
                "cond": task["cond"],
                "seed": task["seed"],
                "criterion": criterion,
                "reference": f"SDP {objective}",
                "case": getattr(result, "case", ""),
                "outside": int(np.sum(~result.ellipsoid.contains(pts))),
                **records.comparison(metric, result.ellipsoid, *sdp[objective], dims),
            }
        )
    figures = []
    if task["figure"] and sdp["volume"][0] is not None:
        drawn = {
            "analytic volume": bounds["volume"].ellipsoid,
            f"analytic projection (onto dims {dims})": bounds["projection"].ellipsoid,
            "analytic robust": bounds["robust"].ellipsoid,
            "SDP volume optimum": sdp["volume"][0].ellipsoid,
        }
        title = f"{task['kind']} strip"
        figures.append(records.figure(title, task["seed"], E, [S], drawn))
    return {"records": out, "figures": figures}


def cost(task: dict) -> float:
    """Estimate the seconds of one task (quick suite, 2-core VM): the SDPs grow with the dimension.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    float
        Estimated seconds on one core.
    """
    return 0.02 * task["dim"]


FAMILY = Family(
    name=NAME,
    title="Ellipsoid ∩ strip: analytic fusion vs SDP optimum",
    kind="tightness",
    requires=(
        "optbound.analytic:intersect_strip",
        "optbound.analytic:bounding_update",
        "optbound.optimal:outer_ellipsoid",
        "optbound.compare:volume_ratio",
    ),
    tasks=tasks,
    run=run,
    cost=cost,
)
