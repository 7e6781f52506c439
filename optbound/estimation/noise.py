"""Noise sets of a linear system and their certified conversions between set types.

``W`` and ``V`` may be boxes (stored as zonotopes), zonotopes or ellipsoids. Each observer
needs them in its own representation, always as an *outer* bound:

- zonotopic and interval observers: an ellipsoid becomes the parallelotope circumscribing it
  along its Cholesky axes (:meth:`Zonotope.from_ellipsoid`, certified);
- ellipsoidal observers: a zonotope becomes ``E(c, Q)`` with ``Q = (sum w_i) sum g_i g_i^T /
  w_i`` (:meth:`Zonotope.outer_ellipsoid`, certified); a *flat* zonotope (generators not
  spanning R^n, e.g. the segment W of Alamo et al. 2005, Sect. 7.1, or with a singular value
  below ``FLAT_INFLATION * s_max``) first gets one extra generator ``FLAT_INFLATION * s_max *
  u`` along each such direction u (s_max the largest singular value of G): the thin
  ellipsoid then has semi-axes of relative size about ``FLAT_INFLATION`` across the flat
  directions. Adding generators only enlarges the set, so the
  enclosure stays guaranteed; the inflation is the only deliberate loss;
- per output row, the interval ``[lo_i, hi_i]`` of ``V``'s i-th coordinate (its interval hull,
  rounded outward); for an ellipsoidal ``V`` with several outputs, treating the rows
  separately is itself an outer approximation (the box hull of V).
"""

from __future__ import annotations

import numpy as np

from optbound._core import Box
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.zonotope import Zonotope

FLAT_INFLATION = 1e-5

NoiseSet = Box | Zonotope | Ellipsoid


def as_noise(name: str, Y, dim: int) -> NoiseSet:
    """``Y`` (a bounded Box, a Zonotope or an Ellipsoid) of dimension ``dim``, checked.

    Parameters
    ----------
    name : str
        The argument's name, for the error messages (``"W"`` or ``"V"``).
    Y : Box, Zonotope or Ellipsoid
        The noise set.
    dim : int
        The dimension it must have.

    Returns
    -------
    Box, Zonotope or Ellipsoid
        ``Y`` unchanged.

    Raises
    ------
    ValueError
        If ``Y`` is an unbounded Box or has the wrong dimension.
    TypeError
        If ``Y`` is of another type.
    """
    if isinstance(Y, Box) and not Y.is_bounded:
        raise ValueError(f"{name} must be bounded")
    if not isinstance(Y, Box | Zonotope | Ellipsoid):
        raise TypeError(f"{name} must be a Box, Zonotope or Ellipsoid, got {type(Y).__name__}")
    if Y.dim != dim:
        raise ValueError(f"{name} must have dimension {dim}, got {Y.dim}")
    return Y


def zonotope_of(Y: NoiseSet) -> Zonotope:
    """``Y`` itself, a box as a zonotope (radii rounded up), or the certified parallelotope
    around an ellipsoid.

    Parameters
    ----------
    Y : Box, Zonotope or Ellipsoid
        A noise set.

    Returns
    -------
    Zonotope
        A zonotope containing ``Y``.
    """
    if isinstance(Y, Box):
        return Zonotope.from_box(Y)
    return Y if isinstance(Y, Zonotope) else Zonotope.from_ellipsoid(Y)


def ellipsoid_of(Y, weights: str = "unit") -> Ellipsoid:
    """An ellipsoid containing ``Y`` (an Ellipsoid, Zonotope or bounded Box), certified; flat
    zonotopes are thickened by ``FLAT_INFLATION`` first (module docstring).

    ``weights`` selects the member of :meth:`Zonotope.outer_ellipsoid` (``"unit"``: the
    minimum-volume ellipsoid of a parallelotope, ``"norms"``: the trace-minimal member).

    Parameters
    ----------
    Y : Ellipsoid, Zonotope or Box
        The set to enclose.
    weights : {"unit", "norms"}
        The member of :meth:`Zonotope.outer_ellipsoid`.

    Returns
    -------
    Ellipsoid
        An ellipsoid containing ``Y`` (``Y`` itself if it is one).

    Raises
    ------
    TypeError
        If ``Y`` is of another type.
    ValueError
        If ``Y`` is a single point.

    Notes
    -----
    For ``Y = <c, [g_1, ..., g_m]>`` and weights ``w_i > 0``, ``E(c, (sum_i w_i) sum_i g_i g_i^T
    / w_i)`` contains Y (module docstring).
    """
    if isinstance(Y, Ellipsoid):
        return Y
    Z = Zonotope.from_box(Y) if isinstance(Y, Box) else Y
    if not isinstance(Z, Zonotope):
        raise TypeError(f"expected a Box, Zonotope or Ellipsoid, got {type(Y).__name__}")
    G = Z.generators[:, np.any(Z.generators != 0, axis=0)]
    n = Z.dim
    if G.shape[1] == 0:
        raise ValueError("the set is a single point: give it a positive size")
    U, s, _ = np.linalg.svd(G)
    rank = int(np.sum(s >= FLAT_INFLATION * s[0]))  # thinner directions count as flat
    if rank < n:
        G = np.hstack([G, FLAT_INFLATION * s[0] * U[:, rank:]])
    return Zonotope(Z.center, G).outer_ellipsoid(weights)


def coordinate_bounds(Y: NoiseSet) -> Box:
    """The interval hull of ``Y``, rounded outward (``lo_i <= x_i <= hi_i`` on all of Y).

    Parameters
    ----------
    Y : Box, Zonotope or Ellipsoid
        A noise set.

    Returns
    -------
    Box
        The box ``[lo, hi]``; for an ellipsoid ``E(c, Q)``, ``c_i ± sqrt(Q_ii)`` rounded
        outward.
    """
    if isinstance(Y, Box):
        return Y
    if isinstance(Y, Zonotope):
        return Y.bounding_box()
    from optbound.interval import Interval

    half = np.sqrt(Interval(np.diag(Y.shape))).hi
    hull = Interval(Y.center) + Interval(-half, half)
    return Box(hull.lo, hull.hi)
