"""The docs' table generator rewrites only its blocks, keeps their indentation, is idempotent."""

import pytest

import tests.doc_tables as rt


def test_update_fills_an_indented_block_and_is_idempotent(monkeypatch):
    monkeypatch.setitem(rt.GENERATORS, "battery", lambda: "| a | b |\n|---|---|\n| 1 | 2 |\n")
    text = "x\n  <!-- BEGIN generated:battery -->\n  old\n  <!-- END generated:battery -->\ny\n"
    out = rt.update(text, ["battery"])
    assert out == (
        "x\n  <!-- BEGIN generated:battery -->\n  | a | b |\n  |---|---|\n  | 1 | 2 |\n"
        "  <!-- END generated:battery -->\ny\n"
    )
    assert rt.update(out, ["battery"]) == out
    assert rt.blocks(out) == {"battery": "  | a | b |\n  |---|---|\n  | 1 | 2 |\n"}


def test_unknown_block_names_are_refused():
    with pytest.raises(ValueError, match="unknown blocks \\['nope'\\]"):
        rt.update("", ["nope"])
