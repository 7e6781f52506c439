"""GLH12 reproduction: the quick variant runs, keeps the truth and reports both sweeps."""

import numpy as np
import pytest

from optbound.papers_repro import glh12_visibility as repro


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    return repro.main(tmp_path_factory.mktemp("glh12"), quick=True)


def test_quick_variant_keeps_the_truth_and_reports(result):
    assert repro.PAPER == "GLH12"
    assert result["lost"] == 0
    assert set(result["robots"]) == set(repro.QUICK["robots"])
    assert set(result["obstacles"]) == set(repro.QUICK["obstacles"])
    assert "| quantity | paper | optbound |" in result["markdown"]
    for path in result["figures"]:
        assert path.suffix == ".png" and path.stat().st_size > 10_000


def test_run_one_is_a_pure_function_of_params_and_seed():
    params = {"robots": 3, "obstacles": 4, "steps": 30, "eps": 0.02, "max_depth": 6}
    a, b = repro.run_one(params, 5), repro.run_one(params, 5)
    assert a["area"] == b["area"] and a["lost"] == 0 and len(a["area"]) == 31
    assert a["area"][0] == pytest.approx(1.0)


def test_sweep_on_two_processes_matches_serial():
    configs = [
        {"robots": n, "obstacles": 3, "steps": 15, "eps": 0.02, "max_depth": 6} for n in (2, 4)
    ]
    serial, parallel = repro.sweep(configs, (0, 1)), repro.sweep(configs, (0, 1), jobs=2)
    assert [r["area"] for r in serial] == [r["area"] for r in parallel]
    assert np.all([r["lost"] == 0 for r in parallel])
