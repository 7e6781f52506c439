"""Certificates that an intersection of quadratic sets is empty (S-lemma, weak direction).

If multipliers ``tau_i >= 0`` make ``sum_i tau_i F_i`` positive definite, no x can satisfy
every ``[x; 1]^T F_i [x; 1] <= 0``: summing the inequalities would give a non-positive value of
a positive definite form at ``[x; 1] != 0``. The check is done in float64 with a margin for the
rounding of forming the (normalised, frame-transformed) ``F_i`` and of the eigenvalues, so it
never fires for a non-empty intersection.

For an empty intersection the volume objective of the outer-ellipsoid SDP is unbounded: the
solver either stops at a vanishing ellipsoid (its multipliers then pass this check) or fails
numerically; in the latter case a second, small SDP looks for such multipliers.
"""

from __future__ import annotations

from collections.abc import Sequence

import cvxpy as cp
import numpy as np

from optbound.optimal import _cvx
from optbound.optimal._small import weighted_sum_eig
from optbound.optimal.errors import EmptyIntersectionError, SolverError
from optbound.optimal.template import Template, cached_template


@cached_template(maxsize=32)
def emptiness_template(n: int, k: int) -> Template:
    """Find ``tau >= 0`` with ``sum tau_i F_i >= I`` for ``k`` forms in R^n (built once)."""
    forms = tuple(cp.Parameter((n + 1, n + 1), symmetric=True) for _ in range(k))
    tau = cp.Variable(k, nonneg=True)
    S = sum(tau[i] * forms[i] for i in range(k))
    problem = cp.Problem(cp.Minimize(cp.sum(tau)), [_cvx.psd(S - np.eye(n + 1))])
    return Template(problem, forms=forms, tau=tau)


def refuse_empty(
    forms: np.ndarray | Sequence[np.ndarray], errors: np.ndarray, tau: np.ndarray
) -> None:
    """Raise ``EmptyIntersectionError`` if ``sum tau_i F_i`` is positive definite with margin.

    ``errors[i]`` bounds the spectral-norm error of ``forms[i]``.

    Parameters
    ----------
    forms : sequence of np.ndarray, shape (n + 1, n + 1) each
        The (normalised, frame-transformed) forms ``F_i``.
    errors : np.ndarray, shape (k,)
        Bounds of the spectral-norm error of each form.
    tau : np.ndarray, shape (k,)
        Candidate multipliers (negative entries are read as 0).

    Raises
    ------
    EmptyIntersectionError
        If the certificate holds: the intersection is empty.
    """
    # Frobenius norms bound the spectral norms from above: a larger margin, never a smaller.
    lowest, margin = weighted_sum_eig(
        np.maximum(tau, 0.0), np.asarray(forms, dtype=float), np.asarray(errors, dtype=float)
    )
    if lowest > margin:
        raise EmptyIntersectionError(
            "the intersection is empty (certified: sum_i tau_i F_i is positive definite)"
        )


def explain_failure(
    forms: Sequence[np.ndarray], errors: np.ndarray, solver: str, err: SolverError
) -> None:
    """After a failed solve, raise ``EmptyIntersectionError`` or re-raise ``err``.

    A small SDP looks for multipliers certifying emptiness (:func:`refuse_empty`).

    Parameters
    ----------
    forms : sequence of np.ndarray, shape (n + 1, n + 1) each
        The (normalised, frame-transformed) forms ``F_i``.
    errors : np.ndarray, shape (k,)
        Bounds of the spectral-norm error of each form.
    solver : str
        The cvxpy solver name.
    err : SolverError
        The error of the failed solve.

    Raises
    ------
    EmptyIntersectionError
        If emptiness can be certified.
    SolverError
        ``err``, otherwise (always raises).
    """
    template = emptiness_template(forms[0].shape[0] - 1, len(forms))
    for param, F in zip(template.forms, forms, strict=True):
        param.value = F
    try:
        template.solve(solver)
    except SolverError:
        raise err from None
    refuse_empty(forms, errors, template.tau.value)
    raise err
