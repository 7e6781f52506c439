"""HS96 3-D pose reproduction: projection-optimal fusion and the kappa criteria."""

import numpy as np
import pytest

from optbound.papers_repro import _hs96_kappa as kappa_poly
from optbound.papers_repro import hs96_projection as repro


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    return repro.main(tmp_path_factory.mktemp("hs96_projection"), quick=True, n=1000, seed=0)


def test_writes_its_figures(result):
    assert len(result["figures"]) == 2
    for path in result["figures"]:
        assert path.suffix == ".png" and path.stat().st_size > 10_000


def test_projection_ebs_is_never_larger_in_xy(result):
    f = result["fusion"]
    assert f["reduced"] > 900
    assert f["frac_xy_not_larger"] == 1.0
    assert np.all(f["xy_ratio"] <= 1 + 1e-9)
    assert f["median_xy_ratio"] < 1.0


def test_volume_ebs_is_never_larger_in_volume(result):
    f = result["fusion"]
    assert f["frac_volume_not_smaller"] == 1.0
    assert np.all(f["volume_ratio"] >= 1 - 1e-9)


def test_psi_claim_holds_mostly_and_fails_for_heading_strips(result):
    f = result["fusion"]
    assert 0.5 < f["frac_claim_holds"] < 1.0
    assert f["median_psi_ratio"] > 1.0
    assert f["psi_share_fails"] > f["psi_share_holds"]


def test_example_bounds_contain_the_intersection_and_match_the_sdp(result):
    ex = result["example"]
    pts = ex["prior"].sample(150_000, np.random.default_rng(3))
    pts = pts[ex["strip"].contains(pts)]
    assert len(pts) >= 10_000
    for key in ("volume", "projection", "sdp"):
        assert ex[key].contains(pts).all()
    xy = repro.area(ex["projection"], repro.XY)
    assert xy == pytest.approx(repro.area(ex["sdp"], repro.XY), rel=1e-5)


def test_random_instances_are_seeded_and_meet_the_prior():
    first = repro.random_instances(50, seed=7)
    second = repro.random_instances(50, seed=7)
    assert all(np.array_equal(x, y) for x, y in zip(first, second, strict=True))
    c, C, a, b = first
    assert np.all(np.linalg.eigvalsh(C) > 0)
    # Each strip is centred on a point of its prior, so the two sets always meet.
    extent = np.sqrt(np.einsum("bi,bij,bj->b", a, C, a))
    assert np.all(np.abs(b - np.einsum("bi,bi->b", a, c)) <= extent)


def test_kappa_cubic_has_one_root_and_matches_the_grid(result):
    k = result["kappa"]
    assert k["cubic_roots_in_unit"] == 1
    assert k["size_xy_psi"]["kappa"] == pytest.approx(k["grid_argmin_size_xy_psi"], abs=1e-3)


def test_trace_criterion_serves_xy_and_neglects_psi(result):
    k = result["kappa"]
    best_xy, best_psi = k["best"]["xy_area"], k["best"]["psi_half"]
    assert k["trace"]["xy_area"] / best_xy < 1.01
    assert k["trace"]["psi_half"] / best_psi > 1.5
    assert k["size_xy_psi"]["psi_half"] < k["volume"]["psi_half"] < k["trace"]["psi_half"]
    for crit in ("volume", "trace", "size_xy_psi"):
        assert k[crit]["xy_area"] >= best_xy * (1 - 1e-6)
        assert k[crit]["psi_half"] >= best_psi * (1 - 1e-6)


@pytest.mark.parametrize("kind", kappa_poly.CRITERIA)
def test_kappa_polynomial_root_on_two_balls(kind):
    # Balls of radii r1, r2: kappa = r2 / (r1 + r2) for volume, trace and size_xy_psi alike.
    r1, r2 = 0.3, 0.1
    roots = kappa_poly.roots_in_unit(
        kappa_poly.polynomial(r1**2 * np.eye(3), r2**2 * np.eye(3), kind)
    )
    assert roots == pytest.approx([r2 / (r1 + r2)], rel=1e-12)


def test_kappa_polynomial_degrees_are_the_papers():
    Xi, Gamma = kappa_poly.random_pair(np.random.default_rng(0))
    degrees = {k: kappa_poly.polynomial(Xi, Gamma, k).degree() for k in kappa_poly.CRITERIA}
    assert degrees == {"volume": 4, "trace": 2, "size_xy_psi": 3}


def test_kappa_check_measures_the_gap_to_the_numerical_minimum(result):
    poly = result["kappa_polynomials"]
    for kind in kappa_poly.CRITERIA:
        r = poly[kind]
        assert r["n"] == repro.KAPPA_PAIRS[True] == len(r["roots"])
        assert r["unique"] == sum(c == 1 for c in r["roots"])
        assert 0.0 <= r["gap"] < 1e-9 and r["kappa_diff"] < 1e-5 and r["library_gap"] < 1e-9
    # A wrong kappa is seen as a gap: the criterion at kappa + 0.05 is measurably above it.
    Xi, Gamma = kappa_poly.random_pair(np.random.default_rng(1))
    (k,) = kappa_poly.roots_in_unit(kappa_poly.polynomial(Xi, Gamma, "trace"))
    at = [kappa_poly.criterion(Xi, Gamma, "trace", x) for x in (k, k + 0.05)]
    assert at[1] > at[0] * (1 + 1e-6)


def test_claim_rows_carry_verdicts(result):
    md = result["markdown"]
    assert "| quantity | paper | optbound | verdict |" in md
    assert "fourth-order polynomial" in md and "second-order polynomial" in md
