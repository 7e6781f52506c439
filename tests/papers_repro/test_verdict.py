"""Verdict rules of the reproduction tables."""

import pytest

from optbound.papers_repro._verdict import (
    NOT_REPRODUCED,
    PARTLY,
    REPRODUCED,
    count_verdict,
    rate_text,
    rate_verdict,
    table,
    wilson,
)


def test_wilson_interval_known_values():
    lo, hi = wilson(10, 10)
    assert hi == 1.0 and 0.72 < lo < 0.73  # 0.7225 for 10/10
    lo, hi = wilson(0, 20)
    assert lo == 0.0 and 0.16 < hi < 0.17  # 0.1611
    assert wilson(0, 0) == (0.0, 1.0)
    with pytest.raises(ValueError, match="0 <= k <= n"):
        wilson(5, 3)


def test_rate_verdict_follows_the_interval():
    assert rate_verdict(100, 100, 0.9) == REPRODUCED  # CI [0.963, 1]
    assert rate_verdict(20, 20, 0.9) == PARTLY  # CI [0.839, 1] straddles 0.9
    assert rate_verdict(3, 3, 0.9) == PARTLY  # three trials prove nothing
    assert rate_verdict(50, 100, 0.9) == NOT_REPRODUCED
    assert rate_verdict(1, 30, 0.9) == NOT_REPRODUCED


def test_count_verdict_brackets():
    assert count_verdict(2, 2, 2) == REPRODUCED
    assert count_verdict(2, 2, 13) == PARTLY
    assert count_verdict(2, 1, 5) == PARTLY
    assert count_verdict(2, 3, 13) == NOT_REPRODUCED  # at least 3 true components
    assert count_verdict(2, 0, 1) == NOT_REPRODUCED
    with pytest.raises(ValueError, match="lo <= hi"):
        count_verdict(2, 3, 1)


def test_table_and_text():
    assert rate_text(3, 4).startswith("3/4 (75%, 95 % CI [")
    text = table([("a", "b", "c", REPRODUCED)])
    assert text.splitlines()[0] == "| quantity | paper | optbound | verdict |"
