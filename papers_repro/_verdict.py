"""Verdicts of the reproduction tables: reproduced / partly / not reproduced, from numbers.

Every claim row of a script gets its verdict from the numbers printed beside it, by one of
two rules stated here (and in the table's caption):

- a **rate** claim ("the truth is kept", "q equals the number of outliers") with k successes
  in n trials against a target rate: *reproduced* when the 95 % Wilson interval of k / n lies
  at or above the target, *not reproduced* when it lies below, *partly* when it straddles it;
- a **count** claim (the paper's number of components) against our bracket ``[lo, hi]`` of
  the true count: *reproduced* when ``lo == hi == paper``, *partly* when ``lo <= paper <= hi``
  (consistent but not established), *not reproduced* otherwise.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from optbound.report.tables import markdown_table
from papers_repro._common import CLAIM_HEADERS

REPRODUCED, PARTLY, NOT_REPRODUCED = "reproduced", "partly", "not reproduced"
VERDICT_HEADERS = (*CLAIM_HEADERS, "verdict")
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


def verdict_table(rows: Sequence[Sequence[str]]) -> str:
    """The ``quantity | paper | optbound | verdict`` table."""
    return markdown_table(VERDICT_HEADERS, rows)
