import pytest

from optbound.report.summary import group, ratio_stats, worst_label
from tests.report.sample import sample_results


def _strip_records():
    return sample_results()["families"]["strip"]["records"]


def test_ratio_stats_min_median_max_and_worst_instance():
    volume = [r for r in _strip_records() if r["criterion"] == "volume"]
    s = ratio_stats(volume)
    assert (s["n"], s["min"], s["median"], s["max"]) == (3, 1.0, 1.5, 3.0)
    assert s["worst"]["seed"] == 12
    assert s["below_one"] == 0


def test_ratios_below_one_are_counted_beyond_solver_noise():
    recs = [{"ratio": 1.0 - 1e-9}, {"ratio": 0.98}, {"ratio": 1.2}]
    assert ratio_stats(recs)["below_one"] == 1


def test_missing_values_are_counted_but_not_used():
    assert ratio_stats([{"lower_ratio": None}], "lower_ratio") == {"n": 0, "missing": 1}
    s = ratio_stats([{"ratio": 2.0}, {"ratio": None}])
    assert (s["n"], s["missing"], s["max"]) == (1, 1, 2.0)


def test_group_keeps_first_seen_order():
    groups = group(_strip_records(), ("criterion",))
    assert list(groups) == [("volume",), ("trace",)]
    assert [len(v) for v in groups.values()] == [3, 3]


def test_worst_label_names_the_seed_and_parameters():
    label = worst_label(_strip_records()[2])
    assert label == "seed 12, narrow, n=2, cond 1e+02"


@pytest.mark.parametrize("k", [1, 5])
def test_worst_label_of_recursive_record_has_k(k):
    rec = {"seed": 3, "variant": "width 0.2", "dim": 2, "k": k}
    assert worst_label(rec).endswith(f"k={k}")


def test_degenerate_lower_bounds_are_flagged_and_left_out():
    from optbound.report.summary import (
        DEGENERATE_GAP,
        is_degenerate_lower,
        ratio_stats,
        without_degenerate_lower,
    )

    fine = {"seed": 1, "dim": 2, "k": 5, "ratio": 2.0, "lower_ratio": 3.0}
    collapsed = {"seed": 2, "dim": 2, "k": 5, "ratio": 2.0, "lower_ratio": 4.6e15}
    edge = {"seed": 3, "dim": 2, "k": 5, "ratio": 1.0, "lower_ratio": DEGENERATE_GAP}
    assert [is_degenerate_lower(r) for r in (fine, collapsed, edge)] == [False, True, False]
    cleaned, flagged = without_degenerate_lower([fine, collapsed, edge])
    assert flagged == [collapsed]
    stats = ratio_stats(cleaned, "lower_ratio")
    assert (stats["n"], stats["missing"], stats["max"]) == (2, 1, DEGENERATE_GAP)
    assert collapsed["lower_ratio"] == 4.6e15  # the input is not modified
