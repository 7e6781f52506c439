"""Solver handling: names, the Clarabel version check, statuses that are refused."""

import cvxpy as cp
import pytest

from optbound.optimal import SolverError
from optbound.optimal.solver import check_solver, solve


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
