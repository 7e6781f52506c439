"""Progress bars: one per family, a total that advances by task cost."""

from optbound.bench.progress import Progress


def test_total_advances_by_cost_and_families_by_task(capsys):
    with Progress("run", {"a": [3.0, 1.0], "b": [4.0]}, enabled=True) as bar:
        bar.done("a", 3.0)
        assert bar.total.n == 3.0 and bar.total.total == 8.0
        assert bar.bars["a"].n == 1 and bar.bars["b"].n == 0
        bar.done("b", 4.0)
        assert bar.total.n == 7.0
    assert "cost-weighted" in capsys.readouterr().err


def test_disabled_progress_does_nothing():
    with Progress("run", {"a": [1.0]}, enabled=False) as bar:
        bar.done("a", 1.0)
    assert not bar.enabled


def test_total_never_overshoots_by_rounding():
    costs = [0.3, 0.2, 0.1]  # total 0.6; done in reverse order they sum to 0.6000000000000001
    with Progress("run", {"a": costs}, enabled=True) as bar:
        for cost in reversed(costs):
            bar.done("a", cost)
        assert bar.total.n <= bar.total.total
