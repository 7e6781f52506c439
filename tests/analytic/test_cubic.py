"""Tests of the compiled real roots of polynomials of degree <= 3 (the criteria's cubics)."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound.analytic._kernels.cubic import real_roots


def _found(coeffs):
    k, *roots = real_roots(*coeffs)
    return np.sort(roots[:k])


@pytest.mark.parametrize(
    ("coeffs", "expected", "rtol"),
    [
        ((1.0, -6.0, 11.0, -6.0), [1, 2, 3], 1e-14),  # (x-1)(x-2)(x-3): trigonometric form
        ((0.0, 1.0, 0.0, -4.0), [-2, 2], 1e-15),  # degree drops: x^2 - 4
        ((1e-14, 1.0, -3.0, 2.0), [1, 2], 1e-12),  # negligible leading term: ~(x-1)(x-2)
        ((0.0, 0.0, 2.0, -1.0), [0.5], 0.0),  # linear
        ((1.0, 0.0, 1.0, 0.0), [0.0], 0.0),  # x (x^2 + 1): one real root (Cardano form)
        ((2.0, -8.0, 8.0, 0.0), [0.0, 2.0], 1e-7),  # 2 x (x-2)^2: the double root once
        ((1.0, -3.0, 3.0, -1.0), [1.0], 1e-5),  # (x-1)^3: triple root (rounding: 1e-5)
    ],
)
def test_known_roots(coeffs, expected, rtol):
    """Each expected root is found and each root found is expected, to rtol (1 + |x|)."""
    got, expected = _found(coeffs), np.array(expected, dtype=float)
    assert got.size >= 1
    gap = np.abs(got[:, None] - expected[None, :]) / (1 + np.abs(expected[None, :]))
    assert np.all(gap.min(axis=0) <= rtol) and np.all(gap.min(axis=1) <= rtol)


@pytest.mark.parametrize(
    "coeffs",
    [(0.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 3.0), (np.nan, 1.0, 0.0, 0.0), (1.0, 0, 0, np.inf)],
)
def test_no_roots_of_constants_and_non_finite_input(coeffs):
    assert real_roots(*coeffs)[0] == 0


@given(
    roots=st.lists(st.floats(-1e3, 1e3), min_size=3, max_size=3),
    lead=st.floats(1e-3, 1e3) | st.floats(-1e3, -1e-3),
)
def test_roots_of_a_product_of_linear_factors(roots, lead):
    """Distinct well-separated roots r of lead (x-r1)(x-r2)(x-r3) are recovered to a residual
    at the polynomial's rounding level (relative to the root's scale)."""
    r = np.sort(roots)
    if np.min(np.diff(r)) < 1e-2 * (1 + np.max(np.abs(r))):
        return  # near-multiple roots are ill-conditioned: covered by test_known_roots
    coeffs = lead * np.poly(r)
    got = _found(coeffs)
    assert got.size == 3
    scale = 1 + np.max(np.abs(r))
    np.testing.assert_allclose(got, r, rtol=0, atol=1e-9 * scale)


# Zero or of moderate size: with coefficients near underflow numpy's companion matrix itself
# loses roots (e.g. 5e-278 x + 5e-278 on top of x^3 + x^2), so it is no reference there.
MODERATE = st.floats(-10, 10).filter(lambda x: x == 0 or abs(x) >= 1e-6)


@given(coeffs=st.lists(MODERATE, min_size=4, max_size=4))
def test_real_roots_agree_with_numpy_roots(coeffs):
    """Every clearly real root of numpy's companion-matrix solver is found, and every root
    found is close to one of numpy's roots."""
    c = np.array(coeffs)
    if np.max(np.abs(c)) == 0 or np.all(np.abs(c[:3]) <= 1e-10 * np.max(np.abs(c))):
        return
    got = _found(c)
    lead = np.argmax(np.abs(c) > 1e-10 * np.max(np.abs(c)))
    ref = np.roots(c[lead:])
    real = ref[np.abs(ref.imag) <= 1e-9 * (1 + np.abs(ref.real))].real  # clearly real
    for x in real:
        assert np.min(np.abs(got - x)) <= 1e-5 * (1 + abs(x))
    for x in got:  # and every root found is one of numpy's (a complex pair's real part counts)
        assert np.min(np.abs(ref - x)) <= 1e-5 * (1 + abs(x))
