"""Per-claim verdicts of the reproduction tables: reproduced / partly / not reproduced.

A verdict is computed from the numbers printed beside it, by a rule stated in the report next
to the table (the thresholds are the scripts' module constants, fixed before the runs). Rows
that set a measurement beside no claim of the paper carry :data:`NO_CLAIM`.

Two further rules: a **rate** claim with k successes in n seeded trials against a target
rate is *reproduced* when the 95 % Wilson interval of k / n lies at or above the target, *not
reproduced* when it lies below, *partly* when it straddles it (:func:`rate_verdict`); a
**count** claim against our bracket ``[lo, hi]`` of the true count is *reproduced* when
``lo == hi == paper``, *partly* when ``lo <= paper <= hi``, *not reproduced* otherwise
(:func:`count_verdict`).
"""

from __future__ import annotations

import math
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


# ----- sampled rates and bracketed counts (KJWM00, LJMW97) ------------------------------------
#: Normal quantile of the two-sided 95 % interval.
Z95 = 1.959963984540054


def wilson(k: int, n: int, z: float = Z95) -> tuple[float, float]:
    """Wilson score interval of a proportion k / n (``(0, 1)`` for n = 0)."""
    if n < 0 or not 0 <= k <= n:
        raise ValueError(f"need 0 <= k <= n, got k={k}, n={n}")
    if n == 0:
        return 0.0, 1.0
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    lo = 0.0 if k == 0 else max(0.0, centre - half)
    return lo, 1.0 if k == n else min(1.0, centre + half)


def rate_verdict(k: int, n: int, target: float) -> str:
    """Verdict of "the rate is at least ``target``" from k successes in n trials."""
    lo, hi = wilson(k, n)
    if lo >= target:
        return REPRODUCED
    if hi < target:
        return NOT_REPRODUCED
    return PARTLY


def count_verdict(paper: int, lo: int, hi: int) -> str:
    """Verdict of the paper's count against our bracket ``lo <= true count <= hi``."""
    if lo > hi:
        raise ValueError(f"need lo <= hi, got [{lo}, {hi}]")
    if lo == hi == paper:
        return REPRODUCED
    if lo <= paper <= hi:
        return PARTLY
    return NOT_REPRODUCED


def rate_text(k: int, n: int) -> str:
    """``k/n (p %, 95 % CI [lo, hi] %)``."""
    lo, hi = wilson(k, n)
    share = k / n if n else float("nan")
    return f"{k}/{n} ({share:.0%}, 95 % CI [{lo:.0%}, {hi:.0%}])"


__all__ = [
    "HEADERS",
    "NOT_REPRODUCED",
    "NO_CLAIM",
    "PARTLY",
    "REPRODUCED",
    "all_or_some",
    "at_least",
    "at_most",
    "count_verdict",
    "rate_text",
    "rate_verdict",
    "table",
    "wilson",
]
