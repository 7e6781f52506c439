"""Markdown tables and number formatting shared by report.md, the documentation and the terminal."""

from __future__ import annotations

from collections.abc import Sequence


def fmt_ratio(x: float | None) -> str:
    """A ratio: near 1 with enough digits to show the gap, otherwise 4 significant digits."""
    if x is None:
        return "–"
    if abs(x - 1.0) < 1e-3:
        return f"{x:.7f}"
    return f"{x:.4g}"


def fmt_seconds(x: float) -> str:
    """A duration with a readable unit (ns, µs, ms, s)."""
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6)):
        if x >= scale:
            return f"{x / scale:.3g} {unit}"
    return f"{x / 1e-9:.3g} ns"


def fmt_factor(x: float) -> str:
    """A speed ratio such as ``1.2e+03×`` or ``37×``."""
    return f"{x:.3g}×"


def markdown_table(headers: Sequence[str], rows: Sequence[Sequence[str]]) -> str:
    """A GitHub-flavoured Markdown table (pipes inside cells are escaped)."""

    def line(cells: Sequence[str]) -> str:
        return "| " + " | ".join(str(c).replace("|", "\\|") for c in cells) + " |"

    out = [line(headers), "|" + "|".join("---" for _ in headers) + "|"]
    out.extend(line(row) for row in rows)
    return "\n".join(out)


def text_table(headers: Sequence[str], rows: Sequence[Sequence[str]]) -> str:
    """A plain fixed-width table for the terminal."""
    cols = list(zip(headers, *rows, strict=True))
    widths = [max(len(str(c)) for c in col) for col in cols]

    def line(cells: Sequence[str]) -> str:
        return "  ".join(str(c).ljust(w) for c, w in zip(cells, widths, strict=True)).rstrip()

    return "\n".join([line(headers), line(["-" * w for w in widths])] + [line(r) for r in rows])
