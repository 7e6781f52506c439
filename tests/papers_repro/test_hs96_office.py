"""HS96 office experiment, quick variant: the report's numbers exist and say what they claim."""

import pytest

from optbound.papers_repro import _verdict as verdict
from optbound.papers_repro import hs96_office as repro
from optbound.scenarios import office


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    return repro.main(tmp_path_factory.mktemp("hs96_office"), quick=True)


def test_writes_its_figures(result):
    assert len(result["figures"]) == 3
    for path in result["figures"]:
        assert path.suffix == ".png" and path.stat().st_size > 10_000


def test_initialization_finds_the_true_association(result):
    init = result["init"]
    assert init["correct"] and init["truth_in_initial"]
    assert init["nodes_expanded"] < 1e-6 * init["nodes_unpruned"]


def test_tracker_keeps_the_true_pose_and_is_accurate(result):
    for stats in result["stats"].values():
        assert stats["containment"] >= 0.95
        assert stats["err_max_cm"] < 5.0 and stats["half_x_cm"] < 10.0


def test_projection_is_tightest_in_xy_among_the_criteria(result):
    s = result["stats"]
    area = {c: s[c]["half_x_cm"] * s[c]["half_y_cm"] for c in s}
    assert area["projection"] <= area["volume"]


def test_dead_reckoning_drifts_more_than_the_tracker_errs(result):
    assert (
        result["dead_reckoning_drift_m"][-1] > 5 * result["stats"]["projection"]["err_max_cm"] / 100
    )


def test_sampled_updates_match_the_sdp_and_contain_the_exact_inner_set(result):
    for row in result["samples"]:
        assert row["projection_area"] <= row["sdp_area"] * (1 + 1e-4)
        assert row["projection_area"] >= row["sdp_area"] * (1 - 1e-4)
        assert row["exact_inner_boxes"] > 0 and row["exact_max_level"] <= 1.0


def test_robust_lambda_keeps_the_pose_under_phantom_outliers(result):
    f = result["fault_stats"]
    assert f["phantom 6 cm / robust"]["containment"] > f["phantom 6 cm / projection"]["containment"]
    assert (
        f["wrong landmark / projection"]["inconsistent"]
        == f["wrong landmark / projection"]["injected"]
    )


def test_markdown_names_the_paper_values(result):
    md = result["markdown"]
    assert "about +-2 cm" in md and "about +-0.5 deg" in md and "our design" in md


def test_association_study_counts_add_up(result):
    rows = result["association"]
    assert [(r["spurious_rate"], r["missing_rate"]) for r in rows] == list(repro.INJECTION[True])
    for r in rows:
        assert r["scans"] == repro.INJECTION_SCANS[True]
        assert 0 <= r["paired"] <= r["true_bearings"] and 0 <= r["discarded"] <= r["spurious"]
        assert r["accuracy"] == (r["paired"] + r["discarded"]) / (
            r["true_bearings"] + r["spurious"]
        )
        assert 0.0 < r["seconds_median"] <= r["seconds_max"]
    # With no injection nothing is spurious; with 10 % spurious some are injected.
    assert rows[0]["spurious"] == 0 and rows[1]["spurious"] > 0


def test_linear_solver_error_is_reported(result):
    lin = result["linear_solver"]
    assert lin["scans"] == round(office.lap_length() / office.SPEED * office.SCAN_RATE) + 1
    assert 0.0 < lin["err_median_cm"] <= lin["err_p95_cm"] <= lin["err_max_cm"] < 50.0


def test_every_claim_row_has_a_computed_verdict(result):
    md = result["markdown"]
    assert "| quantity | paper | optbound | verdict |" in md
    worst = min(r["accuracy"] for r in result["association"])
    expected = verdict.at_least(worst, repro.ASSOCIATION_REPRODUCED, repro.ASSOCIATION_PARTLY)
    line = next(x for x in md.splitlines() if x.startswith("| association search discards"))
    assert line.rstrip().endswith(f"| {expected} |")
