"""Progress bars: one per family, a total that advances by task cost."""

import io

from optbound.bench.progress import Progress


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_total_advances_by_cost_and_families_by_task():
    terminal = _Terminal()
    with Progress("run", {"a": [3.0, 1.0], "b": [4.0]}, enabled=True, stream=terminal) as bar:
        bar.done("a", 3.0)
        assert bar.total.n == 3.0 and bar.total.total == 8.0
        assert bar.bars["a"].n == 1 and bar.bars["b"].n == 0
        bar.done("b", 4.0)
        assert bar.total.n == 7.0
    assert "cost-weighted" in terminal.getvalue()


def test_disabled_progress_does_nothing():
    with Progress("run", {"a": [1.0]}, enabled=False) as bar:
        bar.done("a", 1.0)
    assert not bar.enabled


def test_total_never_overshoots_by_rounding():
    costs = [0.3, 0.2, 0.1]  # total 0.6; done in reverse order they sum to 0.6000000000000001
    with Progress("run", {"a": costs}, enabled=True, stream=_Terminal()) as bar:
        for cost in reversed(costs):
            bar.done("a", cost)
        assert bar.total.n <= bar.total.total


def test_no_bars_into_a_file_or_pipe_only_a_line_per_finished_family(capsys):
    with Progress("run", {"a": [3.0, 1.0], "b": [4.0]}, enabled=True) as bar:
        bar.done("a", 3.0)
        bar.done("b", 4.0)
        bar.done("a", 1.0)
    lines = capsys.readouterr().err.splitlines()
    assert [line.split(" (")[0] for line in lines] == ["run: b done", "run: a done"]
    assert "\x1b" not in "".join(lines) and "\r" not in "".join(lines)
