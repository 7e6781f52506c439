"""Executors: inline, process pool and Dask give the same results; bad choices are refused."""

import pytest

from benchmarks import runner
from benchmarks.executors import executor
from benchmarks.registry import families


def _square(x):
    return x * x


def _records(results):
    """Every record without its timings (``*_s`` fields), which differ from run to run."""
    return {
        name: [{k: v for k, v in rec.items() if not k.endswith("_s")} for rec in fam["records"]]
        for name, fam in results["families"].items()
    }


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
    assert _records(dask) == _records(pool)
    assert all(fam["records"] for fam in dask["families"].values())
