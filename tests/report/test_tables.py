import pytest

from optbound.report.tables import fmt_factor, fmt_ratio, fmt_seconds, markdown_table, text_table


def test_markdown_table_shape_and_pipe_escaping():
    table = markdown_table(["a", "b"], [["x|y", 1], ["z", 2.5]])
    lines = table.splitlines()
    assert lines[0] == "| a | b |"
    assert lines[1] == "|---|---|"
    assert lines[2] == "| x\\|y | 1 |"
    assert len(lines) == 4


def test_text_table_aligns_columns():
    lines = text_table(["name", "v"], [["long name", "1"], ["x", "22"]]).splitlines()
    assert lines[2].index("1") == lines[3].index("22") == lines[0].index("v")


@pytest.mark.parametrize(
    ("value", "text"),
    [(1.0000001, "1.0000001"), (1.5, "1.5"), (1234.5, "1234"), (None, "–")],
)
def test_fmt_ratio_shows_small_gaps(value, text):
    assert fmt_ratio(value) == text


@pytest.mark.parametrize(
    ("value", "text"), [(2.5, "2.5 s"), (0.012, "12 ms"), (4.2e-5, "42 µs"), (3e-8, "30 ns")]
)
def test_fmt_seconds_picks_a_readable_unit(value, text):
    assert fmt_seconds(value) == text


def test_fmt_factor():
    assert fmt_factor(1234.0) == "1.23e+03×"
