"""Per-claim verdicts of the reproduction tables: reproduced / partly / not reproduced.

A verdict is computed from the numbers printed beside it, by a rule stated in the report next
to the table (the thresholds are the scripts' module constants, fixed before the runs). Rows
that set a measurement beside no claim of the paper carry :data:`NO_CLAIM`.
"""

from __future__ import annotations

from collections.abc import Sequence

from optbound.report.tables import markdown_table

REPRODUCED, PARTLY, NOT_REPRODUCED = "reproduced", "partly", "not reproduced"
NO_CLAIM = "— (no claim)"
HEADERS = ("quantity", "paper", "optbound", "verdict")


def at_least(value: float, reproduced: float, partly: float) -> str:
    """``reproduced`` if ``value >= reproduced``, ``partly`` if ``>= partly``, else not."""
    if not reproduced >= partly:
        raise ValueError(f"reproduced ({reproduced}) must be >= partly ({partly})")
    if value >= reproduced:
        return REPRODUCED
    return PARTLY if value >= partly else NOT_REPRODUCED


def at_most(value: float, reproduced: float, partly: float) -> str:
    """``reproduced`` if ``value <= reproduced``, ``partly`` if ``<= partly``, else not."""
    if not reproduced <= partly:
        raise ValueError(f"reproduced ({reproduced}) must be <= partly ({partly})")
    if value <= reproduced:
        return REPRODUCED
    return PARTLY if value <= partly else NOT_REPRODUCED


def all_or_some(flags: Sequence[bool]) -> str:
    """``reproduced`` when every flag holds, ``partly`` when some do, else not reproduced."""
    flags = [bool(f) for f in flags]
    if not flags:
        raise ValueError("flags is empty: a verdict needs at least one test")
    if all(flags):
        return REPRODUCED
    return PARTLY if any(flags) else NOT_REPRODUCED


def table(rows: Sequence[Sequence[str]]) -> str:
    """The ``quantity | paper | optbound | verdict`` table."""
    allowed = {REPRODUCED, PARTLY, NOT_REPRODUCED, NO_CLAIM}
    for row in rows:
        if len(row) != len(HEADERS) or row[-1] not in allowed:
            raise ValueError(f"a claim row needs {len(HEADERS)} cells ending in a verdict: {row}")
    return markdown_table(HEADERS, rows)


__all__ = [
    "HEADERS",
    "NOT_REPRODUCED",
    "NO_CLAIM",
    "PARTLY",
    "REPRODUCED",
    "all_or_some",
    "at_least",
    "at_most",
    "table",
]
