"""Family ``linear_estimation``: suites, the exact polygon test, an observer evaluated."""

import time

import numpy as np
import pytest

from optbound import problems
from optbound.estimation import METHODS, observe
from optbound.interval import Interval, Tri
from optbound.problems import linear_estimation as family
from tests.problems.exact_membership import check, check_outside

TINY = problems.suite("tiny", families=["linear_estimation"])


def test_tiny_is_alamo_at_5_and_one_random_system_at_10():
    assert [p.name for p in TINY] == ["alamo-k5", "random-k10-r0"]
    alamo, rand = TINY
    assert alamo.truth is None and len(alamo.data["ys"]) == 5
    assert rand.truth.shape == (2,) and len(rand.data["ys"]) == 10
    assert rand.member(rand.truth)[0] != Tri.FALSE
    assert check(rand, rand.truth)


def test_quick_has_more_steps_and_seeds_and_bad_suite_is_refused():
    quick = family.tasks("quick", 0)
    assert len(quick) > len(family.tasks("tiny", 0))
    assert len({(t["system"], t["k"]) for t in quick}) >= 6
    with pytest.raises(ValueError, match="suite"):
        family.tasks("huge", 0)
    with pytest.raises(ValueError, match="system"):
        family.instance("lorenz", 0, 3)


@pytest.mark.parametrize("p", TINY, ids=lambda p: p.name)
def test_box_test_agrees_with_exact_membership(p):
    X = p.domain.sample(400, np.random.default_rng(5))
    tri = p.member(X)
    assert np.any(tri == Tri.TRUE) and np.any(tri == Tri.FALSE)
    for x in X[tri == Tri.TRUE][:30]:
        assert check(p, x)
    for x in X[tri == Tri.FALSE][:30]:
        assert check_outside(p, x)
    # A box test: the domain box is UNKNOWN, a box far away FALSE.
    lo, hi = p.domain.lo, p.domain.hi
    assert p.test(Interval(lo[0], hi[0]), Interval(lo[1], hi[1])) == Tri.UNKNOWN
    assert p.test(Interval(hi[0] + 1, hi[0] + 2), Interval(lo[1], hi[1])) == Tri.FALSE


@pytest.mark.parametrize("method", METHODS)
def test_every_observer_is_evaluated_at_bounded_cost_and_never_refuted(method):
    # A constrained zonotope was once sized by paving it with one LP per box, and its
    # soundness audited with one LP per point: minutes per problem. Now a few seconds at most
    # (generous for a loaded machine), with a certified size.
    start = time.perf_counter()
    result = problems.evaluate(
        lambda p: observe(p.data["system"], p.data["X0"], p.data["ys"], method)[-1], TINY
    )
    assert time.perf_counter() - start < 30.0
    assert [r["error"] for r in result.rows] == [None] * len(TINY)
    assert {r["soundness"] for r in result.rows} <= {"proven", "undecided"}
    for r in result.rows:
        assert 0 < r["size_lo"] <= r["size_hi"] < np.inf
        assert r["ratio_hi"] >= 1.0  # an outer bound is at least the exact set's size
