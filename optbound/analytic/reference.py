"""The analytic updates' formulas written plainly: one instance, no certification.

These are the formulas of [HS96] as the paper states them, evaluated as written: no validation,
no error bounds, no margin. They are the oracle the tests hold the compiled kernels of
``optbound.analytic._kernels`` against, and the baseline of the speed benchmark
(``optbound/bench/analytic_reference.py`` compiles them unchanged).

**Not guaranteed**: the float result of a member is the member up to rounding, and may miss
points of the true set by a few units in the last place; use :func:`~optbound.analytic.
intersect_strip` and :func:`~optbound.analytic.minkowski_sum` for guaranteed bounds.

Written in explicit loops over plain arrays with preallocated outputs, so that the same code
runs three ways: in Python on floats, in Python on ``fractions.Fraction`` objects (object
arrays: :func:`strip_member` and :func:`minkowski_member` use only + - * /, so they give the
member *exactly*), and compiled by numba (no allocation per call).
"""

from __future__ import annotations

import math

import numpy as np

from optbound.analytic.strip_fusion import MIN_REL_WIDTH  # the update's floor of the width

__all__ = [
    "intersect_strip_volume",
    "minkowski_member",
    "minkowski_p_volume",
    "strip_lam_volume",
    "strip_member",
]


def strip_member(c, C, a, eps, half, lam, out_c, out_C, w) -> None:
    """Write the member lambda of E ∩ S [HS96, eq. (24)] into ``out_c`` and ``out_C``.

    The strip ``|a^T (x - c) - eps| <= half`` is normalized to ``|a'^T (x - c) - e| <= 1``
    (``a' = a / half``, ``e = eps / half``). With ``w = C a'``, ``G = a'^T C a'`` and
    ``u = 1 + lambda G``::

        centre = c + (lambda e / u) w,
        shape  = K (C - (lambda / u) w w^T),   K = 1 + lambda - lambda e^2 / u,

    the ellipsoid ``{x : (x - c)^T C^{-1} (x - c) + lambda ((a'^T (x - c) - e)^2 - 1) <= 1}``,
    which contains E ∩ S for every lambda >= 0 [HS96, eq. (25)].

    Parameters
    ----------
    c : array, shape (n,)
        Centre of E (floats or Fractions).
    C : array, shape (n, n)
        Shape of E.
    a : array, shape (n,)
        Normal of the strip.
    eps : float or Fraction
        Offset of the strip from ``a^T c``.
    half : float or Fraction
        Half-width of the strip, positive.
    lam : float or Fraction
        The member's lambda >= 0.
    out_c : np.ndarray, shape (n,)
        Output: the member's centre.
    out_C : np.ndarray, shape (n, n)
        Output: the member's shape.
    w : np.ndarray, shape (n,)
        Scratch.

    References
    ----------
    .. [HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
       on an angle measurement technique", IFAC, 1996.
    """
    n = len(c)
    e = eps / half
    G = 0 * e  # zero of the inputs' number type (float or Fraction)
    for i in range(n):
        s = 0 * e
        for j in range(n):
            s += C[i, j] * a[j]
        w[i] = s / half
        G += a[i] / half * w[i]
    u = 1 + lam * G
    K = 1 + lam - lam * e * e / u
    for i in range(n):
        out_c[i] = c[i] + lam * e / u * w[i]
        for j in range(n):
            out_C[i, j] = K * (C[i, j] - lam / u * w[i] * w[j])


def strip_lam_volume(G: float, eps: float, n: int) -> float:
    """The volume-optimal lambda for the strip ``|a^T (x - c) - eps| <= 1``.

    With ``G = a^T C a``, the positive root of [HS96, eq. (26)] with N = n::

        (n - 1) G^2 lambda^2 + (2n - 1 + eps^2 - G) G lambda + n (1 - eps^2) - G = 0,

    or 0 when it has none (then no member is smaller than E itself: G <= n (1 - eps^2)).

    Parameters
    ----------
    G : float
        ``a^T C a`` for the normalized strip.
    eps : float
        Offset of the normalized strip.
    n : int
        Dimension.

    Returns
    -------
    float
        The lambda (0 when E itself is the smallest member).
    """
    qa = (n - 1) * G * G
    qb = (2 * n - 1 + eps * eps - G) * G
    qc = n * (1 - eps * eps) - G
    if qc >= 0:
        return 0.0
    if qa == 0:
        return -qc / qb
    return (-qb + math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)


def intersect_strip_volume(c, C, a, b, out_c, out_C, w) -> float:
    """``E ∩ {x : |a^T x - b| <= 1}``, volume criterion, with the strip clipped to E's extent
    ``[a^T c - g, a^T c + g]`` along a (g = sqrt(a^T C a)) and floored at MIN_REL_WIDTH g, as
    ``intersect_strip(E, S, "volume")`` does; returns lambda (0: the member is E itself).

    The clipped strip is ``|a^T (x - c) - mid| <= half``, normalized to a half-width of 1 for
    :func:`strip_lam_volume` (``G / half^2``, ``mid / half``) and :func:`strip_member`.
    Outputs and scratch as in :func:`strip_member`. Inconsistent instances (S misses E) are
    not detected here (lo > hi then).

    Parameters
    ----------
    c : np.ndarray, shape (n,)
        Centre of E.
    C : np.ndarray, shape (n, n)
        Shape of E.
    a : np.ndarray, shape (n,)
        Normal of the strip.
    b : float
        Offset of the strip.
    out_c : np.ndarray, shape (n,)
        Output: the member's centre.
    out_C : np.ndarray, shape (n, n)
        Output: the member's shape.
    w : np.ndarray, shape (n,)
        Scratch.

    Returns
    -------
    float
        The lambda used (0: the member is E itself).
    """
    n = len(c)
    G = 0.0
    ac = 0.0
    for i in range(n):
        for j in range(n):
            G += a[i] * C[i, j] * a[j]
        ac += a[i] * c[i]
    g = math.sqrt(G)
    lo = max(b - ac - 1, -g)
    hi = min(b - ac + 1, g)
    half = max((hi - lo) / 2, MIN_REL_WIDTH * g)
    mid = (lo + hi) / 2
    lam = strip_lam_volume(G / (half * half), mid / half, n)
    strip_member(c, C, a, mid, half, lam, out_c, out_C, w)
    return lam


def minkowski_member(c1, C1, c2, C2, p, out_c, out_C) -> None:
    """The Schweppe member of E1 + E2 for p = (1 - kappa) / kappa [HS96, eq. (14)]: centre
    ``c1 + c2``, shape ``C1 / (1 - kappa) + C2 / kappa = (1 + p) (C1 / p + C2)``; it
    contains E1 + E2 for every p > 0.

    Parameters
    ----------
    c1 : array, shape (n,)
        Centre of E1 (floats or Fractions).
    C1 : array, shape (n, n)
        Shape of E1.
    c2 : array, shape (n,)
        Centre of E2.
    C2 : array, shape (n, n)
        Shape of E2.
    p : float or Fraction
        The parameter ``(1 - kappa) / kappa > 0``.
    out_c : np.ndarray, shape (n,)
        Output: the member's centre.
    out_C : np.ndarray, shape (n, n)
        Output: the member's shape.
    """
    n = len(c1)
    for i in range(n):
        out_c[i] = c1[i] + c2[i]
        for j in range(n):
            out_C[i, j] = (1 + p) * (C1[i, j] / p + C2[i, j])


def minkowski_p_volume(C1, C2) -> float:
    """The parameter p of the minimum-volume Schweppe member.

    It is the root of ``h(p) = sum_i p (p + 1) / (l_i + p) - n`` (l_i the generalized eigenvalues of
    ``C1 v = l C2 v``), which is increasing in p and changes sign on
    ``[sqrt(min l), sqrt(max l)]`` (Durieu, Walter & Polyak 2001); found by bisection to the
    resolution of floats.

    Parameters
    ----------
    C1 : np.ndarray, shape (n, n)
        Shape of E1 (SPD).
    C2 : np.ndarray, shape (n, n)
        Shape of E2 (SPD).

    Returns
    -------
    float
        The minimizing p.
    """
    n = C1.shape[0]
    L = np.linalg.cholesky(C2)  # the l_i: eigenvalues of L^{-1} C1 L^{-T}, symmetric
    lam = np.linalg.eigvalsh(np.linalg.solve(L, np.linalg.solve(L, C1).T))
    lo, hi = math.sqrt(lam[0]), math.sqrt(lam[-1])
    while True:
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            return mid
        if np.sum(mid * (mid + 1) / (lam + mid)) - n < 0:
            lo = mid
        else:
            hi = mid
