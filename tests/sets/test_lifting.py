"""Polynomial liftings [BH, eqs. (22)-(23)] on points and on interval boxes."""

import mpmath
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound.sets import PolynomialLifting

coord = st.floats(-3.0, 3.0)


def _bh8_explicit(u):
    x, y = u
    r = x * x + y * y
    return [x, y, x * y, x * x, y * y, x**3 + x * y * y, x * x * y + y**3, r * r]


@given(coord, coord, coord, coord, st.floats(0.1, 5.0))
def test_bh4_and_bh8_are_the_papers_maps(x, y, ox, oy, s):
    u = ((x - ox) / s, (y - oy) / s)
    T4 = PolynomialLifting.bh4([ox, oy], s)
    T8 = PolynomialLifting.bh8([ox, oy], s)
    np.testing.assert_allclose(
        T4([x, y]), [u[0], u[1], u[0] ** 2, u[1] ** 2], rtol=1e-12, atol=1e-12
    )
    np.testing.assert_allclose(T8([x, y]), _bh8_explicit(u), rtol=1e-12, atol=1e-12)
    assert T8.size == 8 and T8.dim == 2 and T4.size == 4


def test_box_image_encloses_exact_values():
    rng = np.random.default_rng(0)
    T = PolynomialLifting.bh8([0.3, -0.2], 0.7)
    lo = rng.uniform(-2, 2, (50, 2))
    boxes = np.stack([lo, lo + rng.uniform(0, 0.5, (50, 2))], axis=-1)
    img = T.box_image(boxes)
    mpmath.mp.prec = 200
    for b, im in zip(boxes, img, strict=True):
        for t in rng.random((20, 2)):
            p = b[:, 0] + t * (b[:, 1] - b[:, 0])
            corner = b[np.arange(2), rng.integers(0, 2, 2)]
            for q in (p, corner):
                u = [
                    (mpmath.mpf(q[j]) - mpmath.mpf(T.offset[j])) / mpmath.mpf(T.scale)
                    for j in range(2)
                ]
                for k, val in enumerate(_bh8_explicit(u)):
                    assert im[k, 0] <= val <= im[k, 1]


def test_jacobian_matches_finite_differences():
    T = PolynomialLifting.bh8([1.0, 2.0], 2.0)
    X = np.random.default_rng(1).normal(size=(6, 2))
    J = T.jacobian(*X.T)
    h = 1e-6
    for j in range(2):
        step = np.zeros(2)
        step[j] = h
        fd = (T(X + step) - T(X - step)) / (2 * h)
        for row in range(8):
            np.testing.assert_allclose(J[row][j], fd[:, row], rtol=1e-6, atol=1e-8)


def test_identity_components():
    assert PolynomialLifting.bh8().identity_components().tolist() == [0, 1]
    T = PolynomialLifting.from_components([{(2, 0): 1.0}, {(0, 1): 2.0}])
    assert T.identity_components().tolist() == [-1, -1]


@pytest.mark.parametrize(
    ("args", "match"),
    [
        (([[-1, 0]], [[1.0]]), "non-negative"),
        (([[1.5, 0]], [[1.0]]), "integer"),
        (([[1, 0]], [[0.0]]), "non-zero"),
        (([[1, 0]], [[np.nan]]), "finite"),
        (([[1, 0]], [[1.0, 2.0]]), "shape"),
    ],
)
def test_bad_input(args, match):
    with pytest.raises(ValueError, match=match):
        PolynomialLifting(*args)


def test_bad_scale_and_coordinates():
    with pytest.raises(ValueError, match="scale"):
        PolynomialLifting.bh4(scale=0.0)
    with pytest.raises(ValueError, match="offset"):
        PolynomialLifting.bh4(offset=[1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="coordinates"):
        PolynomialLifting.bh4().components(np.zeros(3))
    with pytest.raises(ValueError, match="boxes"):
        PolynomialLifting.bh4().box_image(np.zeros((2, 3, 2)))
