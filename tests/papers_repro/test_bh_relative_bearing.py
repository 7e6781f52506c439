"""BH Sect. V reproduction (quick variant): claims, proofs, areas, sweep."""

import pytest

from optbound.papers_repro import bh_relative_bearing as repro


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    return repro.main(tmp_path_factory.mktemp("bh"), quick=True)


def test_paper_key_and_figures(result):
    assert repro.PAPER == "BH"
    assert len(result["figures"]) == 2
    for path in result["figures"]:
        assert path.suffix == ".png" and path.stat().st_size > 10_000
    assert "| quantity | paper | optbound |" in result["markdown"]


def test_bounds_are_proven_and_ordered(result):
    a = result["areas"]
    assert all(p.proven for p in result["proofs"].values())
    # Every outer bound's area is at least the exact set's lower area.
    for key in ("L8", "L4", "opt4", "box"):
        assert a[key][1] >= a["exact"][0]
    # The paper's claims: L = 8 tighter than L = 4, both after step 1 and at the end.
    assert a["L8"][1] < a["L4"][0]
    assert result["first"]["L8"][1] < result["first"]["L4"][0]
    # Fig. 6b: after the first step even L = 4 is far below the best box.
    assert result["first"]["L4"][1] < 0.5 * result["first"]["box"][0]
    # The best ellipse is bracketed; the certified one contains the exact set.
    assert a["ellipse"][0] <= a["ellipse"][1] <= a["sdp"][1]
    assert a["ellipse"][1] >= a["exact"][0]


def test_optimal_reference_bracket(result):
    ref = result["references"]["opt4"]
    assert ref.lower <= ref.upper
    assert ref.bound.lifted.volume() == pytest.approx(ref.upper)


def test_sweep(result):
    sw = result["sweep"]
    assert sw["n"] == 4
    assert sw["proven"] == sw["n"] and sw["truth_inside"] == sw["n"]
    assert all(r["L8"] >= 1.0 - r["exact_rel_width"] for r in sw["rows"])
