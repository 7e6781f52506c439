"""Running a cached cvxpy problem: solver choice, version check, status handling, timing."""

from __future__ import annotations

import time
from functools import cache

import cvxpy as cp

from optbound.optimal.errors import SolverError

SOLVERS = ("CLARABEL", "SCS")
# Clarabel gained PSD cones in 0.5.0; log det needs them together with exponential cones.
_MIN_CLARABEL = (0, 5, 0)
_SOLVER_OPTIONS = {"CLARABEL": {}, "SCS": {"eps_abs": 1e-9, "eps_rel": 1e-9, "max_iters": 200_000}}


@cache
def check_solver(solver: str) -> str:
    """Return the canonical solver name, or raise ``ValueError`` if it cannot do the job."""
    name = str(solver).upper()
    if name not in SOLVERS:
        raise ValueError(f"solver must be one of {SOLVERS}, got {solver!r}")
    if name not in cp.installed_solvers():
        raise ValueError(f"solver {name} is not installed for cvxpy")
    if name == "CLARABEL":
        import clarabel

        version = tuple(int(part) for part in clarabel.__version__.split(".")[:3])
        has_cones = hasattr(clarabel, "PSDTriangleConeT") and hasattr(clarabel, "ExponentialConeT")
        if version < _MIN_CLARABEL or not has_cones:
            raise ValueError(
                f"clarabel {clarabel.__version__} is too old: PSD and exponential cones together "
                f"need clarabel >= {'.'.join(map(str, _MIN_CLARABEL))}"
            )
    return name


def solve(problem: cp.Problem, solver: str) -> float:
    """Solve ``problem`` in place and return the wall time of the solve in seconds.

    Raises
    ------
    SolverError
        Unless the status is exactly "optimal" (inaccurate answers are refused).
    """
    name = check_solver(solver)
    start = time.perf_counter()
    try:
        problem.solve(solver=name, **_SOLVER_OPTIONS[name])
    except cp.error.SolverError as err:
        raise SolverError("solver_error", str(err)) from err
    elapsed = time.perf_counter() - start
    if problem.status != cp.OPTIMAL:
        raise SolverError(problem.status)
    return elapsed
