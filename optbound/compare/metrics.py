"""Size ratios between two bounds of one set (``A`` relative to ``B``; > 1 means A is larger).

Volumes are compared through log volumes, so the ratio stays accurate for very small or very
large ellipsoids in high dimension. ``volume_ratio`` and ``log_volume_ratio`` take any pair of
sets with a size measure (:func:`~optbound.compare.size.size_bracket`): closed forms for
ellipsoids and boxes, the midpoint of the certified bracket for paving-backed sets;
``volume_ratio_bracket`` is the certified bracket itself.
"""

from __future__ import annotations

from collections.abc import Sequence
from math import exp, log

import numpy as np

from optbound.compare._ellipsoid import as_ellipsoid, bound_set, same_dim
from optbound.compare.size import size_bracket
from optbound.sets import Box, Ellipsoid


def _sized(name: str, S, **paving):
    """``S`` (or its ``.ellipsoid``) and its certified volume bracket."""
    S = bound_set(S)
    try:
        return S, size_bracket(S, **paving)
    except TypeError as err:
        raise ValueError(f"{name} must be a set with a size measure: {err}") from None


def _dims_agree(A, B) -> None:
    if A.dim != B.dim:
        raise ValueError(f"the two bounds have different dimensions, {A.dim} and {B.dim}")


def log_volume_ratio(A, B, *, eps: float | None = None, domain=None) -> float:
    """Compute ``log(vol A / vol B)``.

    Exact formula for ellipsoids and boxes, else the midpoint (in log) of
    :func:`volume_ratio_bracket` (``eps``, ``domain``: its paving's parameters).

    Parameters
    ----------
    A, B : set or result
        The two bounds (``Ellipsoid``, ``Box``, ``PseudoEllipsoid``, ``Paving``, ...; see
        :func:`~optbound.compare.size.size_bracket`), or results holding one.
    eps : float, optional
        Box width of the paving of a paving-backed set.
    domain : Box or (n, 2) array, optional
        Where to pave a user set.

    Returns
    -------
    float
        The log volume ratio; > 0 when ``A`` is larger.

    Raises
    ------
    ValueError
        If either set has no size measure or the dimensions differ.
    """
    A, B = bound_set(A), bound_set(B)
    closed = (Ellipsoid, Box)
    if isinstance(A, closed) and isinstance(B, closed):
        _dims_agree(A, B)
        return A.log_volume() - B.log_volume()
    lo, hi = volume_ratio_bracket(A, B, eps=eps, domain=domain)
    return 0.5 * (log(lo) + log(hi))


def volume_ratio(A, B, *, eps: float | None = None, domain=None) -> float:
    """Compute ``vol A / vol B`` (see :func:`log_volume_ratio`).

    Parameters
    ----------
    A, B : set or result
        The two bounds (``Ellipsoid``, ``Box``, ``PseudoEllipsoid``, ``Paving``, ...; see
        :func:`~optbound.compare.size.size_bracket`), or results holding one.
    eps : float, optional
        Box width of the paving of a paving-backed set.
    domain : Box or (n, 2) array, optional
        Where to pave a user set.

    Returns
    -------
    float
        The volume ratio; > 1 when ``A`` is larger.

    Raises
    ------
    ValueError
        If either set has no size measure or the dimensions differ.

    Examples
    --------
    >>> from optbound.sets import Ellipsoid
    >>> unit = Ellipsoid(np.zeros(2), np.eye(2))
    >>> twice = Ellipsoid(np.zeros(2), 4 * np.eye(2))
    >>> round(volume_ratio(twice, unit), 12)
    4.0
    """
    return exp(log_volume_ratio(A, B, eps=eps, domain=domain))


def volume_ratio_bracket(A, B, *, eps: float | None = None, domain=None) -> tuple[float, float]:
    """Certified bracket ``[vol_lo A / vol_hi B, vol_hi A / vol_lo B]`` of ``vol A / vol B``.

    Parameters
    ----------
    A, B : set or result
        The two bounds (``Ellipsoid``, ``Box``, ``PseudoEllipsoid``, ``Paving``, ...; see
        :func:`~optbound.compare.size.size_bracket`), or results holding one.
    eps : float, optional
        Box width of the paving of a paving-backed set.
    domain : Box or (n, 2) array, optional
        Where to pave a user set.

    Returns
    -------
    lo, hi : float
        Bounds of the volume ratio, rounded outward.

    Raises
    ------
    ValueError
        If either set has no size measure or the dimensions differ.
    """
    A, (a_lo, a_hi) = _sized("A", A, eps=eps, domain=domain)
    B, (b_lo, b_hi) = _sized("B", B, eps=eps, domain=domain)
    _dims_agree(A, B)
    return ratio_bracket((a_lo, a_hi), (b_lo, b_hi))


def ratio_bracket(num: tuple[float, float], den: tuple[float, float]) -> tuple[float, float]:
    """Bracket a ratio by ``[num_lo / den_hi, num_hi / den_lo]``, rounded outward.

    Parameters
    ----------
    num, den : tuple of float
        Brackets ``(lo, hi)`` of the numerator and the denominator, both >= 0.

    Returns
    -------
    lo, hi : float
        Bounds of the ratio (``hi = inf`` for a zero denominator).
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        lo = num[0] / den[1] if den[1] > 0 else 0.0
        hi = num[1] / den[0] if den[0] > 0 else np.inf
    return float(np.nextafter(lo, 0.0)), float(np.nextafter(hi, np.inf))


def trace_ratio(A, B) -> float:
    """Compute ``tr C_A / tr C_B`` (sum of squared semi-axes, the HS96 trace criterion).

    Parameters
    ----------
    A, B : Ellipsoid or result
        Ellipsoids of one dimension, or results holding one (``.ellipsoid``).

    Returns
    -------
    float
        The trace ratio.

    Raises
    ------
    ValueError
        If an argument is not an ellipsoid or the dimensions differ.

    Notes
    -----
    The trace of the shape matrix is one of Schweppe's size criteria discussed in [HS96,
    eqs. (14)-(17)].

    References
    ----------
    .. [HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
       on an angle measurement technique", IFAC, 1996.
    """
    A, B = as_ellipsoid("A", A), as_ellipsoid("B", B)
    same_dim(A, B)
    return float(np.trace(A.shape) / np.trace(B.shape))


def projection_volume_ratio(A, B, dims: Sequence[int]) -> float:
    """Compute the volume ratio of the projections onto the coordinates ``dims`` [HS96, eq. (27)].

    Parameters
    ----------
    A, B : Ellipsoid or result
        Ellipsoids of one dimension, or results holding one (``.ellipsoid``).
    dims : sequence of int
        The coordinates projected on (e.g. ``(0, 1)`` for x, y of a pose).

    Returns
    -------
    float
        ``vol proj A / vol proj B``.

    Raises
    ------
    ValueError
        If an argument is not an ellipsoid, the dimensions differ or ``dims`` is invalid.

    Notes
    -----
    The projection of ``E(c, C)`` onto coordinates ``P`` is ``E(Pc, P C P^T)`` [HS96, eq. (27)].

    References
    ----------
    .. [HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
       on an angle measurement technique", IFAC, 1996.
    """
    A, B = as_ellipsoid("A", A), as_ellipsoid("B", B)
    same_dim(A, B)
    return volume_ratio(A.project(dims), B.project(dims))
