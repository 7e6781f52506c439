"""The localization family: tiny suite runs, records carry the documented fields, guaranteed
bounds contain the exact set and the truth, and the figure is attached."""

import base64

import numpy as np
import pytest

from optbound.bench import localization_tightness as lt
from optbound.bench.registry import families

FIELDS = {
    "family",
    "variant",
    "dim",
    "seed",
    "criterion",
    "reference",
    "metric",
    "ratio",
    "ratio_lo",
    "ratio_hi",
    "exact_lo",
    "exact_hi",
    "guaranteed",
}
MEASURED = {"area_lo", "area_hi", "outside", "truth_outside"}


@pytest.fixture(scope="module")
def tiny():
    (task,) = lt.tasks("tiny", 0)
    return task, lt.run(task)


def test_registered_as_a_tightness_family():
    (fam,) = [f for f in families() if f.name == lt.NAME]
    assert fam.kind == "tightness" and fam.parallel and not fam.missing()


def test_suites():
    assert [t["variant"] for t in lt.tasks("tiny", 0)] == ["BH geometry"]
    quick, full = lt.tasks("quick", 0), lt.tasks("full", 0)
    assert [t["variant"] for t in quick] == ["BH geometry", "random", "random"]
    assert len(full) == 13 and all(t["orders"] == [1, 2] for t in full)
    assert sum(t["figure"] for t in full) == 1
    assert lt.cost(full[0]) > lt.cost(quick[0]) > lt.cost(quick[1])


def test_records_have_the_documented_fields(tiny):
    _, out = tiny
    criteria = [r["criterion"] for r in out["records"]]
    assert criteria == ["hs96_linearized", "bh_L4", "bh_L8", "best_ellipse", "optimal_pseudo_L4"]
    for rec in out["records"]:
        assert FIELDS | MEASURED <= set(rec), rec["criterion"]
        assert rec["ratio_lo"] <= rec["ratio"] <= rec["ratio_hi"]
        assert 0 < rec["exact_lo"] <= rec["exact_hi"]


def test_guaranteed_bounds_contain_the_exact_set_and_the_truth(tiny):
    _, out = tiny
    guaranteed = [r for r in out["records"] if r["guaranteed"]]
    assert len(guaranteed) == 4
    for rec in guaranteed:
        # Containing the exact set: area >= exact area >= the paving's inner area.
        assert rec["ratio_hi"] >= 1.0, rec["criterion"]
        assert rec["outside"] == 0 and rec["truth_outside"] == 0, rec["criterion"]
    assert all(r["proven"] for r in guaranteed if r["criterion"].startswith("bh_"))


def test_linearized_bound_is_flagged_and_measured(tiny):
    """On the BH geometry the HS96 linearized ellipse misses part of the exact set."""
    _, out = tiny
    (lin,) = [r for r in out["records"] if r["criterion"] == "hs96_linearized"]
    assert lin["guaranteed"] is False
    assert lin["outside"] > 0


def test_figure_is_an_attached_png(tiny):
    _, out = tiny
    png = base64.b64decode(out["attachments"][lt.FIGURE])
    assert png[:8] == b"\x89PNG\r\n\x1a\n"


def test_sample_exact_draws_points_of_the_inner_boxes():
    data = lt.rb.measurements(*lt.instance(lt.tasks("tiny", 0)[0])[:4])
    paving, _ = lt.exact_set(data, 10)
    pts = lt.sample_exact(paving, 500, np.random.default_rng(0))
    inside = np.zeros(len(pts), dtype=bool)
    for b in paving.inner:
        inside |= np.all((pts >= b[:, 0]) & (pts <= b[:, 1]), axis=1)
    assert inside.all()
    assert lt.rb.in_exact_set(data, pts).all()


def test_each_bound_is_labelled_for_what_it_is(tiny):
    """The best ellipse found on a coarse paving is an outer ellipse, not the optimum; it is
    named as the BH reproduction names its own (``relative_bearing.best_ellipse().best``)."""
    _, out = tiny
    kinds = {rec["criterion"]: rec["bound"] for rec in out["records"]}
    assert kinds["best_ellipse"] == "best outer ellipse found (certified, not optimal)"
    [best] = [rec for rec in out["records"] if rec["criterion"] == "best_ellipse"]
    assert best["lower_area"] <= best["area_lo"] == best["area_hi"]
    assert kinds["hs96_linearized"] == kinds["bh_L4"] == "analytic"
    assert all(k == "optimal" for c, k in kinds.items() if c.startswith("optimal_pseudo"))
