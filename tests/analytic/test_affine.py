"""The certified affine image of an ellipsoid contains the exact image (Fraction arithmetic)."""

from fractions import Fraction

import numpy as np
import pytest

from optbound import Ellipsoid
from optbound.analytic.affine import affine_map
from tests.sets import exact_polytopes as X

F = Fraction


def _exact_boundary_images(E, A, t, count=24):
    """Exact images ``A (c + L u) + t`` of rational points u on the unit circle (u_2 = 0 in
    higher dimensions is enough: they are boundary points of the exact image)."""
    A, t, c, L = X.exact(A), X.exact(t), X.exact(E.center), X.exact(E.chol)
    n = len(c)
    out = []
    for k in range(count):
        s = F(k, 3) - 4  # u = ((1 - s^2), 2 s) / (1 + s^2), exact
        for i, j in ((0, 1), (n - 2, n - 1)):
            u = [F(0)] * n
            u[i], u[j] = (1 - s * s) / (1 + s * s), 2 * s / (1 + s * s)
            for sign in (1, -1):
                x = [ci + sign * sum(L[r][q] * u[q] for q in range(n)) for r, ci in enumerate(c)]
                out.append(
                    tuple(
                        sum(a * xq for a, xq in zip(row, x, strict=True)) + tr
                        for row, tr in zip(A, t, strict=True)
                    )
                )
    return out


@pytest.mark.parametrize("seed", range(6))
def test_affine_image_contains_the_exact_image(seed):
    rng = np.random.default_rng(seed)
    n = 2 + seed % 2
    L = np.tril(rng.normal(size=(n, n))) + 2.0 * np.eye(n)
    E = Ellipsoid(rng.normal(size=n) * 10.0, L @ L.T)
    A, t = rng.normal(size=(n, n)), rng.normal(size=n)
    image = affine_map(E, A, t)
    assert X.in_ellipsoid(image, _exact_boundary_images(E, A, t))
    plain = E.affine_map(A, t)  # the float image; the certified one is larger by rounding only
    assert np.allclose(image.shape, plain.shape, rtol=1e-12)


def test_flat_image_is_widened_not_refused():
    E = Ellipsoid([1.0, 2.0], [[2.0, 0.3], [0.3, 1.0]])
    A = np.array([[1.0, 1.0], [1.0, 1.0]])  # rank 1: the exact image is a segment
    image = affine_map(E, A)
    assert X.in_ellipsoid(image, _exact_boundary_images(E, A, [0.0, 0.0]))
    assert image.semi_axes()[0] < 1e-3 * image.semi_axes()[1]


def test_bad_input_is_refused():
    E = Ellipsoid([0.0, 0.0], np.eye(2))
    with pytest.raises(TypeError, match="E must be an Ellipsoid"):
        affine_map(np.eye(2), np.eye(2))
    with pytest.raises(ValueError, match="A must have shape"):
        affine_map(E, np.eye(3))
    with pytest.raises(ValueError, match="t must"):
        affine_map(E, np.eye(2), [0.0, np.nan])
