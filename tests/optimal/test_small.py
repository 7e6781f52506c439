"""``optbound.optimal._small``: the compiled extreme eigenvalues are numpy's ``eigvalsh``
(to rounding: numba may call another LAPACK build)."""

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from optbound.optimal._small import max_eig, min_eig, min_eigs


@given(st.integers(0, 10_000), st.integers(1, 7))
def test_extreme_eigenvalues_are_numpys(seed, m):
    rng = np.random.default_rng(seed)
    A = rng.standard_normal((3, m + 1, m + 1))
    A = A + A.transpose(0, 2, 1)
    close = {"rtol": 0, "atol": 1e-13 * np.max(np.abs(A))}
    np.testing.assert_allclose(max_eig(A[0]), np.linalg.eigvalsh(A[0])[-1], **close)
    np.testing.assert_allclose(min_eig(A[1]), np.linalg.eigvalsh(A[1])[0], **close)
    parts = A[:, :-1, :-1]  # a non-contiguous stack, as ``intersection`` passes
    np.testing.assert_allclose(min_eigs(parts), np.linalg.eigvalsh(parts)[:, 0], **close)


def test_only_the_lower_triangle_is_read_as_by_numpy():
    A = np.array([[1.0, 5.0], [0.0, 2.0]])
    assert max_eig(A) == 2.0 and min_eig(A) == 1.0
