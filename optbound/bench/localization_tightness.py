"""Bearing-only localization: every bound's area against the exact set's [BH, Sect. V].

The product's question asked of localization. Instances: the geometry of [BH, Sect. V]
(landmarks ``[0, 1]``, ``[1, 1]``, ``[-1, 0]``, vehicle at the origin, the pairs (3, 1), (1, 2),
(2, 3), noise-free bearings, eps = 4°) and seeded random landmark triples and vehicles
(``scenarios.bh_geometry.random_instance``: eps in [1°, 8°], uniform noise). On each, the same
relative-bearing data give:

- ``hs96_linearized``: the ellipsoidal set-membership filter of [HS96, eqs. (18)-(24)] on
  bearing strips linearized around the current centre (one relinearization around the fused
  centre), volume (= area) criterion, from the ellipse through the corners of the prior box
  (``localization.linearized_bearing``). **Not guaranteed**: the tangent strips are not the
  crescents, so it can miss part of the exact set and the truth;
- ``bh_L4`` / ``bh_L8``: the BH pseudo-ellipsoids, L = 4 and L = 8 (``relative_bearing.localize``,
  volume criterion), guaranteed; containment of the exact set is also *proven* on the paving
  (``relative_bearing.certify_contains``, field ``proven``);
- ``best_ellipse``: the best outer ellipse found, certified to contain the exact set: the
  smaller of two candidates built on the paving, the S-procedure SDP of the rings ∩ the
  paving's hull and the MVEE of the paving's boxes (``relative_bearing.best_ellipse``; on the
  BH instance the MVEE). Not proven optimal, and larger on a coarser paving: the BH
  reproduction's finer paving finds a smaller one. ``lower_area`` is an area no outer ellipse
  can beat;
- ``optimal_pseudo_L4`` / ``optimal_pseudo_L8``: the minimum-lifted-volume pseudo-ellipsoid
  containing the paved exact set (``optimal.optimal_pseudo_ellipsoid``, certified upper set);
  L = 8 only in the full suite (about 8 s per instance).

Each area is divided by the exact area, bracketed by a paving of the exact set
(``relative_bearing.exact_paving``, box width 1/``relative`` of the set's hull): ``ratio`` is
the ratio of the midpoints of the two brackets, ``[ratio_lo, ratio_hi]`` =
``[area_lo / exact_hi, area_hi / exact_lo]`` a certified bracket of the true ratio (a bound
that contains the exact set has ``ratio_hi >= 1``). ``outside`` counts points drawn uniformly
in the paving's inner boxes (points of the exact set) that the bound misses, and
``truth_outside`` is 1 when the true position is outside it (float64 tests).
"""

from __future__ import annotations

import base64
import io
import time

import numpy as np

from optbound.bench.family import Family
from optbound.localization import relative_bearing as rb
from optbound.localization.linearized_bearing import linearized_localize
from optbound.problems.generators import task_seeds
from optbound.scenarios import bh_geometry as bh
from optbound.sets import Box

NAME = "localization"
REFERENCE = "exact area (paving)"
SAMPLES = 2000  # points of the exact set tested against each bound
# (random instances, paving width relative to the hull, optimal-reference orders on the BH
# instance, on the random ones) per suite; the quick suite keeps the family's cost near 10 s.
SIZES = {
    "tiny": (0, 40, (1,), ()),
    "quick": (2, 40, (1,), ()),
    "full": (12, 100, (1, 2), (1, 2)),
}
FIGURE = "localization/bh_instance.png"
#: What each reference is, for the report (``bound`` field); the rest are analytic bounds.
#: ``best_ellipse`` is built on the paving's coarse hull and boxes: an outer ellipse, not the
#: optimum (it can come out larger than the linearized HS96 ellipse).
KINDS = {
    "best_ellipse": "best outer ellipse found (certified, not optimal)",
    "optimal_pseudo": "optimal",
}


def tasks(suite: str, seed: int) -> list[dict]:
    """Build the seeded tasks of ``suite``: the BH instance and seeded random instances.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run (:data:`SIZES`).
    seed : int
        Suite seed; each task's instance seed is derived from it.

    Returns
    -------
    list of dict
        One JSON-able task per instance (the BH geometry first), with its ``"seed"``, the paving
        resolution ``"relative"``, the pseudo-ellipsoid orders compared and whether it draws the
        figure.
    """
    count, relative, bh_orders, random_orders = SIZES[suite]
    seeds = task_seeds(seed, NAME, count + 1)
    variants = [("BH geometry", bh_orders)] + [("random", random_orders)] * count
    return [
        {
            "seed": s,
            "variant": variant,
            "relative": relative,
            "orders": list(orders),
            "figure": variant == "BH geometry",
        }
        for s, (variant, orders) in zip(seeds, variants, strict=True)
    ]


def instance(task: dict):
    """Rebuild the bearing data of a task from its seed.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    tuple
        ``(landmarks, pairs, gammas, eps, truth)``: the BH geometry of [BH, Sect. V], or a
        seeded ``scenarios.bh_geometry.random_instance``.
    """
    if task["variant"] == "BH geometry":
        return bh.sect5_instance()
    return bh.random_instance(np.random.default_rng(task["seed"]))


def exact_set(data: rb.Measurements, relative: float):
    """Pave the exact set: coarse on the prior box, then fine on the coarse hull.

    Parameters
    ----------
    data : relative_bearing.Measurements
        The bearing measurements.
    relative : float
        The fine boxes' width is the coarse hull's largest width divided by ``relative``.

    Returns
    -------
    paving : Paving
        The fine paving (inner and boundary boxes) of the exact set.
    width : float
        Its box width.
    """
    args = (data.landmarks, data.pairs, data.gammas, data.eps)
    box = rb.prior_box(data)
    coarse = rb.exact_paving(*args, _rows(box), float(np.max(box.hi - box.lo)) / 40)
    hull = coarse.hull()
    width = float(np.max(hull.hi - hull.lo)) / relative
    return rb.exact_paving(*args, _rows(hull), width), width


def _rows(box: Box) -> np.ndarray:
    return np.stack([box.lo, box.hi], axis=1)


def sample_exact(paving, count: int, rng: np.random.Generator) -> np.ndarray:
    """Draw points uniformly in the paving's inner boxes (all of them in the exact set).

    Parameters
    ----------
    paving : Paving
        A 2-D paving of the exact set.
    count : int
        Number of points.
    rng : numpy.random.Generator
        The random generator.

    Returns
    -------
    numpy.ndarray
        ``(count, 2)`` points of the exact set.
    """
    inner = paving.inner
    widths = inner[:, :, 1] - inner[:, :, 0]
    weights = np.prod(widths, axis=1)
    k = rng.choice(len(inner), count, p=weights / weights.sum())
    return inner[k, :, 0] + rng.uniform(size=(count, 2)) * widths[k]


def _bounds(task: dict, data: rb.Measurements, paving, width: float) -> dict:
    """Every bound of the module docstring: ``name -> (set, area bracket, extra fields)``."""
    from optbound import optimal

    out = {}
    start = time.perf_counter()
    lin = linearized_localize(data.landmarks, data.pairs, data.gammas, data.eps)
    area = lin.ellipse.volume()
    out["hs96_linearized"] = (
        lin.ellipse,
        (area, area),
        {"guaranteed": False, "rejected": lin.rejected, "seconds": time.perf_counter() - start},
    )
    filters = {}
    for order in (1, 2):
        start = time.perf_counter()
        res = rb.localize(data.landmarks, data.pairs, data.gammas, data.eps, order=order)
        seconds = time.perf_counter() - start
        filters[order] = res.bound
        proof = rb.certify_contains(res.bound, data, paving)
        out[f"bh_L{4 * order}"] = (
            res.bound,
            res.bound.area_bounds(width),
            {"guaranteed": True, "proven": bool(proof.proven), "seconds": seconds},
        )
    start = time.perf_counter()
    ell = rb.best_ellipse(data, paving)
    area = ell.best.volume()
    out["best_ellipse"] = (
        ell.best,
        (area, area),
        {"guaranteed": True, "lower_area": ell.lower, "seconds": time.perf_counter() - start},
    )
    for order in task["orders"]:
        start = time.perf_counter()
        key = f"optimal_pseudo_L{4 * order}"
        try:
            ref = optimal.optimal_pseudo_ellipsoid(
                filters[order].lift, paving.inner, paving.boundary, rb.exact_test(data)
            )
        except ValueError as exc:  # too coarse a paving for the certificate: say so
            out[key] = (None, None, {"guaranteed": True, "error": str(exc)})
            continue
        # The references are nearly flat in some lifted directions: a finer area paving.
        bracket = ref.bound.area_bounds(width / 4)
        out[key] = (
            ref.bound,
            bracket,
            {"guaranteed": True, "seconds": time.perf_counter() - start},
        )
    return out


def run(task: dict) -> dict:
    """Run one task: every bound's area against the exact set's paved area.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    dict
        ``{"records": [...], "notes": [...]}``: one record per bound (certified area-ratio
        bracket, sampled exact points and truth outside it), notes on a truth outside or an
        unproven or refused bound; the figure task adds the PNG under ``"attachments"``.
    """
    landmarks, pairs, gammas, eps, truth = instance(task)
    data = rb.measurements(landmarks, pairs, gammas, eps)
    paving, width = exact_set(data, task["relative"])
    exact_lo, exact_hi = paving.volume_bounds()
    points = sample_exact(paving, SAMPLES, np.random.default_rng(task["seed"]))
    bounds = _bounds(task, data, paving, width)
    records = []
    for criterion, (bound, bracket, extra) in bounds.items():
        rec = {
            "family": NAME,
            "variant": task["variant"],
            "dim": 2,
            "seed": task["seed"],
            "eps_deg": float(np.degrees(eps)),
            "criterion": criterion,
            "bound": KINDS.get(criterion.split("_L")[0], "analytic"),
            "reference": REFERENCE,
            "metric": "area_ratio",
            "exact_lo": float(exact_lo),
            "exact_hi": float(exact_hi),
            "paving_width": width,
            **extra,
        }
        if bound is None:
            rec.update(ratio=None, ratio_lo=None, ratio_hi=None)
        else:
            lo, hi = (float(a) for a in bracket)
            rec.update(
                area_lo=lo,
                area_hi=hi,
                ratio=(lo + hi) / (exact_lo + exact_hi),
                ratio_lo=lo / exact_hi,
                ratio_hi=hi / exact_lo,
                outside=int(np.count_nonzero(~np.asarray(bound.contains(points)))),
                truth_outside=int(not bound.contains(truth)),
            )
        records.append(rec)
    out = {"records": records, "notes": _notes(task, records)}
    if task.get("figure"):
        png = figure(bounds, paving, truth, task["variant"], float(np.degrees(eps)))
        out["attachments"] = {FIGURE: base64.b64encode(png).decode("ascii")}
    return out


def _notes(task: dict, records: list[dict]) -> list[str]:
    """Sentences for the report: the truth outside a bound, an unproven or failed bound."""
    where = f"{task['variant']} instance, seed {task['seed']}"
    notes = []
    for rec in records:
        if rec.get("truth_outside"):
            notes.append(f"{where}: the true position is outside `{rec['criterion']}`.")
        if rec.get("proven") is False:
            notes.append(f"{where}: containment of `{rec['criterion']}` not proven.")
        if "error" in rec:
            notes.append(f"{where}: `{rec['criterion']}` refused: {rec['error']}")
    return notes


STYLES = {
    "hs96_linearized": {"color": "tab:red", "ls": "--", "lw": 1.4},
    "bh_L4": {"color": "tab:blue", "ls": "-", "lw": 1.4},
    "bh_L8": {"color": "k", "ls": "-", "lw": 1.8},
    "best_ellipse": {"color": "tab:orange", "ls": "-.", "lw": 1.4},
    "optimal_pseudo_L4": {"color": "tab:green", "ls": ":", "lw": 1.8},
    "optimal_pseudo_L8": {"color": "tab:purple", "ls": ":", "lw": 1.8},
}


def figure(bounds: dict, paving, truth, variant: str, eps_deg: float) -> bytes:
    """Draw the paved exact set, every bound and the truth, zoomed on the exact set.

    Parameters
    ----------
    bounds : dict
        Bound name -> ``(set or None, area bracket, extra fields)``; None is not drawn.
    paving : Paving
        The paving of the exact set.
    truth : numpy.ndarray
        The true position.
    variant : str
        The instance's variant, for the title.
    eps_deg : float
        The bearing error bound in degrees, for the title.

    Returns
    -------
    bytes
        The PNG image.
    """
    from matplotlib.collections import PolyCollection

    from optbound.report.figures import pyplot

    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 6.5), layout="constrained")
    for boxes, alpha, label in ((paving.inner, 1.0, "exact set"), (paving.boundary, 0.4, None)):
        polys = [np.column_stack([b[0, [0, 1, 1, 0]], b[1, [0, 0, 1, 1]]]) for b in boxes]
        ax.add_collection(
            PolyCollection(polys, facecolor="0.6", edgecolor="none", alpha=alpha, label=label)
        )
    hull = paving.hull()
    pad = 0.6 * (hull.hi - hull.lo)
    window = Box(hull.lo - pad, hull.hi + pad)
    t = np.linspace(0.0, 2.0 * np.pi, 400)
    for name, (bound, _, _) in bounds.items():
        if bound is None:
            continue
        if hasattr(bound, "boundary") and hasattr(bound, "lift"):
            lines = bound.boundary(500, _rows(window))
        else:
            chol = np.linalg.cholesky(bound.shape)
            lines = [bound.center + (chol @ np.vstack([np.cos(t), np.sin(t)])).T]
        for k, line in enumerate(lines):
            ax.plot(line[:, 0], line[:, 1], label=name if k == 0 else None, **STYLES[name])
    ax.plot(*truth, "k*", ms=10, label="true position")
    ax.set_xlim(window.lo[0], window.hi[0])
    ax.set_ylim(window.lo[1], window.hi[1])
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(
        f"Bearing-only localization, {variant} (eps = {eps_deg:.1f}°): bounds vs exact set"
    )
    ax.legend(fontsize=8, loc="upper right")
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110)
    plt.close(fig)
    return buf.getvalue()


def cost(task: dict) -> float:
    """Estimate the seconds of one task: the L = 4 reference ~3 s, the L = 8 one ~8 s.

    Measured at load ~4.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    float
        Estimated seconds on one core.
    """
    return 1.5 + 3.0 * (1 in task["orders"]) + 8.0 * (2 in task["orders"])


FAMILY = Family(
    name=NAME,
    title="Localization: bearing-only bounds vs the exact set",
    kind="tightness",
    requires=(
        "optbound.localization.relative_bearing:localize",
        "optbound.localization.linearized_bearing:linearized_localize",
        "optbound.optimal:optimal_pseudo_ellipsoid",
    ),
    tasks=tasks,
    run=run,
    cost=cost,
)
