"""size_bracket: certified volume brackets for every set type."""

from fractions import Fraction

import mpmath
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound import Box, Ellipsoid, PseudoEllipsoid, Strip
from optbound.compare import size_bracket, tri_contains, volume_ratio, volume_ratio_bracket
from optbound.compare.size import ellipsoid_strip_volume_bracket
from optbound.compare.tri import as_pseudo_ellipsoid, tri_test
from optbound.interval import pave, sivia, tri_and
from optbound.sets import PolynomialLifting
from tests.strategies import ellipsoids


@given(st.lists(st.floats(-1e3, 1e3), min_size=2, max_size=12))
def test_box_bracket_holds_the_exact_product(values):
    n = len(values) // 2
    lo = np.array(values[:n])
    hi = lo + np.abs(np.array(values[n : 2 * n])) + 1e-3
    box = Box(lo, hi)
    exact = np.prod([Fraction(b) - Fraction(a) for a, b in zip(box.lo, box.hi, strict=True)])
    b_lo, b_hi = size_bracket(box)
    assert Fraction(b_lo) <= exact <= Fraction(b_hi)
    assert b_hi / b_lo - 1 < 1e-13


@given(ellipsoids(min_dim=1, max_dim=6))
def test_ellipsoid_bracket_holds_the_exact_volume(E):
    with mpmath.workdps(50):
        det = mpmath.matrix([[mpmath.mpf(float(c)) for c in row] for row in E.shape])
        n = E.dim
        volume = mpmath.pi ** (mpmath.mpf(n) / 2) / mpmath.gamma(mpmath.mpf(n) / 2 + 1)
        volume *= mpmath.sqrt(mpmath.det(det))
        lo, hi = size_bracket(E)
        assert mpmath.mpf(lo) <= volume <= mpmath.mpf(hi)
    assert hi / lo - 1 < 1e-13
    assert lo <= E.volume() * (1 + 1e-9) and hi >= E.volume() * (1 - 1e-9)


def test_paving_bracket_is_volume_bounds_rounded_outward():
    paving = sivia(lambda x, y: x**2 + y**2, [[-np.inf, 1.0]], [[-2, 2], [-2, 2]], 0.05)
    lo, hi = size_bracket(paving)
    v_lo, v_hi = paving.volume_bounds()
    assert lo <= v_lo <= np.pi <= v_hi <= hi
    assert (v_lo - lo) / v_lo < 1e-12 and (hi - v_hi) / v_hi < 1e-12


def test_pseudo_ellipsoid_and_user_objects_are_paved():
    E = Ellipsoid([0.5, -0.2], [[1.0, 0.3], [0.3, 0.5]])
    lo, hi = size_bracket(as_pseudo_ellipsoid(E), eps=0.01)
    assert lo <= E.volume() <= hi and hi / lo < 1.1
    bh = PseudoEllipsoid(PolynomialLifting.bh4(), [0.0, 0.0, 0.5, 0.5], np.eye(4))
    b_lo, b_hi = size_bracket(bh, eps=0.05)
    assert 0 < b_lo < b_hi

    class Disc:
        dim = 2

        def tri_contains(self, boxes):
            return tri_contains(Ellipsoid([0.0, 0.0], np.eye(2)), boxes)

    lo, hi = size_bracket(Disc(), domain=[[-2, 2], [-2, 2]], eps=0.01)
    assert lo <= np.pi <= hi < 3.2
    # A domain cutting the set: the measured part is bracketed, the set's size is not.
    assert size_bracket(Disc(), domain=[[-0.5, 2], [-2, 2]], eps=0.05)[1] == np.inf
    with pytest.raises(ValueError, match="domain is required"):
        size_bracket(Disc())
    with pytest.raises(ValueError, match="dimension"):
        size_bracket(Disc(), domain=[[-1, 1]])


def test_volume_bracket_protocol_objects():
    class Square:
        dim = 2

        def volume_bounds(self, eps):
            return (4.0 - eps, 4.0 + eps)

    assert size_bracket(Square(), eps=0.5) == (3.5, 4.5)
    assert size_bracket(Square(), domain=[[0, 64], [0, 1]]) == (3.0, 5.0)  # eps = 64 / 64
    with pytest.raises(ValueError, match="eps or domain is required"):
        size_bracket(Square())

    class Broken(Square):
        def volume_bounds(self, eps):
            return (np.nan, 1.0)

    with pytest.raises(ValueError, match="0 <= lower <= upper"):
        size_bracket(Broken(), eps=0.1)


def test_objects_without_a_certified_size_are_refused():
    class OnlyContains:
        dim = 2

        def contains(self, X):
            return np.ones(len(X), bool)

    with pytest.raises(TypeError, match="no certified size measure"):
        size_bracket(OnlyContains())
    with pytest.raises(TypeError, match="no certified size measure"):
        size_bracket(np.eye(2))


def test_ratios_on_mixed_pairs():
    E = Ellipsoid([0.0, 0.0], np.eye(2))
    box = Box([-1.0, -1.0], [1.0, 1.0])
    assert volume_ratio(box, E) == pytest.approx(4 / np.pi, rel=1e-14)
    lo, hi = volume_ratio_bracket(box, E)
    assert lo <= 4 / np.pi <= hi and hi - lo < 1e-14
    paving = sivia(lambda x, y: x**2 + y**2, [[-np.inf, 1.0]], [[-2, 2], [-2, 2]], 0.02)
    p_lo, p_hi = volume_ratio_bracket(paving, E)
    assert p_lo <= 1.0 <= p_hi
    assert p_lo <= volume_ratio(paving, E) <= p_hi
    with pytest.raises(ValueError, match="different dimensions"):
        volume_ratio(box, Ellipsoid([0.0], [[1.0]]))


def test_ellipsoid_strip_volume_closed_form():
    ball = Ellipsoid(np.zeros(3), np.eye(3))
    # A cap of height 0.5 of the unit ball: pi h^2 (3 - h) / 3 with h = 1/2.
    lo, hi = ellipsoid_strip_volume_bracket(ball, Strip.from_bounds([0.0, 0.0, 1.0], 0.5, 5.0))
    assert lo <= np.pi * 0.25 * 2.5 / 3 <= hi and hi - lo < 1e-14
    disc = Ellipsoid(np.zeros(2), np.eye(2))
    lo, hi = ellipsoid_strip_volume_bracket(disc, Strip.from_bounds([1.0, 0.0], -2.0, 2.0))
    assert lo <= np.pi <= hi
    lo, hi = ellipsoid_strip_volume_bracket(disc, Strip.from_bounds([1.0, 0.0], 3.0, 4.0))
    assert lo == 0.0 and hi < 1e-15  # a strip missing the disc


@given(ellipsoids(min_dim=2, max_dim=4), st.floats(-0.9, 0.5), st.floats(0.1, 1.0))
def test_ellipsoid_strip_closed_form_lies_in_the_paving_bracket(E, u_lo, width):
    d = np.ones(E.dim) / np.sqrt(E.dim)
    lo_x, hi_x = E.extent(d)
    mid, half = 0.5 * (lo_x + hi_x), 0.5 * (hi_x - lo_x)
    S = Strip.from_bounds(d, mid + half * u_lo, mid + half * (u_lo + width))
    tests = (tri_test(E), tri_test(S))
    paving = pave(
        lambda *c: tri_and(*(t(*c) for t in tests)),
        as_pseudo_ellipsoid(E).bounding_box(),
        float(np.max(E.bounding_box().widths)) / 16,
    )
    p_lo, p_hi = size_bracket(paving)
    lo, hi = ellipsoid_strip_volume_bracket(E, S)
    assert p_lo <= hi and lo <= p_hi
