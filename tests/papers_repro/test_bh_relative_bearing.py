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


def test_the_area_table_has_one_best_ellipse_and_names_the_others(result):
    """One "best" ellipse row: the certified one found, its own area (not the midpoint of its
    bracket with the lower bound, which is no ellipse's area); the lower bound and the two
    candidates each in a row named for what it is; the bench's localization family uses the
    same name for the same construction."""
    from optbound.bench.localization_tightness import KINDS

    md, a = result["markdown"], result["areas"]
    table = md.split("### Areas")[1].split("###")[0]
    rows = {r.split(" | ")[0].lstrip("| "): r.split(" | ")[2].rstrip(" |") for r in
            table.splitlines()[2:] if r.startswith("| ")}  # fmt: skip
    assert set(repro.ELLIPSE_NAMES.values()) <= set(rows)
    assert [name for name in rows if "best" in name and "ellips" in name] == [
        repro.ELLIPSE_NAMES["best"]
    ]
    ex_mid = (a["exact"][0] + a["exact"][1]) / 2
    assert rows[repro.ELLIPSE_NAMES["best"]] == f"{a['ellipse'][1] / ex_mid:.2f}"
    assert rows[repro.ELLIPSE_NAMES["lower"]] == f"{a['ellipse'][0] / ex_mid:.2f}"
    assert rows[repro.ELLIPSE_NAMES["sdp"]] == f"{a['sdp'][1] / ex_mid:.2f}"
    best = KINDS["best_ellipse"]
    assert repro.ELLIPSE_NAMES["best"].startswith(best.split(" (")[0])


def test_optimal_reference_bracket(result):
    ref = result["references"]["opt4"]
    assert ref.lower <= ref.upper
    assert ref.bound.lifted.volume() == pytest.approx(ref.upper)


def test_sweep(result):
    sw = result["sweep"]
    assert sw["n"] == 4
    assert sw["proven"] == sw["n"] and sw["truth_inside"] == sw["n"]
    assert all(r["L8"] >= 1.0 - r["exact_rel_width"] for r in sw["rows"])


def test_linearized_filter_failures_are_counted(result):
    sw = result["sweep"]
    assert sw["lin_truth_lost"] == sum(r["lin_truth_lost"] for r in sw["rows"])
    assert sw["lin_set_lost"] == sum(r["lin_set_lost"] for r in sw["rows"])
    assert sw["l8_beats_lin"] == sum(r["L8_beats_lin"] for r in sw["rows"])
    # Sect. V: recompute the filter's verdict on the truth and on the exact set's inner corners.
    lin = result["linearized"]
    assert lin["truth_lost"] == (lin["ellipse"].level(repro.VEHICLE) > 1.0)
    assert lin["area"] == lin["ellipse"].volume() == result["areas"]["linearized"][0]


def test_linearized_check_detects_a_lost_truth():
    # An instance whose filter ellipse misses the true position is reported as lost.
    import numpy as np

    from optbound.localization import relative_bearing as rb

    L, pairs, eps = repro.LANDMARKS, repro.PAIRS, np.radians(repro.EPS_DEG)
    gammas = rb.bearings(repro.VEHICLE, L, pairs)
    paving = rb.exact_paving(L, pairs, gammas, eps, [[-0.3, 0.3], [-0.3, 0.3]], 0.02)
    inside = repro.linearized_check(L, pairs, gammas, eps, paving, repro.VEHICLE)
    far = inside["ellipse"].center + 10 * np.sqrt(np.diag(inside["ellipse"].shape))
    assert repro.linearized_check(L, pairs, gammas, eps, paving, far)["truth_lost"]


def test_claim_rows_carry_verdicts(result):
    claims = result["claims"]
    assert all(len(row) == 4 for row in claims)
    tighter = next(r for r in claims if r[0] == "pseudo-ellipsoid tighter than ellipsoidal bounds")
    sw, a = result["sweep"], result["areas"]
    flags = [
        a["L8"][1] < a["ellipse"][0],
        a["L8"][1] < a["linearized"][0],
        sw["l8_beats_lin"] >= repro.MOSTLY * sw["n"],
    ]
    assert tighter[3] == repro.verdict.all_or_some(flags)
