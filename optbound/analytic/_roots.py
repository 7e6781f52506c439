"""Vectorized real roots of low-degree polynomials and the choice of the best stationary point.

The closed-form criteria of [HS96] reduce to "the root of a quadratic or cubic that minimizes a
size measure". Instead of trusting a root-selection rule in every edge case, all real roots are
taken as candidates and the one with the smallest size wins (together with fixed safe candidates
such as lambda = 0), so the answer is never worse than any candidate.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numba import njit

# Leading coefficients below this (relative to the largest one) are dropped: the polynomial is
# treated as one degree lower, and Newton polishing on the full polynomial restores precision.
LEAD_RTOL = 1e-10
# Eigenvalues of the companion matrix with a relative imaginary part below this count as real;
# double roots come out with imaginary parts of order sqrt(eps). A spurious candidate is harmless.
IMAG_RTOL = 1e-6
POLISH_STEPS = 4


@njit(cache=True)
def _horner(c: np.ndarray, x: float) -> float:
    """One polynomial (highest degree first) at ``x``, Horner's scheme from 0."""
    out = 0.0
    for cj in c:
        out = out * x + cj
    return out


@njit(cache=True)
def _polish(c: np.ndarray, dc: np.ndarray, roots: np.ndarray) -> np.ndarray:
    """Newton polishing of every root on its row's polynomial; a step is kept only if it is
    finite and reduces |p|. Compiled: the tracker calls this once per update on one row, where
    the array version was dominated by the overhead of ~50 tiny numpy operations."""
    out = roots.copy()
    for i in range(out.shape[0]):
        for r in range(out.shape[1]):
            x = out[i, r]
            for _ in range(POLISH_STEPS):
                value = _horner(c[i], x)
                slope = _horner(dc[i], x)
                trial = x - value / slope if slope != 0.0 else x
                if np.isfinite(trial) and abs(_horner(c[i], trial)) < abs(value):
                    x = trial
            out[i, r] = x
    return out


def real_roots(coeffs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Real roots of each row polynomial.

    Parameters
    ----------
    coeffs : ndarray, shape (B, d+1)
        Coefficients, highest degree first.

    Returns
    -------
    roots : ndarray, shape (B, d)
        Real parts of the roots (entries beyond the effective degree are 0).
    real : ndarray of bool, shape (B, d)
        Which entries are (numerically) real roots.
    """
    coeffs = np.asarray(coeffs, dtype=float)
    n_rows, d = coeffs.shape[0], coeffs.shape[1] - 1
    scale = np.max(np.abs(coeffs), axis=1, keepdims=True)
    c = coeffs / np.where(scale > 0, scale, 1.0)
    negligible = np.abs(c) <= LEAD_RTOL
    n_lead = np.argmin(negligible, axis=1)  # index of the first significant coefficient
    degree = np.where(negligible.all(axis=1), 0, d - n_lead)

    roots = np.zeros((n_rows, d))
    real = np.zeros((n_rows, d), dtype=bool)
    for k in range(1, d + 1):  # loop over degrees, never over rows
        rows = np.flatnonzero(degree == k)
        if rows.size == 0:
            continue
        p = c[rows, d - k :]
        companion = np.zeros((rows.size, k, k))
        companion[:, 0, :] = -p[:, 1:] / p[:, :1]
        companion[:, np.arange(1, k), np.arange(k - 1)] = 1.0
        z = np.linalg.eigvals(companion)
        roots[rows, :k] = z.real
        real[rows, :k] = np.abs(z.imag) <= IMAG_RTOL * (1.0 + np.abs(z.real))

    # Newton polishing on the full polynomial.
    dc = c[:, :-1] * np.arange(d, 0, -1)
    roots = _polish(c, np.ascontiguousarray(dc), roots)
    return roots, real


def argmin_candidates(
    candidates: np.ndarray, allowed: np.ndarray, size: Callable[[np.ndarray], np.ndarray]
) -> np.ndarray:
    """Per row, the allowed candidate with the smallest ``size`` (B, k) -> (B,).

    ``size`` maps a (B, k) array of candidates to sizes; it may return +inf for infeasible
    candidates. Every row must have at least one allowed candidate with a finite size.
    """
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        values = np.where(allowed, size(np.where(allowed, candidates, 0.0)), np.inf)
    values = np.where(np.isnan(values), np.inf, values)
    best = np.argmin(values, axis=1)
    return candidates[np.arange(candidates.shape[0]), best]
