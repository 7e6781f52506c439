"""The compiled triangular inverse behind ``Ellipsoid.chol_inv``."""

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from optbound import Ellipsoid
from optbound.sets._triangular import lower_inverse


@given(st.integers(1, 8), st.integers(0, 2**32 - 1))
def test_chol_inv_is_the_triangular_inverse(n, seed):
    """Lower triangular, and ``X L = I`` up to the rounding of forward substitution."""
    rng = np.random.default_rng(seed)
    A = rng.standard_normal((n, n))
    E = Ellipsoid(rng.standard_normal(n), A @ A.T + 0.1 * np.eye(n))
    X = E.chol_inv
    assert np.array_equal(X, np.tril(X))
    np.testing.assert_allclose(X @ E.chol, np.eye(n), atol=1e-12 * np.linalg.cond(E.chol))


def test_known_inverse_is_exact():
    L = np.array([[2.0, 0.0, 0.0], [1.0, 4.0, 0.0], [-2.0, 2.0, 0.5]])
    X = lower_inverse(L)
    assert np.array_equal(X @ L, np.eye(3))  # every product and sum here is exact in binary
