"""The parabola-arc noise ellipse of eta(z) = [z, z^2] [BH, eqs. (12)-(13), Fig. 2]."""

import mpmath
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound import analytic, optimal

mpmath.mp.prec = 200


def exact_levels(noise, w):
    C_inv = mpmath.inverse(mpmath.matrix(noise.shape.tolist()))
    out = []
    for wi in w:
        wi = mpmath.mpf(wi)
        y = mpmath.matrix([wi - mpmath.mpf(noise.center[0]), wi * wi - mpmath.mpf(noise.center[1])])
        out.append((y.T * C_inv * y)[0])
    return out


@given(st.floats(-5.0, 5.0), st.floats(0.01, 3.0))
def test_contains_the_whole_arc_in_exact_arithmetic(lo, width):
    hi = lo + width
    noise = analytic.parabola_arc_ellipse(lo, hi)
    w = np.concatenate([[lo, hi, 0.5 * (lo + hi)], np.linspace(lo, hi, 41)])
    assert all(level <= 1 for level in exact_levels(noise, w))


def test_touches_at_the_ends_and_the_middle():
    noise = analytic.parabola_arc_ellipse(1.0, 3.0)
    levels = [float(x) for x in exact_levels(noise, [1.0, 2.0, 3.0, 1.5])]
    np.testing.assert_allclose(levels[:3], 1.0, atol=1e-8)
    assert levels[3] == pytest.approx((9 * 0.25**2 - 9 * 0.25 + 4) / 4, rel=1e-8)


def test_area_is_the_closed_form():
    r = 0.7
    v_hat, V = analytic.parabola_arc_ellipse(2.0 - r, 2.0 + r)
    area = np.pi * np.sqrt(np.linalg.det(V))
    assert area == pytest.approx(4 * np.pi * r**3 / (3 * np.sqrt(3)), rel=1e-8)
    np.testing.assert_allclose(v_hat, [2.0, 4.0 + 2 * r * r / 3], rtol=1e-12)


@pytest.mark.parametrize(("lo", "hi"), [(-1.0, 1.0), (0.5, 2.0), (-3.0, -2.2)])
def test_is_the_minimum_area_ellipse_of_dense_arc_samples(lo, hi):
    w = np.linspace(lo, hi, 400)
    ref = optimal.mvee(np.column_stack([w, w * w])).ellipsoid
    noise = analytic.parabola_arc_ellipse(lo, hi)
    area = np.pi * np.sqrt(np.linalg.det(noise.shape))
    # Dense samples of the arc: their MVEE is at most the arc's, and close to it.
    assert ref.volume() <= area * (1 + 1e-6)
    assert ref.volume() == pytest.approx(area, rel=2e-3)
    np.testing.assert_allclose(ref.center, noise.center, atol=2e-3 * (1 + abs(hi)) ** 2)


@pytest.mark.parametrize(("lo", "hi"), [(1.0, 1.0), (2.0, 1.0), (np.nan, 1.0), (0.0, np.inf)])
def test_bad_input(lo, hi):
    with pytest.raises(ValueError, match=r"lo|hi"):
        analytic.parabola_arc_ellipse(lo, hi)
