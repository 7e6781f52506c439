"""Inverse of a small lower-triangular matrix, compiled.

scipy's ``solve_triangular`` goes through a multi-threaded OpenBLAS: on a busy machine even a
2x2 solve can wait for a worker thread's time slice, thousands of times its own cost. The
matrices here are the Cholesky factors of set shapes
(n <= a few dozen), for which plain forward substitution is the fast and predictable choice.
"""

from __future__ import annotations

import numpy as np

from optbound._core.jit import njit


@njit(cache=True)
def lower_inverse(L: np.ndarray) -> np.ndarray:
    """``L^{-1}`` of a lower-triangular ``L`` with a non-zero diagonal, by forward
    substitution column by column (the result is exactly lower triangular)."""
    n = L.shape[0]
    X = np.zeros((n, n))
    for j in range(n):
        X[j, j] = 1.0 / L[j, j]
        for i in range(j + 1, n):
            s = 0.0
            for k in range(j, i):
                s += L[i, k] * X[k, j]
            X[i, j] = -s / L[i, i]
    return X
