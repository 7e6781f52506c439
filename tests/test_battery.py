"""The known-answer battery, run through both the analytic and the optimal code."""

import numpy as np
import pytest

from optbound import Ellipsoid, Strip, compare
from optbound.optimal import EmptyIntersectionError, minkowski_outer, outer_ellipsoid
from tests import battery
from tests.optimal.sampling import MIN_POINTS, points_of

CASES = battery.agreeing()


@pytest.fixture(scope="module")
def solved():
    """Each case solved once by both routes: name -> (case, analytic ellipsoid, SDP result)."""
    return {case.name: (case, case.analytic(), case.sdp()) for case in CASES}


@pytest.mark.parametrize("name", [case.name for case in CASES])
def test_analytic_and_sdp_agree(solved, name):
    case, analytic_E, result = solved[name]
    assert result.certified and 1.0 <= result.inflation < 1.0 + 1e-5
    assert case.ratio(analytic_E, result.ellipsoid) == pytest.approx(1.0, rel=case.rtol)
    # The certified SDP answer can only exceed the true optimum; analytic = true optimum here.
    assert case.size(analytic_E) <= result.objective * (1.0 + 1e-7)
    if case.expected is not None:
        assert result.objective == pytest.approx(case.expected, rel=case.rtol)
        assert case.size(analytic_E) == pytest.approx(case.expected, rel=case.rtol)


def test_partial_case_raw_is_not_tight_and_clipping_fixes_it(solved):
    _, raw_analytic, raw_sdp = solved["partial_raw"]
    _, clipped_analytic, clipped_sdp = solved["partial_clipped"]
    saving = 1.0 - clipped_sdp.objective / raw_sdp.objective
    assert saving == pytest.approx(0.27, abs=0.01)  # Known facts: ~27 % less volume
    assert raw_sdp.objective > 1.3 * clipped_sdp.objective
    assert compare.volume_ratio(clipped_analytic, clipped_sdp) == pytest.approx(1, rel=1e-5)
    assert compare.volume_ratio(raw_analytic, raw_sdp) == pytest.approx(1, rel=1e-5)


@pytest.mark.parametrize("name", [case.name for case in CASES if case.kind == "intersection"])
def test_sdp_result_contains_sampled_set(solved, name):
    case, analytic_E, result = solved[name]
    X = points_of(case.sets, rng=7)
    assert X.shape[0] >= MIN_POINTS
    assert np.all(result.ellipsoid.contains(X, tol=0.0))
    assert np.all(analytic_E.contains(X, tol=1e-9))


@pytest.mark.parametrize("name", [case.name for case in CASES if case.kind == "minkowski"])
def test_sdp_result_contains_sampled_sum(solved, name):
    case, _, result = solved[name]
    rng = np.random.default_rng(8)
    X = sum(E.sample_boundary(MIN_POINTS, rng) for E in case.sets)
    assert np.all(result.ellipsoid.contains(X, tol=0.0))


def test_empty_intersection_is_clear_on_both_routes():
    from optbound import analytic

    E = Ellipsoid([0.0, 0.0], np.eye(2))
    S = Strip.from_bounds([1.0, 0.0], 1.5, 2.5)
    fused = analytic.intersect_strip(E, S)
    assert fused.ellipsoid is None and fused.case == "inconsistent"
    with pytest.raises(EmptyIntersectionError):
        outer_ellipsoid([E, S])


def test_bad_inputs_are_refused_on_both_routes():
    from optbound import analytic

    E2, E3 = Ellipsoid([0.0, 0.0], np.eye(2)), Ellipsoid(np.zeros(3), np.eye(3))
    S3 = Strip([1.0, 0.0, 0.0], 0.0)
    with pytest.raises(ValueError):
        analytic.intersect_strip(E2, S3)
    with pytest.raises(ValueError):
        outer_ellipsoid([E2, S3])
    with pytest.raises(ValueError):
        analytic.minkowski_sum(E2, E3)
    with pytest.raises(ValueError):
        minkowski_outer(E2, E3)
    with pytest.raises(ValueError):
        outer_ellipsoid([E3, S3], objective="projection")  # dims missing


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(1, 11))
def test_agreement_sweep_over_seeds(seed):
    cases = [battery.strip_both_planes(n, "volume", seed) for n in range(2, 7)]
    cases += [battery.strip_projection_3d(seed), battery.minkowski_random(3, "volume", seed)]
    for case in cases:
        result = case.sdp()
        assert case.ratio(case.analytic(), result.ellipsoid) == pytest.approx(1.0, rel=case.rtol)
