"""Tests of the vectorized polynomial root helper used by the closed-form criteria."""

import numpy as np

from optbound.analytic._roots import argmin_candidates, real_roots


def test_real_roots_of_mixed_degrees():
    coeffs = np.array(
        [
            [1.0, -6.0, 11.0, -6.0],  # (x-1)(x-2)(x-3)
            [0.0, 1.0, 0.0, -4.0],  # degree drops: x^2 - 4
            [1e-14, 1.0, -3.0, 2.0],  # negligible leading term: ~(x-1)(x-2)
            [0.0, 0.0, 2.0, -1.0],  # linear
            [1.0, 0.0, 1.0, 0.0],  # x (x^2 + 1): one real root
        ]
    )
    roots, real = real_roots(coeffs)
    found = [np.sort(r[ok]) for r, ok in zip(roots, real, strict=True)]
    np.testing.assert_allclose(found[0], [1, 2, 3], rtol=1e-14)
    np.testing.assert_allclose(found[1], [-2, 2], rtol=1e-14)
    np.testing.assert_allclose(found[2], [1, 2], rtol=1e-12)
    np.testing.assert_allclose(found[3], [0.5], rtol=1e-14)
    np.testing.assert_allclose(found[4], [0.0], atol=1e-15)


def test_argmin_candidates_skips_disallowed_and_infinite():
    cands = np.array([[0.0, 1.0, 2.0], [0.0, 1.0, 2.0]])
    allowed = np.array([[True, True, False], [True, True, True]])

    def size(x):
        return np.where(x == 1.0, np.inf, (x - 1.8) ** 2)

    np.testing.assert_array_equal(argmin_candidates(cands, allowed, size), [0.0, 2.0])
