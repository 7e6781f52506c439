"""PNG figures of a run: ratio histograms, tightness vs recursion depth, 2-D instance pictures.

matplotlib is imported lazily with the non-interactive Agg backend, so writing a report
works on machines without a display.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from optbound.report.summary import group, without_degenerate_lower
from optbound.sets import Ellipsoid, Strip

# Gaps ratio - 1 below this are solver-level noise; the histograms pile them into the first bin.
GAP_FLOOR = 1e-6
LINEAR_FROM = 0.01  # every |ratio - 1| at least this: a linear histogram axis (_gap_panel)
GRID = 500  # pixels per side of the exact-set shading
EXACT_COLOR = "#d0d0d0"
BOUND_COLORS = {
    "trace": "tab:red",
    "volume": "tab:blue",
    "projection": "tab:orange",
    "robust": "tab:green",
    "recursive": "tab:purple",
}
#: Dash pattern of each SDP reference (matched in its label), and their colours in order.
SDP_DASHES = {
    "volume": (0, (5, 3)),
    "trace": (0, (1.5, 1.5)),
    "projection": (0, (6, 2, 1.5, 2)),
    "batch": (0, (3, 1.5, 1, 1.5, 1, 1.5)),
}
SDP_COLORS = ("k", "#7a0000", "#003d7a", "#3d3d00")
#: Inset zoom when the exact set's extent is below this fraction of the panel's.
ZOOM_BELOW = 0.3


def pyplot():
    """Import matplotlib.pyplot with the non-interactive Agg backend (works without a display).

    Returns
    -------
    module
        ``matplotlib.pyplot``.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _gap_bins(gaps: np.ndarray) -> np.ndarray:
    """Bins for ``ratio - 1`` on a symlog axis: log-spaced on each side of ±GAP_FLOOR.

    Gaps within ±GAP_FLOOR (solver-level agreement) share the centre bin; negative gaps (the
    analytic bound beat the reference) get their own log bins instead of being hidden.
    """
    top = np.log10(max(float(gaps.max()), GAP_FLOOR * 10))
    bins = [-GAP_FLOOR, *np.logspace(np.log10(GAP_FLOOR), top, 24)]
    if gaps.min() < -GAP_FLOOR:
        bottom = np.log10(-float(gaps.min()))
        bins = [*(-np.logspace(bottom, np.log10(GAP_FLOOR), 12)[:-1]), *bins]
    return np.array(bins)


def ratio_histograms(records: list[dict], path: Path, title: str) -> Path:
    """Plot one panel per criterion: histogram of ``ratio - 1`` (symlog axis), stacked by variant.

    Parameters
    ----------
    records : list of dict
        Tightness records with ``"criterion"``, ``"reference"``, ``"variant"`` and
        ``"ratio"`` (records with a None ratio are left out).
    path : Path
        The PNG file to write.
    title : str
        The figure's title.

    Returns
    -------
    Path
        ``path``.
    """
    plt = pyplot()
    panels = group([r for r in records if r["ratio"] is not None], ("criterion", "reference"))
    ncols = min(3, len(panels))
    nrows = -(-len(panels) // ncols)
    fig, axes = plt.subplots(
        nrows, ncols, figsize=(4.6 * ncols, 3.4 * nrows + 0.8), squeeze=False, layout="constrained"
    )
    for ax, ((criterion, reference), recs) in zip(axes.ravel(), panels.items(), strict=False):
        _gap_panel(ax, recs, criterion, reference)
    for ax in axes.ravel()[len(panels) :]:
        ax.axis("off")
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(
        handles, labels, loc="outside lower center", ncol=len(labels), title="variant", fontsize=9
    )
    fig.suptitle(
        f"{title}: left of 0 the reference is larger than the analytic bound; "
        f"|ratio − 1| < {GAP_FLOOR:g} is the bar at 0",
        fontsize=10,
    )
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def _gap_panel(ax, records: list[dict], criterion: str, reference: str) -> None:
    """One histogram of ``ratio - 1``, stacked by variant, titled by what the bound is.

    The symlog axis resolves gaps from GAP_FLOOR to orders of magnitude above; when every gap
    is at least LINEAR_FROM (no ratio near 1), it would be mostly empty and a linear axis is
    used instead.
    """
    by_variant = group(records, ("variant",))
    gaps = [np.array([r["ratio"] for r in v]) - 1.0 for v in by_variant.values()]
    every = np.concatenate(gaps)
    linear = float(np.min(np.abs(every))) >= LINEAR_FROM
    bins = np.linspace(min(0.0, every.min()), every.max(), 25) if linear else _gap_bins(every)
    labels = [str(key[0]) for key in by_variant]
    # One filled outline per variant, not one bar patch per bin: the same stack, drawn faster.
    ax.hist(gaps, bins=bins, stacked=True, histtype="stepfilled", label=labels)
    if not linear:
        ax.set_xscale("symlog", linthresh=GAP_FLOOR, linscale=0.5)
    ax.axvline(0.0, color="k", lw=0.8)
    kind = records[0].get("bound", "analytic")  # the families label their references
    ax.set_title(f"{kind} {criterion} vs {reference}", fontsize=10)
    ax.set_xlabel("ratio − 1", fontsize=9)
    ax.set_ylabel("instances", fontsize=9)
    ax.tick_params(labelsize=8)
    ax.grid(alpha=0.3)


def recursive_plot(records: list[dict], path: Path) -> Path:
    """Plot the ratio of the recursive filter to the batch SDP against the depth k.

    One panel per strip width: per dimension the median line and the min-max band, and the
    median ratio to the lower bound on the optimum (dotted; degenerate lower bounds left
    out, :func:`~optbound.report.summary.without_degenerate_lower`).

    Parameters
    ----------
    records : list of dict
        Records of the ``recursive`` family, with ``"variant"``, ``"dim"``, ``"k"``,
        ``"ratio"`` and ``"lower_ratio"``.
    path : Path
        The PNG file to write.

    Returns
    -------
    Path
        ``path``.
    """
    plt = pyplot()
    cleaned, flagged = without_degenerate_lower(records)
    by_variant = group([r for r in cleaned if r["ratio"] is not None], ("variant",))
    fig, axes = plt.subplots(
        1,
        len(by_variant),
        figsize=(5.2 * len(by_variant), 4.4),
        squeeze=False,
        sharey=True,
        layout="constrained",
    )
    for ax, ((variant,), recs) in zip(axes[0], by_variant.items(), strict=True):
        for (dim,), drecs in sorted(group(recs, ("dim",)).items()):
            at_k = group(sorted(drecs, key=lambda r: r["k"]), ("k",))
            ks = [k for (k,) in at_k]
            vals = [np.array([r["ratio"] for r in v]) for v in at_k.values()]
            marker = "o" if len(ks) <= 12 else None
            (line,) = ax.plot(
                ks, [np.median(v) for v in vals], marker=marker, ms=3, label=f"n = {dim}"
            )
            ax.fill_between(
                ks,
                [v.min() for v in vals],
                [v.max() for v in vals],
                color=line.get_color(),
                alpha=0.15,
            )
            lows = [
                (k, np.median(lo))
                for (k,), v in at_k.items()
                if (lo := [r["lower_ratio"] for r in v if r.get("lower_ratio") is not None])
            ]
            if lows:
                ax.plot(*zip(*lows, strict=True), ls=":", color=line.get_color())
        ax.set_yscale("log")
        ax.set_xlabel("k (strips fused)")
        ax.set_title(f"strips of {variant}", fontsize=10)
        ax.grid(alpha=0.3, which="both")
        ax.axhline(1.0, color="k", lw=0.8)
    axes[0][0].set_ylabel("volume ratio")
    handles, labels = axes[0][0].get_legend_handles_labels()
    (dotted,) = axes[0][0].plot([], [], ls=":", color="0.3")
    fig.legend(
        [*handles, dotted],
        [*labels, "vs lower bound (median)"],
        loc="outside lower center",
        ncol=len(labels) + 1,
        fontsize=8,
        title="vs batch SDP: median line, min–max band",
        title_fontsize=8,
    )
    title = (
        "Recursive analytic filter vs batch SDP (solid; below 1: the SDP is loose) and vs a "
        "lower bound on the optimum (dotted)"
    )
    if flagged:
        title += f"\n{len(flagged)} degenerate lower bound(s) left out (listed in the report)"
    fig.suptitle(title, fontsize=10)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def _ellipsoid(spec: dict) -> Ellipsoid:
    return Ellipsoid(spec["center"], spec["shape"])


def _exact_mask(E: Ellipsoid, strips: list[Strip], xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
    """Membership of every grid point in ``E ∩ strips`` (a fine-grid picture of the exact set)."""
    X, Y = np.meshgrid(xs, ys)
    pts = np.column_stack([X.ravel(), Y.ravel()])
    inside = E.contains(pts)
    for S in strips:
        inside &= S.contains(pts)
    return inside.reshape(X.shape)


def _limits(ellipsoids: list[Ellipsoid]) -> tuple[np.ndarray, np.ndarray]:
    """A square view around all the ellipses (equal panels, equal aspect)."""
    boxes = [E.bounding_box() for E in ellipsoids]
    lo = np.min([b.lo for b in boxes], axis=0)
    hi = np.max([b.hi for b in boxes], axis=0)
    half = 0.56 * float(np.max(hi - lo))
    mid = 0.5 * (lo + hi)
    return mid - half, mid + half


def _minkowski_boundary(summands: list[Ellipsoid], m: int = 720) -> np.ndarray:
    """Boundary of a Minkowski sum of ellipses, in order: the sum of the summands' support
    points ``c + C d / sqrt(d^T C d)`` for each direction d."""
    t = np.linspace(0.0, 2.0 * np.pi, m)
    d = np.column_stack([np.cos(t), np.sin(t)])
    return sum(
        E.center + (d @ E.shape) / np.sqrt(np.einsum("ij,jk,ik->i", d, E.shape, d))[:, None]
        for E in summands
    )


def _draw_instance(ax, fig_spec: dict) -> None:
    """One panel: the exact set (shaded, outlined on top of the bounds) and every bound over
    it, with an inset zoom when the exact set is small in the panel; ``summands`` specs show
    a Minkowski sum, the others a prior ellipse cut by strips."""
    bounds = [(b["label"], _ellipsoid(b)) for b in fig_spec["bounds"]]
    lo, hi = _limits([B for _, B in bounds])
    exact = _draw_exact(ax, fig_spec, lo, hi, prior=True)
    for label, B in bounds:
        ax.plot(*B.boundary(400).T, label=label, **_style(label))
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.set_xlabel("x₁", fontsize=8)
    ax.set_ylabel("x₂", fontsize=8)
    ax.set_title(f"{fig_spec['title']} (seed {fig_spec['seed']})", fontsize=9)
    ax.tick_params(labelsize=7)
    if exact is not None and np.max(exact[1] - exact[0]) < ZOOM_BELOW * np.max(hi - lo):
        _zoom(ax, fig_spec, bounds, exact)


def _draw_exact(ax, fig_spec: dict, lo, hi, prior: bool) -> tuple[np.ndarray, np.ndarray] | None:
    """Shade the exact set and outline it (above the bounds' lines); its bounding box."""
    if "summands" in fig_spec:
        boundary = _minkowski_boundary([_ellipsoid(e) for e in fig_spec["summands"]])
        ax.fill(*boundary.T, color=EXACT_COLOR)
        ax.plot(*boundary.T, color="0.25", lw=0.7, zorder=5)
        return boundary.min(axis=0), boundary.max(axis=0)
    E = _ellipsoid(fig_spec["ellipsoid"])
    strips = [Strip(s["a"], s["b"]) for s in fig_spec["strips"]]
    xs, ys = np.linspace(lo[0], hi[0], GRID), np.linspace(lo[1], hi[1], GRID)
    mask = _exact_mask(E, strips, xs, ys)
    ax.contourf(xs, ys, mask.astype(float), levels=[0.5, 1.5], colors=[EXACT_COLOR])
    ax.contour(xs, ys, mask.astype(float), levels=[0.5], colors=["0.25"], linewidths=0.7, zorder=5)
    if prior:
        ax.plot(*E.boundary(400).T, color="0.55", lw=0.8, label="prior ellipse")
        for S in strips:
            _draw_strip(ax, S, lo, hi)
    if not mask.any():
        return None
    rows, cols = np.nonzero(mask)
    return np.array([xs[cols.min()], ys[rows.min()]]), np.array([xs[cols.max()], ys[rows.max()]])


def _zoom(ax, fig_spec: dict, bounds: list, exact: tuple[np.ndarray, np.ndarray]) -> None:
    """An inset magnifying the exact set and the bounds' lines around it."""
    lo, hi = exact
    half = 0.75 * float(np.max(hi - lo)) + 1e-12
    mid = 0.5 * (lo + hi)
    zlo, zhi = mid - half, mid + half
    inset = ax.inset_axes([0.6, 0.6, 0.38, 0.38])
    _draw_exact(inset, fig_spec, zlo, zhi, prior=False)
    for label, B in bounds:
        inset.plot(*B.boundary(2000).T, **{**_style(label), "lw": 1.2})
    inset.set_xlim(zlo[0], zhi[0])
    inset.set_ylim(zlo[1], zhi[1])
    inset.set_aspect("equal")
    inset.set_xticks([])
    inset.set_yticks([])
    # Inside the inset: a title above it would reach past the panel's top edge, over the
    # panel's own title (the inset sits in the panel's top-right corner).
    inset.text(
        0.5,
        0.03,
        "zoom on the exact set",
        transform=inset.transAxes,
        ha="center",
        va="bottom",
        fontsize=6,
        bbox={"facecolor": "white", "edgecolor": "none", "alpha": 0.8, "pad": 1},
        zorder=10,
    )
    ax.indicate_inset_zoom(inset, edgecolor="0.3")


def _style(label: str) -> dict:
    """One style per kind of bound across all panels.

    Analytic bounds: wide translucent lines, one colour per criterion. SDP references: thin
    dark lines on top, one dash pattern per reference (volume, trace, projection, ...), so
    two references in one panel stay apart.
    """
    if label.startswith("SDP"):
        for i, (key, dash) in enumerate(SDP_DASHES.items()):
            if key in label:
                return {
                    "color": SDP_COLORS[i % len(SDP_COLORS)],
                    "lw": 1.3,
                    "ls": dash,
                    "zorder": 4,
                }
        return {"color": "k", "lw": 1.3, "ls": (0, (1, 1)), "zorder": 4}
    # Wide and translucent, so that a bound equal to the SDP optimum shows beside its dashes.
    for key, color in BOUND_COLORS.items():
        if key in label:
            return {"color": color, "lw": 2.6, "alpha": 0.6}
    return {"lw": 2.6, "alpha": 0.6}


def _draw_strip(ax, S: Strip, lo: np.ndarray, hi: np.ndarray) -> None:
    """The two boundary lines a^T x = b ± 1, clipped to the axes by parametrising along them."""
    a = S.a
    t = np.linspace(-1.0, 1.0, 2) * float(np.linalg.norm(hi - lo)) * 2
    direction = np.array([-a[1], a[0]]) / np.linalg.norm(a)
    for offset in (S.b - 1.0, S.b + 1.0):
        base = a * offset / (a @ a)
        pts = base + t[:, None] * direction
        ax.plot(pts[:, 0], pts[:, 1], color="0.4", lw=0.6, ls=":")


def instance_pictures(figures: list[dict], path: Path) -> Path:
    """Draw each 2-D instance: the exact set shaded on a fine grid, every bound drawn over it.

    Parameters
    ----------
    figures : list of dict
        Instance specs as the tightness families record them: ``"title"``, ``"seed"``,
        ``"bounds"`` (label, centre and shape of each ellipse) and either ``"summands"`` (a
        Minkowski sum) or ``"ellipsoid"`` and ``"strips"`` (a prior cut by strips).
    path : Path
        The PNG file to write.

    Returns
    -------
    Path
        ``path``.
    """
    plt = pyplot()
    from matplotlib.patches import Patch

    ncols = min(3, len(figures))
    nrows = -(-len(figures) // ncols)
    fig, axes = plt.subplots(
        nrows, ncols, figsize=(4.2 * ncols, 4.2 * nrows + 0.9), squeeze=False, layout="constrained"
    )
    for ax, spec in zip(axes.ravel(), figures, strict=False):
        _draw_instance(ax, spec)
    for ax in axes.ravel()[len(figures) :]:
        ax.axis("off")
    legend = {"exact set": Patch(color=EXACT_COLOR)}
    for ax in axes.ravel():
        for handle, label in zip(*ax.get_legend_handles_labels(), strict=True):
            legend.setdefault(label, handle)
    fig.legend(legend.values(), legend.keys(), loc="outside lower center", ncol=4, fontsize=8)
    fig.suptitle(
        "Bounds over the exact set (grey): prior ellipse ∩ strips (dotted lines) on a fine "
        "grid, or the exact Minkowski sum"
    )
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
