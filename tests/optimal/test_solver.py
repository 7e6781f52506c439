"""Solver handling: names, the Clarabel version check, statuses that are refused, and the fast
re-solve path (``solve(..., primal_only=True)``) against ``problem.solve``.

For the fast path, each public call leaves its cached template with that instance's parameter
values; the template is then solved by both paths with the same Clarabel settings, which must
give the same status and the same values of every variable.
"""

import cvxpy as cp
import mpmath
import numpy as np
import pytest

from optbound import Ellipsoid
from optbound.optimal import SolverError, intersection, minkowski, mvee, solver, template
from optbound.optimal.lift import lift
from optbound.optimal.solver import check_solver, solve
from tests.analytic.instances import random_ellipsoid, strip_relative_to


def test_names_are_canonicalised_and_unknown_refused():
    assert check_solver("clarabel") == "CLARABEL"
    with pytest.raises(ValueError, match="solver"):
        check_solver("GUROBI")


def test_old_clarabel_is_refused(monkeypatch):
    import clarabel

    monkeypatch.setattr(clarabel, "__version__", "0.4.1")
    check_solver.cache_clear()
    try:
        with pytest.raises(ValueError, match="too old"):
            check_solver("CLARABEL")
    finally:
        monkeypatch.undo()
        check_solver.cache_clear()


class _FakeProblem:
    def __init__(self, status):
        self.status = status

    def solve(self, **kwargs):
        pass


@pytest.mark.parametrize("status", [cp.OPTIMAL_INACCURATE, cp.INFEASIBLE, cp.UNBOUNDED])
def test_non_optimal_statuses_raise_with_the_status(status):
    with pytest.raises(SolverError) as err:
        solve(_FakeProblem(status), "CLARABEL")
    assert err.value.status == status
    assert isinstance(err.value, RuntimeError)


def test_optimal_returns_a_time():
    assert solve(_FakeProblem(cp.OPTIMAL), "CLARABEL") >= 0.0


RTOL = 1e-9
SEEDS = range(10)


@pytest.fixture
def solved_problems(monkeypatch):
    """The problems solved by the public calls made during a test, in order."""
    problems = []

    def recording_solve(problem, name, primal_only=False):
        problems.append(problem)
        return solver.solve(problem, name, primal_only=primal_only)

    # Every cached template solves through ``Template.solve``.
    monkeypatch.setattr(template, "solve", recording_solve)
    return problems


def _assert_paths_agree(problem: cp.Problem) -> None:
    fast_solved = solver._fast_solve(problem)
    fast = [v.value.copy() for v in problem.variables()] if fast_solved else None
    fast_value = problem.value
    assert problem.status == cp.OPTIMAL
    status = solver._status_of(problem, "CLARABEL", solver.ATTEMPTS["CLARABEL"][0])
    assert fast_solved == (status == cp.OPTIMAL)
    assert fast_solved, "every instance here should solve"
    for value, variable in zip(fast, problem.variables(), strict=True):
        scale = max(1.0, np.max(np.abs(variable.value)))
        np.testing.assert_allclose(value, variable.value, rtol=0, atol=RTOL * scale)
    # The fast path reports the conic objective (e.g. the exponential-cone epigraph of a log
    # det), cvxpy the objective evaluated at the variables: equal to the solver's gap.
    assert fast_value == pytest.approx(problem.value, rel=1e-7, abs=1e-7)


def _strip_sets(n: int, seed: int) -> list:
    rng = np.random.default_rng(seed)
    E = random_ellipsoid(rng, n)
    return [E, strip_relative_to(E, rng.standard_normal(n), rng.uniform(-0.5, 0.5), 0.3)]


@pytest.mark.parametrize("n", [2, 3, 4, 5, 6])
@pytest.mark.parametrize("objective", ["volume", "trace", "projection"])
def test_strip_instances(solved_problems, n, objective):
    dims = [0, n - 1] if objective == "projection" else None
    for seed in SEEDS:
        intersection.outer_ellipsoid(_strip_sets(n, seed), objective=objective, dims=dims)
        _assert_paths_agree(solved_problems[-1])


@pytest.mark.parametrize("n", [2, 3, 4, 5, 6])
@pytest.mark.parametrize("objective", ["volume", "trace"])
def test_minkowski_instances(solved_problems, n, objective):
    for seed in SEEDS:
        rng = np.random.default_rng(seed)
        summands = [random_ellipsoid(rng, n) for _ in range(3)]
        minkowski.minkowski_outer(*summands, objective=objective)
        _assert_paths_agree(solved_problems[-1])


@pytest.mark.parametrize("n", [2, 3, 4, 5, 6])
def test_mvee_instances(solved_problems, n):
    for seed in SEEDS:
        rng = np.random.default_rng(seed)
        mvee(Ellipsoid(np.zeros(n), np.eye(n)).sample(4 * n, rng))
        _assert_paths_agree(solved_problems[-1])


def test_re_solves_take_the_fast_path(solved_problems, monkeypatch):
    """After the first solve of a template, the full ``problem.solve`` is not called again."""
    calls = []
    full = solver._status_of
    monkeypatch.setattr(solver, "_status_of", lambda *args: calls.append(args) or full(*args))
    for seed in SEEDS:
        intersection.outer_ellipsoid(_strip_sets(7, seed))
    assert len(calls) <= 1
    assert len(solved_problems) == len(SEEDS)


def test_a_failed_fast_solve_falls_back_to_the_full_path(solved_problems, monkeypatch):
    intersection.outer_ellipsoid(_strip_sets(3, 0))
    monkeypatch.setattr(solver, "_fast_solve", lambda problem: False)
    calls = []
    monkeypatch.setattr(solver, "_status_of", lambda *args: calls.append(args) or cp.INFEASIBLE)
    with pytest.raises(SolverError):
        solver.solve(solved_problems[-1], "CLARABEL", primal_only=True)
    assert len(calls) == 1


def _exact_certificate_margin(result, sets) -> mpmath.mpf:
    """Largest eigenvalue, at 50 digits with the floats read as exact numbers, of
    ``[I, -c]^T C^{-1} [I, -c] - e e^T - sum_i mu_i F_i`` (``e`` the last unit vector) for the
    returned ellipsoid (c, C) and multipliers mu: <= 0 certifies that the ellipsoid contains
    the intersection (the S-procedure)."""
    with mpmath.workdps(50):
        E = result.ellipsoid
        n = E.dim
        B = mpmath.matrix(n, n + 1)
        for i in range(n):
            B[i, i] = 1
            B[i, n] = -mpmath.mpf(E.center[i])
        lhs = B.T * mpmath.inverse(mpmath.matrix(E.shape.tolist())) * B
        lhs[n, n] -= 1
        for mu, q in zip(result.multipliers, lift(sets), strict=True):
            lhs -= mpmath.mpf(mu) * mpmath.matrix(q.F.tolist())
        return max(mpmath.eigsy(lhs, eigvals_only=True))


@pytest.mark.parametrize("n", [2, 3, 4])
@pytest.mark.parametrize("objective", ["volume", "trace", "projection"])
def test_fast_path_gives_the_plain_cvxpy_ellipsoid_certified(monkeypatch, n, objective):
    """On random ellipsoid-and-strip instances, the re-solve with Clarabel called directly on
    the cached data gives the ellipsoid that ``problem.solve`` gives (to solver tolerance),
    without calling ``problem.solve``, and that ellipsoid is certified in exact arithmetic."""
    dims = [0, n - 1] if objective == "projection" else None
    intersection.outer_ellipsoid(_strip_sets(n, 100), objective=objective, dims=dims)
    full = solver._status_of
    calls = []
    for seed in SEEDS:
        sets = _strip_sets(n, seed)
        calls.clear()
        monkeypatch.setattr(solver, "_status_of", lambda *a: calls.append(a) or full(*a))
        fast = intersection.outer_ellipsoid(sets, objective=objective, dims=dims)
        assert not calls  # the fast path only
        monkeypatch.setattr(solver, "_fast_solve", lambda problem: False)
        plain = intersection.outer_ellipsoid(sets, objective=objective, dims=dims)
        monkeypatch.undo()
        assert calls  # problem.solve only
        scale = np.linalg.norm(plain.ellipsoid.shape)
        np.testing.assert_allclose(fast.ellipsoid.shape, plain.ellipsoid.shape, atol=1e-8 * scale)
        np.testing.assert_allclose(
            fast.ellipsoid.center, plain.ellipsoid.center, atol=1e-8 * np.sqrt(scale)
        )
        assert fast.status == plain.status == cp.OPTIMAL and fast.certified
        assert _exact_certificate_margin(fast, sets) <= 0


def test_the_fast_path_is_limited_to_verified_cvxpy_releases():
    assert solver.fast_path_supported(cp.__version__) == solver.FAST_PATH
    major, minor = solver.FAST_PATH_CVXPY[0]
    assert solver.fast_path_supported(f"{major}.{minor}.0")
    assert solver.fast_path_supported(f"{major}.{minor}.12rc1")
    assert not solver.fast_path_supported(f"{major}.{minor + 1}.0")
    assert not solver.fast_path_supported(f"{major + 1}.{minor}.0")
    assert not solver.fast_path_supported("unknown")


@pytest.mark.skipif(not solver.FAST_PATH, reason="the fast path is off under this cvxpy")
@pytest.mark.parametrize("objective", ["volume", "trace", "projection"])
def test_an_unverified_cvxpy_takes_the_public_path_with_the_same_results(monkeypatch, objective):
    """With the fast path switched off (as under an unverified cvxpy), every solve goes
    through ``problem.solve``, the fast path's private reads are never made, and the answers
    are those of the fast path."""
    n = 3
    dims = [0, n - 1] if objective == "projection" else None
    intersection.outer_ellipsoid(_strip_sets(n, 100), objective=objective, dims=dims)
    fast = [
        intersection.outer_ellipsoid(_strip_sets(n, seed), objective=objective, dims=dims)
        for seed in SEEDS
    ]
    monkeypatch.setattr(solver, "FAST_PATH", False)
    private = []
    monkeypatch.setattr(solver, "_fast_program", lambda problem: private.append(problem))
    monkeypatch.setattr(solver, "_fast_solve", lambda problem: private.append(problem))
    full = solver._status_of
    calls = []
    monkeypatch.setattr(solver, "_status_of", lambda *a: calls.append(a) or full(*a))
    for seed, quick in zip(SEEDS, fast, strict=True):
        calls.clear()
        sets = _strip_sets(n, seed)
        plain = intersection.outer_ellipsoid(sets, objective=objective, dims=dims)
        assert calls  # problem.solve
        scale = np.linalg.norm(plain.ellipsoid.shape)
        np.testing.assert_allclose(quick.ellipsoid.shape, plain.ellipsoid.shape, atol=1e-8 * scale)
        np.testing.assert_allclose(
            quick.ellipsoid.center, plain.ellipsoid.center, atol=1e-8 * np.sqrt(scale)
        )
        assert plain.status == cp.OPTIMAL and plain.certified
        assert _exact_certificate_margin(plain, sets) <= 0
    assert not private
