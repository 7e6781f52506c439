"""ABC05 Sect. 7.1 reproduction (quick variant): the numbers behind the claims."""

import pytest

from optbound.papers_repro import alamo05_linear as repro


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    return repro.main(tmp_path_factory.mktemp("abc05"), quick=True)


def test_report_and_figures(result):
    assert repro.PAPER == "ABC05"
    assert len(result["figures"]) == 2
    for path in result["figures"]:
        assert path.suffix == ".png" and path.stat().st_size > 10_000
    assert "| quantity | paper | optbound |" in result["markdown"]


def test_every_observer_is_at_least_the_exact_set(result):
    exact, upper = result["exact_areas"][-1]
    assert exact <= upper <= exact * (1 + 1e-6)
    for method, a in result["final_areas"].items():
        assert a >= exact, method
    for curve in result["ratios"].values():
        assert len(curve) == 20 and min(curve) >= 1.0 - 1e-9
    # Every observer's set contains X_k at every step, proven in exact arithmetic.
    assert result["proven_steps"] == {m: 20 for m in result["final_areas"]}
