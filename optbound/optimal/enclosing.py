"""The minimum-volume ellipsoid enclosing a finite point set (MVEE), as an SDP.

[Boyd & Vandenberghe 2004, Sect. 8.4.1]: with ``E = {x : ||A x + b|| <= 1}``, maximise
``log det A`` subject to ``||A p_i + b|| <= 1`` for every point (second-order cones); the centre
is ``-A^{-1} b`` and the shape ``A^{-2}``. Points are translated to their mean and scaled to
the unit ball before solving; the problem is cached per (number of points, dimension) and
re-solved by setting the points.
"""

from __future__ import annotations

import cvxpy as cp
import numpy as np

from optbound._core import COND_MAX, MAG, RATIO_MAX
from optbound._core import validate as v
from optbound.optimal import _cvx
from optbound.optimal.certify import certify_points
from optbound.optimal.result import OuterResult
from optbound.optimal.template import Template, cached_template
from optbound.sets import Ellipsoid

# Relative singular value below which a point cloud counts as flat: its enclosing ellipsoid
# would be (nearly) degenerate, beyond the supported condition number (optbound._core.domain).
_FLAT_RTOL = 10.0 / np.sqrt(COND_MAX)


@cached_template(maxsize=32)
def mvee_template(m: int, n: int) -> Template:
    """The MVEE problem for ``m`` points in R^n (built once per shape)."""
    points = cp.Parameter((n, m))
    A = cp.Variable((n, n), symmetric=True)
    b = cp.Variable(n)
    images = A @ points + _cvx.column(b) @ np.ones((1, m))
    problem = cp.Problem(cp.Maximize(cp.log_det(A)), [cp.norm(images, 2, axis=0) <= 1])
    return Template(problem, points=points, A=A, b=b)


def validated_points(points) -> np.ndarray:
    """An (m, n) finite array whose affine hull is all of R^n (else no ellipsoid encloses it).

    Parameters
    ----------
    points : array_like, shape (m, n)
        The points to enclose.

    Returns
    -------
    np.ndarray, shape (m, n)
        The points as a float64 array.

    Raises
    ------
    ValueError
        If the points are non-finite, fewer than n + 1, outside the supported domain, or
        (nearly) flat.
    """
    X = v.finite_matrix("points", points)
    m, n = X.shape
    if m < n + 1:
        raise ValueError(f"points must hold at least n + 1 = {n + 1} points, got {m}")
    # Magnitudes checked before any arithmetic that could overflow or underflow.
    top = float(np.max(np.abs(X)))
    if top > MAG:
        raise ValueError(f"points must have coordinates <= {MAG:.0e} (the supported domain)")
    centre = X.mean(axis=0)
    spread = float(np.max(np.abs(X - centre)))
    if not spread >= max(1.0 / MAG, top / RATIO_MAX):
        raise ValueError(
            f"points must spread over more than {1 / MAG:.0e} and {1 / RATIO_MAX:.0e} times "
            "their distance from the origin (the supported domain)"
        )
    sv = np.linalg.svd((X - centre) / spread, compute_uv=False)
    if sv[-1] <= _FLAT_RTOL * sv[0]:
        raise ValueError(
            "points lie in (or within relative thickness "
            f"{_FLAT_RTOL:.0e} of) a lower-dimensional affine subspace: no ellipsoid in the "
            "supported domain fits"
        )
    return X


def mvee(points, solver: str = "CLARABEL") -> OuterResult:
    """Certified minimum-volume ellipsoid enclosing a point set.

    Parameters
    ----------
    points : array_like, shape (m, n)
        At least n + 1 finite points not all in one hyperplane.
    solver : {"CLARABEL", "SCS"}
        The conic solver.

    Returns
    -------
    OuterResult
        ``objective`` is the volume; ``multipliers`` is empty; every point is checked in
        float64 and the ellipsoid inflated by the smallest factor if one lies outside.

    Raises
    ------
    ValueError
        For non-finite, too few or flat point sets.
    SolverError
        If the solve is not accurately optimal.

    Examples
    --------
    The corners of the square ``[-1, 1]^2`` lie on the circle of radius sqrt(2):

    >>> import numpy as np
    >>> from optbound.optimal.enclosing import mvee
    >>> corners = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])
    >>> (np.round(mvee(corners).ellipsoid.shape, 5) + 0.0).tolist()
    [[2.0, 0.0], [0.0, 2.0]]
    """
    X = validated_points(points)
    m, n = X.shape
    center = X.mean(axis=0)
    scale = float(np.max(np.linalg.norm(X - center, axis=1)))
    template = mvee_template(m, n)
    template.set(points=((X - center) / scale).T)
    solve_time = template.solve(solver, primal_only=True)
    A_inv = np.linalg.inv(template.A.value)
    candidate = Ellipsoid(center - scale * A_inv @ template.b.value, scale**2 * A_inv @ A_inv.T)
    ellipsoid, inflation = certify_points(candidate, X)
    return OuterResult(
        ellipsoid=ellipsoid,
        objective=ellipsoid.volume(),
        status=template.problem.status,
        solve_time=solve_time,
        multipliers=np.empty(0),
        certified=True,
        inflation=inflation,
    )
