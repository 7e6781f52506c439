"""README.md: every Python code block runs, and every table of measured numbers is generated.

The blocks are found automatically (every fenced ``python`` block, in every section, including
sections added later), and each runs in a fresh namespace in a temporary folder.
"""

import re
from pathlib import Path

import pytest

from optbound.interval.fenv import round_to_nearest
from tests.readme_tables import BLOCK, GENERATORS, blocks

README = Path(__file__).resolve().parents[1] / "README.md"
TEXT = README.read_text()
HEADLINE = re.compile(r"<!-- BEGIN bench-headline -->.*?<!-- END bench-headline -->", re.S)
# A measured value: a decimal fraction (1.0013, 6.2e-10) or a time in ms; "1e6" or "n = 2–6"
# in a descriptive table are not.
MEASURED = re.compile(r"(?<![\w.])\d+\.\d+|\d\s*ms\b")


def python_blocks(text: str) -> list[tuple[str, str]]:
    """``(id, code)`` of every fenced python block; the id names the heading above it."""
    found = []
    for m in re.finditer(r"^```python\n(.*?)^```", text, flags=re.S | re.M):
        headings = re.findall(r"^#+ (.+)$", text[: m.start()], flags=re.M)
        slug = re.sub(r"\W+", "_", headings[-1] if headings else "top").strip("_")
        found.append((f"{len(found)}-{slug}", m.group(1)))
    return found


BLOCKS = python_blocks(TEXT)


def test_the_readme_has_python_blocks():
    assert len(BLOCKS) >= 3


@pytest.mark.parametrize(("name", "code"), BLOCKS, ids=[name for name, _ in BLOCKS])
def test_readme_python_block_runs(name, code, tmp_path, monkeypatch):
    import matplotlib

    matplotlib.use("Agg")
    monkeypatch.chdir(tmp_path)
    # A block may import codac, which sets round-upward process-wide: give the mode back.
    with round_to_nearest():
        exec(compile(code, f"{README}:{name}", "exec"), {"__name__": "__readme__"})


def _tables(text: str) -> list[str]:
    """Markdown tables of ``text``: runs of lines that start with ``|``."""
    return re.findall(r"(?:^\|.*\|[ \t]*\n)+", text + "\n", flags=re.M)


def test_every_table_of_measured_numbers_is_generated():
    outside = HEADLINE.sub("", BLOCK.sub("", TEXT))
    typed = [t.splitlines()[0] for t in _tables(outside) if MEASURED.search(t)]
    assert not typed, (
        "tables with measured numbers outside a generated block (tests/readme_tables.py) "
        f"or the bench headline: {typed}"
    )


def test_every_generated_block_has_a_generator():
    assert set(blocks(TEXT)) <= set(GENERATORS)
    assert {"battery", "clip-effect", "sivia-codac"} <= set(blocks(TEXT))


def test_the_checks_catch_a_typed_table():
    typed = "| case | ratio |\n|---|---|\n| x | 1.0013 |\n"
    assert MEASURED.search(_tables(typed)[0])
    assert not MEASURED.search("| n = 2–6 | condition number 1–1e6 |")  # ranges are not data


def test_papers_table_gives_every_key_a_venue_and_year():
    from optbound.bench.registry import PAPERS

    text = README.read_text()
    table = text[text.index("## Papers") :].split("\n\n")[1].splitlines()
    assert table[0] == "| key | paper | venue | year |"
    rows = {cells[1].strip(): cells[2:] for cells in (r.split("|") for r in table[2:])}
    assert set(rows) == set(PAPERS)
    for key, (_, venue, year, _) in rows.items():
        assert venue.strip() and re.fullmatch(r" (19|20)\d\d ", year), key
        assert year.strip()[2:] in key or key == "BH", key  # the key's digits are the year


def test_no_jargon_in_the_readme_or_docs():
    docs = [README, *sorted((README.parent / "docs").rglob("*.md"))]
    for path in docs:
        assert "as the mission requires" not in path.read_text(), path
