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
    """Compute the largest level ``(x - c_o)^T C_o^{-1} (x - c_o)`` over the inner ellipsoid.

    Parameters
    ----------
    outer, inner : Ellipsoid or result
        Ellipsoids of one dimension, or results holding one (``.ellipsoid``).

    Returns
    -------
    float
        The maximum (in float64) of the outer ellipsoid's level over ``inner``; ``inner`` lies
        in ``outer`` iff it is at most 1.

    Raises
    ------
    ValueError
        If an argument is not an ellipsoid or the dimensions differ.

    Notes
    -----
    With ``L_o`` the Cholesky factor of ``C_o``, ``c = L_o^{-1}(c_i - c_o)`` and
    ``K = L_o^{-1} L_i``, the maximum of ``|c + K u|^2`` over ``|u| <= 1`` is the trust-region
    value ``min_{t > 0} t + lambda_max + |c|^2 + sum_j g_j^2 / (t + lambda_max - lambda_j)``
    over the eigenpairs of ``K^T K`` (``g = V^T K^T c``), solved by Brent's method.
    """
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
    t_max = gnorm  # slope(gnorm) <= 0 in exact arithmetic; rounding can tip it over 0
    while slope(t_max) > 0.0:
        t_max *= 2.0
    return psi(brentq(slope, t_min, t_max, xtol=1e-15 * gnorm, rtol=4 * np.finfo(float).eps))


#: Default slack of ``contains`` between two float ellipsoids (rounding of ``max_level``).
ROUNDING_TOL = 1e-9


def contains(outer, inner, tol: float | None = None) -> bool:
    """True if the ellipsoid ``inner`` lies in ``outer`` up to the relative tolerance ``tol``.

    The test is ``max_level(outer, inner) <= 1 + tol``: ``inner`` lies in ``outer`` scaled
    about its centre by ``sqrt(1 + tol)`` (about ``1 + tol / 2``). ``max_level`` is computed
    in float64 from Cholesky factors and an eigendecomposition, so for two equal ellipsoids,
    or an inner one touching the outer, it comes out at 1 up to a few ulps times the condition
    number of ``outer``'s shape; ``tol`` absorbs that. It is therefore a numerical comparison
    of two bounds (e.g. an analytic bound against an SDP optimum), not a guarantee: ``tol=0``
    asks for ``max_level <= 1`` exactly in float64, which can still be off by that rounding
    either way.

    An SDP reference is the optimum only to its solver's accuracy, in either direction: an
    analytic bound equal to the optimum neither contains nor lies inside it to 1e-9. So when
    an argument is a result that states its ``accuracy`` (``optimal.OuterResult``), the
    default tolerance is the larger of that and ``ROUNDING_TOL``.

    Parameters
    ----------
    outer, inner : Ellipsoid or result
        Ellipsoids of one dimension, or results carrying one (``.ellipsoid``).
    tol : float, optional
        Relative slack on the level, >= 0. Default: ``ROUNDING_TOL`` (1e-9), or the
        ``accuracy`` of a result argument if larger.

    Returns
    -------
    bool
        ``max_level(outer, inner) <= 1 + tol``.

    Raises
    ------
    ValueError
        If ``tol`` is negative or not finite, an argument is not an ellipsoid, or the
        dimensions differ.

    See Also
    --------
    optbound.compare.exact.ellipsoid_in_ellipsoid : the same question decided exactly.

    Examples
    --------
    >>> from optbound.sets import Ellipsoid
    >>> unit = Ellipsoid(np.zeros(2), np.eye(2))
    >>> twice = Ellipsoid(np.zeros(2), 4 * np.eye(2))
    >>> contains(twice, unit), contains(unit, twice)
    (True, False)
    """
    if tol is None:
        tol = max(ROUNDING_TOL, *(getattr(b, "accuracy", 0.0) for b in (outer, inner)))
    if not np.isfinite(tol) or tol < 0:
        raise ValueError(f"tol must be a finite number >= 0, got {tol}")
    return max_level(outer, inner) <= 1.0 + tol
