"""The problem families rebuild the benchmark's instances bitwise, for the same suite and seed."""

import numpy as np
import pytest

from optbound import problems

CASES = [("tiny", 0), ("quick", 0), ("quick", 7)]


@pytest.mark.parametrize(("suite", "seed"), CASES)
def test_minkowski_instances_are_the_bench_s(suite, seed):
    from optbound.bench import minkowski_tightness as bench

    tasks = bench.tasks(suite, seed)
    ours = problems.suite(suite, families=["minkowski"], seed=seed)
    assert len(ours) == len(tasks)
    for p, task in zip(ours, tasks, strict=True):
        assert p.seed == task["seed"] and p.dim == task["dim"]
        for mine, theirs in zip(p.data["summands"], bench.instance(task), strict=True):
            assert np.array_equal(mine.center, theirs.center)
            assert np.array_equal(mine.shape, theirs.shape)


@pytest.mark.parametrize(("suite", "seed"), CASES)
def test_recursive_instances_are_the_bench_s(suite, seed):
    from optbound.bench import recursive_tightness as bench

    tasks = bench.tasks(suite, seed)
    ours = iter(problems.suite(suite, families=["recursive"], seed=seed))
    for task in tasks:
        E0, point, strips = bench.instance(task)
        for k in task["ks"]:
            p = next(ours)
            assert p.seed == task["seed"] and p.dim == task["dim"]
            assert np.array_equal(p.data["prior"].center, E0.center)
            assert np.array_equal(p.data["prior"].shape, E0.shape)
            assert np.array_equal(p.truth, point)
            assert len(p.data["strips"]) == k
            for mine, theirs in zip(p.data["strips"], strips[:k], strict=True):
                assert np.array_equal(mine.a, theirs.a) and mine.b == theirs.b
    assert next(ours, None) is None


@pytest.mark.parametrize(("suite", "seed"), CASES)
def test_bh_bearings_instances_are_the_bench_s(suite, seed):
    from optbound.bench import localization_tightness as bench

    tasks = bench.tasks(suite, seed)
    ours = problems.suite(suite, families=["bh_bearings"], seed=seed)
    assert len(ours) == len(tasks)
    for p, task in zip(ours, tasks, strict=True):
        landmarks, pairs, gammas, eps, truth = bench.instance(task)
        data = p.data["measurements"]
        assert p.seed == task["seed"]
        assert np.array_equal(data.landmarks, landmarks)
        assert np.array_equal(data.pairs, np.asarray(pairs))
        assert np.array_equal(p.data["gammas"], gammas)
        assert np.array_equal(p.data["eps"], np.broadcast_to(eps, data.gammas.shape))
        assert np.array_equal(p.truth, truth)


def test_bh_bearings_exact_set_is_the_bench_paving():
    from optbound.bench import localization_tightness as bench

    p = problems.suite("tiny", families=["bh_bearings"])[0]
    task = bench.tasks("tiny", 0)[0]
    theirs, width = bench.exact_set(p.data["measurements"], task["relative"])
    assert p.eps == width
    assert np.array_equal(p.exact().inner, theirs.inner)
    assert np.array_equal(p.exact().boundary, theirs.boundary)
