"""Outward-rounded kernels for sqrt and the transcendental functions, on raw bound arrays.

Same contract as :mod:`optbound.interval._arith` (run under ``np.errstate(all="ignore")``):
non-empty inputs, ``(lo, hi)`` out, the canonical empty ``(+inf, -inf)`` where the input
misses the function's domain (sqrt and log are restricted to their domain:
``sqrt([-1, 4]) = [0, 2]``, ``log([-1, 0]) = empty``).
"""

from __future__ import annotations

import numpy as np

from optbound.interval._rounding import TRANSCENDENTAL_ULPS as K
from optbound.interval._rounding import down, up

INF = np.inf
TWO_PI = 2.0 * np.pi
#: An upper bound of pi (the float ``np.pi`` is below pi).
PI_UP = np.nextafter(np.pi, INF)
#: Beyond this magnitude the float grid is too coarse to locate extrema of sin/cos.
_PERIODIC_RANGE = float.fromhex("0x1p50")


def _restrict(lo, hi, outside):
    return np.where(outside, INF, lo), np.where(outside, -INF, hi)


def sqrt(al, ah):
    lo = np.maximum(down(np.sqrt(np.maximum(al, 0.0))), 0.0)
    hi = up(np.sqrt(np.maximum(ah, 0.0)))
    return _restrict(lo, hi, ah < 0.0)


def exp(al, ah):
    return np.maximum(down(np.exp(al), K), 0.0), up(np.exp(ah), K)


def log(al, ah):
    lo = np.where(al > 0.0, down(np.log(np.maximum(al, 0.0)), K), -INF)
    hi = up(np.log(np.maximum(ah, 0.0)), K)
    return _restrict(lo, hi, ah <= 0.0)


def _contains_point_of(al, ah, offset):
    """Whether ``[al, ah]`` may contain a point ``offset + 2 k pi`` (k integer).

    Errs on the side of "yes": the position in periods is computed in floating point, so it
    is widened by a relative 1e-14 before the integer test. A wrong "yes" only loosens the
    bound to the extremum the function nearly reaches anyway.
    """
    t_lo = (al - offset) / TWO_PI
    t_hi = (ah - offset) / TWO_PI
    slack = 1e-14 * (np.abs(t_lo) + np.abs(t_hi) + 1.0)
    return np.floor(t_hi + slack) >= np.ceil(t_lo - slack)


def _periodic(fun, al, ah, max_at, min_at):
    """Range of sin or cos: the endpoint values, widened to +-1 where an extremum lies inside."""
    finite = np.isfinite(al) & np.isfinite(ah)
    a = np.where(finite, al, 0.0)
    b = np.where(finite, ah, 0.0)
    fa, fb = fun(a), fun(b)
    lo = np.maximum(down(np.minimum(fa, fb), K), -1.0)
    hi = np.minimum(up(np.maximum(fa, fb), K), 1.0)
    whole = (
        ~finite | (b - a >= TWO_PI) | (np.abs(a) > _PERIODIC_RANGE) | (np.abs(b) > _PERIODIC_RANGE)
    )
    lo = np.where(whole | _contains_point_of(a, b, min_at), -1.0, lo)
    hi = np.where(whole | _contains_point_of(a, b, max_at), 1.0, hi)
    return lo, hi


def sin(al, ah):
    return _periodic(np.sin, al, ah, max_at=0.5 * np.pi, min_at=-0.5 * np.pi)


def cos(al, ah):
    return _periodic(np.cos, al, ah, max_at=0.0, min_at=np.pi)


def atan2(yl, yh, xl, xh):
    """Range of ``atan2(y, x)`` in ``[-pi, pi]`` over a box.

    Off the branch cut (the negative x axis, where atan2 jumps from pi to -pi) the box is seen
    from the origin under an angle below pi and the extremes are at its corners. A box that
    meets the cut (y straddles 0 with y_hi >= 0 and x_lo < 0, which includes boxes holding the
    origin) gets the whole ``[-pi, pi]``. ``y = 0`` counts as +0 (angle pi on the cut).
    """
    yl, yh, xl, xh = np.broadcast_arrays(yl + 0.0, yh + 0.0, xl + 0.0, xh + 0.0)  # -0 -> +0
    c1, c2 = np.arctan2(yl, xl), np.arctan2(yl, xh)
    c3, c4 = np.arctan2(yh, xl), np.arctan2(yh, xh)
    lo = np.maximum(down(np.minimum(np.minimum(c1, c2), np.minimum(c3, c4)), K), -PI_UP)
    hi = np.minimum(up(np.maximum(np.maximum(c1, c2), np.maximum(c3, c4)), K), PI_UP)
    cut = (yl < 0.0) & (yh >= 0.0) & (xl < 0.0)
    return np.where(cut, -PI_UP, lo), np.where(cut, PI_UP, hi)
