"""Shared plumbing of the reproduction scripts: command line, figures, tables, drawing."""

from __future__ import annotations

import argparse
from collections.abc import Callable, Sequence
from pathlib import Path

import numpy as np

from optbound.report.figures import pyplot
from optbound.report.tables import markdown_table
from optbound.sets import Ellipsoid, Strip

DEFAULT_OUT = Path(__file__).resolve().parent / "out"
CLAIM_HEADERS = ("quantity", "paper", "optbound")


def save_figure(fig, out_dir: Path, name: str) -> Path:
    """Write ``fig`` as ``out_dir/name`` (PNG), close it and return the path."""
    out_dir.mkdir(parents=True, exist_ok=True)
    path = out_dir / name
    fig.savefig(path, dpi=120, bbox_inches="tight")
    pyplot().close(fig)
    return path


def claim_table(rows: Sequence[Sequence[str]]) -> str:
    """The ``quantity | paper | optbound`` table every script prints."""
    return markdown_table(CLAIM_HEADERS, rows)


def area(E: Ellipsoid, dims: Sequence[int] = (0, 1)) -> float:
    """Area of the projection of ``E`` onto two coordinates."""
    return E.project(list(dims)).volume()


def half_extent(E: Ellipsoid, dim: int) -> float:
    """Half-width of ``E`` along one coordinate axis (half of its projection's length)."""
    return float(np.sqrt(E.shape[dim, dim]))


def draw_ellipse(ax, E: Ellipsoid, dims: Sequence[int] = (0, 1), **style) -> None:
    """Outline of (the projection of) ``E`` on two coordinates."""
    pts = E.project(list(dims)).boundary(400)
    ax.plot(pts[:, 0], pts[:, 1], **style)


def draw_strip(ax, S: Strip, xlim, ylim, **style) -> None:
    """Shade the 2-D strip ``S`` inside the window ``xlim`` x ``ylim`` (a clipped polygon)."""
    from matplotlib.patches import Polygon

    a, b = S.a, S.b
    t = np.array([-a[1], a[0]]) / np.linalg.norm(a)  # direction along the strip
    far = 4.0 * max(np.ptp(xlim), np.ptp(ylim)) + float(np.abs(np.r_[xlim, ylim]).max())
    base_lo = a * (b - 1.0) / (a @ a)
    base_hi = a * (b + 1.0) / (a @ a)
    corners = [base_lo - far * t, base_lo + far * t, base_hi + far * t, base_hi - far * t]
    ax.add_patch(Polygon(corners, closed=True, **style))


def finish_axes(ax, title: str, xlim=None, ylim=None) -> None:
    """Equal aspect, limits and a title: the common look of the 2-D panels."""
    if xlim is not None:
        ax.set_xlim(xlim)
        ax.set_ylim(ylim)
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=9)


def run_cli(main: Callable[..., dict], description: str) -> dict:
    """Parse ``--out`` (and ``--quick``), run ``main(out_dir)`` and print its Markdown tables."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT, help="output folder for PNGs")
    parser.add_argument("--quick", action="store_true", help="fast variant (<= ~20 s)")
    args = parser.parse_args()
    result = main(args.out, quick=True) if args.quick else main(args.out)
    print(result["markdown"])
    return result
