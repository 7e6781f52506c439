"""Certification of SDP answers in float64, with the smallest inflation that makes them hold.

A solver returns numbers that satisfy its constraints only up to its tolerance (~1e-8), so an
outer ellipsoid straight from the solver may miss the set by that much. Every answer is
re-checked here from the returned ellipsoid and multipliers alone:

- S-procedure answers: the certificate is a matrix inequality ``P(E) / alpha^2 <= G`` where
  ``P(E)`` is positive semidefinite and built from the ellipsoid, and ``G`` from the
  multipliers. It holds when the largest eigenvalue of ``P / alpha^2 - G`` is below ``-delta``,
  ``delta`` a bound on the floating-point error of forming and diagonalising the matrix (plus
  any error the caller made in forming the inputs, ``uncertainty``). The smallest ``alpha`` is
  a generalized eigenvalue, ``alpha^2 = lambda_max(P, G - delta I)`` (see ``certify_lmi`` for
  the multiplier scaling that keeps ``G`` definite). Callers pass the matrices in a
  well-conditioned frame (a congruence ``T^T (.) T`` with T invertible preserves the sign of a
  matrix inequality), so that ``delta`` is small relative to every eigenvalue.
- point sets: each point's level ``(p - c)^T C^{-1} (p - c)`` must be below 1 with margin.

Scaling an ellipsoid by ``alpha`` about its centre divides ``C^{-1}`` by ``alpha^2``, which is
why ``alpha`` enters as ``1 / alpha^2``. The inflated ellipsoid is always re-checked from its own
matrices; if that fails a few times, ``CertificationError`` is raised.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from optbound.optimal._small import lmi_check, smallest_inflation, weighted_sum
from optbound.optimal.errors import CertificationError
from optbound.sets import Ellipsoid

EPS = np.finfo(float).eps
_RETRIES = 8
_BETAS = np.array([1.0, *(1.0 - 10.0**-j for j in range(14, 0, -1))])


def _smallest_inflation(
    P: np.ndarray, fixed: np.ndarray, S: np.ndarray, delta: float
) -> tuple[float, float]:
    """Smallest inflation ``alpha = sqrt(lambda_max(P, R))`` over the betas, and its beta.

    ``R = G0 + beta S - delta I`` for every beta (``_small.smallest_inflation``); betas whose
    ``R`` is not definite are skipped.
    """
    alpha, beta = smallest_inflation(P, fixed, S, delta, _BETAS)
    if not np.isfinite(alpha):
        raise CertificationError("the multipliers certify no inflation of the solver's ellipsoid")
    return float(alpha), float(beta)


def certify_lmi(
    ellipsoid: Ellipsoid,
    form: Callable[[Ellipsoid], np.ndarray],
    fixed: np.ndarray,
    weights: np.ndarray,
    matrices: np.ndarray,
    uncertainty: float = 0.0,
) -> tuple[Ellipsoid, float, float]:
    """Certify ``form(E) <= G0 + beta sum_j tau_j M_j``; inflate E by the smallest factor.

    Parameters
    ----------
    ellipsoid : Ellipsoid
        The solver's candidate.
    form : callable
        ``E -> P(E)``, positive semidefinite, proportional to ``C^{-1}``.
    fixed : ndarray
        ``G0``, the part of the right-hand side that does not carry multipliers.
    weights : ndarray, shape (k,)
        The multipliers ``tau_j >= 0``.
    matrices : ndarray, shape (k, m, m)
        The matrices ``M_j`` they multiply.
    uncertainty : float
        Bound on the spectral-norm error of the supplied ``M_j`` (weighted by ``tau_j``),
        added to the margin.

    Returns
    -------
    (Ellipsoid, float, float)
        The certified ellipsoid, the inflation ``alpha >= 1`` applied to its semi-axes, and the
        factor ``beta`` in (0, 1] by which the multipliers must be scaled for the certificate.

    Raises
    ------
    CertificationError
        If no ``beta`` makes the right-hand side positive definite with margin, or the
        inflated ellipsoid still fails the re-check.

    Notes
    -----
    At an S-procedure optimum ``G0 + S`` is typically singular exactly where ``P`` is (the
    lifted centre ``[c; 1]``), and no inflation gives a strict margin there. Scaling the
    multipliers by ``beta < 1`` restores it, so ``alpha`` is minimised over
    ``beta in {1} U {1 - 10^-j : j = 1..14}``; for each, the smallest ``alpha`` is the
    generalized eigenvalue ``lambda_max(P, G0 + beta S - delta I)``.
    """
    S, weighted = weighted_sum(np.asarray(weights, dtype=float), matrices)
    g_scale = float(np.linalg.norm(fixed)) + weighted

    P = form(ellipsoid)
    worst, delta = lmi_check(P, fixed + S, g_scale, uncertainty)
    if worst <= -delta:
        return ellipsoid, 1.0, 1.0
    alpha, beta = _smallest_inflation(P, fixed, S, delta)
    for attempt in range(_RETRIES):
        candidate = ellipsoid.scaled(alpha)
        P = form(candidate)
        worst, delta = lmi_check(P, fixed + beta * S, g_scale, uncertainty)
        if worst <= -delta:
            return candidate, alpha, beta
        alpha *= 1.0 + 1e-13 * 4.0**attempt
    raise CertificationError(f"inflation by {alpha} still fails the float64 certificate")


def certify_points(ellipsoid: Ellipsoid, X: np.ndarray) -> tuple[Ellipsoid, float]:
    """Certify that every row of ``X`` lies in the ellipsoid; inflate by the smallest factor.

    The level of each point carries a relative rounding error of a few ``n eps``; points must
    clear 1 by that margin.

    Parameters
    ----------
    ellipsoid : Ellipsoid
        The candidate outer ellipsoid.
    X : np.ndarray, shape (m, n)
        The points to contain.

    Returns
    -------
    ellipsoid : Ellipsoid
        ``ellipsoid`` itself or its smallest certified inflation.
    alpha : float
        The inflation factor of the semi-axes (1.0 if none was needed).

    Raises
    ------
    CertificationError
        If repeated inflation still leaves a point outside.
    """
    slack = 1.0 - 16.0 * ellipsoid.dim * EPS
    worst = float(np.max(ellipsoid.level(X)))
    if worst <= slack:
        return ellipsoid, 1.0
    alpha = float(np.sqrt(worst / slack))
    for attempt in range(_RETRIES):
        candidate = ellipsoid.scaled(alpha)
        if float(np.max(candidate.level(X))) <= slack:
            return candidate, alpha
        alpha *= 1.0 + 1e-13 * 4.0**attempt
    raise CertificationError(f"inflation by {alpha} still leaves points outside")
