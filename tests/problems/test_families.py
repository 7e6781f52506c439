"""Every problem family: suites, exact member TRUE points, the hull never refuted, a shrunk
hull refuted with an exact counterexample."""

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from optbound import Box, problems
from optbound.compare import prove_contains
from optbound.interval import Tri
from tests.problems.exact_membership import OUTSIDE_FAMILIES, check, check_outside

FAMILIES = problems.families()
TINY = problems.suite("tiny")


def test_every_family_is_in_every_suite():
    assert FAMILIES == [
        "strip",
        "minkowski",
        "recursive",
        "bh_bearings",
        "hs96_pose",
        "sonar",
        "visibility",
    ]
    assert {p.family for p in TINY} == set(FAMILIES)
    for p in TINY:
        assert isinstance(p.seed, int) and p.dim == len(p.domain.lo)
    names = [(p.family, p.name) for p in TINY]
    assert len(set(names)) == len(names)


@pytest.mark.parametrize("family", FAMILIES)
def test_suite_seed_changes_instances_reproducibly(family):
    a, b = (problems.suite("tiny", families=[family], seed=s)[0] for s in (3, 3))
    c = problems.suite("tiny", families=[family], seed=4)[0]
    assert a.seed == b.seed and a.name == b.name and a.seed != c.seed


def _problem(family: str):
    return next(p for p in TINY if p.family == family)


@pytest.mark.parametrize("family", FAMILIES)
def test_member_true_points_are_in_the_true_set(family):
    p = _problem(family)
    rng = np.random.default_rng(1)
    paving = p.exact()
    # Points of the inner boxes (members) and of the whole domain (members and not).
    inner = paving.inner[rng.choice(len(paving.inner), min(20, len(paving.inner)), replace=False)]
    X = np.concatenate(
        [
            inner[:, :, 0] + rng.uniform(size=inner.shape[:2]) * (inner[:, :, 1] - inner[:, :, 0]),
            p.domain.sample(200, rng),
        ]
    )
    tri = p.member(X)
    assert np.any(tri == Tri.TRUE)
    for x in X[tri == Tri.TRUE][:30]:
        assert check(p, x), (p.name, x.tolist())
    if p.truth is not None:
        assert p.member(p.truth)[0] != Tri.FALSE  # the simulated state is never excluded
        assert check(p, p.truth) or p.member(p.truth)[0] == Tri.UNKNOWN


@pytest.mark.parametrize("family", OUTSIDE_FAMILIES)
def test_member_false_points_are_outside_the_true_set(family):
    p = _problem(family)
    X = p.domain.sample(300, np.random.default_rng(2))
    tri = p.member(X)
    assert np.any(tri == Tri.FALSE)
    for x in X[tri == Tri.FALSE][:30]:
        assert check_outside(p, x), (p.name, x.tolist())


@pytest.mark.parametrize("family", FAMILIES)
@settings(max_examples=2, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 2**16))
def test_hull_of_the_exact_paving_is_never_refuted(family, seed):
    p = problems.suite("tiny", families=[family], seed=seed)[0]
    paving = p.exact()
    verdict = prove_contains(paving.hull(), paving, member=p.test)
    assert verdict.status == "proven", (p.name, verdict)


@pytest.mark.parametrize("family", FAMILIES)
def test_shrunk_hull_is_refuted_with_an_exact_counterexample(family):
    p = _problem(family)
    hull = p.exact().hull()
    half = 0.35 * hull.widths
    shrunk = Box(hull.center - half, hull.center + half)
    verdict = prove_contains(shrunk, p.exact(), member=p.test)
    assert verdict.status == "refuted", (p.name, verdict)
    x = np.asarray(verdict.counterexample, dtype=float)
    assert p.member(x)[0] == Tri.TRUE
    assert check(p, x)
    assert any(
        Fraction(c) < Fraction(lo) or Fraction(c) > Fraction(hi)
        for c, lo, hi in zip(x, shrunk.lo, shrunk.hi, strict=True)
    )


@pytest.mark.parametrize("family", FAMILIES)
def test_references_contain_the_exact_paving(family):
    from optbound.compare import exact

    p = _problem(family)
    refs = p.references()
    assert set(refs) >= {"optimal_ellipsoid", "best_box"}
    outer = p.exact().outer()
    box = refs["best_box"]
    assert np.all(box.lo <= outer[:, :, 0]) and np.all(outer[:, :, 1] <= box.hi)
    E = refs["optimal_ellipsoid"]
    for b in p.exact().inner[:20]:
        assert exact.member(E, b[:, 0]) and exact.member(E, b[:, 1])


@pytest.mark.parametrize(
    "module", ["minkowski", "recursive", "bh_bearings", "hs96_pose", "sonar", "visibility"]
)
def test_tasks_refuse_unknown_suites(module):
    import importlib

    family = importlib.import_module(f"optbound.problems.{module}")
    with pytest.raises(ValueError, match="suite must be one of"):
        family.tasks("huge", 0)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_recursive_domains_contain_the_true_set(seed):
    from optbound.compare import exact

    for p in problems.suite("tiny", families=["recursive"], seed=seed):
        sets = (p.data["prior"], *p.data["strips"])
        X = p.data["prior"].sample(4000, np.random.default_rng(seed))
        inside = [x for x in X if all(exact.member(S, x) for S in sets)]
        assert inside, p.name
        assert all(exact.member(p.domain, x) for x in inside)


def test_minkowski_domain_contains_the_sum():
    for p in problems.suite("tiny", families=["minkowski"]):
        E1, E2 = p.data["summands"]
        rng = np.random.default_rng(0)
        # Extreme points of the sum: the support points of both summands in one direction.
        for d in rng.standard_normal((200, p.dim)):
            x = sum(E.center + E.shape @ d / np.sqrt(d @ E.shape @ d) for E in (E1, E2))
            assert np.all(p.domain.lo <= x) and np.all(x <= p.domain.hi)
