"""Discovery of the reproduction scripts and the shared command line."""

import inspect
import subprocess
import sys
from importlib import import_module
from pathlib import Path

import pytest

from optbound.papers_repro import _common
from optbound.papers_repro._common import scripts

ROOT = Path(__file__).resolve().parents[2]


def test_discovery_finds_the_scripts_by_their_paper_key():
    found = {s.name: s.paper for s in scripts()}
    assert found["hs96_fusion"] == "HS96"
    assert found["hs96_projection"] == "HS96"
    assert found["ljmw97_appendix_a"] == "LJMW97"
    assert not any(name.startswith("_") or name == "run_all" for name in found)


@pytest.mark.parametrize("script", scripts(), ids=lambda s: s.name)
def test_every_script_follows_the_convention(script):
    module = import_module(script.module)
    assert module.PAPER == script.paper
    quick = inspect.signature(module.main).parameters["quick"]
    assert quick.default is False


def test_paper_selection_is_case_insensitive_and_refuses_unknown_keys():
    assert {s.paper for s in scripts(["hs96"])} == {"HS96"}
    with pytest.raises(ValueError, match="unknown keys \\['NOPE'\\]"):
        scripts(["nope"])


def test_scripts_come_in_paper_order():
    order = [s.paper for s in scripts()]
    ranks = [_common.PAPER_ORDER.index(p) for p in order if p in _common.PAPER_ORDER]
    assert ranks == sorted(ranks)


def test_paper_is_read_from_the_source_without_importing(tmp_path):
    path = tmp_path / "x_demo.py"
    path.write_text('import not_a_module\nPAPER = "ZZ99"\n\ndef main(out_dir, quick=False): ...\n')
    assert _common._paper_of(path) == "ZZ99"
    path.write_text("VALUE = 1\n")
    assert _common._paper_of(path) is None


def test_command_line_has_quick(tmp_path):
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "optbound.papers_repro.ljmw97_appendix_a",
            "--quick",
            "--out",
            str(tmp_path),
        ],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    assert "## LJMW97 Appendix A" in out
    assert "0.002 |" not in out  # the quick variant stops at eps = 0.01
