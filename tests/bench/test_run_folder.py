"""Runs that survive: each finished task stored at once, ``--resume``, and dead workers."""

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from optbound.bench import registry, runner
from optbound.bench.run_folder import RunFolder, RunFolderError
from optbound.cli import main
from optbound.report import load_results
from tests.bench import test_only_families as test_only
from tests.bench.test_executors import _assert_same_records

ROOT = Path(__file__).parents[2]


@pytest.mark.parametrize(("target", "jobs"), [("KILLER", 2), ("KILLER_ISOLATED", 1)])
def test_a_dead_worker_fails_its_task_and_the_run_completes(target, jobs, tmp_path, monkeypatch):
    """A worker killed by SIGKILL inside a task: that task failed with the reason, every other
    task's records there (tasks in flight with it are run again), every task stored. Pool
    workers are forked, so they see the test-only family registered here."""
    monkeypatch.setitem(registry.FAMILIES, "killer", f"tests.bench.test_only_families:{target}")
    folder = RunFolder(tmp_path, {"command": "bench"})
    res = runner.run_suite("tiny", jobs=jobs, progress=False, names=["killer"], folder=folder)
    fam = res["families"]["killer"]
    assert [r["seed"] for r in fam["records"]] == [0, 1, 3, 4]
    [error] = fam["errors"]
    assert error["task"] == {"seed": test_only.KILLED}
    assert error["error"].startswith("WorkerDied: the process running this task was killed by")
    assert "SIGKILL" in error["error"]
    assert sorted(p.name for p in (tmp_path / "tasks").iterdir()) == [
        f"killer-{k:04d}.json" for k in range(5)
    ]


def test_a_killed_run_resumes_to_the_uninterrupted_results(tmp_path, monkeypatch):
    """SIGKILL to a real run whose pooled tasks are stored while a serial task runs;
    ``--resume`` runs only the tasks not stored, and the report's records equal those of an
    uninterrupted run of the same seed."""
    out, mark = tmp_path / "out", tmp_path / "blocking"
    argv = ["bench", "--suite", "tiny", "--family", "minkowski", "--family", "sleeper",
            "--jobs", "1", "--no-progress"]  # fmt: skip
    main_call = f"from optbound.cli import main; main({[*argv, '--out', str(out)]})"
    code = test_only.REGISTER_SLEEPER + main_call
    proc = subprocess.Popen(
        [sys.executable, "-c", code],
        cwd=ROOT,
        env={**os.environ, test_only.BLOCK_ENV: str(mark)},
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        start_new_session=True,
    )
    deadline = time.monotonic() + 120
    while not mark.exists():
        assert proc.poll() is None and time.monotonic() < deadline, "the run did not block"
        time.sleep(0.01)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    stored = {p.name for p in out.glob("tasks/*.json")}
    assert stored == {"minkowski-0000.json", "minkowski-0001.json"}
    assert not (out / "results.json").exists()

    monkeypatch.setitem(registry.FAMILIES, "sleeper", "tests.bench.test_only_families:SLEEPER")
    ran = []
    real = runner._run_registered
    monkeypatch.setattr(runner, "_run_registered", lambda item: ran.append(item) or real(item))
    assert main(["bench", "--resume", str(out), "--jobs", "1", "--no-progress"]) == 0
    assert [(name, index) for name, index, _ in ran] == [("sleeper", 0), ("sleeper", 1)]
    resumed = load_results(out)
    assert resumed["meta"]["resumed_tasks"] == len(stored)
    assert "(2 task(s) were)" in (out / "report.md").read_text()
    assert (resumed["meta"]["suite"], resumed["meta"]["seed"]) == ("tiny", 0)
    whole = runner.run_suite("tiny", 0, jobs=1, progress=False, names=["minkowski", "sleeper"])
    _assert_same_records(resumed["families"], whole["families"])


@pytest.fixture
def run_dir(tmp_path):
    """A run folder with one stored task, as an interrupted ``bench --suite tiny`` leaves."""
    arguments = {"command": "bench", "suite": "tiny", "seed": 3, "family": ["strip"],
                 "estimator": None}  # fmt: skip
    RunFolder(tmp_path, arguments).save("strip", 0, {"seed": 1}, {"records": [], "seconds": 0})
    return tmp_path


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--seed", "4"], "was started with seed 3, not 4; leave seed out to resume it"),
        (["--suite", "quick"], "was started with suite 'tiny', not 'quick'"),
        (["--family", "minkowski"], "was started with family ['strip'], not ['minkowski']"),
        (["--force"], "--resume finishes a run; it cannot be combined with --force"),
        (["--out", "elsewhere"], "differs from --resume"),
    ],
)
def test_resume_refuses_other_arguments(run_dir, argv, message, capsys):
    assert main(["bench", "--resume", str(run_dir), *argv]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and message in err


def test_resume_refuses_what_is_not_a_run_of_the_command(run_dir, tmp_path, capsys):
    assert main(["repro", "--resume", str(run_dir)]) == 2
    assert "holds a run of optbound bench, not of optbound repro" in capsys.readouterr().err
    empty = tmp_path / "empty"
    empty.mkdir()
    for folder, message in ((empty, "is not a run folder"), (tmp_path / "no", "does not exist")):
        assert main(["bench", "--resume", str(folder)]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and message in err
    (empty / "run.json").write_text("{")
    with pytest.raises(RunFolderError, match="cannot read"):
        RunFolder.open(empty)


def test_a_fresh_run_does_not_take_over_an_interrupted_one(run_dir, capsys):
    assert main(["bench", "--suite", "tiny", "--out", str(run_dir)]) == 2
    assert f"--resume {str(run_dir)!r} to finish its run" in capsys.readouterr().err


def test_a_stored_task_is_used_only_for_the_same_task(run_dir):
    folder = RunFolder.open(run_dir)
    assert folder.arguments["seed"] == 3
    assert folder.load("strip", 0, {"seed": 1}) == {"records": [], "seconds": 0}
    assert folder.load("strip", 0, {"seed": 2}) is None
    assert folder.load("strip", 1, {"seed": 1}) is None
    assert sorted(p.name for p in run_dir.rglob("*")) == ["run.json", "strip-0000.json", "tasks"]
    assert json.loads((run_dir / "run.json").read_text())["arguments"]["family"] == ["strip"]


def test_repro_resume_refuses_other_papers(tmp_path, capsys):
    arguments = {"command": "repro", "papers": ["BH"], "quick": True}
    RunFolder(tmp_path, arguments).save("papers", 0, {"seed": 1}, {"records": [], "seconds": 0})
    assert main(["repro", "GLH12", "--resume", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "was started with papers ['BH'], not ['GLH12']" in err and err.count("\n") == 1


def test_ctrl_c_after_a_stored_task_keeps_the_folder_and_says_how_to_resume(
    tmp_path, capsys, monkeypatch
):
    def interrupted(*args, folder, **kwargs):
        folder.save("strip", 0, {"seed": 1}, {"records": [], "seconds": 0})
        raise KeyboardInterrupt

    monkeypatch.setattr(runner, "run_suite", interrupted)
    out = tmp_path / "new" / "out"
    assert main(["bench", "--suite", "tiny", "--out", str(out)]) == 130
    err = capsys.readouterr().err
    assert err == f"optbound bench: interrupted; finish it with: optbound bench --resume {out}\n"
    assert RunFolder.open(out).arguments["suite"] == "tiny"
