"""LJMW97 Sect. 4 reproduction: triangular room, components and association hypotheses."""

import numpy as np
import pytest

from optbound.localization.sonar import measurement_box, simulate_ranges
from optbound.papers_repro import ljmw97_triangle as repro
from optbound.papers_repro._verdict import count_verdict


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    return repro.main(tmp_path_factory.mktemp("ljmw97_triangle"), quick=True)


def test_declares_its_paper_and_figures(result):
    assert repro.PAPER == "LJMW97"
    assert len(result["figures"]) == 2
    for path in result["figures"]:
        assert path.suffix == ".png" and path.stat().st_size > 10_000
    assert "| quantity | paper | optbound |" in result["markdown"]


def test_truth_is_in_exactly_one_component_whose_hypothesis_is_the_true_association(result):
    for rows in (result["components"], result["components_prior"]):
        [q1] = [r for r in rows if r["contains_truth"]]
        seen = tuple(
            (
                int(
                    np.argmin(
                        [
                            simulate_ranges(repro.WORLD[j : j + 1], s, repro.TRUTH)[0]
                            for j in range(len(repro.WORLD))
                        ]
                    )
                ),
            )
            for s in repro.SONARS
        )
        assert q1["hypothesis"] == seen


def test_prior_only_removes_components(result):
    """The clearance prior is a conjunction: it cannot add poses, only drop some."""
    plain = {(tuple(r["lo"]), tuple(r["hi"])) for r in result["components"]}
    prior = {(tuple(r["lo"]), tuple(r["hi"])) for r in result["components_prior"]}
    assert len(prior) <= len(plain)
    assert len(result["components_prior"]) >= 1
    for r in result["components_prior"]:
        # each remaining hull lies inside the hull of some component of the plain problem
        assert any(
            np.all(np.asarray(lo) <= r["lo"]) and np.all(r["hi"] <= np.asarray(hi))
            for lo, hi in plain
        )


def test_proven_components_hold_checked_poses(result):
    """A proven component's witness is in it and its ranges are inside the readings."""
    box = measurement_box(repro.SONARS, repro.readings())
    for rows in (result["components"], result["components_prior"]):
        assert any(r["proven"] for r in rows)
        for r in rows:
            if r["proven"]:
                w = r["witness"]
                assert np.all(r["lo"] <= w) and np.all(w <= r["hi"])
                d = simulate_ranges(repro.WORLD, repro.SONARS, w)
                assert np.all((box[:, 0] <= d) & (d <= box[:, 1]))
            else:
                assert r["witness"] is None


def _row(volume, proven, truth=False, h=((0,), (1,))):
    return {"volume": volume, "proven": proven, "contains_truth": truth, "hypothesis": h}


def test_q2_is_the_second_largest_proven_component():
    rows = [_row(5, True, truth=True), _row(4, False), _row(3, True), _row(2, True)]
    q1, q2 = repro.proven_pair(rows)
    assert q1 is rows[0] and q2 is rows[2]  # not the unproven rows[1]
    rows = [_row(5, True), _row(4, True, truth=True), _row(3, True)]
    q1, q2 = repro.proven_pair(rows)
    assert q1 is rows[1] and q2 is rows[0]
    assert repro.proven_pair([_row(5, True, truth=True), _row(4, False)])[1] is None


def test_count_verdict_uses_proven_and_all_components(result):
    rows = result["components"]
    proven = sum(r["proven"] for r in rows)
    [count] = [c for c in result["claims"] if c[0].startswith("number of components")]
    assert count[3] == count_verdict(repro.PAPER_COMPONENTS, proven, len(rows))
    assert f"proven {proven} of {len(rows)}" in count[2]


def test_sweep_counts(result):
    sweep = result["sweep"]
    assert {(r["prior"], r["contract"]) for r in sweep} == {
        (p, c) for p in (False, True) for c in (False, True)
    }
    for r in sweep:
        assert 1 <= r["proven"] <= r["components"]
