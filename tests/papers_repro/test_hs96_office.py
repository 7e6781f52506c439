"""HS96 office experiment, quick variant: the report's numbers exist and say what they claim."""

import pytest

from optbound.papers_repro import hs96_office as repro


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
