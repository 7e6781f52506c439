"""KJWM00 reproduction: the relaxed intersection keeps the truth despite outliers."""

import numpy as np
import pytest

from optbound.localization.sonar import localize
from optbound.papers_repro import kjwm00_outliers as repro
from optbound.papers_repro._verdict import (
    NO_CLAIM,
    NOT_REPRODUCED,
    PARTLY,
    REPRODUCED,
    rate_verdict,
)


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    return repro.main(tmp_path_factory.mktemp("kjwm00"), quick=True)


def test_declares_its_paper_and_figure(result):
    assert repro.PAPER == "KJWM00"
    [fig] = result["figures"]
    assert fig.suffix == ".png" and fig.stat().st_size > 10_000
    assert "| quantity | paper | optbound |" in result["markdown"]


def test_guarantees_hold_on_every_trial(result):
    trials = result["trials"]
    groups = {t["label"] for t in trials}
    assert len(groups) == 2 and result["n"] == 20
    assert len(trials) == 20 * len(groups)  # >= 20 seeded trials per outlier rate
    for t in trials:
        if t["outliers"] == 0:
            assert t["q = 0"]["success"]
        if t["outliers"] <= repro.Q_FIXED and f"q = {repro.Q_FIXED}" in t:
            assert t[f"q = {repro.Q_FIXED}"]["success"]
        # q = auto stops at the first q whose set is not proven empty: never above the truth's.
        assert t["q = auto"]["q"] <= t["outliers"]
        if t["q = auto"]["q"] == t["outliers"]:
            assert t["q = auto"]["success"]


def test_verdicts_are_computed_from_the_rows(result):
    claims = result["claims"]
    trials = result["trials"]
    belt = [t for t in trials if t["sonars"] == 16]
    kept = sum(t["q = auto"]["success"] for t in belt)
    assert claims[0][2].startswith(f"{kept}/{len(belt)} ")
    assert claims[0][3] == rate_verdict(kept, len(belt), repro.TARGET)
    assert "our reading" in claims[3][1]
    for row in claims:
        assert row[3] in (REPRODUCED, PARTLY, NOT_REPRODUCED, NO_CLAIM)
        assert row[3] in result["markdown"]
    assert f"{result['n']} seeded trials per group" in result["markdown"]


def _comparable(trial: dict) -> dict:
    """The trial without its CPU time, NaN volumes (empty sets) as None."""
    out = {k: v for k, v in trial.items() if k != "cpu_seconds"}
    for m in repro.METHODS:
        if m in out:
            out[m] = {**out[m], "volume": None if out[m]["empty"] else out[m]["volume"]}
    return out


def test_trials_are_deterministic_per_seed():
    plan, _, eps = repro._plan(quick=True)
    a = _comparable(repro.trial(7, 1, 2, plan[1], eps))
    assert a == _comparable(repro.trial(7, 1, 2, plan[1], eps))
    cases = [repro.scenario(np.random.default_rng([s, 0, 0]), "random", 2) for s in (7, 7, 8)]
    assert np.array_equal(cases[0]["ranges"], cases[1]["ranges"])
    assert not np.array_equal(cases[0]["truth"], cases[2]["truth"])


def test_reused_auto_equals_localize_auto():
    """q = auto taken from the fixed-q pavings is what localize(q="auto") returns."""
    rng = np.random.default_rng(5)
    case = repro.scenario(rng, "random", 2)
    ours = repro._pavings(case, 0.15)["q = auto"]
    theirs = localize(case["world"], case["sonars"], case["ranges"], repro.X0, 0.15, q="auto")
    assert ours.q == theirs.q
    assert np.array_equal(ours.outer(), theirs.outer())


def test_injected_random_outliers_are_counted():
    rng = np.random.default_rng(3)
    case = repro.scenario(rng, "random", 3)
    assert case["outliers"] <= 3
    clean = repro.scenario(rng, "random", 0)
    assert clean["outliers"] == 0
    # An added partition changes what some sonar sees in most placements.
    caused = [repro.scenario(rng, "added wall")["outliers"] for _ in range(10)]
    assert max(caused) >= 1
