"""Small linear programs, solved by HiGHS through its own Python binding (``highspy``).

``scipy.optimize.linprog(method="highs")`` runs the same solver (scipy vendors HiGHS), but
its wrapper converts the problem and validates every option on every call: about 1.3 ms per
call, four times HiGHS's own solve of the LPs optbound poses (supports and vertices of
constrained zonotopes, membership parameters, Farkas certificates, gain LPs: a few variables
and rows, thousands per run). :func:`solve_lp` passes the model as arrays to one HiGHS
instance per thread (0.3 ms per call), with scipy's settings: HiGHS's default solver choice
and the dual simplex strategy, or the dual simplex itself (``dual_simplex=True``, scipy's
``"highs-ds"``).

Nothing here is certified. Callers use a solution as a candidate that they verify (exact
arithmetic, outward-rounded bounds in :mod:`optbound.sets.certified`), or as a float estimate
that they say is one.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass

import highspy
import numpy as np

# HiGHS's infinity (a bound beyond it is no bound); numpy's inf is mapped to it.
_INF = highspy.kHighsInf
_CONTINUOUS = 0  # HiGHS's integrality code of a continuous variable
_local = threading.local()


@dataclass(frozen=True)
class LPResult:
    """What :func:`solve_lp` found.

    Attributes
    ----------
    optimal : bool
        Whether HiGHS reports an optimal solution; the other fields are None otherwise.
    status : str
        HiGHS's model status, e.g. ``"Optimal"``, ``"Infeasible"``, ``"Unbounded"``.
    x : np.ndarray or None
        The solution, shape (n,).
    eq_duals : np.ndarray or None
        The equality rows' multipliers: the objective's sensitivity to ``b_eq`` (scipy's
        ``res.eqlin.marginals``).
    """

    optimal: bool
    status: str
    x: np.ndarray | None = None
    eq_duals: np.ndarray | None = None


def _solver() -> highspy.Highs:
    """This thread's HiGHS instance, silent. ``highspy._Highs`` (exported by highspy) is the
    bare binding: its ``Highs`` subclass also installs callbacks, which print HiGHS's banner
    before any option can silence it, and cost time on every run."""
    h = getattr(_local, "highs", None)
    if h is None:
        h = highspy._Highs()
        h.setOptionValue("output_flag", False)
        h.setOptionValue("simplex_strategy", 1)  # dual simplex, as scipy sets it
        _local.highs = h
    return h


def _column_wise(A: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``A``'s non-zeros in compressed columns: (starts, row indices, values)."""
    nonzero = A.T != 0.0
    starts = np.zeros(A.shape[1] + 1, dtype=np.int32)
    np.cumsum(nonzero.sum(axis=1), out=starts[1:])
    return starts[:-1], np.nonzero(nonzero)[1].astype(np.int32), A.T[nonzero]


def _bound(value, n: int) -> np.ndarray:
    bound = np.broadcast_to(np.asarray(value, dtype=float), (n,))
    return np.clip(bound, -_INF, _INF) if np.isinf(bound).any() else bound


def solve_lp(
    c: np.ndarray,
    *,
    A_ub: np.ndarray | None = None,
    b_ub: np.ndarray | None = None,
    A_eq: np.ndarray | None = None,
    b_eq: np.ndarray | None = None,
    lower: float | np.ndarray = 0.0,
    upper: float | np.ndarray = np.inf,
    dual_simplex: bool = False,
) -> LPResult:
    """Minimise ``c^T x`` subject to ``A_ub x <= b_ub``, ``A_eq x = b_eq``, ``lower <= x <= upper``.

    The same problem, defaults included (``x >= 0``), as ``scipy.optimize.linprog``.

    Parameters
    ----------
    c : np.ndarray, shape (n,)
        Cost vector.
    A_ub, b_ub : np.ndarray, shape (p, n) and (p,), optional
        Inequality rows.
    A_eq, b_eq : np.ndarray, shape (q, n) and (q,), optional
        Equality rows.
    lower, upper : float or np.ndarray, shape (n,)
        Bounds on ``x``; ``-np.inf`` / ``np.inf`` for none.
    dual_simplex : bool
        Use the dual simplex method (a basic solution, scipy's ``"highs-ds"``) instead of
        HiGHS's own choice.

    Returns
    -------
    LPResult
        The solution if HiGHS finds it optimal; else ``optimal`` is False and ``status`` says
        why (HiGHS's model status, or non-finite data in ``c``, the rows or their right-hand
        sides; bounds may be infinite).
    """
    c = np.asarray(c, dtype=float)
    n = c.shape[0]
    blocks = [
        (np.asarray(A, dtype=float).reshape(-1, n), np.asarray(b, dtype=float))
        for A, b in ((A_ub, b_ub), (A_eq, b_eq))
        if A is not None
    ]
    A = np.vstack([block for block, _ in blocks]) if blocks else np.zeros((0, n))
    n_ub = 0 if A_ub is None else blocks[0][0].shape[0]
    rhs = np.concatenate([b for _, b in blocks]) if blocks else np.zeros(0)
    if not (np.isfinite(c).all() and np.isfinite(A).all() and np.isfinite(rhs).all()):
        # HiGHS would reject some and silently read others (a NaN cost as a number).
        return LPResult(False, "Non-finite problem data")
    lhs = rhs.copy()
    lhs[:n_ub] = -_INF
    starts, rows, values = _column_wise(A)
    h = _solver()
    h.setOptionValue("solver", "simplex" if dual_simplex else "choose")
    passed = h.passModel(
        n, A.shape[0], values.shape[0], 1, 1, 0.0,  # column-wise, minimise, no offset
        c, _bound(lower, n), _bound(upper, n), lhs, rhs,
        starts, rows, values, np.full(n, _CONTINUOUS, dtype=np.int32),
    )  # fmt: skip
    if passed == highspy.HighsStatus.kError:
        return LPResult(False, "Model rejected by HiGHS")
    h.run()
    status = h.getModelStatus()
    if status != highspy.HighsModelStatus.kOptimal:
        return LPResult(False, h.modelStatusToString(status))
    solution = h.getSolution()
    return LPResult(
        True,
        "Optimal",
        np.array(solution.col_value),
        np.array(solution.row_dual[n_ub:]),
    )


def least_inf_norm(M: np.ndarray, r: np.ndarray) -> LPResult:
    """``min t`` subject to ``M xi = r``, ``|xi_j| <= t``: a least-infinity-norm solution.

    Parameters
    ----------
    M : np.ndarray, shape (p, m)
        Rows (``p`` may be 0).
    r : np.ndarray, shape (p,)
        Right-hand side.

    Returns
    -------
    LPResult
        ``x`` is ``(xi, t)``, shape (m + 1,); ``eq_duals`` the multipliers of ``M xi = r``
        (a Farkas certificate candidate when the set ``|xi| <= 1`` misses the rows).
    """
    m = M.shape[1]
    eye, ones = np.eye(m), np.ones((m, 1))
    return solve_lp(
        np.r_[np.zeros(m), 1.0],
        A_ub=np.block([[eye, -ones], [-eye, -ones]]),
        b_ub=np.zeros(2 * m),
        A_eq=np.column_stack([M, np.zeros(M.shape[0])]),
        b_eq=r,
        lower=np.r_[np.full(m, -np.inf), 0.0],
    )


__all__ = ["LPResult", "least_inf_norm", "solve_lp"]
