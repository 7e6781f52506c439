"""Bench family ``linear_estimation``: records per method and step, the report's tables."""

import numpy as np
import pytest

from optbound.bench import linear_estimation as family
from optbound.estimation import METHODS, observe
from optbound.report.estimation import estimation_rows, estimation_section


@pytest.fixture(scope="module")
def tiny():
    (task,) = family.tasks("tiny", 0)
    return family.run(task)


def test_tiny_is_alamo_with_every_method_at_every_step(tiny):
    recs = tiny["records"]
    assert {r["method"] for r in recs} == set(METHODS)
    assert {r["k"] for r in recs} == {1, 2, 3, 5}
    assert all(r["error"] is None for r in recs)
    for r in recs:
        # An outer bound's area is at least the exact polygon's.
        assert 0 < r["ratio_lo"] <= r["ratio_hi"] and r["ratio_hi"] >= 1.0
        assert r["mvee_ratio_lo"] <= r["mvee_ratio_hi"]
        assert r["ms_per_step"] > 0
        # Proven exactly for every method (constrained zonotopes by parameter certificates).
        assert r["contained"] is True
    (png,) = tiny["attachments"].values()
    assert len(png) > 10_000


def test_report_tables_and_headline(tiny):
    text = "\n".join(estimation_section(tiny["records"]))
    assert "**Alamo 2005 Sect. 7.1** (n = 2, 5 steps; area / exact area)" in text
    for method in METHODS:
        assert f"| `{method}` |" in text
    ((label, value),) = estimation_rows(tiny["records"])
    assert label.endswith("k=5, Alamo 2005 Sect. 7.1") and "zonotope" in value


@pytest.mark.parametrize("noise", ["box", "ellipsoid"])
def test_hull_widths_beyond_2d(noise):
    task = {"seed": 3, "system": "random", "n": 3, "noise": noise, "steps": 4, "rep": 0}
    out = family.run(task)
    recs = [r for r in out["records"] if r["error"] is None]
    assert "attachments" not in out
    assert {r["k"] for r in recs} == {1, 2, 3, 4}
    for r in recs:
        assert r["measure"] == "interval-hull widths" and r["contained"] is None
        if noise == "box":  # against the exact set's certified hull (rounded outward)
            assert r["ratio_lo"] >= 1.0 - 1e-9 and r["ratio_hi"] is None
        else:  # against the best method in each state
            assert r["hull_ratio"] >= 1.0
    if noise == "ellipsoid":
        for k in (1, 4):
            assert min(r["hull_ratio"] for r in recs if r["k"] == k) >= 1.0
    assert np.isfinite([r["mean_width"] for r in recs]).all()


def test_suites_and_steps():
    assert [t["system"] for t in family.tasks("quick", 0)] == ["alamo", "random", "random"]
    assert "tank" in {t["system"] for t in family.tasks("full", 0)}
    assert family.recorded_steps(20) == [1, 2, 3, 5, 7, 10, 14, 20]
    assert family.recorded_steps(55) == [10, 20, 30, 40, 50, 55]
    with pytest.raises(ValueError, match="suite"):
        family.tasks("huge", 0)


def test_one_step_optimal_sampled_and_reported():
    # The tank's sampled SDP column, on a small 3-D system (the tank is full-suite only).
    task = {"seed": 5, "system": "random", "n": 3, "noise": "box", "steps": 20, "rep": 0}
    _, system, X0, ys = family.instance(task)
    out = family.run(task)
    runs = {m: (observe(system, X0, ys, m), 1.0) for m in ("ellipsoid_volume", "ellipsoid_trace")}
    losses = family._one_step_losses(system, ys, runs, family.recorded_steps(20))
    assert set(losses) == {(m, k) for m in runs for k in (10, 20)}
    for loss in losses.values():
        # The analytic step contains the same prediction ∩ strips as the optimal ellipsoid.
        assert loss["one_step_ratio"] >= 1.0 - 1e-6 and loss["sdp_seconds"] > 0
    records = [
        {**r, **losses.get((r["method"], r["k"]), {})} for r in out["records"] if r["k"] is not None
    ]
    text = "\n".join(estimation_section(records))
    assert "/ one-step optimal (k=20; SDP at 10, 20) | s/SDP |" in text
    assert "| `interval` |" in text and "| – | – |" in text


def test_an_uncertifiable_one_step_sdp_is_recorded_not_fatal(monkeypatch):
    from optbound.estimation import references

    def fail(*_):
        raise ValueError("not jointly positive definite")

    monkeypatch.setattr(references, "one_step_optimal", fail)
    task = {"seed": 5, "system": "random", "n": 3, "noise": "box", "steps": 20, "rep": 0}
    _, system, X0, ys = family.instance(task)
    runs = {"ellipsoid_volume": (observe(system, X0, ys, "ellipsoid_volume"), 1.0)}
    losses = family._one_step_losses(system, ys, runs, [10, 20])
    for loss in losses.values():
        assert loss["one_step_ratio"] is None and "positive definite" in loss["sdp_error"]
    base = {"family": "linear_estimation", "system": "s", "dim": 3, "steps": 20, "error": None}
    records = [
        {**base, "method": "ellipsoid_volume", "k": k, "ms_per_step": 1.0, "ratio_lo": 1.5,
         "ratio_hi": None, "measure": "interval-hull widths", "contained": None, **losses[
             "ellipsoid_volume", k]}
        for k in (10, 20)
    ]  # fmt: skip
    assert "(2 of 2 not certified)" in "\n".join(estimation_section(records))
