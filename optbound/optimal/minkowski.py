"""Minimum-volume / -trace ellipsoid containing a Minkowski sum of ellipsoids.

S-procedure in the joint space [Boyd, El Ghaoui, Feron & Balakrishnan 1994, Sect. 3.7.4;
Durieu, Walter & Polyak 2001]. Each summand is ``E_i = {c_i + L_i u_i : ||u_i|| <= 1}``
(``C_i = L_i L_i^T``), so a point of the sum is ``c + L u`` with ``c = sum c_i``,
``L = [L_1, ..., L_k]`` and ``u = (u_1, ..., u_k)``. The sum is symmetric about ``c``, so an
optimal ellipsoid can be centred there. ``{x : (x - c)^T M (x - c) <= 1}`` contains it if there
are ``tau_i >= 0`` with ``sum tau_i <= 1`` and

    u^T L^T M L u <= sum_i tau_i ||u_i||^2   for all u,   i.e.   L^T M L <= D = diag(tau_i I_n).

- ``"volume"``: maximise ``log det M`` with the LMI written as ``[[D, L^T M], [M L, M]] >= 0``
  (Schur complement; this form keeps the problem DPP with L a parameter);
- ``"trace"``: in shape form ``Q = M^{-1}``, minimise ``tr Q`` subject to
  ``[[D, L^T], [L, Q]] >= 0`` (Schur complement of ``L^T Q^{-1} L <= D``).

The problem is solved in the frame ``x = c + W y`` with ``W W^T = sum_i C_i`` (the optimum lies
between ``sum C_i`` and ``k sum C_i``, so the problem in y is well conditioned; the trace
objective becomes ``tr(W^T W Q_y)``); the certificate ``L^T C^{-1} L <= D`` is checked on the
returned ellipsoid in x.

For two summands the optimum equals the best member of the family
``C_1 / (1 - kappa) + C_2 / kappa`` [HS96, eqs. (9)-(11)]; for three or more the S-procedure
can be slightly above the true minimum.

References
----------
[HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
on an angle measurement technique", IFAC, 1996.
"""

from __future__ import annotations

import cvxpy as cp
import numpy as np

from optbound.optimal import _cvx
from optbound.optimal.certify import certify_lmi
from optbound.optimal.result import OuterResult, objective_value
from optbound.optimal.template import Template, cached_template
from optbound.sets import Ellipsoid

OBJECTIVES = ("volume", "trace")


@cached_template(maxsize=32)
def minkowski_template(n: int, k: int, objective: str) -> Template:
    """The joint-space S-procedure for ``k`` summands in R^n (built once per shape)."""
    L = cp.Parameter((n, k * n))
    tau = cp.Variable(k, nonneg=True)
    D = cp.diag(np.kron(np.eye(k), np.ones((n, 1))) @ tau)
    X = cp.Variable((n, n), symmetric=True)
    weight = None
    if objective == "volume":
        lmi = cp.bmat([[D, (X @ L).T], [X @ L, X]])
        goal = cp.Maximize(cp.log_det(X))
    else:
        weight = cp.Parameter((n, n), PSD=True)
        lmi = cp.bmat([[D, L.T], [L, X]])
        goal = cp.Minimize(cp.trace(weight @ X))
    problem = cp.Problem(goal, [_cvx.psd(lmi), cp.sum(tau) <= 1])
    return Template(problem, factors=L, weight=weight, matrix=X, tau=tau)


def _gram(X: np.ndarray) -> np.ndarray:
    """``X^T X``: here ``L^T C^{-1} L`` with ``X = L_C^{-1} L``, without an explicit inverse."""
    return X.T @ X


def minkowski_outer(
    *ellipsoids: Ellipsoid, objective: str = "volume", solver: str = "CLARABEL"
) -> OuterResult:
    """Certified optimal outer ellipsoid of ``E_1 + ... + E_k`` (Minkowski sum).

    Parameters
    ----------
    *ellipsoids : Ellipsoid
        At least one summand, all of one dimension.
    objective : {"volume", "trace"}
        The size minimized.
    solver : {"CLARABEL", "SCS"}
        The conic solver.

    Returns
    -------
    OuterResult
        ``multipliers`` are the ``tau_i`` (one per summand, summing to at most 1); the
        certificate ``L^T C^{-1} L <= diag(tau_i I)`` is re-checked in float64.

    Raises
    ------
    ValueError
        For no summands, non-ellipsoids, mixed dimensions or an unknown objective.
    SolverError
        If the solve is not accurately optimal.

    Examples
    --------
    Two unit discs, one shifted: the sum is the disc of radius 2 about ``(1, 0)``.

    >>> import numpy as np
    >>> from optbound.optimal.minkowski import minkowski_outer
    >>> from optbound.sets import Ellipsoid
    >>> r = minkowski_outer(Ellipsoid([0.0, 0.0], np.eye(2)), Ellipsoid([1.0, 0.0], np.eye(2)))
    >>> r.ellipsoid.center.tolist(), (np.round(r.ellipsoid.shape, 5) + 0.0).tolist()
    ([1.0, 0.0], [[4.0, 0.0], [0.0, 4.0]])
    >>> r.certified
    True
    """
    if not ellipsoids:
        raise ValueError("minkowski_outer needs at least one ellipsoid")
    if not all(isinstance(e, Ellipsoid) for e in ellipsoids):
        raise ValueError("minkowski_outer sums Ellipsoid objects only")
    if len({e.dim for e in ellipsoids}) != 1:
        raise ValueError("all ellipsoids must have the same dimension")
    if objective not in OBJECTIVES:
        raise ValueError(f"objective must be one of {OBJECTIVES}, got {objective!r}")
    n, k = ellipsoids[0].dim, len(ellipsoids)
    L = np.hstack([e.chol for e in ellipsoids])
    # Frame x = c + W y with W W^T = sum C_i: the optimum lies between sum C_i and
    # k sum C_i, so the problem in y is well conditioned (volume: equivariant; trace: weighted).
    W = np.linalg.cholesky(sum(e.shape for e in ellipsoids))
    L_y = np.linalg.solve(W, L)
    scale = float(np.linalg.norm(L_y, 2))

    template = minkowski_template(n, k, objective)
    template.set(factors=L_y / scale)
    if template.weight is not None:
        template.set(weight=_cvx.trace_weight(W))
    solve_time = template.solve(solver, primal_only=True)
    X = template.matrix.value
    shape_y = np.linalg.inv(X) if objective == "volume" else X
    center = np.sum([e.center for e in ellipsoids], axis=0)
    candidate = Ellipsoid(center, scale**2 * (W @ shape_y @ W.T))

    tau = np.maximum(template.tau.value, 0.0)
    tau /= max(1.0, float(np.sum(tau)))
    blocks = [np.kron(np.diag(np.eye(k)[i]), np.eye(n)) for i in range(k)]  # u_i^T u_i
    ellipsoid, inflation, beta = certify_lmi(
        candidate,
        lambda e: _gram(np.linalg.solve(e.chol, L)),
        np.zeros((k * n, k * n)),
        tau,
        np.stack(blocks),
    )
    return OuterResult(
        ellipsoid=ellipsoid,
        objective=objective_value(ellipsoid, objective, None),
        status=template.problem.status,
        solve_time=solve_time,
        multipliers=beta * tau,
        certified=True,
        inflation=inflation,
    )
