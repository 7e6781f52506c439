"""LJMW97 Appendix A: SIVIA on the unit disc minus an ellipse (Fig. 6), and its area bracket.

[LJMW97, Appendix A] characterises ``Q = {(x, y) : x^2 + y^2 <= 1, 2 x^2 + y^2 >= 1}``
(eqs. (12)-(13)) in the search box ``X(0) = [-2.5, 2.5] x [-2, 2]`` by SIVIA's inner,
indeterminate and outside subpavings, ``Q_in ⊂ Q ⊂ Q_in ∪ Q_ind`` (Fig. 6, no numbers). The
exact area, ``pi (1 - 1/sqrt 2) ≈ 0.920151`` (disc area pi minus ellipse area pi / sqrt 2), is
not in the paper; it is the anchor the bracket is checked against here, at several eps.
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
from matplotlib.patches import Patch

from optbound.interval import Paving, sivia
from optbound.interval.plot import COLORS
from optbound.papers_repro._common import claim_table, finish_axes, pyplot, run_cli, save_figure
from optbound.report.tables import markdown_table

PAPER = "LJMW97"
X0 = [[-2.5, 2.5], [-2.0, 2.0]]
Y = [[-np.inf, 1.0], [1.0, np.inf]]  # x^2 + y^2 <= 1 (eq. 12) and 2 x^2 + y^2 >= 1 (eq. 13)
EXACT_AREA = np.pi * (1.0 - 1.0 / np.sqrt(2.0))
EPS = (0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002)
QUICK_EPS = (0.2, 0.1, 0.05, 0.02, 0.01)
FIGURE_EPS = 0.05


def constraints(x, y):
    """The two functions of [LJMW97, eqs. (12)-(13)], on points or on interval boxes."""
    return x**2 + y**2, 2 * x**2 + y**2


def characterise(eps: float) -> tuple[Paving, float]:
    """SIVIA paving of Q at ``eps`` and its wall-clock time in seconds."""
    start = time.perf_counter()
    paving = sivia(constraints, Y, X0, eps)
    return paving, time.perf_counter() - start


def _figure(paving: Paving, out_dir: Path) -> Path:
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 6.2))
    paving.plot(ax=ax)
    t = np.linspace(0, 2 * np.pi, 400)
    ax.plot(np.cos(t), np.sin(t), "k", lw=1.2, label="x² + y² = 1 (eq. 12)")
    ax.plot(np.cos(t) / np.sqrt(2), np.sin(t), "k--", lw=1.2, label="2x² + y² = 1 (eq. 13)")
    handles = [
        Patch(facecolor=COLORS["inner"], edgecolor="k", label=f"Q_in ({len(paving.inner)})"),
        Patch(facecolor=COLORS["boundary"], edgecolor="k", label=f"Q_ind ({len(paving.boundary)})"),
        Patch(facecolor=COLORS["outside"], edgecolor="k", label=f"Q_out ({len(paving.outside)})"),
    ]
    ax.legend(
        handles=handles + ax.get_lines(),
        fontsize=8,
        loc="upper right",
        framealpha=0.95,
    )
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    finish_axes(
        ax,
        f"LJMW97 Fig. 6: SIVIA subpavings of Q in X(0), eps = {paving.eps} "
        "(box counts in the legend)",
    )
    return save_figure(fig, out_dir, "ljmw97_fig6_paving.png")


def _convergence_figure(rows: list[dict], out_dir: Path) -> Path:
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    eps = [r["eps"] for r in rows]
    ax.plot(eps, [r["inner_area"] for r in rows], "o-", color="#d62728", label="area(Q_in)")
    ax.plot(eps, [r["outer_area"] for r in rows], "s-", color="#b8860b", label="area(Q_in ∪ Q_ind)")
    ax.axhline(EXACT_AREA, color="k", ls="--", label="exact π(1 − 1/√2)")
    ax.set_xscale("log")
    ax.set_xlabel("eps (SIVIA width threshold)")
    ax.set_ylabel("area")
    ax.set_title("LJMW97 Appendix A: guaranteed area bracket vs eps")
    ax.legend()
    return save_figure(fig, out_dir, "ljmw97_area_bracket.png")


def main(out_dir: Path | str, quick: bool = False, eps_values=None) -> dict:
    """Pave Q at each eps; draw Fig. 6 (at ``FIGURE_EPS`` if listed) and the bracket plot.

    ``eps_values`` defaults to ``EPS``, or ``QUICK_EPS`` when ``quick``.

    Returns
    -------
    dict
        ``rows`` (per eps: areas, box counts, seconds), ``exact_area``, ``figures``,
        ``markdown``.
    """
    out_dir = Path(out_dir)
    eps_values = eps_values if eps_values is not None else (QUICK_EPS if quick else EPS)
    rows, figure_paving = [], None
    for eps in eps_values:
        paving, seconds = characterise(eps)
        inner, outer = paving.volume_bounds()
        rows.append(
            {
                "eps": eps,
                "inner_area": inner,
                "outer_area": outer,
                "n_inner": len(paving.inner),
                "n_boundary": len(paving.boundary),
                "n_outside": len(paving.outside),
                "seconds": seconds,
            }
        )
        if eps == FIGURE_EPS or figure_paving is None:
            figure_paving = paving
    figures = [_figure(figure_paving, out_dir), _convergence_figure(rows, out_dir)]
    claims = [
        (
            "Q_in ⊂ Q ⊂ Q_in ∪ Q_ind (areas, every eps)",
            "'Q_in ⊂ Q ⊂ Q_in ∪ Q_ind'",
            "holds"
            if all(r["inner_area"] <= EXACT_AREA <= r["outer_area"] for r in rows)
            else "VIOLATED",
        ),
        (
            "area of Q",
            "— ('we do not know ... its shape and volume')",
            f"exact {EXACT_AREA:.6f} (known fact); bracket at eps = {rows[-1]['eps']}: "
            f"[{rows[-1]['inner_area']:.6f}, {rows[-1]['outer_area']:.6f}]",
        ),
    ]
    table = markdown_table(
        (
            "eps",
            "area(Q_in)",
            "exact",
            "area(Q_in ∪ Q_ind)",
            "width",
            "inner",
            "boundary",
            "outside",
            "time",
        ),
        [
            (
                r["eps"],
                f"{r['inner_area']:.6f}",
                f"{EXACT_AREA:.6f}",
                f"{r['outer_area']:.6f}",
                f"{r['outer_area'] - r['inner_area']:.4g}",
                r["n_inner"],
                r["n_boundary"],
                r["n_outside"],
                f"{1e3 * r['seconds']:.1f} ms",
            )
            for r in rows
        ],
    )
    markdown = "\n\n".join(
        [
            "## LJMW97 Appendix A: SIVIA on the unit disc minus an ellipse",
            claim_table(claims),
            "Area bracket and box counts:",
            table,
        ]
    )
    return {"rows": rows, "exact_area": EXACT_AREA, "figures": figures, "markdown": markdown}


if __name__ == "__main__":
    run_cli(main, __doc__.splitlines()[0])
