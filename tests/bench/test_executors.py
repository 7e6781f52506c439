"""Executors: inline, process pool and Dask give the same results; bad choices are refused."""

import pytest

from optbound.bench import runner
from optbound.bench.executors import executor
from optbound.bench.registry import families


def _square(x):
    return x * x


def _assert_same_records(a, b):
    """Same records, field by field, except timings (``*_s``), which differ from run to run.

    SDP-derived floats may differ in the last digits: a worker's first solve of a problem
    shape goes through ``problem.solve``, later ones through the direct Clarabel path
    (``optimal/solver.py``), which agree to about 1e-9; which task comes first in a worker
    depends on scheduling, with any executor.
    """
    assert a.keys() == b.keys()
    for name in a:
        recs_a, recs_b = a[name]["records"], b[name]["records"]
        assert len(recs_a) == len(recs_b) > 0, name
        for ra, rb in zip(recs_a, recs_b, strict=True):
            assert ra.keys() == rb.keys()
            for key in ra:
                if key.endswith("_s"):
                    continue
                if isinstance(ra[key], float) and isinstance(rb[key], float):
                    assert ra[key] == pytest.approx(rb[key], rel=1e-7, abs=1e-12), (name, key)
                else:
                    assert ra[key] == rb[key], (name, key)


@pytest.mark.parametrize(("kind", "jobs"), [("process", 1), ("process", 2)])
def test_every_executor_runs_every_task_once(kind, jobs):
    with executor(kind, jobs) as pool:
        futures = [pool.submit(_square, x, priority=x) for x in range(6)]
        assert sorted(f.result() for f in pool.completed(futures)) == [0, 1, 4, 9, 16, 25]


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [({"kind": "threads"}, "executor must be one of"), ({"jobs": 0}, "jobs must be")],
)
def test_bad_executor_arguments(kwargs, message):
    with pytest.raises(ValueError, match=message), executor(**kwargs):
        pass


def test_parallel_tasks_start_longest_first(monkeypatch):
    order = []
    real = runner._run_registered

    def recording(item):
        order.append(item)
        return real(item)

    monkeypatch.setattr(runner, "_run_registered", recording)
    runner.run_suite("tiny", jobs=1, progress=False, names=["strip", "recursive"])
    fams = {f.name: f for f in families()}
    costs = [fams[name].cost(task) for name, _, task in order]
    assert costs == sorted(costs, reverse=True)
    assert {name for name, _, _ in order} == {"strip", "recursive"}


def test_dask_local_cluster_gives_the_same_results_as_jobs():
    pytest.importorskip("distributed")
    names = ["strip", "minkowski"]
    dask = runner.run_suite("tiny", seed=2, jobs=2, progress=False, names=names, executor="dask")
    pool = runner.run_suite("tiny", seed=2, jobs=2, progress=False, names=names)
    assert dask["meta"]["executor"] == "dask"
    _assert_same_records(dask["families"], pool["families"])
