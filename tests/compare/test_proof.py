"""prove_contains and the exact closed-form containment proofs."""

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound import Box, Ellipsoid, Halfspace, Strip
from optbound.compare import exact, max_level, prove_contains, tri_test
from optbound.interval import Tri, pave, tri_and
from tests.strategies import ellipsoids


@given(ellipsoids(max_dim=5), st.floats(1.001, 3.0))
def test_an_ellipsoid_is_proven_inside_itself_and_its_enlargement(E, factor):
    assert exact.ellipsoid_in_ellipsoid(E, E)
    assert exact.ellipsoid_in_ellipsoid(E.scaled(factor), E)
    assert not exact.ellipsoid_in_ellipsoid(E.scaled(1 / factor), E)


@given(ellipsoids(max_dim=4), st.integers(0, 2**32 - 1))
def test_exact_proof_agrees_with_the_float_level(E, seed):
    rng = np.random.default_rng(seed)
    shifted = Ellipsoid(E.center + 0.05 * rng.standard_normal(E.dim) * E.semi_axes()[0], E.shape)
    big = E.scaled(1.2)
    proven = exact.ellipsoid_in_ellipsoid(big, shifted)
    level = max_level(big, shifted)
    if proven:
        assert level <= 1 + 1e-9
    if level < 0.99:  # a clear margin is always proven
        assert proven


def test_is_psd_handles_semidefinite_and_indefinite():
    F = Fraction
    assert exact.is_psd([[F(0), F(0)], [F(0), F(0)]])
    assert exact.is_psd([[F(1), F(1)], [F(1), F(1)]])
    assert not exact.is_psd([[F(0), F(1)], [F(1), F(0)]])
    assert not exact.is_psd([[F(1), F(2)], [F(2), F(1)]])


def test_box_and_ellipsoid_closed_forms():
    E = Ellipsoid([0.0, 0.0], np.diag([4.0, 1.0]))
    assert exact.contains_set(Box([-2.0, -1.0], [2.0, 1.0]), E)
    assert not exact.contains_set(Box([-2.0, -1.0], [1.999, 1.0]), E)
    assert exact.contains_set(E, Box([-1.0, -0.5], [1.0, 0.5]))
    assert not exact.contains_set(E, Box([-1.5, -0.75], [1.5, 0.75]))  # corner level 1.125
    assert exact.contains_set(Box([-1, -1], [1, 1]), Box([-1, 0], [0, 1]))


def _lens():
    """E ∩ S and its paving: a set known by a test, as a Problem would give it."""
    E = Ellipsoid([0.2, -0.1], [[1.0, 0.4], [0.4, 0.6]])
    S = Strip.from_bounds([1.0, 0.5], -0.3, 0.4)
    tests = (tri_test(E), tri_test(S))

    def member(*coords):
        return tri_and(*(t(*coords) for t in tests))

    return E, S, member, pave(member, E.bounding_box().as_array() * 1.01, 0.01)


def test_paving_proofs_and_exact_counterexamples():
    E, S, member, paving = _lens()
    hull = paving.hull()
    assert prove_contains(hull, paving, member=member).status == "proven"
    assert prove_contains(paving, paving).status == "proven"
    assert prove_contains(E, E).status == "proven"
    half = 0.3 * hull.widths
    small = Box(hull.center - half, hull.center + half)
    verdict = prove_contains(small, paving, member=member)
    assert verdict.status == "refuted"
    x = verdict.counterexample
    assert exact.member(E, x) and exact.member(S, x) and not exact.member(small, x)
    # A half-plane cutting the set: refuted; the one containing it: proven.
    cut = Halfspace([1.0, 0.0], float(hull.center[0]))
    verdict = prove_contains(cut, paving, member=member)
    assert verdict.status == "refuted" and not exact.member(cut, verdict.counterexample)
    whole = Halfspace([1.0, 0.0], float(hull.hi[0]))
    assert prove_contains(whole, paving, member=member).status == "proven"


def test_counterexamples_satisfy_the_member_test():
    from optbound.compare.tri import point_test

    E, _, member, paving = _lens()

    scaled = E.scaled(0.8)
    verdict = prove_contains(scaled, paving, member=member)
    assert verdict.status == "refuted"
    assert point_test(member, verdict.counterexample[None, :])[0] == Tri.TRUE
    assert not exact.member(scaled, verdict.counterexample)


def test_prove_contains_refuses_bad_arguments():
    *_, paving = _lens()
    with pytest.raises(ValueError, match="dimension"):
        prove_contains(Box([0.0], [1.0]), paving)
    with pytest.raises(TypeError, match="inner must be"):
        prove_contains(Box([0.0, 0.0], [1.0, 1.0]), Strip([1.0, 0.0], 0.0))


def test_s_procedure_proves_the_sdp_optimum_of_a_lens_exactly():
    from optbound import optimal

    E, S, member, paving = _lens()
    sdp = optimal.outer_ellipsoid([E, S]).ellipsoid
    assert exact.contains_intersection(sdp, [E, S])
    assert prove_contains(sdp, [E, S]) == prove_contains(sdp, (E, S))
    assert prove_contains(sdp, [E, S]).status == "proven"
    # 1 % smaller about its centre: no certificate (and the paving refutes it).
    assert not exact.contains_intersection(sdp.scaled(0.99), [E, S])
    assert prove_contains(sdp.scaled(0.99), paving, member=member).status == "refuted"
    # A half-space cut works the same way; a box outer has no S-procedure proof.
    H = Halfspace(S.a, S.b + 1.0)
    assert exact.contains_intersection(optimal.outer_ellipsoid([E, H]).ellipsoid, [E, H])
    assert not exact.contains_intersection(Box([-9.0, -9.0], [0.0, 0.0]), [E, S])
