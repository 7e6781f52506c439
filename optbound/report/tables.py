"""Markdown tables and number formatting shared by report.md, the documentation and the terminal."""

from __future__ import annotations

from collections.abc import Sequence


def fmt_ratio(x: float | None) -> str:
    """Format a ratio: near 1 with enough digits to show the gap, otherwise 4 significant digits.

    Parameters
    ----------
    x : float or None
        The ratio; None for a missing one.

    Returns
    -------
    str
        7 decimals within 1e-3 of 1, else 4 significant digits; "–" for None.

    Examples
    --------
    >>> from optbound.report.tables import fmt_ratio
    >>> fmt_ratio(1.00001234), fmt_ratio(2.345678), fmt_ratio(None)
    ('1.0000123', '2.346', '–')
    """
    if x is None:
        return "–"
    if abs(x - 1.0) < 1e-3:
        return f"{x:.7f}"
    return f"{x:.4g}"


def fmt_seconds(x: float) -> str:
    """Format a duration with a readable unit (ns, µs, ms, s).

    Parameters
    ----------
    x : float
        The duration [s], >= 0.

    Returns
    -------
    str
        3 significant digits and the largest unit not exceeding ``x``.

    Examples
    --------
    >>> from optbound.report.tables import fmt_seconds
    >>> fmt_seconds(2.5e-5), fmt_seconds(3.0)
    ('25 µs', '3 s')
    """
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6)):
        if x >= scale:
            return f"{x / scale:.3g} {unit}"
    return f"{x / 1e-9:.3g} ns"


def fmt_factor(x: float) -> str:
    """Format a speed ratio such as ``1.2e+03×`` or ``37×``.

    Parameters
    ----------
    x : float
        The ratio.

    Returns
    -------
    str
        3 significant digits and "×".
    """
    return f"{x:.3g}×"


def markdown_table(headers: Sequence[str], rows: Sequence[Sequence[str]]) -> str:
    """Render a GitHub-flavoured Markdown table (pipes inside cells are escaped).

    Parameters
    ----------
    headers : sequence of str
        The column names.
    rows : sequence of sequence
        The cells, one sequence per row (converted with ``str``).

    Returns
    -------
    str
        The table, without a trailing newline.

    Examples
    --------
    >>> from optbound.report.tables import markdown_table
    >>> print(markdown_table(["a", "b"], [["1", "x|y"]]))
    | a | b |
    |---|---|
    | 1 | x\\|y |
    """

    def line(cells: Sequence[str]) -> str:
        return "| " + " | ".join(str(c).replace("|", "\\|") for c in cells) + " |"

    out = [line(headers), "|" + "|".join("---" for _ in headers) + "|"]
    out.extend(line(row) for row in rows)
    return "\n".join(out)


def text_table(headers: Sequence[str], rows: Sequence[Sequence[str]]) -> str:
    """Render a plain fixed-width table for the terminal.

    Parameters
    ----------
    headers : sequence of str
        The column names.
    rows : sequence of sequence
        The cells, one sequence per row, each as long as ``headers``.

    Returns
    -------
    str
        The header, a dashed rule and the rows, columns left-aligned two spaces apart.

    Raises
    ------
    ValueError
        If a row's length differs from ``headers``'s.
    """
    cols = list(zip(headers, *rows, strict=True))
    widths = [max(len(str(c)) for c in col) for col in cols]

    def line(cells: Sequence[str]) -> str:
        return "  ".join(str(c).ljust(w) for c, w in zip(cells, widths, strict=True)).rstrip()

    return "\n".join([line(headers), line(["-" * w for w in widths])] + [line(r) for r in rows])
