"""LJMW97 Appendix A reproduction: the SIVIA bracket of the disc-minus-ellipse area."""

import numpy as np
import pytest

from optbound.papers_repro import ljmw97_appendix_a as repro

EPS = (0.1, 0.05, 0.01)


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    return repro.main(tmp_path_factory.mktemp("ljmw97"), eps_values=EPS)


def test_writes_its_figures(result):
    assert len(result["figures"]) == 2
    for path in result["figures"]:
        assert path.suffix == ".png" and path.stat().st_size > 10_000


def test_exact_area_is_the_known_fact():
    assert repro.EXACT_AREA == pytest.approx(0.920151, abs=1e-6)


def test_bracket_contains_the_exact_area_and_tightens(result):
    rows = result["rows"]
    assert [r["eps"] for r in rows] == list(EPS)
    for r in rows:
        assert r["inner_area"] <= repro.EXACT_AREA <= r["outer_area"]
    widths = [r["outer_area"] - r["inner_area"] for r in rows]
    assert widths == sorted(widths, reverse=True)
    assert widths[-1] < 0.15


def _in_boxes(pts, boxes):
    lo, hi = boxes[None, :, :, 0], boxes[None, :, :, 1]
    return np.any(np.all((pts[:, None] >= lo) & (pts[:, None] <= hi), axis=2), axis=1)


def _in_q(pts):
    x, y = pts.T
    return (x**2 + y**2 <= 1) & (2 * x**2 + y**2 >= 1)


def test_paving_is_guaranteed_on_samples():
    paving, _ = repro.characterise(0.05)
    rng = np.random.default_rng(4)
    # Points of the inner boxes are in Q.
    k = rng.integers(0, len(paving.inner), 20_000)
    box = paving.inner[k]
    pts = box[:, :, 0] + rng.random((20_000, 2)) * (box[:, :, 1] - box[:, :, 0])
    assert _in_q(pts).all()
    # Points of Q (which lies in [-1, 1]^2) are in inner ∪ boundary.
    pts = rng.uniform(-1.0, 1.0, (50_000, 2))
    pts = pts[_in_q(pts)]
    assert len(pts) >= 10_000
    assert _in_boxes(pts, paving.outer()).all()
