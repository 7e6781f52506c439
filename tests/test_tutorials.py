"""The tutorials of ``docs/tutorials`` run as written and print the output they show.

Each tutorial's ``python`` blocks run in order in one namespace; the ``text`` block that
follows a ``python`` block is what that block prints, compared line by line except the
table's last column (``seconds``: the estimator's own time, which varies).
"""

from __future__ import annotations

import contextlib
import io
import re
from pathlib import Path

import pytest

TUTORIALS = sorted((Path(__file__).resolve().parents[1] / "docs" / "tutorials").glob("*.md"))
BLOCK = re.compile(r"```(\w+)\n(.*?)```", re.S)


def _without_timings(text: str) -> list[str]:
    """Lines of ``text`` without trailing blank lines, a table row's last cell (its seconds)
    replaced by a placeholder."""
    lines = text.rstrip("\n").splitlines()
    return [re.sub(r"\| [^|]* \|$", "| <seconds> |", line) for line in lines]


def test_there_is_a_tutorial():
    assert [p.name for p in TUTORIALS] == ["evaluate_your_estimator.md"]


@pytest.mark.parametrize("path", TUTORIALS, ids=lambda p: p.stem)
def test_tutorial_runs_and_prints_what_it_shows(path):
    blocks = BLOCK.findall(path.read_text(encoding="utf-8"))
    namespace: dict = {"__name__": f"tutorial_{path.stem}"}
    checked = 0
    for i, (lang, code) in enumerate(blocks):
        if lang != "python":
            continue
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            exec(compile(code, f"{path}#block{i}", "exec"), namespace)
        following = blocks[i + 1] if i + 1 < len(blocks) else None
        if following is not None and following[0] == "text":
            assert _without_timings(out.getvalue()) == _without_timings(following[1])
            checked += 1
        else:
            assert out.getvalue() == "", f"block {i} prints output the tutorial does not show"
    assert checked >= 2
