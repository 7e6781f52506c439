"""A forward-backward contractor for one sonar's upper range bound [LJMW97], [KJWM00].

A reading ``d <= hi < d_max`` means the sonar sees some point ``P`` of a reflecting face within
``hi`` of its vertex (the apex): ``f_i(q) <= hi`` holds only if, for some wall ``j``, ``P`` lies
on ``Seg(a_j, b_j)``, the apex is on the wall's reflecting side and ``|P - apex| <= hi``. Both
consequences are cheap to propagate backward to the box of ``(x, y)``:

- the apex lies in the wall's bounding box widened by ``hi`` on each side;
- its signed distance to the wall's line is in ``[0, hi]``:
  ``g = e_x (p_y - a_y) - e_y (p_x - a_x)`` lies in ``[0, hi |e|]`` (``e = b - a``), a linear
  constraint contracted on ``p_x`` and ``p_y`` by the usual backward step.

The apex box is the hull over walls of the contracted apex boxes (the constraint is a
disjunction over walls), and ``x`` (``y``) is contracted to ``apex - R(theta) s`` with the
sonar's mounting point ``s`` rotated by the box's headings. Everything is outward-rounded
interval arithmetic on the map's floats read as exact numbers, so a pose that satisfies the
reading is never removed. The heading is not contracted, nor is the lower bound ``d >= lo``
(no face closer than ``lo`` in the cone): that needs the cone, which bisection handles.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from optbound.interval import Interval
from optbound.localization import geometry as g


def _meet(a: Interval, lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return np.maximum(a.lo, lo), np.minimum(a.hi, hi)


def upper_range_contractor(
    world: np.ndarray, position: tuple[float, float], hi: float
) -> Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]:
    """Contractor of ``f_i(x, y, theta) <= hi`` on (3, m) pose bounds (see module docstring).

    Parameters
    ----------
    world
        (s, 2, 2) oriented segments, reflecting face on the left.
    position
        The sonar's ``(x, y)`` in the robot frame.
    hi
        Upper end of the measured range interval; must be below ``d_max`` (a reading of
        ``d_max`` may mean "no face", which constrains nothing here).

    Returns
    -------
    callable
        ``contract(lo, hi)`` on coordinate-major (3, m) arrays of ``x, y, theta`` bounds:
        the contracted bounds, with ``lo > hi`` on ``x`` for boxes holding no consistent pose.
    """
    a, b = g.segment_points(world)
    ax, ay = Interval(a[0]), Interval(a[1])
    ex, ey = Interval(b[0]) - ax, Interval(b[1]) - ay
    reach = Interval(hi)
    box_x = (
        (Interval(np.minimum(a[0], b[0])) - reach).lo,
        (Interval(np.maximum(a[0], b[0])) + reach).hi,
    )
    box_y = (
        (Interval(np.minimum(a[1], b[1])) - reach).lo,
        (Interval(np.maximum(a[1], b[1])) + reach).hi,
    )
    span = Interval(np.zeros(len(world)), (reach * np.sqrt(ex * ex + ey * ey)).hi)  # [0, hi |e|]
    use_x, use_y = (ey.lo > 0) | (ey.hi < 0), (ex.lo > 0) | (ex.hi < 0)  # divisors without 0
    sx, sy = position

    def contract(lo: np.ndarray, hi_: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        x, y, theta = (Interval._make(lo[k], hi_[k]) for k in range(3))
        c, s = np.cos(theta), np.sin(theta)
        rx, ry = c * sx - s * sy, s * sx + c * sy
        px, py = x + rx, y + ry
        px, py = (
            Interval._make(px.lo[:, None], px.hi[:, None]),
            Interval._make(py.lo[:, None], py.hi[:, None]),
        )
        # Bounding box of the wall widened by hi.
        x_lo, x_hi = _meet(px, *box_x)
        y_lo, y_hi = _meet(py, *box_y)
        ok = (x_lo <= x_hi) & (y_lo <= y_hi)
        u = Interval._make(np.where(ok, x_lo, 0.0), np.where(ok, x_hi, 0.0)) - ax
        w = Interval._make(np.where(ok, y_lo, 0.0), np.where(ok, y_hi, 0.0)) - ay
        with np.errstate(divide="ignore", invalid="ignore"):
            u_new = (ex * w - span) / ey
            u_lo, u_hi = _meet(
                u, np.where(use_x, u_new.lo, -np.inf), np.where(use_x, u_new.hi, np.inf)
            )
            u = Interval._make(u_lo, np.maximum(u_hi, u_lo))
            w_new = (span + ey * u) / ex
            w_lo, w_hi = _meet(
                w, np.where(use_y, w_new.lo, -np.inf), np.where(use_y, w_new.hi, np.inf)
            )
        ok &= (u_lo <= u_hi) & (w_lo <= w_hi)
        qx, qy = u + ax, Interval._make(w_lo, np.maximum(w_hi, w_lo)) + ay
        # Hull over the walls that remain possible.
        apex_x = (np.where(ok, qx.lo, np.inf).min(axis=1), np.where(ok, qx.hi, -np.inf).max(axis=1))
        apex_y = (np.where(ok, qy.lo, np.inf).min(axis=1), np.where(ok, qy.hi, -np.inf).max(axis=1))
        none = ~ok.any(axis=1)
        new_x = Interval._make(np.where(none, 0.0, apex_x[0]), np.where(none, 0.0, apex_x[1])) - rx
        new_y = Interval._make(np.where(none, 0.0, apex_y[0]), np.where(none, 0.0, apex_y[1])) - ry
        out_lo, out_hi = lo.copy(), hi_.copy()
        out_lo[0], out_hi[0] = _meet(x, new_x.lo, new_x.hi)
        out_lo[1], out_hi[1] = _meet(y, new_y.lo, new_y.hi)
        out_lo[0, none], out_hi[0, none] = np.inf, -np.inf
        return out_lo, out_hi

    return contract


__all__ = ["upper_range_contractor"]
