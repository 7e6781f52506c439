"""KJWM00 reproduction: the relaxed intersection keeps the truth despite outliers."""

import numpy as np
import pytest

from optbound.papers_repro import kjwm00_outliers as repro


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
    assert len(trials) == 3
    for t in trials:
        if t["outliers"] == 0:
            assert t["q = 0"]["success"]
        if t["outliers"] <= repro.Q_FIXED:
            assert t[f"q = {repro.Q_FIXED}"]["success"]
        # q = auto stops at the first q whose set is not proven empty: never above the truth's.
        assert t["q = auto"]["q"] <= t["outliers"]


def test_injected_random_outliers_are_counted():
    rng = np.random.default_rng(3)
    case = repro.scenario(rng, "random", 3)
    assert case["outliers"] <= 3
    clean = repro.scenario(rng, "random", 0)
    assert clean["outliers"] == 0
    # An added partition changes what some sonar sees in most placements.
    caused = [repro.scenario(rng, "added wall")["outliers"] for _ in range(10)]
    assert max(caused) >= 1
