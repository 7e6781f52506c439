"""GLH12 reproduction: the quick variant runs, keeps the truth and reports both sweeps."""

import numpy as np
import pytest

from optbound.papers_repro import _glh12_verdicts as verdicts
from optbound.papers_repro import glh12_visibility as repro


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    return repro.main(tmp_path_factory.mktemp("glh12"), quick=True)


def test_quick_variant_keeps_the_truth_and_reports(result):
    assert repro.PAPER == "GLH12"
    assert result["lost"] == 0 and result["contraction"]["truth_lost"] == 0
    assert set(result["robots"]) == set(repro.ROBOTS)
    assert set(result["obstacles"]) == set(repro.OBSTACLES)
    assert set(result["factors"]) == set(repro.FACTORS)
    n = len(repro.QUICK["seeds"])
    assert all(s["n"] == n for s in (*result["robots"].values(), *result["obstacles"].values()))
    assert "| quantity | paper | optbound | verdict |" in result["markdown"]
    assert "**Why ours differ.**" in result["markdown"]
    n_runs = f"({n} runs each)"
    assert all(n_runs in row[2] or f"({n} each)" in row[2] for row in result["claims"][1:])
    for path in result["figures"]:
        assert path.suffix == ".png" and path.stat().st_size > 10_000


def test_verdicts_are_computed_from_the_reported_fractions(result):
    """Each verdict in the table is the rule applied to the distributions beside it."""
    rows = {row[0]: row[3] for row in result["claims"]}
    for key, reading in repro.READINGS.items():
        frac_r = {n: s[key] for n, s in result["robots"].items()}
        frac_o = {n: s[key] for n, s in result["obstacles"].items()}
        assert rows[f"robots needed, 6 obstacles ({reading})"] == verdicts.threshold_verdict(
            frac_r, 7
        )
        assert rows[f"obstacles that work, 7 robots ({reading})"] == verdicts.window_verdict(
            frac_o, (4, 5, 6, 8)
        )
        assert rows[f"7 obstacles, 7 robots ({reading})"] == verdicts.dip_verdict(frac_o, 7, (6, 8))
        med_r = {n: s["median"] for n, s in result["robots"].items()}
        assert rows[f"more robots than 9 ({reading})"] == verdicts.plateau_verdict(
            med_r, frac_r, 9, 11
        )


def test_distribution_summarizes_final_areas():
    runs = [{"final_area": a, "lost": 0, "visible_fraction": 0.5, "cpu_seconds": 1.0,
             "drift": d} for a, d in ((0.5, 1.0), (2.0, 1.5), (0.9, 1.1), (4.0, 0.9))]  # fmt: skip
    s = repro.distribution(runs)
    assert s["n"] == 4 and s["median"] == pytest.approx(1.45)
    assert s["efficient"] == 0.5 and s["drift_free"] == 0.75


def test_run_one_is_a_pure_function_of_params_and_seed():
    params = {**repro.BASE, "robots": 3, "obstacles": 4, "steps": 30, "eps": 0.02,
              "max_depth": 6}  # fmt: skip
    a, b = repro.run_one(params, 5), repro.run_one(params, 5)
    assert a["area"] == b["area"] and a["lost"] == 0 and len(a["area"]) == 31
    assert a["area"][0] == pytest.approx(1.0)
    assert repro.run_one(params, 6)["area"] != a["area"]  # another seed: another room


def test_sweep_on_two_processes_matches_serial():
    configs = [
        {**repro.BASE, "robots": n, "obstacles": 3, "steps": 15, "eps": 0.02, "max_depth": 6}
        for n in (2, 4)
    ]
    serial, parallel = repro.sweep(configs, (0, 1)), repro.sweep(configs, (0, 1), jobs=2)
    assert [r["area"] for r in serial] == [r["area"] for r in parallel]
    assert np.all([r["lost"] == 0 for r in parallel])


def test_sweep_stores_each_run_and_takes_the_stored_ones(tmp_path, monkeypatch):
    """``runs``: every finished run appended to the file; a second sweep runs only what is
    missing (a torn last line, left by a killed process, is skipped)."""
    configs = [{**repro.BASE, "robots": 2, "obstacles": 3, "steps": 10, "eps": 0.02,
                "max_depth": 6}]  # fmt: skip
    runs = tmp_path / "runs.jsonl"
    first = repro.sweep(configs, (0, 1), runs=runs)
    assert len(runs.read_text().splitlines()) == 2
    with runs.open("a") as fh:
        fh.write('{"robots": 2, "obst')
    ran = []
    real = repro.run_one
    monkeypatch.setattr(repro, "run_one", lambda c, s: ran.append(s) or real(c, s))
    again = repro.sweep(configs, (0, 1, 2), runs=runs)
    assert ran == [2]
    assert [r["area"] for r in again[:2]] == [r["area"] for r in first]
    assert again[2] == real(configs[0], 2) | {k: again[2][k] for k in ("seconds", "cpu_seconds")}


def test_contraction_rows_are_kept_beside_the_runs(tmp_path, monkeypatch):
    calls = []
    fake = lambda params, seed, at, eps, split: calls.append(seed) or [{"seed": seed}]  # noqa: E731
    monkeypatch.setattr(repro.contraction, "study", fake)
    study = {"seeds": (0, 1), "at": (5,), "paving_eps": 0.1, "split": 2}
    runs = tmp_path / "runs.jsonl"
    first = repro._contraction_rows({"robots": 2}, study, runs)
    assert (
        repro._contraction_rows({"robots": 2}, study, runs) == first == [{"seed": 0}, {"seed": 1}]
    )
    assert calls == [0, 1]
    repro._contraction_rows({"robots": 3}, study, runs)  # another study: run, not taken
    assert calls == [0, 1, 0, 1]
