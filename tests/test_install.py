"""What ``pip install`` puts into an environment: ``optbound`` only, and both commands work.

In a fresh virtual environment, an editable and (separately) a regular install of this
repository are checked from a folder outside it: ``import benchmarks`` and ``import
papers_repro`` fail (nothing is installed under a generic top-level name), while ``optbound
bench --suite tiny`` and ``optbound repro HS96 --quick`` write their reports. The
environment reuses the running interpreter's third-party packages through a ``.pth`` line
(numpy, numba, cvxpy, ... are not downloaded again), leaving out its own optbound install.
"""

import json
import os
import site
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _venv(where: Path) -> Path:
    """A virtual environment at ``where`` that sees this interpreter's packages but optbound."""
    subprocess.run([sys.executable, "-m", "venv", str(where)], check=True)
    deps = where / "deps"
    deps.mkdir()
    for folder in site.getsitepackages():
        for entry in Path(folder).iterdir():
            if not entry.name.startswith(("optbound", "__editable__")):
                if not (deps / entry.name).exists():
                    (deps / entry.name).symlink_to(entry)
    python = where / "bin" / "python"
    purelib = subprocess.run(
        [str(python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
        check=True,
        capture_output=True,
        text=True,
    ).stdout.strip()
    (Path(purelib) / "deps.pth").write_text(f"{deps}\n")
    return where / "bin"


def _run(args: list, cwd: Path) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "NUMBA_CACHE_DIR")}
    return subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True)


@pytest.mark.slow
@pytest.mark.parametrize("editable", [True, False], ids=["editable", "regular"])
def test_install_puts_only_optbound_and_both_commands_work(tmp_path, editable):
    bin_dir = _venv(tmp_path / "venv")
    target = ["-e", str(ROOT)] if editable else [str(ROOT)]
    install = _run([bin_dir / "pip", "install", "--no-deps", *target], tmp_path)
    assert install.returncode == 0, install.stdout + install.stderr
    away = tmp_path / "elsewhere"
    away.mkdir()
    python = str(bin_dir / "python")
    for name in ("benchmarks", "papers_repro"):
        result = _run([python, "-c", f"import {name}"], away)
        assert f"No module named '{name}'" in result.stderr
    where = _run([python, "-c", "import optbound.papers_repro as p; print(p.__file__)"], away)
    installed = Path(where.stdout.strip())
    assert installed.is_relative_to(ROOT / "papers_repro") == editable, where.stderr

    bench = _run(
        [bin_dir / "optbound", "bench", "--suite", "tiny", "--out", "b", "--no-progress"], away
    )
    assert bench.returncode == 0, bench.stdout + bench.stderr
    results = json.loads((away / "b" / "results.json").read_text())
    for name, fam in results["families"].items():
        assert fam["status"] == "ok" and not fam["errors"], (name, fam)
    repro = _run(
        [bin_dir / "optbound", "repro", "HS96", "--quick", "--out", "r", "--no-progress"], away
    )
    assert repro.returncode == 0, repro.stdout + repro.stderr
    papers = json.loads((away / "r" / "results.json").read_text())["families"]["papers"]
    assert papers["records"] and {rec["paper"] for rec in papers["records"]} == {"HS96"}
    assert not papers["errors"]
