"""The speed families turn their helpers' measurements into ratio records, or into a note."""

import time

import pytest

from optbound.bench import sivia_codac, speed_sdp, speed_sivia
from optbound.bench.timing import batch_times, per_call


def test_missing_codac_becomes_a_note_not_a_failure(monkeypatch):
    note = "codac not installed (pip install -e '.[bench]'): comparison skipped"
    monkeypatch.setattr(sivia_codac, "run", lambda **kwargs: [{"note": note}])
    out = speed_sivia.run(speed_sivia.tasks("tiny", 0)[0])
    assert out == {"records": [], "notes": [note]}


def test_sivia_rows_give_codac_and_optbound_records():
    row = {"name": "ring eps=0.01", "seconds": 0.002, "codac_seconds": 0.02, "ratio": 10.0}
    codac, ours = speed_sivia.sivia_records([row])
    assert (codac["name"], codac["value"]) == ("codac sivia, ring eps=0.01", 0.02)
    assert (ours["value"], ours["ratio"]) == (0.002, 10.0)
    assert "codac" in ours["ratio_label"]


def test_sdp_cache_ratio_is_rebuilt_over_cached():
    timings = {
        "cached_s": 0.003,
        "rebuilt_s": 0.021,
        "cached_solve_s": 0.002,
        "clarabel_s": 0.001,
        "call_over_clarabel": 2.8,
        "n_solves": 5,
        "dim": 3,
    }
    rebuilt, cached, solver, clarabel = speed_sdp.cache_records(timings)
    assert rebuilt["value"] == 0.021
    assert cached["ratio"] == pytest.approx(7.0)
    assert solver["ratio"] == pytest.approx(1.5)
    assert (clarabel["value"], clarabel["ratio"]) == (0.001, 2.8)


def test_sdp_cache_measures_clarabels_own_time():
    from optbound.bench import sdp_cache

    numbers = sdp_cache.run(n_solves=3, seed=1)
    assert 0 < numbers["clarabel_s"] < numbers["cached_s"]
    assert numbers["call_over_clarabel"] > 1.0
    assert 0 < numbers["repeated_clarabel_s"] < numbers["repeated_s"]
    assert numbers["repeated_over_clarabel"] > 1.0


def test_per_call_measures_seconds_per_call():
    seconds = per_call(lambda: time.sleep(0.002), repeat=2, min_time=0.01)
    assert 0.002 <= seconds < 0.05


def test_batch_times_counts_the_calibrating_batch_as_a_sample():
    calls = []
    times = batch_times(lambda: calls.append(time.sleep(0.002)), repeat=3, min_time=0.005)
    assert len(times) == 3 and all(0.002 <= t < 0.05 for t in times)
    # Calibration batches of 1, 2, ..., N calls (N a power of two); the one of N calls reached
    # min_time and is the first sample, so only 2 more batches of N run: 4 N - 1 calls in all
    # (5 N - 1 if the calibrating batch were not counted).
    assert (len(calls) + 1) % 4 == 0 and ((len(calls) + 1) // 4).bit_count() == 1


def test_one_analytic_call_is_measured_once_and_the_sdp_ratio_uses_it():
    from optbound.bench import speed_analytic

    for run in (speed_analytic.run_strip, speed_analytic.run_minkowski):
        records = run({"seed": 3, "batches": [10]})
        one_call = [r for r in records if "one call" in r["name"] and "optbound" in r["name"]]
        sdp = [r for r in records if r["name"].startswith("SDP")]
        assert len(one_call) == 1 and len(sdp) == 1
        assert len([r for r in records if "one call" in r["name"]]) == 2  # optbound, reference
        assert sdp[0]["ratio"] == sdp[0]["value"] / one_call[0]["value"]
        assert one_call[0]["name"] in sdp[0]["ratio_label"]
