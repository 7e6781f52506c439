"""Size measures with a certified bracket: ``size_bracket(S) -> (lo, hi)``, ``lo <= vol S <= hi``.

The n-dimensional volume (area in 2-D) of any set, read as the exact set its floats describe:

- ``Box``: the product of the widths, with the rounding of the n subtractions and n - 1
  products bounded and rounded outward;
- ``Ellipsoid``: ``vol(unit ball) sqrt(det C)`` with ``det C`` computed exactly (rational
  elimination) and ``pi``, the square root and the unit-ball constant in mpmath interval
  arithmetic, so the bracket is a few ulps wide;
- ``PseudoEllipsoid``: its paving's ``volume_bounds`` [BH, eq. (10)];
- ``Paving``: ``(vol inner, vol inner + vol boundary)`` [LJMW97, eq. (11)], rounded outward;
- any object with ``volume_bounds(eps)`` (the set protocol's ``VolumeBracket``): that bracket;
- any object with ``dim`` and ``tri_contains(boxes)``: a SIVIA paving of its indicator over
  ``domain``; if the paving reaches the border of ``domain`` the set may extend beyond it and
  the upper end is ``inf``.
"""

from __future__ import annotations

from fractions import Fraction
from math import factorial

import numpy as np

from optbound.compare._ellipsoid import bound_set
from optbound.compare.exact import determinant, fractions
from optbound.compare.tri import tri_test
from optbound.interval import Paving, pave
from optbound.interval.paving import box_volumes
from optbound.sets import Box, Ellipsoid, PseudoEllipsoid, Strip

#: Unit roundoff of float64.
_U = np.finfo(float).eps / 2
#: Paving resolution, as a fraction of the widest side of the domain, when ``eps`` is None.
DEFAULT_RELATIVE_EPS = 1.0 / 64


def size_bracket(S, *, eps: float | None = None, domain=None) -> tuple[float, float]:
    """Certified bracket ``(lo, hi)`` of the n-dimensional volume of ``S``.

    Parameters
    ----------
    S
        An optbound set (``Box``, ``Ellipsoid``, ``PseudoEllipsoid``), a ``Paving``, an object
        with ``volume_bounds(eps)`` or with ``dim`` and ``tri_contains(boxes)``; a result
        holding one of these (``BoundResult.set`` or ``.ellipsoid``) is accepted too.
    eps : float, optional
        Box width of the paving for the paving-backed types (default: ``1/64`` of the widest
        side of the domain).
    domain : Box or (n, 2) array, optional
        Where to pave a user object (required for it) or a ``PseudoEllipsoid`` (default: its
        bounding box).

    Returns
    -------
    lo, hi : float
        Bounds of the volume of ``S`` (``hi = inf`` when a paved set reaches the domain's
        border).

    Raises
    ------
    TypeError
        If ``S`` has no certified size measure (e.g. only a ``contains`` method).
    ValueError
        If a user object is given without ``domain``, or the domain's dimension differs.

    Examples
    --------
    >>> from optbound.sets import Ellipsoid
    >>> lo, hi = size_bracket(Ellipsoid(np.zeros(2), np.eye(2)))
    >>> bool(lo < hi), bool(lo <= np.pi <= hi)
    (True, True)
    """
    S = bound_set(S)
    if isinstance(S, Box):
        return box_volume_bracket(S)
    if isinstance(S, Ellipsoid):
        return ellipsoid_volume_bracket(S)
    if isinstance(S, Paving):
        return paving_volume_bracket(S)
    if isinstance(S, PseudoEllipsoid):
        box = S.bounding_box() if domain is None else _domain_box(domain, S.dim)
        return paving_volume_bracket(S.paving(_eps(eps, box), box))
    if callable(getattr(S, "volume_bounds", None)):  # the protocol's VolumeBracket
        if eps is None:
            if domain is None:
                raise ValueError(f"eps or domain is required for {type(S).__name__}.volume_bounds")
            eps = _eps(None, _domain_box(domain, S.dim))
        return _checked(S.volume_bounds(eps))
    if callable(getattr(S, "tri_contains", None)) and isinstance(getattr(S, "dim", None), int):
        if domain is None:
            raise ValueError("domain is required to pave a set given by tri_contains")
        box = _domain_box(domain, S.dim)
        paving = pave(tri_test(S), box, _eps(eps, box))
        lo, hi = paving_volume_bracket(paving)
        return lo, (hi if _inside_border(paving, box) else np.inf)
    raise TypeError(
        f"no certified size measure for {type(S).__name__}: expected an optbound set, a Paving, "
        "or an object with dim and tri_contains(boxes)"
    )


def _outward(value: float, rel: float) -> tuple[float, float]:
    """``[value (1 - rel), value (1 + rel)]`` rounded outward (value >= 0)."""
    return (
        float(np.nextafter(value * (1.0 - rel), 0.0)),
        float(np.nextafter(value * (1.0 + rel), np.inf)),
    )


def box_volume_bracket(B: Box) -> tuple[float, float]:
    """Volume of a box: ``n`` rounded subtractions and ``n - 1`` rounded products, each with
    relative error at most ``u``, so the float product is within ``(1 + u)^(2n) - 1`` of it."""
    if not B.is_bounded:
        return np.inf, np.inf
    n = B.dim
    return _outward(float(np.prod(B.widths)), 4 * n * _U)


def paving_volume_bracket(P: Paving) -> tuple[float, float]:
    """``volume_bounds`` of a paving with the rounding of the sums and products bounded.

    Each box volume carries ``2n`` roundings, a sum of m non-negative terms at most ``m - 1``
    more, so ``(2n + m) u`` (doubled for the second-order terms) bounds the relative error.
    """
    n = P.dim
    v_in = box_volumes(P.inner)
    v_bd = box_volumes(P.boundary)
    lo = _outward(float(v_in.sum()), 2 * (2 * n + v_in.size) * _U)[0]
    total = float(v_in.sum() + v_bd.sum())
    hi = _outward(total, 2 * (2 * n + v_in.size + v_bd.size) * _U)[1]
    return max(lo, 0.0), hi


def ellipsoid_volume_bracket(E: Ellipsoid) -> tuple[float, float]:
    """``vol(B_n) sqrt(det C)`` with ``det C`` exact and the rest in mpmath interval arithmetic."""
    return _floats(_ball_volume(E.dim) * _iv_sqrt(determinant(fractions(E.shape))))


def ellipsoid_strip_volume_bracket(E: Ellipsoid, S: Strip) -> tuple[float, float]:
    """Certified volume bracket of ``E ∩ S`` (closed form, no paving).

    With ``x = c + L y`` the ellipsoid is the unit ball and the strip the slab
    ``u_lo <= w^T y <= u_hi`` (``w`` a unit vector, ``u = (a^T x - a^T c) / sqrt(a^T C a)``).
    Slicing the ball across ``w`` gives (n-1)-balls of radius ``sqrt(1 - u^2)``, so

        vol(E ∩ S) = sqrt(det C) vol(B_{n-1}) [I_{n-1}(u_hi) - I_{n-1}(u_lo)],

    ``I_m`` an antiderivative of ``(1 - u^2)^(m/2)`` (``u`` clipped to [-1, 1]), by the recursion
    ``I_m(u) = u (1 - u^2)^(m/2) / (m + 1) + m / (m + 1) I_{m-2}(u)``, ``I_0 = u``,
    ``I_{-1} = asin u``. ``a^T C a``, ``a^T c`` and ``det C`` are exact rationals; the rest is
    mpmath interval arithmetic, and ``I_m`` is increasing, so evaluating it on the interval
    enclosures of ``u_lo`` and ``u_hi`` bounds the difference.
    """
    from mpmath import iv

    if E.dim == 1:
        raise ValueError("ellipsoid_strip_volume_bracket needs dimension >= 2")
    a, c = fractions(S.a), fractions(E.center)
    C = fractions(E.shape)
    n = E.dim
    aCa = sum(a[i] * C[i][j] * a[j] for i in range(n) for j in range(n))
    ac = sum(ai * ci for ai, ci in zip(a, c, strict=True))
    h = _iv_sqrt(aCa)
    b = Fraction(S.b)
    u_lo, u_hi = (_iv_rational(b - 1 - ac) / h), (_iv_rational(b + 1 - ac) / h)
    upper, lower = _antiderivative(n - 1, u_hi), _antiderivative(n - 1, u_lo)
    width = iv.mpf([max(upper.a - lower.b, 0), max(upper.b - lower.a, 0)])
    return _floats(_iv_sqrt(determinant(C)) * _ball_volume(n - 1) * width)


def _antiderivative(m: int, u):
    """An enclosure of ``I_m`` (see :func:`ellipsoid_strip_volume_bracket`) over the interval
    ``u`` clipped to [-1, 1]."""
    from mpmath import iv

    u = iv.mpf([min(max(u.a, -1), 1), min(max(u.b, -1), 1)])
    rest = 1 - u * u
    rest = iv.mpf([max(rest.a, 0), max(rest.b, 0)])
    root = iv.sqrt(rest)
    value = u if m % 2 == 0 else iv.atan2(u, root)  # I_0 = u, I_{-1} = asin u
    power = iv.mpf(1) if m % 2 == 0 else root  # (1 - u^2)^(j/2), j = m % 2 (+2 per step)
    for j in range(2 - m % 2, m + 1, 2):
        power = power * rest
        value = u * power / (j + 1) + iv.mpf(j) / (j + 1) * value
    return value


def _ball_volume(n: int):
    """``vol(B_n)`` as an mpmath interval: ``pi^k / k!`` (n = 2k), ``2^n pi^k k! / n!`` (2k+1)."""
    from mpmath import iv

    k = n // 2
    ball = Fraction(1, factorial(k)) if n % 2 == 0 else Fraction(2**n * factorial(k), factorial(n))
    return iv.pi**k * _iv_rational(ball)


def _iv_rational(q: Fraction):
    from mpmath import iv

    return iv.mpf(q.numerator) / iv.mpf(q.denominator)


def _iv_sqrt(q: Fraction):
    from mpmath import iv

    return iv.sqrt(_iv_rational(q))


def _floats(value) -> tuple[float, float]:
    """An mpmath interval as floats; float() rounds to nearest, so one step outward each end."""
    return (
        max(float(np.nextafter(float(value.a), -np.inf)), 0.0),
        float(np.nextafter(float(value.b), np.inf)),
    )


def _domain_box(domain, dim: int) -> Box:
    box = domain if isinstance(domain, Box) else Box.from_array(domain)
    if box.dim != dim:
        raise ValueError(f"domain has dimension {box.dim}, the set has {dim}")
    if not box.is_bounded:
        raise ValueError(f"domain must be bounded, got {box}")
    return box


def _checked(bracket) -> tuple[float, float]:
    """A user type's ``(lower, upper)``, checked to be two ordered non-negative numbers."""
    try:
        lo, hi = (float(v) for v in bracket)
    except (TypeError, ValueError):
        raise ValueError(f"volume_bounds must return (lower, upper), got {bracket!r}") from None
    if not 0.0 <= lo <= hi:
        raise ValueError(f"volume_bounds must return 0 <= lower <= upper, got ({lo}, {hi})")
    return lo, hi


def _eps(eps: float | None, box: Box) -> float:
    return float(np.max(box.widths)) * DEFAULT_RELATIVE_EPS if eps is None else eps


def _inside_border(P: Paving, box: Box) -> bool:
    """Whether no inner or boundary box touches the border of ``box``."""
    outer = P.outer()
    if outer.shape[0] == 0:
        return True
    return bool(np.all(outer[:, :, 0] > box.lo) and np.all(outer[:, :, 1] < box.hi))


__all__ = ["size_bracket"]
