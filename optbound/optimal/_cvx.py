"""Small cvxpy helpers shared by the problem templates."""

from __future__ import annotations

import cvxpy as cp
import numpy as np


def psd(expr: cp.Expression) -> cp.Constraint:
    """``expr >= 0`` in the PSD order for an expression that is symmetric by construction.

    Symmetrizing explicitly tells cvxpy so, instead of letting it add equality constraints.
    """
    return 0.5 * (expr + expr.T) >> 0


def column(vec: cp.Expression) -> cp.Expression:
    """A length-n expression as an (n, 1) column, for ``cp.bmat``."""
    return cp.reshape(vec, (vec.shape[0], 1), order="F")


def require_dpp(problem: cp.Problem) -> cp.Problem:
    """Refuse a template that cvxpy cannot re-solve by only updating parameters."""
    if not problem.is_dpp():
        raise RuntimeError("internal error: problem template is not DPP-compliant")
    return problem


def trace_weight(W: np.ndarray) -> np.ndarray:
    """The trace objective's weight ``W^T W`` in the frame ``x = c + W y``
    (``tr C = tr(W^T W C_y)``), exactly symmetric for a PSD Parameter and of unit norm."""
    weight = W.T @ W
    return 0.5 * (weight + weight.T) / np.linalg.norm(weight)


def set_value(param: cp.Parameter, value: np.ndarray) -> None:
    """``param.value = value`` for a finite array of the parameter's shape, built by our own
    code: cvxpy's checks (shape, sign, attributes) are skipped for a parameter without
    attributes, as they cost as much as a third of Clarabel's time on small problems."""
    if param.num_attributes or value.shape != param.shape or not np.isfinite(value).all():
        param.value = value  # cvxpy's checks, and its error for bad values
    else:
        param.save_value(value)
