"""evaluate(): size and ratio brackets, soundness with exact counterexamples, bad estimators."""

import csv
import io
import json
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import optbound
from optbound import Box, Ellipsoid, problems
from optbound.compare import tri_contains
from optbound.interval import Tri
from optbound.problems.evaluation import COLUMNS
from tests.problems.estimators import hull_box, prior_ellipsoid, shrunk_box
from tests.problems.exact_membership import check as exactly_in_true_set

ALL = problems.suite("tiny")  # every family
TINY = [p for p in ALL if p.family == "strip"]  # the strip-specific tests


def test_evaluate_is_exported():
    assert optbound.evaluate is problems.evaluate
    from optbound import evaluate

    assert evaluate is problems.evaluate


def test_hull_box_is_proven_and_its_ratios_are_brackets():
    result = problems.evaluate(hull_box, ALL)
    assert [r["soundness"] for r in result.rows] == ["proven"] * len(ALL)
    for r in result.rows:
        assert set(r) == set(COLUMNS)
        assert r["error"] is None and r["counterexample"] is None
        assert 0 < r["size_lo"] <= r["size_hi"] and 0 < r["exact_lo"] <= r["exact_hi"]
        assert r["ratio_lo"] <= r["size_lo"] / r["exact_hi"] * (1 + 1e-15)
        assert r["ratio_hi"] >= r["size_hi"] / r["exact_lo"] * (1 - 1e-15)
        # The hull is the best box itself: ratio 1 up to the outward rounding.
        assert r["ratio_best_box_lo"] <= 1.0 <= r["ratio_best_box_hi"]
        assert r["ratio_best_box_hi"] - r["ratio_best_box_lo"] < 1e-12
        assert r["ratio_lo"] >= 1.0 or r["ratio_hi"] >= 1.0


def test_shrunk_box_is_refuted_with_exact_counterexamples():
    result = problems.evaluate(shrunk_box, ALL)
    for p, r, S in zip(ALL, result.rows, result.sets, strict=True):
        assert r["soundness"] == "refuted", r
        x = np.array(r["counterexample"])
        assert p.member(x)[0] == Tri.TRUE
        assert exactly_in_true_set(p, x)
        # Outside the shrunk box, compared as exact rationals.
        fx = [Fraction(c) for c in x]
        assert any(
            c < Fraction(lo) or c > Fraction(hi) for c, lo, hi in zip(fx, S.lo, S.hi, strict=True)
        )


def test_prior_ellipsoid_is_proven_exactly():
    result = problems.evaluate(prior_ellipsoid, TINY)
    assert [(r["soundness"], r["method"]) for r in result.rows] == [("proven", "exact")] * 4
    for r in result.rows:
        assert r["size_lo"] <= r["size_hi"] and r["ratio_optimal_ellipsoid_lo"] >= 1 - 1e-9


@settings(max_examples=8)
@given(st.integers(0, 2**20), st.integers(0, 3), st.sampled_from([0.5, 1.0, 2.0]))
def test_hull_of_the_exact_paving_is_never_refuted(seed, index, eps_factor):
    p = problems.suite("tiny", families=["strip"], seed=seed)[index]
    eps = p.eps * eps_factor

    def hull(problem):
        return problem.exact(eps).hull()

    row = problems.evaluate(hull, p).rows[0]
    assert row["soundness"] == "proven"


class _NaNSet:
    dim = 2

    def contains(self, X):
        return np.full(len(X), np.nan)


class _ContainsOnly:
    """A user set known only by contains: the shrunk box."""

    def __init__(self, box):
        self.box, self.dim = box, box.dim

    def contains(self, X):
        return self.box.contains(X, tol=0.0)


class _TriSet(_ContainsOnly):
    """A user set that also proves box membership."""

    def tri_contains(self, boxes):
        return tri_contains(self.box, boxes)


def _raises(p):
    raise RuntimeError("solver diverged")


@pytest.mark.parametrize(
    ("estimator", "message"),
    [
        (_raises, "RuntimeError: solver diverged"),
        (lambda p: None, "returned None"),
        (lambda p: Ellipsoid(np.zeros(3), np.eye(3)), "dimension 3, expected 2"),
        (lambda p: Ellipsoid([np.nan, 0.0], np.eye(2)), "ValueError"),
        (lambda p: _NaNSet(), "must return 1 booleans|must return \\d+ booleans"),
        (lambda p: np.array([np.nan, np.nan]), "not a set"),
        (lambda p: "a box", "str, which is not a set"),
    ],
)
def test_bad_estimators_give_error_rows(estimator, message):
    result = problems.evaluate(estimator, TINY[:2], name="bad")
    assert len(result.rows) == 2
    for r in result.rows:
        assert r["error"] is not None
        assert __import__("re").search(message, r["error"]), r["error"]
        assert r["soundness"] is None and r["size_lo"] is None and r["seconds"] >= 0
    assert result.counts()["error"] == 2


def test_user_objects_contains_only_and_tri_contains():
    p = TINY[0]
    only = problems.evaluate(lambda q: _ContainsOnly(shrunk_box(q)), p).rows[0]
    assert only["soundness"] == "refuted" and only["size_lo"] is None
    assert exactly_in_true_set(p, np.array(only["counterexample"]))
    tri = problems.evaluate(lambda q: _TriSet(hull_box(q)), p).rows[0]
    assert tri["soundness"] == "proven"
    box_lo, box_hi = hull_box(p).volume(), hull_box(p).volume()
    assert tri["size_lo"] <= box_hi and tri["size_hi"] >= box_lo
    assert tri["size_hi"] < np.inf


def test_the_sdp_reference_is_proven_by_its_s_procedure_certificate():
    def sdp(p):
        return p.references()["optimal_ellipsoid"]

    result = problems.evaluate(sdp, TINY)
    assert [(r["soundness"], r["method"]) for r in result.rows] == [("proven", "exact")] * 4
    for r in result.rows:
        assert r["ratio_optimal_ellipsoid_lo"] <= 1.0 <= r["ratio_optimal_ellipsoid_hi"]


def test_result_objects_are_read_through_their_set():
    from optbound import analytic

    def volume_update(p):
        return analytic.intersect_strip(p.data["ellipsoid"], p.data["strip"], criterion="volume")

    result = problems.evaluate(volume_update, TINY)
    for r, S in zip(result.rows, result.sets, strict=True):
        assert r["error"] is None and isinstance(S, Ellipsoid)
        assert r["soundness"] in ("proven", "undecided")  # sound: never refuted


def test_paving_and_pseudo_ellipsoid_answers():
    rows = problems.evaluate(lambda q: q.exact(), TINY[:1]).rows
    assert rows[0]["soundness"] == "proven"
    from optbound.compare.tri import as_pseudo_ellipsoid

    row = problems.evaluate(lambda q: as_pseudo_ellipsoid(q.data["ellipsoid"]), TINY[:1]).rows[0]
    assert row["error"] is None and row["soundness"] in ("proven", "undecided")
    E = TINY[0].data["ellipsoid"]
    assert row["size_lo"] <= E.volume() <= row["size_hi"]


def test_renderings():
    result = problems.evaluate(shrunk_box, TINY, name="shrunk")
    md = result.to_markdown()
    assert "shrunk" in md and all(p.name in md for p in TINY) and "refuted at" in md
    data = json.loads(result.to_json())
    assert data["estimator"] == "shrunk"
    for row, back in zip(result.rows, data["rows"], strict=True):
        assert back["counterexample"] == row["counterexample"]  # floats round-trip exactly
        assert set(back) == set(COLUMNS)
    table = list(csv.DictReader(io.StringIO(result.to_csv())))
    assert len(table) == len(TINY) and tuple(table[0]) == COLUMNS
    assert json.loads(table[0]["counterexample"]) == result.rows[0]["counterexample"]
    fig = result.figure()
    assert len(fig.axes) >= 2


def test_evaluate_validates_its_arguments():
    with pytest.raises(TypeError, match="estimator must be callable"):
        problems.evaluate(3, TINY)
    with pytest.raises(TypeError, match="Problem objects"):
        problems.evaluate(hull_box, [Box([0.0], [1.0])])
