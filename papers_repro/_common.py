"""Shared plumbing of the reproduction scripts: discovery, command line, figures, tables.

A reproduction script is a module ``papers_repro/<key>_<topic>.py`` (name not starting with
``_``) with a module-level ``PAPER = "<KEY>"`` and ``main(out_dir, quick=False) -> dict``
returning at least ``{"markdown": str, "figures": list[Path]}``. :func:`scripts` finds them
without importing them (it reads ``PAPER`` from the source), so ``optbound repro``,
``optbound bench`` and ``run_all`` pick up a new script with no registry to edit.
"""

from __future__ import annotations

import argparse
import ast
import importlib
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from optbound.bench.registry import PAPERS
from optbound.report.figures import pyplot
from optbound.report.tables import markdown_table
from optbound.sets import Ellipsoid, Strip

HERE = Path(__file__).resolve().parent
DEFAULT_OUT = HERE / "out"
CLAIM_HEADERS = ("quantity", "paper", "optbound")
#: Paper keys in the order of the report (others follow alphabetically).
PAPER_ORDER = PAPERS


@dataclass(frozen=True)
class Script:
    """A reproduction script found by :func:`scripts`: its module name and paper key."""

    name: str
    paper: str

    @property
    def module(self) -> str:
        return f"{__package__}.{self.name}"

    def run(self, out_dir: Path | str, quick: bool = False) -> dict:
        """Import the script and return ``main(out_dir, quick=quick)``."""
        result = importlib.import_module(self.module).main(Path(out_dir), quick=quick)
        for key in ("markdown", "figures"):
            if key not in result:
                raise ValueError(f"{self.module}.main returned no {key!r}")
        return result


def _paper_of(path: Path) -> str | None:
    """The string assigned to ``PAPER`` at module level of ``path``, if any (not imported)."""
    for node in ast.parse(path.read_text(), str(path)).body:
        if isinstance(node, ast.Assign) and any(
            isinstance(t, ast.Name) and t.id == "PAPER" for t in node.targets
        ):
            value = node.value
            if isinstance(value, ast.Constant) and isinstance(value.value, str):
                return value.value
    return None


def scripts(papers: Sequence[str] | None = None) -> list[Script]:
    """The reproduction scripts in ``papers_repro/``, in paper order, then by name.

    Parameters
    ----------
    papers : sequence of str, optional
        Only these paper keys (case-insensitive); default all.

    Raises
    ------
    ValueError
        If ``papers`` names a key no script reproduces.
    """
    found = []
    for path in sorted(HERE.glob("*.py")):
        paper = None if path.name.startswith("_") else _paper_of(path)
        if paper is not None:
            found.append(Script(path.stem, paper))
    if papers is not None:
        wanted = {key.upper() for key in papers}
        unknown = sorted(wanted - {s.paper.upper() for s in found})
        if unknown:
            known = sorted({s.paper for s in found})
            raise ValueError(f"papers has unknown keys {unknown}; scripts exist for {known}")
        found = [s for s in found if s.paper.upper() in wanted]
    rank = {key: i for i, key in enumerate(PAPER_ORDER)}
    return sorted(found, key=lambda s: (rank.get(s.paper, len(rank)), s.paper, s.name))


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
    """Parse ``--out`` and ``--quick``, run ``main(out_dir, quick=...)`` and print its tables."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT, help="output folder for PNGs")
    parser.add_argument(
        "--quick", action="store_true", help="the fast variant (smaller sweeps, seconds)"
    )
    args = parser.parse_args()
    result = main(args.out, quick=args.quick)
    print(result["markdown"])
    return result
