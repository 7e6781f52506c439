"""Bearings: angle wrapping and the relative-bearing constraint [BH, eq. (2)].

One formula each, on float points and on interval boxes (see :mod:`.primitives`).
"""

from __future__ import annotations

import numpy as np

from optbound.interval import Interval


def wrap_angle(a):
    """Wrap angles to (-pi, pi].

    Parameters
    ----------
    a : array_like
        Angles [rad].

    Returns
    -------
    numpy.ndarray
        ``a`` modulo 2 pi, in (-pi, pi].
    """
    w = np.mod(np.asarray(a, dtype=float) + np.pi, 2.0 * np.pi) - np.pi
    return np.where(w == -np.pi, np.pi, w)


def bearing_residual(x, y, li, lj, gamma):
    """``wrap(gamma_ij(x, y) - gamma)`` [BH, eq. (2)], on float arrays or ``Interval`` boxes.

    ``gamma_ij = angle(x - L_i) - angle(x - L_j)`` is the angle of the complex product
    ``(x - L_i) conj(x - L_j)``; rotating that product by ``-gamma`` and taking one ``atan2``
    gives the wrapped residual, with the branch cut at residual ``±pi``, far from the
    constraint ``|residual| <= eps < pi/2``. For intervals ``cos gamma``, ``sin gamma`` are
    enclosed too, so the residual's enclosure is guaranteed.

    Parameters
    ----------
    x, y : array_like or Interval
        Coordinates of the points (or boxes).
    li, lj : array_like, shape (2,)
        The two landmarks.
    gamma : float
        Measured relative bearing [rad].

    Returns
    -------
    numpy.ndarray or Interval
        The wrapped residual, in (-pi, pi].
    """
    ux, uy = x - lj[0], y - lj[1]
    wx, wy = x - li[0], y - li[1]
    dot = ux * wx + uy * wy
    cross = ux * wy - uy * wx
    g = Interval(gamma) if isinstance(x, Interval) else gamma
    c, s = np.cos(g), np.sin(g)
    return np.arctan2(c * cross - s * dot, c * dot + s * cross)


def bearing_sides(x, y, li, lj, gamma, eps):
    """``|x - L_i| |x - L_j|`` times ``(sin(r + eps), -sin(r - eps))``, ``r = gamma_ij - gamma``.

    Both are >= 0 exactly when ``|wrap(gamma_ij - gamma)| <= eps`` (for eps < pi/2): the same
    constraint as :func:`bearing_residual`, written as two cross products with the rotated
    vectors, polynomial in x and free of atan2's branch cut (where the residual is near
    ±pi, on the other arc of the circle, interval atan2 cannot exclude a box). Float arrays or
    ``Interval`` boxes, from one formula; at the landmarks both vanish.

    Parameters
    ----------
    x, y : array_like or Interval
        Coordinates of the points (or boxes).
    li, lj : array_like, shape (2,)
        The two landmarks.
    gamma : float
        Measured relative bearing [rad].
    eps : float
        Noise bound [rad], below pi/2.

    Returns
    -------
    tuple
        The two cross products, both >= 0 exactly on the feasible set.
    """
    ux, uy = x - lj[0], y - lj[1]
    wx, wy = x - li[0], y - li[1]
    dot = ux * wx + uy * wy
    cross = ux * wy - uy * wx
    g, e = (Interval(gamma), Interval(eps)) if isinstance(x, Interval) else (gamma, eps)
    lo, hi = g - e, g + e
    return cross * np.cos(lo) - dot * np.sin(lo), dot * np.sin(hi) - cross * np.cos(hi)


def bearing_gradient(x, y, li, lj):
    """Gradient ``(d gamma_ij / dx, d gamma_ij / dy)`` of [BH, eq. (2)] at float points.

    ``d angle(x - L) = (-(y - y_L), x - x_L) / |x - L|^2``, the difference of the two
    landmarks' terms. Float arrays only: it serves linearization (HS96-style strips), not
    guaranteed tests.

    Parameters
    ----------
    x, y : array_like
        Coordinates of the points (not at a landmark).
    li, lj : array_like, shape (2,)
        The two landmarks.

    Returns
    -------
    gx, gy : numpy.ndarray
        The partial derivatives of ``gamma_ij``.
    """
    gx, gy = 0.0, 0.0
    for (lx, ly), sign in ((li, 1.0), (lj, -1.0)):
        dx, dy = x - lx, y - ly
        r2 = dx * dx + dy * dy
        gx, gy = gx - sign * dy / r2, gy + sign * dx / r2
    return gx, gy


__all__ = ["bearing_gradient", "bearing_residual", "bearing_sides", "wrap_angle"]
