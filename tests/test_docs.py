"""README.md and the documentation pages: every code block runs or is checked, and every table
of measured numbers is generated.

Every fenced block of README.md and ``docs/**/*.md`` is found automatically and must be one of:

- ``python``: runs in a fresh namespace in a temporary folder; when a ``text`` block follows
  it, that block is exactly what it prints. The tutorials (``docs/tutorials``, one namespace
  per page: ``tests/test_tutorials.py``) and the extending guide's worked example
  (``tests/test_extending_guide.py``) are run by their own tests;
- ``text``: output shown after a python block, not run;
- ``bash``: shell commands, not run here (they install, benchmark or build): each line is one
  of the commands this project documents, and every ``optbound ...`` line parses with the real
  command-line parser, every ``python -m M`` names a module that exists;
- ``toml``: parses;
- ``{toctree}``: a MyST directive (the site's table of contents), not code.

The gallery's examples (``examples/``) run in the documentation build (``.ci/run`` builds it
with ``-W``).
"""

import importlib.util
import re
import shlex
from pathlib import Path

import pytest

from optbound.interval.fenv import round_to_nearest
from tests.doc_tables import BLOCK, GENERATORS, ROOT, blocks, pages

README = ROOT / "README.md"
PAGES = pages()
OWN_TESTS = {ROOT / "docs" / "extending.md", *sorted((ROOT / "docs" / "tutorials").glob("*.md"))}
HEADLINE = re.compile(r"<!-- BEGIN bench-headline -->.*?<!-- END bench-headline -->", re.S)
# A table of the papers' stated values and settings (no measurement) is marked as such.
DESCRIPTIVE = re.compile(r"<!-- descriptive table: [^>]+ -->\n(?:\|.*\|[ \t]*\n)+")
# A measured value: a decimal fraction (1.0013, 6.2e-10) or a time in ms; "1e6" or "n = 2–6"
# in a descriptive table are not.
MEASURED = re.compile(r"(?<![\w.])\d+\.\d+|\d\s*ms\b")
FENCE = re.compile(r"^```(\S*)\n(.*?)^```", re.S | re.M)
SHELL_COMMANDS = {"optbound", "pip", "pytest", "python", "sphinx-build", "dask"}


def _name(page: Path) -> str:
    return str(page.relative_to(ROOT))


def fenced_blocks(text: str) -> list[tuple[str, str, str]]:
    """``(id, language, code)`` of every fenced block; the id names the heading above it."""
    found = []
    for m in FENCE.finditer(text):
        headings = re.findall(r"^#+ (.+)$", text[: m.start()], flags=re.M)
        slug = re.sub(r"\W+", "_", headings[-1] if headings else "top").strip("_")
        found.append((f"{len(found)}-{slug}", m.group(1), m.group(2)))
    return found


BLOCKS = [(page, *block) for page in PAGES for block in fenced_blocks(page.read_text())]
PYTHON = [
    (page, i, name, code)
    for page in PAGES
    if page not in OWN_TESTS
    for i, (name, lang, code) in enumerate(fenced_blocks(page.read_text()))
    if lang == "python"
]


def test_the_pages_have_python_blocks():
    assert len(PYTHON) >= 10
    assert any(page == README for page, *_ in PYTHON)


def test_every_block_has_a_known_language():
    unknown = [(_name(p), n, lang) for p, n, lang, _ in BLOCKS if lang not in LANGUAGES]
    assert not unknown, f"fenced blocks must be one of {sorted(LANGUAGES)}: {unknown}"


@pytest.mark.parametrize(
    ("page", "index", "name", "code"),
    PYTHON,
    ids=[f"{_name(page)}:{name}" for page, _, name, _ in PYTHON],
)
def test_python_block_runs_and_prints_what_follows_it(
    page, index, name, code, tmp_path, monkeypatch, capsys
):
    import matplotlib

    matplotlib.use("Agg")
    monkeypatch.chdir(tmp_path)
    # A block may import codac, which sets round-upward process-wide: give the mode back.
    with round_to_nearest():
        exec(compile(code, f"{page}:{name}", "exec"), {"__name__": "__docs__"})
    following = fenced_blocks(page.read_text())[index + 1 : index + 2]
    if following and following[0][1] == "text":
        assert capsys.readouterr().out == following[0][2]


def _check_shell_line(line: str) -> None:
    from optbound.cli import build_parser

    words = shlex.split(line, comments=True)
    if not words:
        return
    if words[0] == "export" or "=" in words[0]:  # an environment assignment before a command
        words = words[1:]
    assert words[0] in SHELL_COMMANDS, f"unknown command in a bash block: {line!r}"
    for command in " ".join(words).split("&&"):
        argv = shlex.split(command)
        if argv[0] == "optbound":
            try:
                build_parser().parse_args(argv[1:])
            except SystemExit as exc:
                raise AssertionError(f"{command!r} does not parse") from exc
        if argv[:2] == ["python", "-m"]:
            assert importlib.util.find_spec(argv[2]) is not None, f"no module {argv[2]}"


def _bash_lines(code: str) -> list[str]:
    """The commands of a bash block: continuation lines joined, background ``&`` dropped."""
    joined = code.replace("\\\n", " ")
    return [re.sub(r"\s&\s", " && ", line) for line in joined.splitlines()]


def test_every_shell_command_is_a_documented_command_that_parses():
    checked = 0
    for _, _, lang, code in BLOCKS:
        if lang == "bash":
            for line in _bash_lines(code):
                _check_shell_line(line)
                checked += 1
    assert checked >= 10


def test_the_shell_check_catches_a_wrong_command():
    with pytest.raises(AssertionError, match="does not parse"):
        _check_shell_line("optbound bench --suite huge")
    with pytest.raises(AssertionError, match="unknown command"):
        _check_shell_line("rm -rf /")
    with pytest.raises(AssertionError, match="no module"):
        _check_shell_line("python -m optbound.no_such_module")


def test_toml_blocks_parse():
    tomllib = pytest.importorskip("tomllib")  # Python >= 3.11
    for _, _, lang, code in BLOCKS:
        if lang == "toml":
            tomllib.loads(code)


LANGUAGES = {"python", "text", "bash", "toml", "{toctree}"}


def _tables(text: str) -> list[str]:
    """Markdown tables of ``text``: runs of lines that start with ``|``."""
    return re.findall(r"(?:^\|.*\|[ \t]*\n)+", text + "\n", flags=re.M)


@pytest.mark.parametrize("page", PAGES, ids=_name)
def test_every_table_of_measured_numbers_is_generated(page):
    if page in OWN_TESTS:  # the tutorial's tables are its code's output, compared by its test
        return
    outside = DESCRIPTIVE.sub("", HEADLINE.sub("", BLOCK.sub("", page.read_text())))
    typed = [t.splitlines()[0] for t in _tables(outside) if MEASURED.search(t)]
    assert not typed, (
        "tables with measured numbers outside a generated block (tests/doc_tables.py) "
        f"or the bench headline: {typed}"
    )


def test_every_generated_block_has_a_generator():
    found = {name for page in PAGES for name in blocks(page.read_text())}
    assert found <= set(GENERATORS)
    assert set(GENERATORS) <= found  # every generator's table is shown somewhere


def test_the_headline_markers_are_on_the_benchmark_page():
    from optbound.report.readme import BEGIN, END, source_readme

    page = ROOT / "docs" / "benchmarks.md"
    assert source_readme() == page
    assert [p for p in PAGES if BEGIN in p.read_text()] == [page]
    assert END in page.read_text()


def test_the_checks_catch_a_typed_table():
    typed = "| case | ratio |\n|---|---|\n| x | 1.0013 |\n"
    assert MEASURED.search(_tables(typed)[0])
    marked = "<!-- descriptive table: settings -->\n" + typed
    assert not _tables(DESCRIPTIVE.sub("", marked))
    assert _tables(DESCRIPTIVE.sub("", "<!-- generated -->\n" + typed))  # only that marker
    assert not MEASURED.search("| n = 2–6 | condition number 1–1e6 |")  # ranges are not data


def test_papers_table_gives_every_key_a_venue_and_year():
    from optbound.bench.registry import PAPERS

    text = (ROOT / "docs" / "papers.md").read_text()
    table = text[text.index("## Papers") :].split("\n\n")[1].splitlines()
    assert table[0] == "| key | paper | venue | year |"
    rows = {cells[1].strip(): cells[2:] for cells in (r.split("|") for r in table[2:])}
    assert set(rows) == set(PAPERS)
    for key, (_, venue, year, _) in rows.items():
        assert venue.strip() and re.fullmatch(r" (19|20)\d\d ", year), key
        assert year.strip()[2:] in key or key == "BH", key  # the key's digits are the year


def test_no_jargon_in_the_readme_or_docs():
    for path in PAGES:
        assert "as the mission requires" not in path.read_text(), path


def test_readme_starts_with_the_two_setup_commands_and_is_short():
    text = README.read_text()
    assert len(text.splitlines()) <= 150
    first = fenced_blocks(text)[0]
    assert first[1:] == (
        "bash",
        'pip install -e . && optbound bench\npip install -e ".[test]" && pytest\n',
    )
    assert "sphinx-build -W -b html docs docs/_build/html" in text


def test_the_readme_links_and_picture_exist():
    text = README.read_text()
    links = re.findall(r"\]\(([^)#]+)(?:#[^)]*)?\)", text)
    assert links and all((ROOT / link).is_file() for link in links), links
    (picture,) = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", text)
    spec = importlib.util.spec_from_file_location(
        "report_figure", ROOT / "docs" / "report_figure.py"
    )
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    assert script.FIGURE == ROOT / picture  # drawn by docs/report_figure.py, not by hand


def test_public_docstrings_have_their_numpydoc_sections():
    pytest.importorskip("numpydoc")  # the docs extra (installed by .ci/run)
    spec = importlib.util.spec_from_file_location(
        "check_docstrings", ROOT / "docs" / "check_docstrings.py"
    )
    checker = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(checker)
    assert checker.failures(checker.ENFORCED) == []
