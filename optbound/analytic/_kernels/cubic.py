"""Compiled real roots of a polynomial of degree <= 3, for the criteria of [HS96].

The closed-form criteria reduce to "the root of a cubic that minimizes a size measure"; the
kernels take every real root as a candidate, together with safe fixed candidates (lambda = 0,
the trace-optimal kappa), and keep the one with the smallest size, so the choice is never worse
than any candidate. Which family member is chosen does not affect the guarantee (every member
is an outer bound and is inflated by its own certified margin): the roots only need to be good
enough to pick the right member.

Method: the coefficients are scaled to a largest magnitude of 1 and leading coefficients below
``LEAD_RTOL`` are dropped (the polynomial is treated as one degree lower); the roots of what is
left come in closed form (stable quadratic formula; trigonometric or Cardano form of the cubic,
Numerical Recipes, 3rd ed., Sect. 5.6) and are polished by Newton's method on the *full*
polynomial, each step kept only while it reduces ``|p|``. A complex pair whose imaginary part
is below ``IMAG_RTOL`` relative counts as one real candidate (a double root in rounding).
"""

from __future__ import annotations

import numpy as np

from optbound._core.jit import njit

# Leading coefficients below this (relative to the largest one) are dropped.
LEAD_RTOL = 1e-10
# A complex pair with |imag| <= IMAG_RTOL (1 + |real|) is a (rounded) double real root.
IMAG_RTOL = 1e-6
POLISH_STEPS = 8


@njit(cache=True, error_model="numpy")
def _horner(c0, c1, c2, c3, x):
    """p(x) and p'(x) of c0 x^3 + c1 x^2 + c2 x + c3."""
    return ((c0 * x + c1) * x + c2) * x + c3, (3.0 * c0 * x + 2.0 * c1) * x + c2


@njit(cache=True, error_model="numpy")
def _quadratic(a, b, c):
    """(k, x1, x2): the k real roots of a x^2 + b x + c (a != 0)."""
    disc = b * b - 4.0 * a * c
    if disc >= 0.0:
        q = -0.5 * (b + np.copysign(np.sqrt(disc), b))
        if q == 0.0:  # b = 0 and c = 0: double root at 0
            return 1, 0.0, 0.0
        return 2, q / a, c / q
    re = -b / (2.0 * a)
    if np.sqrt(-disc) / (2.0 * abs(a)) <= IMAG_RTOL * (1.0 + abs(re)):
        return 1, re, 0.0
    return 0, 0.0, 0.0


@njit(cache=True, error_model="numpy")
def _cubic(a, b, c):
    """(k, x1, x2, x3): the k real roots of x^3 + a x^2 + b x + c
    (Numerical Recipes, eqs. (5.6.10)-(5.6.18))."""
    q = (a * a - 3.0 * b) / 9.0
    r = (2.0 * a * a * a - 9.0 * a * b + 27.0 * c) / 54.0
    if r * r < q * q * q:  # three distinct real roots
        theta = np.arccos(min(max(r / np.sqrt(q * q * q), -1.0), 1.0))
        s = -2.0 * np.sqrt(q)
        third = 2.0 * np.pi / 3.0
        return (
            3,
            s * np.cos(theta / 3.0) - a / 3.0,
            s * np.cos(theta / 3.0 + third) - a / 3.0,
            s * np.cos(theta / 3.0 - third) - a / 3.0,
        )
    big = -np.copysign(np.cbrt(abs(r) + np.sqrt(r * r - q * q * q)), r)
    small = q / big if big != 0.0 else 0.0
    x1 = big + small - a / 3.0
    re = -0.5 * (big + small) - a / 3.0
    if 0.5 * np.sqrt(3.0) * abs(big - small) <= IMAG_RTOL * (1.0 + abs(re)):
        return 2, x1, re, 0.0
    return 1, x1, 0.0, 0.0


@njit(cache=True, error_model="numpy")
def _polish(c0, c1, c2, c3, x):
    """Newton on the full polynomial, each step kept only while it reduces |p|."""
    value, slope = _horner(c0, c1, c2, c3, x)
    for _ in range(POLISH_STEPS):
        if slope == 0.0 or value == 0.0:
            break
        trial = x - value / slope
        t_value, t_slope = _horner(c0, c1, c2, c3, trial)
        if not (np.isfinite(trial) and abs(t_value) < abs(value)):
            break
        x, value, slope = trial, t_value, t_slope
    return x


@njit(cache=True, error_model="numpy")
def real_roots(p0, p1, p2, p3):
    """The real roots of ``p0 x^3 + p1 x^2 + p2 x + p3`` as ``(k, x1, x2, x3)``: the first k
    entries are roots (k = 0 if every coefficient is negligible or one is not finite)."""
    scale = max(abs(p0), abs(p1), abs(p2), abs(p3))
    if not (scale > 0.0 and np.isfinite(scale)):
        return 0, 0.0, 0.0, 0.0
    c0, c1, c2, c3 = p0 / scale, p1 / scale, p2 / scale, p3 / scale
    x3 = 0.0
    if abs(c0) > LEAD_RTOL:
        k, x1, x2, x3 = _cubic(c1 / c0, c2 / c0, c3 / c0)
    elif abs(c1) > LEAD_RTOL:
        k, x1, x2 = _quadratic(c1, c2, c3)
    elif abs(c2) > LEAD_RTOL:
        k, x1, x2 = 1, -c3 / c2, 0.0
    else:
        return 0, 0.0, 0.0, 0.0
    return (
        k,
        _polish(c0, c1, c2, c3, x1) if k > 0 else 0.0,
        _polish(c0, c1, c2, c3, x2) if k > 1 else 0.0,
        _polish(c0, c1, c2, c3, x3) if k > 2 else 0.0,
    )
