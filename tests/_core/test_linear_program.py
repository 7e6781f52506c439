"""``solve_lp``: HiGHS through highspy, the problem of ``scipy.optimize.linprog``.

The solutions are floats (callers certify them), so they are compared with scipy's (the same
solver, perhaps another HiGHS version) to a tolerance; what must hold exactly is tested
exactly: statuses, basic solutions, independence of earlier solves and of the thread.
"""

from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest
from scipy.optimize import linprog

from optbound._core.linear_program import least_inf_norm, solve_lp


def _problems(count: int, seed: int = 0):
    """Random feasible ``min c^T xi, A xi = b, |xi| <= 1`` (constrained-zonotope supports)."""
    rng = np.random.default_rng(seed)
    for _ in range(count):
        n, m = int(rng.integers(2, 12)), int(rng.integers(1, 5))
        A = rng.standard_normal((m, n))
        A[rng.random(A.shape) < 0.3] = 0.0  # sparse rows: the column-wise packing
        yield rng.standard_normal(n), A, A @ rng.uniform(-0.5, 0.5, n)


@pytest.mark.parametrize("k", range(20))
def test_box_constrained_problem_agrees_with_scipy(k):
    c, A, b = list(_problems(20))[k]
    ours = solve_lp(c, A_eq=A, b_eq=b, lower=-1.0, upper=1.0)
    ref = linprog(c, A_eq=A, b_eq=b, bounds=(-1.0, 1.0), method="highs")
    assert ours.optimal and ours.status == "Optimal"
    assert abs(c @ ours.x - ref.fun) <= 1e-9 * (1.0 + abs(ref.fun))
    assert np.all(np.abs(ours.x) <= 1.0)
    assert np.allclose(A @ ours.x, b, atol=1e-9)
    # The duals are what ``sets.certified.max_bound`` uses: by weak duality they bound the
    # optimum, ``lam^T b - |c - A^T lam|_1 <= c^T xi``, with equality at optimal duals.
    lam = ours.eq_duals
    assert lam @ b - np.abs(c - A.T @ lam).sum() == pytest.approx(ref.fun, rel=1e-9, abs=1e-9)


def test_least_inf_norm_agrees_with_scipy():
    """``min t s.t. |xi_j| <= t, A xi = b``: inequality rows, free and half-bounded variables."""
    for c, A, b in _problems(10, seed=1):
        m = c.shape[0]
        eye, ones = np.eye(m), np.ones((m, 1))
        rows = {"A_ub": np.block([[eye, -ones], [-eye, -ones]]), "b_ub": np.zeros(2 * m)}
        rows |= {"A_eq": np.column_stack([A, np.zeros(A.shape[0])]), "b_eq": b}
        cost = np.r_[np.zeros(m), 1.0]
        ours = least_inf_norm(A, b)
        ref = linprog(cost, bounds=[(None, None)] * m + [(0.0, None)], method="highs", **rows)
        assert ours.optimal
        assert abs(ours.x[-1] - ref.x[-1]) <= 1e-9
        assert np.max(np.abs(ours.x[:m])) <= ours.x[-1]


def test_default_bounds_are_nonnegative_as_in_scipy():
    # min x0 + x1 s.t. x0 + x1 >= 1: with x >= 0 the optimum is 1 (free variables: unbounded).
    ours = solve_lp(np.ones(2), A_ub=-np.ones((1, 2)), b_ub=[-1.0])
    assert ours.optimal and ours.x.sum() == pytest.approx(1.0) and np.all(ours.x >= 0.0)
    free = solve_lp(np.r_[1.0, -1.0], A_ub=-np.ones((1, 2)), b_ub=[-1.0], lower=-np.inf)
    assert not free.optimal and free.status == "Unbounded"


def test_infeasible_problem_is_not_optimal_and_says_why():
    res = solve_lp(np.ones(2), A_eq=np.ones((1, 2)), b_eq=[5.0], lower=-1.0, upper=1.0)
    assert not res.optimal and res.status == "Infeasible"
    assert res.x is None and res.eq_duals is None


@pytest.mark.parametrize(
    "bad",
    [
        {"c": np.array([np.nan, 1.0])},
        {"A_eq": np.array([[np.inf, 1.0]]), "b_eq": np.array([0.0])},
        {"A_ub": np.ones((1, 2)), "b_ub": np.array([np.nan])},
    ],
)
def test_non_finite_data_is_not_optimal_and_says_so(bad):
    problem = {"c": np.ones(2), "lower": -1.0, "upper": 1.0} | bad
    res = solve_lp(**problem)
    assert not res.optimal and res.status == "Non-finite problem data" and res.x is None


def test_a_model_highs_rejects_is_not_optimal_and_says_so():
    res = solve_lp(np.ones(2), lower=np.array([np.nan, 0.0]), upper=1.0)  # a NaN bound
    assert not res.optimal and res.status == "Model rejected by HiGHS" and res.x is None


def test_dual_simplex_returns_a_basic_solution():
    """At most as many parameters off their bounds as there are rows (scipy's "highs-ds")."""
    for _, A, b in _problems(20, seed=2):
        res = solve_lp(
            np.zeros(A.shape[1]), A_eq=A, b_eq=b, lower=-1.0, upper=1.0, dual_simplex=True
        )
        assert res.optimal
        assert np.count_nonzero(np.abs(res.x) < 1.0) <= A.shape[0]


def test_a_solve_does_not_depend_on_earlier_solves_or_the_thread():
    problems = list(_problems(12, seed=3))
    first = [solve_lp(c, A_eq=A, b_eq=b, lower=-1.0, upper=1.0).x for c, A, b in problems]
    for c, A, b in problems[::-1]:  # other models, the other method, in between
        solve_lp(-c, A_eq=A, b_eq=b, lower=-1.0, upper=1.0, dual_simplex=True)
    again = [solve_lp(c, A_eq=A, b_eq=b, lower=-1.0, upper=1.0).x for c, A, b in problems]
    with ThreadPoolExecutor(4) as pool:
        threaded = list(
            pool.map(
                lambda p: solve_lp(p[0], A_eq=p[1], b_eq=p[2], lower=-1.0, upper=1.0).x, problems
            )
        )
    for x, y, z in zip(first, again, threaded, strict=True):
        assert np.array_equal(x, y) and np.array_equal(x, z)
