"""``optbound bench`` and ``optbound report DIR`` end to end on the tiny suite.

The tiny suite runs the same families through the same code path as quick, only smaller.
"""

import json
import os
import subprocess
import sys

import pytest

from optbound.bench.registry import FAMILIES, families
from optbound.bench.runner import run_suite
from optbound.cli import main
from optbound.report import load_results
from tests.bench.test_family import FULL_ONLY

TIGHTNESS = [f.name for f in families() if f.kind == "tightness"]


@pytest.fixture(scope="module")
def bench_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("bench")
    argv = ["bench", "--suite", "tiny", "--out", str(out), "--jobs", "2", "--no-progress"]
    assert main([*argv, "--force"]) == 0  # mktemp created the (empty) folder
    return out


def test_bench_writes_a_complete_report(bench_dir, capsys):
    results = load_results(bench_dir)
    assert results["meta"]["suite"] == "tiny"
    for name, fam in results["families"].items():
        # codac is optional: its family may report a note instead of records
        assert fam["status"] == "ok", (name, fam["reason"])
        assert not fam["errors"], (name, fam["errors"])
        assert bool(fam["records"] or fam["notes"]) == (name not in FULL_ONLY), name
    text = (bench_dir / "report.md").read_text()
    assert "## Headline" in text
    for name in TIGHTNESS:
        assert f"![{name} ratio histograms](hist_{name}.png)" in text
        assert (bench_dir / f"hist_{name}.png").stat().st_size > 10_000
    for png in ("recursive.png", "instances_2d.png"):
        assert (bench_dir / png).stat().st_size > 10_000
    assert (bench_dir / "tightness.csv").read_text().startswith("family,variant,dim")
    assert (bench_dir / "speed.csv").exists()


def test_tiny_ratios_are_outer_bounds_of_a_tight_reference(bench_dir):
    """On one ellipsoid and one strip the clipped SDP is the true optimum, so volume ratios
    must be >= 1 up to solver accuracy, and no analytic bound may miss a sampled point."""
    strip = load_results(bench_dir)["families"]["strip"]["records"]
    volume = [r["ratio"] for r in strip if r["criterion"] == "volume" and r["ratio"] is not None]
    assert volume and min(volume) > 1 - 1e-4
    assert sum(r["outside"] for r in strip) == 0


def test_report_rebuilds_from_results_json_alone(bench_dir, capsys):
    report = bench_dir / "report.md"
    before = report.read_text()
    report.unlink()
    for png in bench_dir.glob("*.png"):
        png.unlink()
    assert main(["report", str(bench_dir)]) == 0
    assert report.read_text() == before
    assert (bench_dir / "instances_2d.png").exists()
    assert "Report:" in capsys.readouterr().out


def test_pool_and_serial_runs_give_the_same_ratios():
    def ratios(jobs):
        res = run_suite("tiny", seed=4, jobs=jobs, progress=False, names=["strip"])
        return [
            (r["seed"], r["criterion"], r["ratio"]) for r in res["families"]["strip"]["records"]
        ]

    assert ratios(1) == ratios(2)


def test_seed_changes_the_instances():
    def seeds(seed):
        res = run_suite("tiny", seed=seed, jobs=1, progress=False, names=["minkowski"])
        return {r["seed"] for r in res["families"]["minkowski"]["records"]}

    assert seeds(0).isdisjoint(seeds(1))


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["bench", "--suite", "huge"], "invalid choice: 'huge'"),
        (["bench", "--seed", "-1"], "seed must be >= 0"),
        (["bench", "--seed", "x"], "seed must be an integer"),
        (["bench", "--jobs", "0"], "jobs must be >= 1"),
        (["bench", "--family", "nope"], "invalid choice: 'nope'"),
        (["frobnicate"], "invalid choice: 'frobnicate'"),
    ],
)
def test_bad_arguments_fail_with_a_clear_message(argv, message, capsys):
    with pytest.raises(SystemExit) as exc:
        main(argv)
    assert exc.value.code == 2
    assert message in capsys.readouterr().err


def test_report_of_a_missing_or_empty_directory_fails_clearly(tmp_path, capsys):
    for target, message in ((tmp_path / "nowhere", "does not exist"), (tmp_path, "no results")):
        with pytest.raises(SystemExit) as exc:
            main(["report", str(target)])
        assert exc.value.code == 2
        assert message in capsys.readouterr().err


def test_report_of_a_corrupt_results_file_fails_clearly(tmp_path, capsys):
    (tmp_path / "results.json").write_text(json.dumps({"schema": 1}))
    with pytest.raises(SystemExit):
        main(["report", str(tmp_path)])
    assert "lacks the 'meta' section" in capsys.readouterr().err


def _fails_at_once(argv, capsys, monkeypatch) -> str:
    """Run ``argv``, expect exit code 2 with one line on stderr, and no task run."""
    import optbound.bench.runner

    def no_work(*args, **kwargs):
        raise AssertionError("work started before the arguments were checked")

    monkeypatch.setattr(optbound.bench.runner, "run_suite", no_work)
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith(f"optbound {argv[0]}: error: ")
    return err


def test_bench_out_must_be_a_directory(tmp_path, capsys, monkeypatch):
    target = tmp_path / "file.txt"
    target.write_text("x")
    err = _fails_at_once(["bench", "--suite", "tiny", "--out", str(target)], capsys, monkeypatch)
    assert "is not a directory" in err
    err = _fails_at_once(["bench", "--out", str(target / "sub")], capsys, monkeypatch)
    assert "cannot write to --out" in err


def test_out_is_created_before_the_run(tmp_path, capsys, monkeypatch):
    target = tmp_path / "new" / "deeper"
    _fails_at_once(["repro", "NOPE", "--out", str(target)], capsys, monkeypatch)
    assert not target.exists()  # the key is checked first
    with pytest.raises(AssertionError, match="work started"):
        main(["bench", "--out", str(target)])  # out is fine: the run is reached ...
    assert target.is_dir()  # ... after creating it


def test_an_existing_report_is_not_overwritten_without_force(bench_dir, capsys, monkeypatch):
    err = _fails_at_once(["bench", "--out", str(bench_dir)], capsys, monkeypatch)
    assert "already holds a report" in err and "--force" in err


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--family", "strip"], "needs a complete run"),
        (["--suite", "tiny"], "default suite only, not --suite tiny"),
        (["--seed", "3"], "not --seed 3"),
    ],
)
def test_update_readme_only_from_a_complete_default_run(
    tmp_path, capsys, monkeypatch, extra, message
):
    err = _fails_at_once(
        ["bench", "--update-readme", "--out", str(tmp_path), *extra], capsys, monkeypatch
    )
    assert message in err


def test_unknown_paper_key_fails_clearly(tmp_path, capsys, monkeypatch):
    err = _fails_at_once(["repro", "HS96", "ZZ01", "--out", str(tmp_path)], capsys, monkeypatch)
    assert "unknown keys ['ZZ01']" in err


def test_repro_writes_the_papers_tables_and_figures(tmp_path, capsys, monkeypatch):
    import optbound.bench.runner

    titles = []
    progress = optbound.bench.runner.Progress
    monkeypatch.setattr(
        optbound.bench.runner,
        "Progress",
        lambda title, *args: titles.append(title) or progress(title, *args),
    )
    argv = ["repro", "ljmw97", "--quick", "--out", str(tmp_path), "--jobs", "1", "--no-progress"]
    assert main(argv) == 0
    assert titles == ["optbound repro ljmw97 --quick"]
    text = (tmp_path / "report.md").read_text()
    assert text.startswith("# optbound paper reproductions\n")
    assert "Re-run with `optbound repro ljmw97 --quick`" in text
    assert "optbound bench" not in text
    assert "tightness.csv" not in text and "speed.csv" not in text
    assert "## The papers' results, reproduced" in text
    assert "### LJMW97 Appendix A" in text and "## HS96" not in text
    assert "typed from the paper" in text
    pngs = sorted((tmp_path / "papers" / "ljmw97_appendix_a").glob("*.png"))
    assert pngs and all(f"(papers/ljmw97_appendix_a/{p.name})" in text for p in pngs)
    saved = load_results(tmp_path)["families"]["papers"]["attachments"]
    # Both LJMW97 scripts ran; results.json keeps the attachments' names only.
    assert {s.split("/")[1] for s in saved} == {"ljmw97_appendix_a", "ljmw97_triangle"}
    appendix = [s for s in saved if s.startswith("papers/ljmw97_appendix_a/")]
    assert appendix == sorted(f"papers/ljmw97_appendix_a/{p.name}" for p in pngs)
    assert all((tmp_path / s).is_file() for s in saved)


def test_bench_includes_the_papers(bench_dir):
    papers = load_results(bench_dir)["families"]["papers"]
    assert papers["status"] == "ok" and papers["records"]
    assert all(rec["quick"] for rec in papers["records"])


@pytest.mark.parametrize(
    "argv", [["--help"], ["bench", "--help"], ["repro", "--help"], ["bench", "--family", "nope"]]
)
def test_help_and_argument_errors_import_no_family_numba_scipy_or_cvxpy(argv):
    """The parser is built from static names: answering ``--help`` or refusing an argument
    imports none of the heavy libraries and no family module."""
    heavy = ["numba", "scipy", "cvxpy", *{t.partition(":")[0] for t in FAMILIES.values()}]
    code = (
        "import sys\n"
        "from optbound.cli import main\n"
        "try:\n"
        f"    main({argv!r})\n"
        "except SystemExit:\n"
        "    pass\n"
        f"loaded = [m for m in {heavy!r} if m in sys.modules]\n"
        "assert not loaded, loaded\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True, stdout=subprocess.DEVNULL)


def test_the_command_makes_numba_errors_plain_text_before_numba_is_imported():
    """``run`` (the console script) sets numba's switch before any import of numba, so that it
    holds in the command's process and in the workers it starts (issue 23: compile CPU)."""
    code = (
        "import os, sys\n"
        "from optbound import cli\n"
        "switch = 'NUMBA_DISABLE_ERROR_MESSAGE_HIGHLIGHTING'\n"
        "cli.main = lambda: print(os.environ.get(switch), 'numba' in sys.modules) or 0\n"
        "cli.run()\n"
    )
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_DISABLE_ERROR_MESSAGE_HIGHLIGHTING"}
    done = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["1", "False"]


def test_every_registered_name_is_its_family_name():
    assert [fam.name for fam in families()] == list(FAMILIES)


def test_no_command_prints_help(capsys):
    assert main([]) == 0
    assert "bench" in capsys.readouterr().out


def test_bench_leaves_the_rounding_mode_alone(bench_dir):
    """codac sets the FPU to round upward; the bench must not leak that into this process."""
    one, half_ulp = 1.0, 2.0**-53
    assert one + half_ulp == one  # ties to even under round-to-nearest; 1 + ulp when upward
    assert float("1.2") == 1.2


def test_report_into_a_read_only_folder_fails_with_one_line(tmp_path, capsys, monkeypatch):
    """A read-only DIR (EROFS; chmod does not stop root, so the write is made to fail)."""
    import errno
    from pathlib import Path

    from optbound.report import save_results
    from tests.report.sample import sample_results

    save_results(sample_results(), tmp_path)

    def read_only(self, *args, **kwargs):
        raise OSError(errno.EROFS, "Read-only file system", str(self))

    monkeypatch.setattr(Path, "write_text", read_only)
    monkeypatch.setattr(Path, "write_bytes", read_only)
    assert main(["report", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("optbound report: error: ")
    assert "Read-only file system" in err


def test_scheduler_without_dask_fails_before_any_work(tmp_path, capsys, monkeypatch):
    import importlib.util

    real_find_spec = importlib.util.find_spec
    monkeypatch.setattr(
        importlib.util,
        "find_spec",
        lambda name, *a: None if name == "distributed" else real_find_spec(name, *a),
    )
    target = tmp_path / "new" / "out"
    argv = ["bench", "--scheduler", "tcp://127.0.0.1:1", "--out", str(target)]
    err = _fails_at_once(argv, capsys, monkeypatch)
    assert 'pip install "optbound[dask]"' in err
    assert not (tmp_path / "new").exists()


def test_a_run_that_fails_removes_the_out_folder_it_created(tmp_path, capsys, monkeypatch):
    import optbound.bench.runner

    def unreachable(*args, **kwargs):
        raise OSError("Timed out trying to connect to tcp://127.0.0.1:1")

    monkeypatch.setattr(optbound.bench.runner, "run_suite", unreachable)
    target = tmp_path / "new" / "out"
    assert main(["bench", "--out", str(target)]) == 2
    assert "Timed out" in capsys.readouterr().err
    assert not (tmp_path / "new").exists()


@pytest.mark.parametrize("families", [["sleeper"], ["minkowski", "sleeper"]])
def test_ctrl_c_prints_one_line_exits_130_and_removes_the_empty_out(tmp_path, families):
    """SIGINT to the whole process group, as a terminal's Ctrl-C sends it, while a task runs.

    The test-only ``sleeper`` family blocks in its first task (after the pooled ``minkowski``
    tasks, if given, are stored), so the interrupt always lands mid-run, whatever the machine's
    speed or the state of numba's cache."""
    import os
    import signal
    import time
    from pathlib import Path

    from tests.bench import test_only_families as test_only

    target, mark = tmp_path / "out", tmp_path / "blocking"
    argv = ["bench", "--suite", "tiny", "--jobs", "2", "--out", str(target)]
    argv += [arg for name in families for arg in ("--family", name)]
    main_call = f"from optbound.cli import main; raise SystemExit(main({argv}))"
    code = test_only.REGISTER_SLEEPER + main_call
    proc = subprocess.Popen(
        [sys.executable, "-c", code],
        cwd=Path(__file__).parents[1],
        env={**os.environ, test_only.BLOCK_ENV: str(mark)},
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
        # as from a terminal: a shell's background job (e.g. CI started with `&`) inherits an
        # ignored SIGINT, and Python then never raises KeyboardInterrupt
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )
    deadline = time.monotonic() + 300
    while not mark.exists():
        assert proc.poll() is None and time.monotonic() < deadline, "the run did not block"
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGINT)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, err
    assert "Traceback" not in err and "KeyboardInterrupt" not in err
    if families == ["sleeper"]:  # no task had finished: nothing is left behind
        assert not target.exists()
        assert err.splitlines()[-1] == "optbound bench: interrupted"
    else:  # the stored tasks are kept, to be resumed (tests/bench/test_run_folder.py)
        assert list(target.glob("tasks/minkowski-*.json")), list(target.iterdir())
        hint = f"; finish it with: optbound bench --resume {target}"
        assert err.splitlines()[-1] == f"optbound bench: interrupted{hint}"


@pytest.fixture(scope="module")
def piped_run(tmp_path_factory):
    """``python -m optbound bench`` with stdout and stderr into pipes, and its outer wall time."""
    import time

    out = tmp_path_factory.mktemp("piped") / "out"
    argv = ["bench", "--suite", "tiny", "--family", "strip", "--jobs", "1", "--out", str(out)]
    start = time.perf_counter()
    run = subprocess.run(
        [sys.executable, "-m", "optbound", *argv], capture_output=True, text=True, check=True
    )
    return run, time.perf_counter() - start, out


def test_bench_into_a_pipe_writes_no_cursor_movements(piped_run):
    run, _, _ = piped_run
    assert "\x1b[" not in run.stderr and "\r" not in run.stderr
    assert "optbound bench --suite tiny --seed 0: strip done (" in run.stderr


def test_printed_wall_time_is_the_commands_own(piped_run):
    """From process start (imports, compiling) to the report, not only the tasks; what it
    misses is the process's exit after the last line (``cli.run`` skips the interpreter's
    teardown), so the printed time, rounded to 0.1 s, is at most half a tenth above the outer."""
    import re

    run, outer, out = piped_run
    printed = float(re.search(r"wall time ([0-9.]+) s since the command started", run.stdout)[1])
    assert 0.7 * outer < printed <= outer + 0.05
    header = (out / "report.md").read_text().split("\n\n")[1]
    meta = load_results(out)["meta"]
    assert meta["wall_time_s"] < meta["since_start_s"] <= printed
    assert f"wall time {meta['since_start_s']:.1f} s from the command's start" in header
    assert f"{meta['wall_time_s']:.1f} s running the tasks" in header


def test_repro_help_lists_every_paper_key(capsys):
    from optbound.bench.registry import PAPERS
    from optbound.papers_repro._common import scripts

    assert {s.paper for s in scripts()} == set(PAPERS)
    with pytest.raises(SystemExit):
        main(["repro", "--help"])
    help_text = " ".join(capsys.readouterr().out.split())
    assert f"any of {' '.join(PAPERS)}" in help_text
