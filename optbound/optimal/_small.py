"""Extreme eigenvalues of the small symmetric matrices of one SDP call, compiled.

numpy's ``eigvalsh`` spends about 4 µs per call on a 4 x 4 matrix in Python-level checks, as
long as LAPACK takes; the same LAPACK routine through numba takes about 1 µs in all. A cached
SDP call needs four of them (``intersection``, ``emptiness``, ``certify``), so on small problems
this is a few per cent of Clarabel's own time (``benchmarks/sdp_cache.py``).
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True)
def max_eig(A: np.ndarray) -> float:
    """Largest eigenvalue of the symmetric matrix A (its lower triangle is read)."""
    return np.linalg.eigvalsh(np.ascontiguousarray(A))[-1]


@njit(cache=True)
def min_eig(A: np.ndarray) -> float:
    """Smallest eigenvalue of the symmetric matrix A (its lower triangle is read)."""
    return np.linalg.eigvalsh(np.ascontiguousarray(A))[0]


@njit(cache=True)
def min_eigs(stack: np.ndarray) -> np.ndarray:
    """Smallest eigenvalue of each symmetric matrix of a stack (k, m, m)."""
    out = np.empty(stack.shape[0])
    for i in range(stack.shape[0]):
        out[i] = np.linalg.eigvalsh(np.ascontiguousarray(stack[i]))[0]
    return out
