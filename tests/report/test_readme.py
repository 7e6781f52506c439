import pytest

from optbound.report.readme import BEGIN, END, headline_markdown, update_readme
from tests.report.sample import sample_results

README = f"""# title

<!-- BEGIN bench -->
intro
{BEGIN}
old numbers
{END}
guide
<!-- END bench -->
tail
"""


def test_update_replaces_only_between_the_markers(tmp_path):
    path = tmp_path / "README.md"
    path.write_text(README)
    assert update_readme(path, sample_results())
    text = path.read_text()
    assert "old numbers" not in text
    assert headline_markdown(sample_results()) in text
    before, after = README.split("old numbers")
    assert text.startswith(before.rstrip("\n"))
    assert text.endswith(after.lstrip("\n"))


def test_update_is_idempotent(tmp_path):
    path = tmp_path / "README.md"
    path.write_text(README)
    update_readme(path, sample_results())
    once = path.read_text()
    update_readme(path, sample_results())
    assert path.read_text() == once


def test_readme_without_markers_is_left_alone(tmp_path):
    path = tmp_path / "README.md"
    path.write_text("# nothing here\n")
    assert not update_readme(path, sample_results())
    assert path.read_text() == "# nothing here\n"


def test_headline_states_where_the_numbers_come_from():
    text = headline_markdown(sample_results())
    assert "optbound bench --suite quick --seed 0" in text
    assert "median 1.5, max 3 (n=3)" in text


def test_only_a_complete_default_run_may_write_the_headline(tmp_path):
    path = tmp_path / "README.md"
    path.write_text(README)
    for change, message in (
        ({"complete": False}, "complete run"),
        ({"suite": "full"}, "--suite full"),
        ({"seed": 2}, "--seed 2"),
    ):
        results = sample_results()
        results["meta"].update(change)
        with pytest.raises(ValueError, match=message):
            update_readme(path, results)
    assert path.read_text() == README


def test_headline_states_machine_load_and_date():
    text = headline_markdown(sample_results())
    assert "2026-01-01T00:00:00+00:00" in text
    assert "Linux x86_64, Test CPU, 2 CPUs" in text
    assert "load average 1.25 / 0.80 / 0.50" in text
