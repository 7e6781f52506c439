"""Set-membership observers of linear systems against the exact set, per step (issue 21).

One task is one system run through every observer of :data:`optbound.estimation.METHODS`:

- the example of Alamo, Bravo & Camacho 2005, Sect. 7.1 (``optbound.scenarios.alamo2005``);
- seeded random stable systems (``optbound.scenarios.linear_systems.random_system``), 2-D
  with box noise in the quick suite, n = 2 ... 6 with box and ellipsoidal noise and 50 - 200
  steps in the full suite;
- CORA's 30-state tank (``optbound.scenarios.tank30``, 234 steps), full suite only.

Records, one per method and recorded step ``k``:

- 2-D with box noise (the exact set is the rational polygon of
  :func:`optbound.estimation.exact_polygon.exact_polygons`): ``ratio_lo/hi``, the certified
  bracket of area(set) / area(exact set) (:func:`optbound.compare.size.size_bracket` of the
  set, the polygon's area exactly); ``mvee_ratio_lo/hi``, the bracket of area(set) / area(MVEE
  of the exact polygon's vertices, :func:`optbound.optimal.mvee`); ``contained``: True when
  :func:`optbound.estimation.references.proven_contains` proves, in rational arithmetic, that
  the set contains the exact polygon (at its vertices: boxes by their bounds, ellipsoids by
  their quadratic form, zonotopes by their facets, constrained zonotopes by an exact parameter
  certificate per vertex), False where a vertex is outside, None where a certificate fails;
- otherwise the size measure is the **interval-hull widths**: ``ratio_lo/hi`` is the bracket
  of the mean over states of width(set's hull) / width(exact set's hull), the exact hull by
  certified LP bounds (:func:`optbound.estimation.references.interval_hull`; box noise and
  n <= 6 only: the exact constrained zonotope grows by one constraint per output and step);
  where there is no exact reference (ellipsoidal noise, the tank) ``hull_ratio`` is the mean
  over states of width / the smallest width any method reached in that state;
  ``mean_width`` is recorded everywhere; ``contained`` is None (not decided in n > 2: the
  exact polytopes of :func:`optbound.estimation.exact_polytopes` take minutes over the 50 - 100
  steps of these runs);
- ``ms_per_step``: the method's wall time over the whole run / number of steps;
- the tank only, for the two ellipsoidal observers at every :data:`SDP_EVERY`-th step (the
  S-procedure SDP takes about 10 s at n = 30, so it is sampled, not run per step):
  ``one_step_ratio``, the observer's size (volume or trace, its own criterion) over that of
  the certified optimal ellipsoid of the same step
  (:func:`optbound.estimation.references.one_step_optimal`: the smallest ellipsoid containing
  the observer's own prediction ∩ the measurement strips), i.e. the loss of the analytic strip
  fusion in that step (float ratio of certified ellipsoids), and ``sdp_seconds``, that SDP's
  wall time; where the SDP cannot be certified (a degenerate prediction), ``one_step_ratio``
  is None and ``sdp_error`` says why.

A method that refuses a system (the volume gain's generator subsets beyond its limit) gives
one record with its ``error``. The first 2-D task of each system attaches a PNG: the exact
polygon and every observer's set at a few steps, and the ratio curves versus k.
"""

from __future__ import annotations

import base64
import io
import time

import numpy as np

from optbound.bench.family import Family
from optbound.problems.generators import task_seeds

NAME = "linear_estimation"
ATTACHMENT_DIR = "linear_estimation"
#: (system, n, noise, steps, reps) per suite; "alamo" and "tank" ignore n, noise and reps.
SUITES = {
    "tiny": [("alamo", 2, "box", 5, 1)],
    "quick": [("alamo", 2, "box", 20, 1), ("random", 2, "box", 20, 2)],
    "full": [
        ("alamo", 2, "box", 20, 1),
        ("random", 2, "box", 50, 3),
        ("random", 2, "ellipsoid", 50, 2),
        *[("random", n, "box", 50 if n > 3 else 100, 2) for n in (3, 4, 6)],
        *[("random", n, "ellipsoid", 200, 1) for n in (3, 4, 6)],
        ("tank", 30, "box", 234, 1),
    ],
}
#: Steps drawn in the 2-D figure (those within the run).
FIGURE_STEPS = (1, 2, 5, 20)
#: Steps recorded in a short run (up to 20 steps; the last step always) ...
SHORT_STEPS = (1, 2, 3, 5, 7, 10, 14, 20)
#: ... and in a longer one, every this many steps (and the last).
EVERY = 10
#: The tank's one-step optimal ellipsoid (an SDP) is solved at every this many steps.
SDP_EVERY = 10


def tasks(suite: str, seed: int) -> list[dict]:
    """Build the seeded tasks of ``suite``: one observer run per system and repetition.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run (:data:`SUITES`).
    seed : int
        Suite seed; each task's instance seed is derived from it.

    Returns
    -------
    list of dict
        One JSON-able task per (system, dimension, noise, steps, repetition), with its
        ``"seed"``.

    Raises
    ------
    ValueError
        For an unknown ``suite``.
    """
    if suite not in SUITES:
        raise ValueError(f"suite must be one of {tuple(SUITES)}, got {suite!r}")
    cells = [
        (system, n, noise, steps, rep)
        for system, n, noise, steps, reps in SUITES[suite]
        for rep in range(reps)
    ]
    return [
        {"seed": s, "system": system, "n": n, "noise": noise, "steps": steps, "rep": rep}
        for s, (system, n, noise, steps, rep) in zip(
            task_seeds(seed, NAME, len(cells)), cells, strict=True
        )
    ]


def instance(task: dict):
    """Rebuild the system and its measurements of a task from its seed.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    label : str
        The system's name in the report.
    system : LinearSystem
        The linear system.
    X0 : set
        The initial set.
    ys : sequence
        The measurements, ``task["steps"]`` of them.
    """
    if task["system"] == "alamo":
        from optbound.scenarios import alamo2005

        ys = alamo2005.MEASUREMENTS[: task["steps"]]
        return "Alamo 2005 Sect. 7.1", alamo2005.system(), alamo2005.X0, ys
    if task["system"] == "tank":
        from optbound.scenarios import tank30

        tank = tank30.scenario()
        return "CORA tank (n=30)", tank.system, tank.X0, tank.ys[: task["steps"]]
    from optbound.scenarios.linear_systems import random_system

    run = random_system(task["n"], task["seed"], task["noise"], steps=task["steps"])
    label = f"random n={task['n']} {task['noise']} noise #{task['rep']}"
    return label, run.system, run.X0, run.ys


def recorded_steps(steps: int) -> list[int]:
    """Choose the steps recorded: few, since each recorded step costs LP polygons in 2-D.

    Parameters
    ----------
    steps : int
        The run's number of steps.

    Returns
    -------
    list of int
        :data:`SHORT_STEPS` of a short run, every :data:`EVERY` steps of a long one, and the
        last step, sorted.
    """
    if steps <= 20:
        return sorted({k for k in SHORT_STEPS if k <= steps} | {steps})
    return sorted({*range(EVERY, steps + 1, EVERY), steps})


def run(task: dict) -> dict:
    """Run one task: every observer of :data:`optbound.estimation.METHODS` on its system.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    dict
        ``{"records": [...]}``: per method and recorded step, its size measures and
        milliseconds per step (on the tank also the one-step loss against the SDP every
        :data:`SDP_EVERY` steps), or the error of a method refusing the system; a 2-D figure
        of the first repetition under ``"attachments"``.
    """
    from optbound import estimation as est

    label, system, X0, ys = instance(task)
    runs, errors = {}, {}
    for method in est.METHODS:
        start = time.perf_counter()
        try:
            sets = est.observe(system, X0, ys, method)
        except ValueError as exc:  # a method refusing the system (its stated limits)
            errors[method] = f"{type(exc).__name__}: {exc}"
            continue
        runs[method] = (sets, 1000 * (time.perf_counter() - start) / len(ys))
    base = {
        "family": NAME,
        "system": label,
        "dim": system.dim,
        "seed": task["seed"],
        "steps": len(ys),
    }
    ks = recorded_steps(len(ys))
    exact_2d = system.dim == 2 and _box_noise(system)
    if exact_2d:
        measured, drawn = _polygon_measures(system, X0, ys, runs, ks)
    else:
        measured, drawn = _hull_measures(system, X0, ys, runs, ks, task), None
    if task["system"] == "tank":
        for (method, k), rec in _one_step_losses(system, ys, runs, ks).items():
            measured[method][k].update(rec)
    out = [{**base, "method": m, "k": None, "error": e} for m, e in errors.items()]
    for method, (_, ms) in runs.items():
        for k in ks:
            out.append({**base, "method": method, "k": k, "ms_per_step": ms, "error": None,
                        **measured[method][k]})  # fmt: skip
    result: dict = {"records": out}
    if drawn is not None and task["rep"] == 0:
        name = f"{ATTACHMENT_DIR}/{task['system']}_{task['seed']}.png"
        result["attachments"] = {name: _png(label, drawn, runs, out)}
    return result


def _box_noise(system) -> bool:
    from optbound.sets import Ellipsoid

    return not isinstance(system.W, Ellipsoid) and not isinstance(system.V, Ellipsoid)


def _polygon_measures(system, X0, ys, runs: dict, ks: list[int]):
    """2-D, box noise: area ratios to the exact polygon and its MVEE, exact containment."""
    from optbound import optimal
    from optbound.compare.metrics import ratio_bracket
    from optbound.compare.size import ellipsoid_volume_bracket, size_bracket
    from optbound.estimation.exact_polygon import exact_polygons
    from optbound.estimation.references import proven_contains
    from optbound.problems.linear_estimation import outward_hull
    from optbound.sets.constrained_zonotope_polygon import polygon_area, round_down, round_up

    polygons = exact_polygons(system, X0, ys)
    out: dict = {m: {} for m in runs}
    for k in ks:
        P = polygons[k - 1]
        area = polygon_area(P)
        exact = (round_down(area), round_up(area))
        mvee = ellipsoid_volume_bracket(optimal.mvee(np.array(P, dtype=float)).ellipsoid)
        domain = outward_hull(P)
        for method, (sets, _) in runs.items():
            S = sets[k - 1]
            size = size_bracket(S, domain=domain)
            ratio, to_mvee = ratio_bracket(size, exact), ratio_bracket(size, mvee)
            out[method][k] = {
                "measure": "area",
                "ratio_lo": ratio[0],
                "ratio_hi": ratio[1],
                "mvee_ratio_lo": to_mvee[0],
                "mvee_ratio_hi": to_mvee[1],
                "contained": proven_contains(S, P),
            }
    return out, polygons


def _hull(S):
    from optbound.sets import Box

    return S if isinstance(S, Box) else S.bounding_box()


def _hull_measures(system, X0, ys, runs: dict, ks: list[int], task: dict) -> dict:
    """Interval-hull widths against the exact hull (box noise, n <= 6) or the best method."""
    widths = {m: {k: _hull(sets[k - 1]).widths for k in ks} for m, (sets, _) in runs.items()}
    exact = None
    if _box_noise(system) and task["system"] != "tank":
        from optbound.estimation import exact_sets
        from optbound.estimation.references import interval_hull

        sets = exact_sets(system, X0, ys)
        exact = {k: interval_hull(sets[k - 1]) for k in ks}
    out: dict = {m: {} for m in runs}
    for k in ks:
        best = np.min([widths[m][k] for m in runs], axis=0)
        for m in runs:
            w = widths[m][k]
            rec = {"measure": "interval-hull widths", "mean_width": float(np.mean(w))}
            if exact is not None:
                # The exact hull's LP bounds are rounded outward: a lower end of the ratio.
                rec["ratio_lo"] = float(np.mean(w / exact[k].widths))
                rec["ratio_hi"] = None
            else:
                rec["hull_ratio"] = float(np.mean(w / best))
            rec["contained"] = None
            out[m][k] = rec
    return out


def _one_step_losses(system, ys, runs: dict, ks: list[int]) -> dict:
    """``{(method, k): {"one_step_ratio", "sdp_seconds"}}`` of the ellipsoidal observers at
    the steps of ``ks`` divisible by :data:`SDP_EVERY` (module docstring)."""
    from optbound import optimal
    from optbound.estimation.ellipsoidal import CRITERIA
    from optbound.estimation.references import one_step_optimal

    out = {}
    for method in CRITERIA:
        if method not in runs:
            continue
        sets = runs[method][0]
        for k in (k for k in ks if k % SDP_EVERY == 0):
            start = time.perf_counter()
            try:
                opt = one_step_optimal(system, sets[k - 2], ys[k - 1], method).ellipsoid
            except (ValueError, optimal.CertificationError) as exc:  # e.g. a degenerate prediction
                out[method, k] = {
                    "one_step_ratio": None,
                    "sdp_seconds": time.perf_counter() - start,
                    "sdp_error": f"{type(exc).__name__}: {exc}",
                }
                continue
            seconds = time.perf_counter() - start
            E = sets[k - 1]
            if CRITERIA[method] == "volume":  # in logs: the volumes of n = 30 underflow
                ratio = float(np.exp(E.log_volume() - opt.log_volume()))
            else:
                ratio = float(np.trace(E.shape) / np.trace(opt.shape))
            out[method, k] = {"one_step_ratio": ratio, "sdp_seconds": seconds}
    return out


def _png(label: str, polygons: list, runs: dict, records: list[dict]) -> str:
    """Base64 PNG: the exact polygon and each observer at :data:`FIGURE_STEPS`, then the
    area-ratio curves (upper ends of the brackets) versus k."""
    from optbound.report.figures import pyplot

    plt = pyplot()
    steps = [k for k in FIGURE_STEPS if k <= len(polygons)]
    fig, axes = plt.subplots(1, len(steps) + 1, figsize=(3.2 * (len(steps) + 1), 3.0))
    for ax, k in zip(axes, steps, strict=False):
        P = np.array(polygons[k - 1], dtype=float)
        ax.fill(P[:, 0], P[:, 1], color="0.8", label="exact")
        for i, (method, (sets, _)) in enumerate(runs.items()):
            _outline(ax, sets[k - 1], f"C{i}", method)
        ax.set_title(f"k = {k}", fontsize=9)
        centre, half = P.mean(axis=0), 1.5 * np.ptp(P, axis=0)  # zoom on the exact set
        ax.set_xlim(centre[0] - half[0], centre[0] + half[0])
        ax.set_ylim(centre[1] - half[1], centre[1] + half[1])
    axes[0].legend(fontsize=6, loc="best")
    ax = axes[-1]
    for i, method in enumerate(runs):
        recs = [r for r in records if r["method"] == method and r.get("ratio_hi") is not None]
        ax.plot([r["k"] for r in recs], [r["ratio_hi"] for r in recs], "-o", color=f"C{i}",
                markersize=3, label=method)  # fmt: skip
    ax.set_yscale("log")
    ax.set_xlabel("k")
    ax.set_ylabel("area / exact area")
    ax.legend(fontsize=6)
    fig.suptitle(label)
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=72)
    plt.close(fig)
    return base64.b64encode(buf.getvalue()).decode("ascii")


def _outline(ax, S, color: str, label: str) -> None:
    from optbound.sets import Box, Ellipsoid

    if isinstance(S, Ellipsoid):
        V = S.boundary()
    elif isinstance(S, Box):
        V = np.array(
            [[S.lo[0], S.lo[1]], [S.hi[0], S.lo[1]], [S.hi[0], S.hi[1]], [S.lo[0], S.hi[1]]]
        )
    else:
        V = S.vertices()
    V = np.vstack([V, V[:1]])
    ax.plot(V[:, 0], V[:, 1], "-", color=color, linewidth=1.0, label=label)


def cost(task: dict) -> float:
    """Estimate the seconds of one task (2-core VM).

    The tank's SDPs, constrained zonotopes and zonotopes dominate the full suite.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    float
        Estimated seconds on one core.
    """
    if task["system"] == "tank":  # the observers, then 2 x 23 SDPs of about 10 s
        return 120.0 + 2 * (task["steps"] // SDP_EVERY) * 10.0
    return 0.1 * task["steps"] * task["n"]


FAMILY = Family(
    name=NAME,
    title="Set-membership observers of linear systems vs the exact set",
    kind="estimation",
    requires=("optbound.estimation:observe",),
    tasks=tasks,
    run=run,
    cost=cost,
)
