"""Every interval operation encloses the exact (mpmath, 300-bit) result at sampled points.

Inputs mix subnormal, tiny, order-one, huge and zero-straddling bounds (seeded arrays), plus
hypothesis-chosen finite floats. For each interval (pair) we evaluate the exact function at the
endpoints and at interior points and check the computed interval contains every value.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound import interval as iv
from tests.interval._samples import awkward_floats, encloses, points_in, random_intervals

N = 150  # intervals per operation

mpf = mpmath.mpf

UNARY = {
    "sqr": (iv.sqr, lambda x: x * x, None),
    "sqrt": (iv.sqrt, mpmath.sqrt, lambda x: x >= 0),
    "exp": (iv.exp, mpmath.exp, None),
    "log": (iv.log, mpmath.log, lambda x: x > 0),
    "sin": (iv.sin, mpmath.sin, None),
    "cos": (iv.cos, mpmath.cos, None),
    "abs": (iv.absolute, abs, None),
    "neg": (iv.negative, lambda x: -x, None),
    "cube": (lambda X: iv.power(X, 3), lambda x: x**3, None),
    "pow4": (lambda X: iv.power(X, 4), lambda x: x**4, None),
    "pow-3": (lambda X: iv.power(X, -3), lambda x: x**-3, lambda x: x != 0),
}

BINARY = {
    "add": (iv.add, lambda x, y: x + y, None),
    "sub": (iv.subtract, lambda x, y: x - y, None),
    "mul": (iv.multiply, lambda x, y: x * y, None),
    "div": (iv.divide, lambda x, y: x / y, lambda x, y: y != 0),
    "atan2": (iv.atan2, mpmath.atan2, None),
    "min": (iv.minimum, min, None),
    "max": (iv.maximum, max, None),
}


def _check_unary(op, exact, domain, lo, hi, rng):
    X = op(iv.Interval(lo, hi))
    for pts in points_in(lo, hi, rng):
        for k, x in enumerate(pts):
            xm = mpf(float(x))
            if domain is not None and not domain(xm):
                continue
            assert not X.is_empty[k], f"empty result at x={x!r}"
            assert encloses(X.lo[k], X.hi[k], exact(xm)), (float(x), X.lo[k], X.hi[k])


def _check_binary(op, exact, domain, a, b, rng):
    Z = op(iv.Interval(*a), iv.Interval(*b))
    for xs, ys in zip(points_in(*a, rng), points_in(*b, rng), strict=True):
        for k, (x, y) in enumerate(zip(xs, ys, strict=True)):
            xm, ym = mpf(float(x)), mpf(float(y))
            if domain is not None and not domain(xm, ym):
                continue
            assert encloses(Z.lo[k], Z.hi[k], exact(xm, ym)), (float(x), float(y), Z.lo[k])


@pytest.mark.parametrize("name", sorted(UNARY))
def test_unary_encloses_exact(name):
    rng = np.random.default_rng(7)
    lo, hi = random_intervals(rng, N)
    if name in ("exp", "sin", "cos"):
        # Also moderate arguments, where the results are not all 0, inf or +-1.
        lo2, hi2 = random_intervals(rng, N)
        lo = np.concatenate([lo, np.clip(lo2, -700, 700) % 50 - 25])
        hi = np.concatenate([hi, lo[N:] + np.abs(hi2 - lo2) % 7])
    _check_unary(*UNARY[name], lo, hi, rng)


@pytest.mark.parametrize("name", sorted(BINARY))
def test_binary_encloses_exact(name):
    rng = np.random.default_rng(11)
    _check_binary(*BINARY[name], random_intervals(rng, N), random_intervals(rng, N), rng)


finite = st.floats(allow_nan=False, allow_infinity=False)


@given(finite, finite, finite, finite)
def test_arithmetic_encloses_exact_hypothesis(a, b, c, d):
    X = iv.Interval(min(a, b), max(a, b))
    Y = iv.Interval(min(c, d), max(c, d))
    for x in (a, b):
        for y in (c, d):
            xm, ym = mpf(x), mpf(y)
            for Z, exact in ((X + Y, xm + ym), (X - Y, xm - ym), (X * Y, xm * ym)):
                assert encloses(Z.lo, Z.hi, exact)
            if y != 0:
                Z = X / Y
                assert encloses(Z.lo, Z.hi, xm / ym)


@given(finite, finite)
def test_transcendental_encloses_exact_hypothesis(a, b):
    X = iv.Interval(min(a, b), max(a, b))
    for x in (a, b):
        xm = mpf(x)
        for Z, exact in ((iv.exp(X), mpmath.exp(xm)), (iv.sin(X), mpmath.sin(xm))):
            assert encloses(Z.lo, Z.hi, exact)
        if x > 0:
            assert encloses(iv.log(X).lo, iv.log(X).hi, mpmath.log(xm))


def test_results_are_tight_for_exact_operations():
    # One-ulp outward steps only: [1, 2] + [3, 4] stays within 2 ulps of [4, 6].
    Z = iv.Interval(1.0, 2.0) + iv.Interval(3.0, 4.0)
    assert 4.0 - 2 * np.spacing(4.0) <= Z.lo < 4.0 and 6.0 < Z.hi <= 6.0 + 2 * np.spacing(6.0)
    assert iv.sqr(iv.Interval(-1.0, 2.0)).lo == 0.0  # sqr is tight at a straddled zero
    assert iv.absolute(iv.Interval(-3.0, 2.0)).lo == 0.0


def test_extrema_of_sin_cos_and_atan2_branch_cut():
    S = iv.sin(iv.Interval(1.0, 2.0))  # contains pi/2
    assert S.hi == 1.0 and S.lo <= math.sin(1.0)
    C = iv.cos(iv.Interval(3.0, 3.5))  # contains pi
    assert C.lo == -1.0
    W = iv.sin(iv.Interval(0.0, 7.0))  # a full period
    assert (W.lo, W.hi) == (-1.0, 1.0)
    A = iv.atan2(iv.Interval(-1.0, 1.0), iv.Interval(-2.0, -1.0))  # crosses the cut
    assert A.lo <= -math.pi and A.hi >= math.pi
    B = iv.atan2(iv.Interval(1.0, 2.0), iv.Interval(1.0, 2.0))
    assert math.atan2(1, 2) - 1e-15 <= B.lo and B.hi <= math.atan2(2, 1) + 1e-15


def test_division_by_interval_containing_zero():
    def bounds(Z):
        return float(Z.lo), float(Z.hi)

    assert bounds(iv.Interval(1.0, 2.0) / iv.Interval(0.0, 1.0))[1] == np.inf
    lo, _ = bounds(iv.Interval(1.0, 2.0) / iv.Interval(0.0, 1.0))
    assert 1.0 - 1e-15 <= lo <= 1.0
    assert bounds(iv.Interval(-2.0, -1.0) / iv.Interval(0.0, 1.0))[0] == -np.inf
    assert bounds(iv.Interval(1.0, 2.0) / iv.Interval(-1.0, 0.0))[0] == -np.inf
    assert bounds(iv.Interval(1.0, 2.0) / iv.Interval(-1.0, 1.0)) == (-np.inf, np.inf)
    assert bounds(iv.Interval(-1.0, 2.0) / iv.Interval(0.0, 1.0)) == (-np.inf, np.inf)
    assert bool((iv.Interval(1.0, 2.0) / iv.Interval(0.0, 0.0)).is_empty)


def test_products_with_unbounded_operands_and_broadcasting():
    # 0 * inf corners: [0, 0] times anything (even [-inf, inf]) encloses 0, never NaN.
    zero = iv.Interval(0.0, 0.0) * iv.Interval(-np.inf, np.inf)
    assert float(zero.lo) <= 0.0 <= float(zero.hi) and np.isfinite([zero.lo, zero.hi]).all()
    Z = iv.Interval(0.0, 2.0) * iv.Interval(-np.inf, 3.0)
    assert float(Z.lo) == -np.inf and 6.0 <= float(Z.hi) < 6.0 + 1e-14
    S = iv.Interval(-np.inf, 1.0) + iv.Interval(2.0, np.inf)
    assert (float(S.lo), float(S.hi)) == (-np.inf, np.inf)
    # Bound arrays of different shapes broadcast like numpy, for +, - and *.
    A = iv.Interval(np.arange(3.0)[:, None], np.arange(3.0)[:, None] + 1.0)
    B = iv.Interval(np.arange(4.0), np.arange(4.0) + 0.5)
    for Z, exact in ((A + B, np.add), (A - B, np.subtract), (A * B, np.multiply)):
        x, y = np.arange(3.0)[:, None] + 0.5, np.arange(4.0) + 0.25
        assert Z.shape == (3, 4) and np.all((Z.lo <= exact(x, y)) & (exact(x, y) <= Z.hi))


def test_domain_restrictions_give_empty_not_nan():
    assert bool(iv.sqrt(iv.Interval(-2.0, -1.0)).is_empty)
    R = iv.sqrt(iv.Interval(-1.0, 4.0))
    assert R.lo == 0.0 and 2.0 <= R.hi <= 2.0 + 1e-15
    assert bool(iv.log(iv.Interval(-1.0, 0.0)).is_empty)
    L = iv.log(iv.Interval(0.0, 1.0))
    assert L.lo == -np.inf and 0.0 <= L.hi < 1e-15


def test_partial_values_never_prove_a_constraint():
    X = iv.Interval([-1.0, 0.25], [0.25, 1.0])
    R = iv.sqrt(X) + 1.0  # the flag propagates through later operations
    assert R.partial.tolist() == [True, False]
    assert (R <= 10.0).tolist() == [iv.Tri.UNKNOWN, iv.Tri.TRUE]
    assert (R > 10.0).tolist() == [iv.Tri.FALSE, iv.Tri.FALSE]
    assert (1.0 / iv.Interval([-1.0, 1.0], [1.0, 2.0])).partial.tolist() == [True, False]
    assert R[0].partial and not R[1].partial


def test_empty_propagates_through_every_operation():
    E = iv.intersection(iv.Interval([0.0, 0.0]), iv.Interval([1.0, 0.0]))  # [empty, [0, 0]]
    assert E.is_empty.tolist() == [True, False]
    ops = [E + 1.0, E * E, 2.0 * E, E / 3.0, iv.sqrt(E), iv.exp(E), iv.sin(E), E**2]
    for Z in ops:
        assert Z.is_empty.tolist() == [True, False]
        assert not np.any(np.isnan(Z.lo)) and not np.any(np.isnan(Z.hi))


def test_hull_intersection_and_tri_comparisons():
    A, B = iv.Interval([0.0, 0.0], [1.0, 1.0]), iv.Interval([0.5, 2.0], [3.0, 3.0])
    H, C = iv.hull(A, B), iv.intersection(A, B)
    assert H.lo.tolist() == [0.0, 0.0] and H.hi.tolist() == [3.0, 3.0]
    assert C.is_empty.tolist() == [False, True] and C.lo[0] == 0.5 and C.hi[0] == 1.0
    assert iv.hull(C, A).lo.tolist() == [0.0, 0.0]  # empty is neutral for the hull
    X = iv.Interval([0.0, 0.0, 2.0], [1.0, 3.0, 3.0])
    assert (X <= 1.0).tolist() == [iv.Tri.TRUE, iv.Tri.UNKNOWN, iv.Tri.FALSE]
    assert (X < 1.0).tolist() == [iv.Tri.UNKNOWN, iv.Tri.UNKNOWN, iv.Tri.FALSE]
    assert (X >= 2.0).tolist() == [iv.Tri.FALSE, iv.Tri.UNKNOWN, iv.Tri.TRUE]
    assert (X > 0.0).tolist() == [iv.Tri.UNKNOWN, iv.Tri.UNKNOWN, iv.Tri.TRUE]
    assert (1.0 >= X).tolist() == (X <= 1.0).tolist()  # reflected comparison
    assert (C <= 10.0).tolist() == [iv.Tri.TRUE, iv.Tri.FALSE]  # empty compares FALSE


def test_bad_operands_raise():
    X = iv.Interval(1.0, 2.0)
    with pytest.raises(ValueError, match="integer exponent"):
        X**0.5
    with pytest.raises(ValueError, match="finite"):
        X + np.inf
    with pytest.raises(ValueError, match="finite"):
        X * np.nan


def test_awkward_floats_cover_the_ranges():
    # Guard against the generator silently losing a class of inputs.
    x = np.abs(awkward_floats(np.random.default_rng(0), 2000))
    assert np.any((x > 0) & (x < 2.0**-1022)) and np.any(x > 1e300) and np.any(x == 0)
