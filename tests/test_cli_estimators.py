"""``optbound evaluate`` and ``optbound bench --estimator`` with a module outside the repository
(issue 20, "Done when"): the three estimators of ``tests/problems/estimators.py``, written to a
temporary folder and found on PYTHONPATH by a child process, as a user's own module would be."""

from __future__ import annotations

import dataclasses
import json
import os
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
import tomllib

from optbound import problems
from optbound.cli import main
from optbound.compare import exact
from optbound.interval import Tri
from optbound.problems import registry
from optbound.problems.estimators import analytic_volume
from optbound.report import load_results
from tests.problems.estimators import shrunk_box

ROOT = Path(__file__).resolve().parents[1]
USER_MODULE = ROOT / "tests" / "problems" / "estimators.py"
NAMES = ("hull_box", "shrunk_box", "prior_ellipsoid")
STRIP = problems.suite("tiny", families=["strip"])


def _optbound(argv: list[str], user_dir: Path) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(user_dir), str(ROOT)])}
    return subprocess.run(
        [sys.executable, "-m", "optbound", *argv],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=900,
    )


@pytest.fixture(scope="module")
def user_dir(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("user")
    (folder / "my_estimators.py").write_text(USER_MODULE.read_text(encoding="utf-8"))
    return folder


@pytest.fixture(scope="module")
def bench_out(user_dir, tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("bench") / "report"
    specs = [arg for name in NAMES for arg in ("--estimator", f"my_estimators:{name}")]
    argv = ["bench", "--suite", "tiny", "--family", "strip", "--jobs", "1", "--no-progress"]
    done = _optbound([*argv, *specs, "--out", str(out)], user_dir)
    assert done.returncode == 0, done.stderr
    return out


def _check_rows(name: str, rows: list[dict]) -> None:
    """The Done-when outcomes, on the rows of the strip problems of the tiny suite."""
    assert [(r["family"], r["name"]) for r in rows] == [(p.family, p.name) for p in STRIP]
    for p, r in zip(STRIP, rows, strict=True):
        assert r["error"] is None, r
        if name == "shrunk_box":
            assert r["soundness"] == "refuted", r
            x = np.array(r["counterexample"])
            assert p.member(x)[0] == Tri.TRUE
            E, S = p.data["ellipsoid"], p.data["strip"]
            assert exact.member(E, x) and exact.member(S, x)  # rational arithmetic
            box = shrunk_box(p)  # the user's box, rebuilt here: outside it, exactly
            assert any(
                Fraction(c) < Fraction(lo) or Fraction(c) > Fraction(hi)
                for c, lo, hi in zip(x, box.lo, box.hi, strict=True)
            )
        else:
            assert r["soundness"] == "proven", r
            assert r["counterexample"] is None


@pytest.mark.parametrize("name", NAMES)
def test_evaluate_prints_the_table_of_a_module_outside_the_repo(user_dir, name):
    done = _optbound(
        ["evaluate", f"my_estimators:{name}", "--family", "strip", "--format", "json"], user_dir
    )
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)  # the table alone on stdout
    assert result["estimator"] == f"my_estimators:{name}"
    _check_rows(name, result["rows"])


def test_bench_adds_a_section_and_rows_for_each_estimator(bench_out):
    results = load_results(bench_out)
    entries = {e["estimator"]: e for e in results["estimators"]}
    assert list(entries) == [f"my_estimators:{name}" for name in NAMES]
    for name in NAMES:
        _check_rows(name, entries[f"my_estimators:{name}"]["rows"])
    assert list(results["families"]) == ["strip"]  # beside the built-in bounds
    report = (bench_out / "report.md").read_text()
    section = report.split("## Your estimators", 1)[1]
    for name in NAMES:
        assert f"**my_estimators:{name}**" in section
    assert section.count("refuted at (") == len(STRIP)


def test_report_rebuilds_the_section_from_results_json(bench_out, tmp_path, capsys):
    copy = tmp_path / "copy"
    copy.mkdir()
    (copy / "results.json").write_text((bench_out / "results.json").read_text())
    assert main(["report", str(copy)]) == 0
    rebuilt = (copy / "report.md").read_text().split("## Your estimators", 1)[1]
    original = (bench_out / "report.md").read_text().split("## Your estimators", 1)[1]
    assert rebuilt == original


@pytest.mark.parametrize(
    "spec, message",
    [
        ("no_colon", "'no_colon' is neither 'pkg.module:callable' nor a registered estimator"),
        (":f", "spec must be 'pkg.module:callable'"),
        ("no_such_module_xyz:f", "cannot import module 'no_such_module_xyz'"),
        ("optbound:no_such_estimator", "module 'optbound' has no attribute"),
        ("optbound:__version__", "not a callable estimator"),
    ],
)
def test_a_bad_estimator_spec_is_one_line_and_exit_2(spec, message, tmp_path, capsys):
    assert main(["evaluate", spec]) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1, err
    out = tmp_path / "never"
    assert main(["bench", "--suite", "tiny", "--estimator", spec, "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("optbound bench: error: --estimator:") and message in err, err
    assert not out.exists()  # checked before any work


def test_evaluate_takes_one_estimator(capsys):
    assert main(["evaluate", registry.ALL_REGISTERED]) == 2
    assert "evaluate takes one estimator" in capsys.readouterr().err


def test_evaluate_rejects_an_unknown_family(capsys):
    assert main(["evaluate", "optbound.problems.estimators:analytic_volume", "--family", "x"]) == 2
    assert "families: unknown ['x']" in capsys.readouterr().err


def test_the_analytic_updates_are_registered_entry_points():
    """pyproject.toml registers the built-in estimators; each target loads and is the function
    of optbound.problems.estimators (the installed metadata may predate the checkout)."""
    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text())
    declared = pyproject["project"]["entry-points"][registry.GROUP]
    assert registry.load(declared["analytic_volume"]) is analytic_volume
    for spec in declared.values():
        assert registry.load(spec).__module__ == "optbound.problems.estimators"


def test_a_package_on_the_path_registers_its_estimators(user_dir):
    """Entry points of a distribution found on the path (its dist-info), as pip installs them:
    registered() lists them, and the registered name runs like a spec."""
    info = user_dir / "my_estimators-1.0.dist-info"
    info.mkdir(exist_ok=True)
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: my-estimators\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text(
        f"[{registry.GROUP}]\nmy_hull = my_estimators:hull_box\n"
    )
    code = (
        "import json\nfrom optbound.problems import registry\n"
        "found = registry.registered()\n"
        "print(json.dumps([found, registry.resolve(['my_hull'])['my_hull'].__name__]))"
    )
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(user_dir), str(ROOT)])}
    done = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr
    found, loaded = json.loads(done.stdout)
    assert found["my_hull"] == "my_estimators:hull_box" and loaded == "hull_box"


def test_all_registered_expands_to_the_entry_points(monkeypatch):
    fake = {"b_box": "tests.problems.estimators:hull_box", "a_ell": "optbound:Ellipsoid"}
    monkeypatch.setattr(registry, "registered", lambda: dict(sorted(fake.items())))
    resolved = registry.resolve(["tests.problems.estimators:shrunk_box", registry.ALL_REGISTERED])
    assert list(resolved) == ["tests.problems.estimators:shrunk_box", "a_ell", "b_box"]
    assert resolved["b_box"].__name__ == "hull_box"
    assert registry.resolve(["a_ell"]) == {"a_ell": resolved["a_ell"]}
    with pytest.raises(ValueError, match=r"registered: \['a_ell', 'b_box'\]"):
        registry.resolve(["c_none"])


def test_the_analytic_estimator_is_proven_or_undecided_never_refuted():
    result = problems.evaluate(analytic_volume, STRIP)
    assert all(r["error"] is None and r["soundness"] != "refuted" for r in result.rows)
    other = dataclasses.replace(STRIP[0], data={"boxes": None})
    row = problems.evaluate(analytic_volume, other).rows[0]
    assert row["error"].startswith("TypeError: the analytic strip update needs")


def test_the_section_renders_rows_read_back_from_json():
    """results.json writes non-finite floats as null: an unbounded size or ratio (a set
    reaching the paving's border) reads back as None and is shown as an open end."""
    from optbound.problems.evaluation import COLUMNS
    from optbound.report.estimators import estimators_section

    row = dict.fromkeys(COLUMNS)
    row.update(family="strip", name="p", size_lo=2.0, ratio_lo=1.5, soundness="undecided")
    row.update(seconds=0.5, estimator="mine")
    parts = estimators_section({"estimators": [{"estimator": "mine", "rows": [row]}]})
    assert parts[0] == "## Your estimators"
    assert "| strip | p | [2, inf] | [1.5, inf] | – | – | undecided | 0.5 |" in parts[2]
    assert estimators_section({"estimators": []}) == estimators_section({}) == []


def test_bench_families_select_the_problem_families_with_their_instances():
    from optbound.bench.user_estimators import problem_families

    assert problem_families(None) == problems.families()
    assert problem_families(["strip"]) == ["strip"]
    assert problem_families(["localization", "strip"]) == ["strip", "bh_bearings"]
    assert problem_families(["speed_sdp"]) == []
