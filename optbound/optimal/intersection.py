"""Minimum-volume / -trace / -projection ellipsoid containing an intersection of quadratic sets.

The S-procedure LMI [Boyd, El Ghaoui, Feron & Balakrishnan 1994, Sect. 3.7.2; Boyd &
Vandenberghe 2004, Sect. 8.4.1]. Write the candidate as ``E = {x : ||A x + b|| <= 1}`` with
``M = A^2`` (the inverse shape matrix) and ``bt = A b``, and each member as
``q_i(x) = [x; 1]^T F_i [x; 1] <= 0``. E contains the intersection if there are multipliers
``tau_i >= 0`` with

    [x; 1]^T [[M, bt], [bt^T, bt^T M^{-1} bt - 1]] [x; 1]  <=  sum_i tau_i q_i(x)   for all x,

and a Schur complement on ``bt^T M^{-1} bt`` turns this into the LMI (linear in M, bt, tau)

    [[M - S_xx,        bt - s_x,        0  ],
     [(bt - s_x)^T,    -1 - s_1,        bt^T],     <=  0,     S = sum_i tau_i F_i.
     [0,               bt,              -M ]]

The centre is ``-M^{-1} bt`` and the shape ``M^{-1}``. Objectives:

- ``"volume"``: maximise ``log det M`` (volume is proportional to ``det M^{-1/2}``);
- ``"trace"``: minimise ``tr M^{-1}`` as ``tr Z`` with ``[[Z, I], [I, M]] >= 0`` (in the
  whitened frame below, the weighted ``tr(R Z)`` with ``R = W^T W`` a parameter);
- ``"projection"``: minimise the volume of the projection onto the coordinates ``J = dims``.
  The projection has shape ``(M^{-1})_JJ``, whose inverse is the Schur complement
  ``M/M_KK = M_JJ - M_JK M_KK^{-1} M_KJ`` (block inverse formula, K the other coordinates).
  That Schur complement is matrix-concave in M, and ``T <= M/M_KK`` is equivalent (for
  ``M_KK > 0``) to ``M - E_J T E_J^T >= 0`` with ``E_J`` the coordinate embedding. So the
  projection volume ``~ det(M/M_KK)^{-1/2}`` is minimised by maximising ``log det T`` subject to
  that LMI; at the optimum ``T = M/M_KK``. This is the SDP counterpart of [HS96, eq. (27)].

For the speed of repeated solves every problem *shape* (dimension, number of inequalities,
objective, dims) is built once with cvxpy Parameters (DPP) and cached; a re-solve only sets
the ``F_i``. Before solving, coordinates are mapped affinely, ``x = c0 + W y``, so that an
ellipsoid of about the intersection's size is the unit ball (see ``_frame``), and each ``F_i``
is normalised. The answer is mapped back to x and certified from the returned ellipsoid and
multipliers (``optbound.optimal.certify``); the eigenvalue check is done after the congruence
by the frame, where the matrices are well conditioned, with the rounding of that congruence
added to the margin.

The optimum is an upper bound on the true minimum over all ellipsoids (the S-procedure is
lossless for one inequality only); ``lower_bound=True`` also returns a lower bound.
"""

from __future__ import annotations

from collections.abc import Sequence

import cvxpy as cp
import numpy as np

from optbound._core import validate as v
from optbound.optimal import _cvx, _small
from optbound.optimal.certify import certify_lmi
from optbound.optimal.emptiness import explain_failure, refuse_empty
from optbound.optimal.errors import EmptyIntersectionError, SolverError
from optbound.optimal.lift import check_clip, lift
from optbound.optimal.lower import sampled_lower_bound
from optbound.optimal.result import OuterResult, objective_value
from optbound.optimal.template import Template, cached_template
from optbound.sets import Ellipsoid, QuadraticSet
from optbound.sets.base import QuadraticallyDescribed

OBJECTIVES = ("volume", "trace", "projection")
# Eigenvalues of normalized quadratic parts below this count as zero.
_DEFINITE_RTOL = 1e-12


@cached_template(maxsize=128)
def intersection_template(n: int, k: int, objective: str, dims: tuple[int, ...] | None) -> Template:
    """The S-procedure problem for ``k`` inequalities in R^n (built once per shape).

    The forms are one parameter, column i the flattened ``F_i``, so that ``S`` is one
    matrix-vector product: compiling stays fast with thousands of inequalities (``products``).
    """
    forms = cp.Parameter(((n + 1) ** 2, k))
    M = cp.Variable((n, n), symmetric=True)
    bt = cp.Variable(n)
    tau = cp.Variable(k, nonneg=True)
    S = cp.reshape(forms @ tau, (n + 1, n + 1), order="F")
    zero = np.zeros((n, n))
    lmi = cp.bmat(
        [
            [M - S[:n, :n], _cvx.column(bt - S[:n, n]), zero],
            [
                _cvx.column(bt - S[:n, n]).T,
                cp.reshape(-1 - S[n, n], (1, 1), order="F"),
                _cvx.column(bt).T,
            ],
            [zero, _cvx.column(bt), -M],
        ]
    )
    constraints = [_cvx.psd(-lmi)]
    weight = None
    if objective == "volume":
        goal = cp.Maximize(cp.log_det(M))
    elif objective == "trace":
        Z = cp.Variable((n, n), symmetric=True)
        weight = cp.Parameter((n, n), PSD=True)
        constraints.append(_cvx.psd(cp.bmat([[Z, np.eye(n)], [np.eye(n), M]])))
        goal = cp.Minimize(cp.trace(weight @ Z))
    else:
        T = cp.Variable((len(dims), len(dims)), symmetric=True)
        embed = np.eye(n)[:, list(dims)]
        constraints.append(_cvx.psd(M - embed @ T @ embed.T))
        goal = cp.Maximize(cp.log_det(T))
    problem = cp.Problem(goal, constraints)
    return Template(problem, forms=forms, weight=weight, M=M, bt=bt, tau=tau)


def _depth(q: QuadraticSet) -> float:
    """``-min_x q(x)`` for a member with a positive semidefinite quadratic part, else 0."""
    A, b, c = q.F[:-1, :-1], q.F[:-1, -1], q.F[-1, -1]
    if np.linalg.eigvalsh(A)[0] < -_DEFINITE_RTOL * np.linalg.norm(A):
        return 0.0
    return float(b @ np.linalg.lstsq(A, b, rcond=None)[0] - c)


def _frame_ellipsoid(quadratics: Sequence[QuadraticSet]) -> Ellipsoid | None:
    """An ellipsoid of about the intersection's size: ``sum_i q_i(x) / depth_i <= 0``.

    Each convex member is scaled to depth 1; the sum is <= 0 on the intersection, and with
    many clipped strips its shape follows the thin polytope, not the (much larger) ellipsoid
    member, which keeps the SDP well conditioned. ``None`` if the sum is not an ellipsoid.
    """
    depths = np.array([_depth(q) for q in quadratics])
    used = depths > 0.0
    if not np.any(used):
        return None
    F = sum(q.F / d for q, d, u in zip(quadratics, depths, used, strict=True) if u)
    total = QuadraticSet(F)
    return total.as_ellipsoid() if total.is_bounded else None


def _frame(
    quadratics: Sequence[QuadraticSet], dims: tuple[int, ...] | None
) -> tuple[np.ndarray, np.ndarray]:
    """Affine frame ``x = c + W y`` in which a set of about the intersection's size is the ball.

    That set is ``_frame_ellipsoid`` with more than two members, else the first bounded
    member (one ellipsoid is its own frame). ``W`` is the Cholesky factor of its shape, taken
    with the ``dims`` coordinates first for the projection objective; then ``x_dims`` depends
    on ``y_dims`` only, so projections map to projections. The S-procedure is invariant under
    the map and the objectives change by constants (trace: it becomes ``tr(W^T W C_y)``), so
    the frame only improves conditioning.
    """
    n = quadratics[0].dim
    bounded = next((q for q in quadratics if q.is_bounded), None)
    if bounded is None:
        return np.zeros(n), np.eye(n)
    ellipsoid = bounded.as_ellipsoid()
    if ellipsoid is None:
        raise EmptyIntersectionError(f"the quadratic set {bounded!r} is empty")
    if len(quadratics) > 2:
        ellipsoid = _frame_ellipsoid(quadratics) or ellipsoid
    if not dims:
        return ellipsoid.center, ellipsoid.chol
    order = list(dims) + [i for i in range(n) if i not in dims]
    W = np.zeros((n, n))
    W[np.ix_(order, order)] = np.linalg.cholesky(ellipsoid.shape[np.ix_(order, order)])
    return ellipsoid.center, W


def _in_frame(
    quadratics: Sequence[QuadraticSet], frame: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``F_hat_i = T^T F_i T / norm_i`` (unit Frobenius norm, stacked), the norms, and error
    bounds.

    ``errors[i]`` bounds the rounding of the congruence, relative to the normalised form (with
    the Frobenius norm of ``|T|^T |F_i| |T|``, an upper bound on its spectral norm).
    """
    return _small.in_frame(np.stack([q.F for q in quadratics]), frame)


def _lifted_form(ellipsoid: Ellipsoid, frame: np.ndarray) -> np.ndarray:
    """``T^T [I, -c]^T C^{-1} [I, -c] T`` for the frame ``T = [[W, c0], [0, 1]]``.

    ``E = {x : [x;1]^T B^T C^{-1} B [x;1] <= 1}`` with ``B = [I, -c]``; in the frame,
    ``B T = [W, c0 - c]``, and the form is ``X^T X`` with ``X = L^{-1} B T`` (``C = L L^T``),
    computed by a triangular solve instead of an explicit inverse.
    """
    return _small.lifted_form(ellipsoid.chol, ellipsoid.center, frame)


def _require_certificate(forms: np.ndarray) -> None:
    """Refuse instances where no multipliers can exist, instead of letting the solver fail.

    The LMI needs ``sum tau_i A_i >= M > 0`` for the quadratic parts ``A_i``. If every ``A_i``
    is positive semidefinite and their sum is singular, that is impossible: the intersection
    is unbounded, or bounded only by half-spaces, which the S-procedure cannot use alone.
    """
    lowest, joint = _small.certificate_eigs(forms)
    if lowest < -_DEFINITE_RTOL:
        return  # an indefinite member (e.g. a ring's outside): leave it to the solver
    if joint <= _DEFINITE_RTOL:
        raise ValueError(
            "no ellipsoid can be certified: the quadratic parts of the members are not jointly "
            "positive definite (the intersection is unbounded, or bounded by half-spaces only; "
            "add a bounded member such as an Ellipsoid)"
        )


def _check_dims(objective: str, dims, n: int) -> tuple[int, ...] | None:
    if objective not in OBJECTIVES:
        raise ValueError(f"objective must be one of {OBJECTIVES}, got {objective!r}")
    if objective != "projection":
        if dims is not None:
            raise ValueError('dims is only used with objective="projection"')
        return None
    if dims is None:
        raise ValueError('objective="projection" needs dims (the coordinates to project on)')
    return tuple(int(i) for i in v.dims_index("dims", dims, n))


def outer_ellipsoid(
    intersection: Sequence[QuadraticallyDescribed],
    objective: str = "volume",
    dims: Sequence[int] | None = None,
    clip: str | bool = "intersection",
    products: bool = False,
    solver: str = "CLARABEL",
    lower_bound: bool = False,
    rng=0,
) -> OuterResult:
    """Certified optimal outer ellipsoid of an intersection, by the S-procedure SDP.

    Parameters
    ----------
    intersection : sequence of QuadraticallyDescribed (Ellipsoid, Strip, Halfspace, Box, ...)
        The sets whose intersection is bounded (same dimension n): any type with a quadratic
        description (``optbound.sets.base.QuadraticallyDescribed``).
    objective : {"volume", "trace", "projection"}
        Minimise the volume, the trace of the shape matrix, or the volume of the projection
        onto ``dims`` (see the module docstring for the projection derivation).
    dims : sequence of int, optional
        Coordinates of the projection (``objective="projection"`` only).
    clip : {"intersection", "ellipsoids", False}
        How strips, half-spaces and boxes are clipped before the S-procedure (the set is
        unchanged; ``True`` means the default, ``"intersection"``). ``"ellipsoids"``: to the
        extent of each bounded member; the S-procedure is not tight with a strip whose far
        plane misses the ellipsoid, and the raw problem (``False``) returns the raw
        [HS96, eq. (24)] family's optimum instead. ``"intersection"``: then to the exact
        extent of each normal over the first bounded member ∩ all the linear ranges (one
        certified SOCP, ``optbound.optimal.extents``); with many strips this is much tighter
        (``docs/user_guide/optimal.md``), and with one strip it is the same as ``"ellipsoids"``.
    products : bool
        Also impose the pair products of the (clipped) linear ranges, four per pair
        (``optbound.optimal.lift``): tighter for many strips, at ``2 r (r - 1)`` extra
        multipliers for ``r`` ranges (``docs/user_guide/optimal.md`` has the measured effect).
    solver : {"CLARABEL", "SCS"}
        Conic solver.
    lower_bound : bool
        Also compute a lower bound on the true minimum over all ellipsoids (a weak-duality
        bound on points of the set pushed toward its extreme points; see
        ``optbound.optimal.lower``). It costs a small multiple of the call without it
        (``python -m benchmarks.lower_bound_cost`` measures it), mostly the search for the
        set's extreme points, on which the bound's quality rests from n = 3 on.
    rng : Generator or int
        Seed of the sampling for ``lower_bound``.

    Returns
    -------
    OuterResult
        Certified; ``multipliers`` has one entry per quadratic inequality of
        ``optbound.optimal.lift.lift(intersection, clip, products)`` (one per member, one per
        finite coordinate of a Box, then the products), valid for the original (unscaled)
        inequalities.

    Raises
    ------
    EmptyIntersectionError
        If clipping finds the intersection empty, or multipliers certify that it is
        (``sum tau_i F_i`` positive definite, checked in float64): those of the solve, or, when
        the solve fails, those of a small emptiness SDP.
    SolverError
        If the solve is infeasible (no ellipsoid contains the set: it is unbounded), inaccurate
        or fails.
    ValueError
        For bad arguments, or when no S-procedure certificate can exist (unbounded
        intersection, or one bounded by half-spaces only).

    References
    ----------
    .. [BEFB94] S. Boyd, L. El Ghaoui, E. Feron, V. Balakrishnan, "Linear Matrix Inequalities
       in System and Control Theory", SIAM, 1994, Sect. 3.7 (the S-procedure).

    Examples
    --------
    >>> import numpy as np
    >>> from optbound import Ellipsoid, Strip, optimal
    >>> r = optimal.outer_ellipsoid([Ellipsoid(np.zeros(2), np.eye(2)), Strip([2.0, 0.0], 0.0)])
    >>> r.certified
    True
    >>> np.round(np.diag(r.ellipsoid.shape), 4)  # the optimum: diag(0.5, 1.5)
    array([0.5, 1.5])
    """
    quadratics = lift(intersection, clip=clip, products=products)
    n, k = quadratics[0].dim, len(quadratics)
    dims_t = _check_dims(objective, dims, n)
    center, W = _frame(quadratics, dims_t)
    frame = np.eye(n + 1)
    frame[:n, :n] = W
    frame[:n, n] = center
    normalized, norms, form_errors = _in_frame(quadratics, frame)
    _require_certificate(normalized)

    template = intersection_template(n, k, objective, dims_t)
    # Column i is F_hat_i flattened in column-major order (symmetric: the same as row-major).
    template.set(forms=normalized.reshape(k, -1).T)
    if template.weight is not None:
        template.set(weight=_cvx.trace_weight(W))
    try:
        solve_time = template.solve(solver, primal_only=True)
    except SolverError as err:
        if err.status == cp.INFEASIBLE:
            raise SolverError(
                err.status, "no ellipsoid satisfies the S-procedure: is the intersection bounded?"
            ) from err
        explain_failure(normalized, form_errors, solver, err)

    refuse_empty(normalized, form_errors, template.tau.value)
    # W is the read-only Cholesky factor, or a new array for the projection: a writable copy
    # in both cases compiles ``ellipsoid_in_x`` once.
    candidate = Ellipsoid._from_kernel(
        *_small.ellipsoid_in_x(template.M.value, template.bt.value, center, np.array(W))
    )
    tau = np.maximum(template.tau.value, 0.0)
    corner = np.zeros((n + 1, n + 1))
    corner[n, n] = 1.0
    # Certified in the frame (congruence by T): tau_i F_hat_i there is (tau_i / norm_i) F_i.
    ellipsoid, inflation, beta = certify_lmi(
        candidate,
        lambda e: _lifted_form(e, frame),
        corner,
        tau,
        normalized,
        uncertainty=float(tau @ form_errors),
    )
    multipliers = tau / norms

    bound = None
    if lower_bound:
        # The same set, without the planes clipped to touch its vertices: with those, the
        # boundary points near a vertex are nearly active in several forms at once and fail
        # the float64 margin of ``lower``.
        if check_clip(clip) == "intersection":
            quadratics = lift(intersection, clip="ellipsoids")
        bound = sampled_lower_bound(quadratics, ellipsoid, objective, dims_t, rng)
    return OuterResult(
        ellipsoid=ellipsoid,
        objective=objective_value(ellipsoid, objective, dims_t),
        status=template.problem.status,
        solve_time=solve_time,
        multipliers=beta * multipliers,
        certified=True,
        inflation=inflation,
        lower_bound=bound,
    )
