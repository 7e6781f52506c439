"""Certified extents of linear functions over an ellipsoid ∩ polyhedron, for clipping strips.

With many strips, each one is much wider than the intersection along its normal, and the
S-procedure (one multiplier per member) cannot see that the other strips cut it. Clipping every
range ``lo_i <= a_i^T x <= hi_i`` to the exact range of ``a_i^T x`` over the *whole*
intersection leaves the set unchanged but makes the SDP far tighter (the user guide's
optimal page, ``docs/user_guide/optimal.md``, has the measured effect).

In the frame ``x = c + W y`` of an ellipsoid E (``C = W W^T``), E is the unit ball and the
rows become ``lo_i - a_i^T c <= (W^T a_i)^T y <= hi_i - a_i^T c``. The extent of each row over
``P = ball ∩ {lo <= A y <= hi}`` is a small SOCP; all ``2 r`` directions ``±a_i`` are solved
as one block problem (one copy of y per direction; the blocks are independent), built once per
shape with cvxpy Parameters (DPP).

The solver's answer is not trusted: each extent is the weak-duality bound, for any
``lambda, mu >= 0`` (the solver's dual values, clipped at 0),

    max_{y in P} d^T y  <=  ||d - A^T (lambda - mu)|| + lambda^T hi - mu^T lo,

since ``d^T y = (d - A^T(lambda - mu))^T y + lambda^T A y - mu^T A y`` and ``||y|| <= 1``.
It is evaluated in float64 with a rounding margin, and the rows and the ball are widened by
the rounding of the frame, so no point of the intersection is ever clipped away. With
``d = 0`` and the Farkas ray that an infeasible solve returns as duals, a negative bound
certifies that the intersection is empty. Non-convex members are ignored here (extents over a
superset are still valid).
"""

from __future__ import annotations

import cvxpy as cp
import numpy as np

from optbound.optimal._small import rounding_bound
from optbound.optimal.errors import EmptyIntersectionError, SolverError
from optbound.optimal.template import Template, cached_template
from optbound.sets import Ellipsoid

_EMPTY = (
    "the strips and half-spaces have no common point inside a bounded member "
    "(certified by weak duality)"
)


@cached_template(maxsize=128)
def extents_template(n: int, r: int) -> Template:
    """Maximise ``a_i^T y`` and ``-a_i^T y`` over ball ∩ polyhedron, all at once."""
    rows = cp.Parameter((r, n))
    lo = cp.Parameter((1, r))
    hi = cp.Parameter((1, r))
    Y = cp.Variable((2 * r, n))  # Y[:r] maximise +a_i, Y[r:] maximise -a_i
    values = Y @ rows.T  # (2r, r): every row evaluated at every block's point
    ones = np.ones((2 * r, 1))
    upper = values <= ones @ hi
    lower = values >= ones @ lo
    goal = cp.Maximize(cp.sum(cp.multiply(Y[:r], rows)) - cp.sum(cp.multiply(Y[r:], rows)))
    problem = cp.Problem(goal, [cp.norm(Y, 2, axis=1) <= 1.0, upper, lower])
    return Template(problem, rows=rows, lo=lo, hi=hi, upper=upper, lower=lower)


def _dual_bounds(
    directions: np.ndarray,
    rows: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
    lam: np.ndarray,
    mu: np.ndarray,
) -> np.ndarray:
    """Weak-duality bound on ``max d_j^T y`` over P for each direction, rounded upward."""
    lam, mu = np.maximum(lam, 0.0), np.maximum(mu, 0.0)
    residual = directions - (lam - mu) @ rows
    bound = np.linalg.norm(residual, axis=1) + lam @ hi - mu @ lo
    size = rows.shape[0] + rows.shape[1]
    magnitude = (
        np.linalg.norm(directions, axis=1)
        + (lam + mu) @ np.linalg.norm(rows, axis=1)
        + lam @ np.abs(hi)
        + mu @ np.abs(lo)
    )
    return bound + rounding_bound(size, magnitude)


def clip_to_intersection(
    ellipsoid: Ellipsoid, A: np.ndarray, lo: np.ndarray, hi: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Ranges ``[lo_i, hi_i]`` shrunk to the range of ``a_i^T x`` over E ∩ {lo <= A x <= hi}.

    Parameters
    ----------
    ellipsoid : Ellipsoid
        A bounded member of the intersection (the ranges are finite inside it).
    A : ndarray, shape (r, n)
        The rows ``a_i``.
    lo, hi : ndarray, shape (r,)
        Finite ranges (already clipped to the ellipsoid's extents).

    Returns
    -------
    (ndarray, ndarray)
        The clipped ranges; unchanged if the solve fails (clipping is only an improvement).

    Raises
    ------
    EmptyIntersectionError
        If the certified extents show that the intersection is empty.
    """
    r, n = A.shape
    W, c = ellipsoid.chol, ellipsoid.center
    rows = A @ W
    offset = A @ c
    # Rounding of the frame: rows, offsets and the ball radius are known to this accuracy.
    scale = np.linalg.norm(W) + np.abs(c).max()
    frame_err = rounding_bound(n, np.linalg.norm(A, axis=1) * scale)
    # The Cholesky factor's backward error moves ||y|| on E by ~ n eps cond(C) = cond(W)^2.
    radius = 1.0 + rounding_bound(n, float(np.linalg.cond(W)) ** 2)
    lo_y = (lo - offset - frame_err) / radius
    hi_y = (hi - offset + frame_err) / radius
    template = extents_template(n, r)
    template.set(rows=rows, lo=lo_y[None, :], hi=hi_y[None, :])
    try:
        template.solve("CLARABEL")
        infeasible = False
    except SolverError as err:
        if err.status != cp.INFEASIBLE:
            return lo, hi
        infeasible = True
    duals = template.upper.dual_value, template.lower.dual_value
    if duals[0] is None or duals[1] is None:
        return lo, hi
    if infeasible:
        # The duals are then a Farkas ray: with d = 0 the bound on "max 0" is negative.
        if np.min(_dual_bounds(np.zeros((2 * r, n)), rows, lo_y, hi_y, *duals)) < 0.0:
            raise EmptyIntersectionError(_EMPTY)
        return lo, hi
    bounds = radius * _dual_bounds(np.vstack([rows, -rows]), rows, lo_y, hi_y, *duals)
    new_hi = np.minimum(hi, bounds[:r] + offset + frame_err)
    new_lo = np.maximum(lo, -bounds[r:] + offset - frame_err)
    if np.any(new_lo > new_hi):
        raise EmptyIntersectionError(_EMPTY)
    return new_lo, new_hi
