"""HS96 Figs. 1-2 reproduction: cases as the paper labels them, and the common/robust claims."""

import numpy as np
import pytest

from optbound.papers_repro import hs96_fusion as repro


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    return repro.main(tmp_path_factory.mktemp("hs96_fusion"))


def test_writes_its_figures(result):
    assert len(result["figures"]) == 3
    for path in result["figures"]:
        assert path.suffix == ".png" and path.stat().st_size > 10_000


def test_fig1_cases_match_the_paper(result):
    assert [r["case"] for r in result["fig1"]] == [r["paper_case"] for r in result["fig1"]]


def test_fig1_areas_are_ordered(result):
    for r in result["fig1"]:
        if r["case"] == "inconsistent":
            assert r["raw_area"] is None and r["exact_area"] == 0.0
            continue
        # exact ∩ <= SDP optimum <= clipped family member <= raw family member
        assert r["exact_area"] <= r["sdp_area"] * (1 + 1e-9)
        assert r["sdp_area"] <= r["clipped_area"] * (1 + 1e-6)
        assert r["clipped_area"] <= r["raw_area"] * (1 + 1e-9)
        # Known fact: the clipped eq. (26) member is the SDP optimum.
        assert r["clipped_area"] == pytest.approx(r["sdp_area"], rel=1e-5)


def test_exact_area_matches_monte_carlo():
    S = repro.strip_at(0.7, 0.4)
    pts = repro.PRIOR.sample(200_000, np.random.default_rng(1))
    estimate = repro.PRIOR.volume() * np.mean(S.contains(pts))
    assert repro.exact_area(repro.PRIOR, S) == pytest.approx(estimate, rel=0.01)


@pytest.mark.parametrize("t", repro.FIG2_CENTRES)
def test_both_schemes_contain_the_intersection(t):
    S = repro.strip_at(t, repro.FIG2_HALF_WIDTH)
    pts = repro.PRIOR.sample(400_000, np.random.default_rng(2))
    pts = pts[S.contains(pts)]
    assert len(pts) >= 10_000
    for fused in repro.fuse_both(S):
        assert fused.ellipsoid.contains(pts).all()


def test_fig2_robust_is_never_smaller_and_equal_when_consistent(result):
    fig2 = result["fig2"]
    for r in fig2:
        assert r["robust_area"] >= r["common_area"] * (1 - 1e-9)
    assert fig2[0]["robust_area"] == pytest.approx(fig2[0]["common_area"], rel=0.01)
    assert fig2[0]["consistency"] > fig2[-1]["consistency"]


def test_fig2_common_collapses_robust_stays_near_prediction(result):
    fig2 = result["fig2"]
    assert fig2[-1]["common_area"] < 0.25 * fig2[0]["common_area"]
    assert fig2[-1]["robust_area"] > 3 * fig2[-1]["common_area"]
    for r in fig2:
        assert r["robust_area"] > 0.7 * r["prior_area"]


def test_sweep_quantifies_the_papers_claim(result):
    s = result["sweep"]
    assert s["area_range_common"] > 100 * s["area_range_robust"]
    assert s["sensitivity_common"] > 10 * s["sensitivity_robust"]
    assert s["outlier_keeps_true_robust"] == 1.0
    assert s["outlier_keeps_true_common"] < 0.6


def test_markdown_has_the_three_columns(result):
    assert "| quantity | paper | optbound |" in result["markdown"]


def test_claim_rows_carry_computed_verdicts(result):
    md = result["markdown"]
    assert "| quantity | paper | optbound | verdict |" in md
    for r in result["fig1"]:
        line = next(x for x in md.splitlines() if x.startswith(f"| Fig. 1.1 {r['paper_label']}"))
        expected = "reproduced" if r["case"] == r["paper_case"] else "not reproduced"
        assert line.rstrip().endswith(f"| {expected} |")
    assert result["sweep"]["outliers"] > 0
