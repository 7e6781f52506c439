"""The strip family: same instances as the bench, one description of the true set."""

import numpy as np
import pytest

from optbound import Box, problems
from optbound.compare import exact
from optbound.interval import Tri
from optbound.problems import strip


@pytest.mark.parametrize(("suite", "seed"), [("tiny", 0), ("quick", 0), ("quick", 7)])
def test_instances_are_bitwise_those_of_the_bench(suite, seed):
    from optbound.bench import strip_tightness

    tasks = strip_tightness.tasks(suite, seed)
    ours = problems.suite(suite, families=["strip"], seed=seed)
    assert len(ours) == len(tasks)
    for p, task in zip(ours, tasks, strict=True):
        E, S = strip_tightness.instance(task)
        assert p.seed == task["seed"] and p.dim == task["dim"]
        assert np.array_equal(p.data["ellipsoid"].center, E.center)
        assert np.array_equal(p.data["ellipsoid"].shape, E.shape)
        assert np.array_equal(p.data["strip"].a, S.a)
        assert p.data["strip"].b == S.b


def test_suites_and_names():
    assert problems.families()[0] == "strip"
    for name in problems.SUITES:
        assert problems.suite(name, families=["strip"]), name
    tiny = problems.suite("tiny", families=["strip"])
    assert {p.family for p in tiny} == {"strip"}
    quick = problems.suite("quick", families=["strip"])
    assert len({p.name for p in quick}) == len(quick)
    assert isinstance(tiny[0].seed, int) and tiny[0].truth is None
    with pytest.raises(ValueError, match="name must be one of"):
        problems.suite("huge")
    with pytest.raises(ValueError, match="families: unknown"):
        problems.suite("tiny", families=["nope"])


def _exactly_in(p, x) -> bool:
    return exact.member(p.data["ellipsoid"], x) and exact.member(p.data["strip"], x)


@pytest.mark.parametrize("index", range(4))
def test_member_is_exact(index):
    p = problems.suite("tiny", families=["strip"])[index]
    rng = np.random.default_rng(index)
    X = p.domain.sample(400, rng)
    tri = p.member(X)
    assert set(np.unique(tri)) <= {Tri.TRUE, Tri.FALSE, Tri.UNKNOWN}
    assert np.any(tri == Tri.TRUE) and np.any(tri == Tri.FALSE)
    for x, t in zip(X, tri, strict=True):
        if t != Tri.UNKNOWN:
            assert _exactly_in(p, x) == (t == Tri.TRUE)


def test_exact_paving_brackets_the_true_set():
    p = problems.suite("tiny", families=["strip"])[1]
    paving = p.exact()
    assert paving is p.exact()  # cached
    outer = paving.outer()
    rng = np.random.default_rng(0)
    # Points proven in the set lie in inner ∪ boundary; corners of inner boxes are in the set.
    X = p.domain.sample(2000, rng)
    for x in X[p.member(X) == Tri.TRUE]:
        assert np.any(np.all((outer[:, :, 0] <= x) & (x <= outer[:, :, 1]), axis=1))
    for box in paving.inner[rng.choice(paving.inner.shape[0], 20, replace=False)]:
        assert _exactly_in(p, box[:, 0]) and _exactly_in(p, box[:, 1])
    lo, hi = paving.volume_bounds()
    assert 0 < lo < hi
    with pytest.raises(ValueError, match="eps must be positive"):
        p.exact(-1.0)


def test_references_are_sound_bounds():
    p = problems.suite("tiny", families=["strip"])[2]
    refs = p.references()
    assert set(refs) == {"optimal_ellipsoid", "best_box"}
    hull = refs["best_box"]
    assert isinstance(hull, Box)
    outer = p.exact().outer()
    assert np.all(hull.lo <= outer[:, :, 0]) and np.all(outer[:, :, 1] <= hull.hi)
    # The SDP optimum is no larger than the prior and contains the paving's inner box corners.
    E = refs["optimal_ellipsoid"]
    assert E.volume() <= p.data["ellipsoid"].volume() * (1 + 1e-9)
    for box in p.exact().inner[:50]:
        assert exact.member(E, box[:, 0]) and exact.member(E, box[:, 1])


def test_member_validates_points():
    p = problems.suite("tiny", families=["strip"])[0]
    with pytest.raises(ValueError, match="X"):
        p.member(np.zeros((3, 5)))
    assert p.member(p.data["ellipsoid"].center).shape == (1,)


def test_tasks_refuse_unknown_suites():
    with pytest.raises(ValueError, match="suite must be one of"):
        strip.tasks("huge", 0)
