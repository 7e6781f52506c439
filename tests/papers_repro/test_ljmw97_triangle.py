"""LJMW97 Sect. 4 reproduction: triangular room, components and association hypotheses."""

import numpy as np
import pytest

from optbound.localization.sonar import simulate_ranges
from optbound.papers_repro import ljmw97_triangle as repro


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
