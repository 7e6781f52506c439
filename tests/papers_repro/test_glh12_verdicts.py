"""GLH12 claim verdicts are computed from the numbers beside them (fixed rules)."""

import pytest

from optbound.papers_repro import _glh12_verdicts as v

R, P, N = v.REPRODUCED, v.PARTLY, v.NOT_REPRODUCED


@pytest.mark.parametrize(
    ("fraction", "expected"),
    [
        ({3: 0.0, 5: 0.2, 7: 0.6, 9: 1.0, 11: 0.9}, R),
        ({3: 0.0, 5: 0.5, 7: 0.6, 9: 1.0, 11: 0.9}, P),  # a threshold, at 5
        ({3: 0.0, 5: 0.0, 7: 0.0, 9: 0.7, 11: 0.9}, P),  # a threshold, at 9
        ({3: 0.0, 5: 0.0, 7: 0.0, 9: 0.0, 11: 0.0}, N),  # nothing is efficient
        ({3: 0.0, 5: 0.0, 7: 0.8, 9: 0.1, 11: 0.9}, N),  # not upward closed
    ],
)
def test_threshold_verdict(fraction, expected):
    assert v.threshold_verdict(fraction, 7) == expected


@pytest.mark.parametrize(
    ("median", "fraction", "expected"),
    [
        ({9: 0.8, 11: 0.6}, {9: 0.9, 11: 1.0}, R),
        ({9: 0.8, 11: 0.3}, {9: 0.9, 11: 1.0}, P),  # 11 robots more than halve the area
        ({9: 1.2, 11: 0.9}, {9: 0.4, 11: 0.6}, P),  # close medians, one side of the rule each
        ({9: 4.0, 11: 0.9}, {9: 0.0, 11: 0.6}, N),
        # both fail, with similar medians: similar failures are not the paper's plateau
        ({9: 4.3, 11: 2.7}, {9: 0.0, 11: 0.0}, v.NOT_APPLICABLE),
        ({9: 1.2, 11: 1.1}, {9: 0.4, 11: 0.3}, v.NOT_APPLICABLE),
    ],
)
def test_plateau_verdict(median, fraction, expected):
    assert v.plateau_verdict(median, fraction, 9, 11) == expected


def test_window_verdict_counts_agreement_and_needs_a_success():
    works = (4, 5, 6, 8)
    paper = {3: 0.0, 4: 1.0, 5: 1.0, 6: 1.0, 7: 0.0, 8: 1.0, 9: 0.0}
    assert v.window_verdict(paper, works) == R
    assert v.window_verdict({**paper, 7: 1.0, 9: 1.0}, works) == P  # 5 of 7 agree
    assert v.window_verdict({**paper, 3: 1.0, 7: 1.0, 9: 1.0, 4: 0.0}, works) == N  # 3 of 7
    nothing = dict.fromkeys(paper, 0.0)  # agrees on 3, 7, 9 only by failing everywhere
    assert v.window_verdict(nothing, works) == N


def test_dip_verdict():
    assert v.dip_verdict({6: 0.8, 7: 0.2, 8: 0.6}, 7, (6, 8)) == R
    assert v.dip_verdict({6: 0.4, 7: 0.2, 8: 0.3}, 7, (6, 8)) == P
    assert v.dip_verdict({6: 0.0, 7: 0.0, 8: 0.0}, 7, (6, 8)) == N
    assert v.dip_verdict({6: 0.8, 7: 0.9, 8: 0.6}, 7, (6, 8)) == N


def test_majority_rule_is_inclusive():
    assert v.efficient_counts({3: v.MAJORITY, 5: v.MAJORITY - 0.01}) == {3}
