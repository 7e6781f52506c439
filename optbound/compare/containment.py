"""Exact containment of one ellipsoid in another (S-lemma / trust-region criterion).

Map the outer ellipsoid to the unit ball, ``y = L_o^{-1} (x - c_o)``; the inner one becomes
``{c + K u : ||u|| <= 1}``. Its largest level in the outer ellipsoid is

    rho = max_{||u|| <= 1} ||c + K u||^2,

a trust-region problem with no duality gap (S-lemma): with ``K^T K = V diag(lambda) V^T`` and
``g = V^T K^T c``,

    rho = min_{tau > lambda_max} psi(tau),
    psi(tau) = tau + c^T c + sum_i g_i^2 / (tau - lambda_i),

``psi`` convex; its minimiser solves the secular equation
``sum_i g_i^2 / (tau - lambda_i)^2 = 1``,
bracketed by ``tau - lambda_max`` in ``(0, ||g||]``. Any ``tau > lambda_max`` gives an upper
bound, so rounding errs on the side of "not contained". The inner ellipsoid is contained iff
``rho <= 1``; ``sqrt(rho)`` is the factor by which the outer ellipsoid (about its centre) must be
scaled to contain the inner one.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq

from optbound.compare._ellipsoid import as_ellipsoid, same_dim


def max_level(outer, inner) -> float:
    """Largest level ``(x - c_o)^T C_o^{-1} (x - c_o)`` over the inner ellipsoid (exact)."""
    outer, inner = as_ellipsoid("outer", outer), as_ellipsoid("inner", inner)
    same_dim(outer, inner)
    c = np.linalg.solve(outer.chol, inner.center - outer.center)
    K = np.linalg.solve(outer.chol, inner.chol)
    lam, V = np.linalg.eigh(K.T @ K)
    g = V.T @ (K.T @ c)
    top, gnorm = float(lam[-1]), float(np.linalg.norm(g))
    base = top + float(c @ c)  # psi at tau = lambda_max without the secular sum
    if gnorm == 0.0:
        return base

    def psi(t: float) -> float:
        return t + base + float(np.sum(g**2 / (t + top - lam)))

    def slope(t: float) -> float:
        return float(np.sum(g**2 / (t + top - lam) ** 2)) - 1.0

    t_min = 1e-15 * (abs(top) + gnorm)
    if slope(t_min) <= 0.0:
        return psi(t_min)  # hard case: the minimum sits at tau -> lambda_max
    return psi(brentq(slope, t_min, gnorm, xtol=1e-15 * gnorm, rtol=4 * np.finfo(float).eps))


def contains(outer, inner, tol: float = 1e-9) -> bool:
    """True if the ellipsoid ``inner`` lies in ``outer`` (max level <= 1 + tol)."""
    return max_level(outer, inner) <= 1.0 + tol
