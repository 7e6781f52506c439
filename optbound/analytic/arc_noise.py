"""Noise ellipse of a measurement transformed by ``eta(z) = [z, z^2]`` [BH, eqs. (12)-(13), Fig. 2].

If ``w`` is known to lie in ``[lo, hi]``, the transformed value ``eta(w) = (w, w^2)`` lies on a
parabola arc. Its minimum-area enclosing ellipse is the Steiner circum-ellipse of the arc's
two endpoints and its midpoint (the image of the interval's midpoint ``w0``): writing
``w = w0 + t``, ``|t| <= r``, the arc is ``(w0, w0^2) + S (t, t^2)`` with the shear
``S = [[1, 0], [2 w0, 1]]``, and in ``(t, t^2)`` the ellipse has centre ``(0, 2 r^2 / 3)`` and
shape ``diag(4 r^2 / 3, 4 r^4 / 9)``. Along the arc its level is ``(9 tau^2 - 9 tau + 4) / 4``
with ``tau = t^2 / r^2``: 1 at the three points of contact, below 1 in between. Its area is
``4 pi r^3 / (3 sqrt 3)``: a Steiner circum-ellipse has ``4 pi / (3 sqrt 3)`` times the area of
its triangle, here ``r^3``; the shear has determinant 1, so the area holds for any centre.

References
----------
[BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
bearing measurements", IEEE Transactions on Robotics and Automation, 2004.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from optbound._core import validate as v

# Relative inflation of the shape so that the three contact points, at level exactly 1 in
# exact arithmetic, stay inside after the rounding of centre and shape (a few ulps each).
MARGIN = 1e-9


@dataclass(frozen=True)
class ArcNoise:
    """Centre ``v_hat`` and shape ``V`` of ``{v : (v - v_hat)^T V^-1 (v - v_hat) <= 1}``.

    Parameters
    ----------
    center : np.ndarray, shape (2,)
        The centre ``v_hat``.
    shape : np.ndarray, shape (2, 2)
        The shape matrix ``V``.
    """

    center: np.ndarray
    shape: np.ndarray

    def __iter__(self):
        """Unpack as ``v_hat, V = parabola_arc_ellipse(lo, hi)``."""
        return iter((self.center, self.shape))


def parabola_arc_ellipse(lo: float, hi: float) -> ArcNoise:
    """Minimum-area ellipse containing ``{(w, w^2) : lo <= w <= hi}`` (Steiner circum-ellipse).

    Parameters
    ----------
    lo, hi : float
        The interval of w, ``lo < hi``.

    Returns
    -------
    ArcNoise
        ``(v_hat, V)``: centre and shape, inflated by the relative ``MARGIN``.

    Raises
    ------
    ValueError
        Non-finite bounds or ``lo >= hi`` (a point has no full-dimensional ellipse).

    Examples
    --------
    >>> import numpy as np
    >>> from optbound.analytic.arc_noise import parabola_arc_ellipse
    >>> v_hat, V = parabola_arc_ellipse(-1.0, 1.0)
    >>> np.round(v_hat, 6).tolist(), np.round(V, 6).tolist()
    ([0.0, 0.666667], [[1.333333, 0.0], [0.0, 0.444444]])
    """
    lo, hi = v.finite_scalar("lo", lo), v.finite_scalar("hi", hi)
    if not lo < hi:
        raise ValueError(f"need lo < hi, got lo={lo}, hi={hi}")
    w0, r = 0.5 * (lo + hi), 0.5 * (hi - lo)
    S = np.array([[1.0, 0.0], [2.0 * w0, 1.0]])
    center = np.array([w0, w0 * w0]) + S @ np.array([0.0, 2.0 * r * r / 3.0])
    shape = S @ np.diag([4.0 * r * r / 3.0, 4.0 * r**4 / 9.0]) @ S.T
    return ArcNoise(center, (1.0 + MARGIN) * 0.5 * (shape + shape.T))
