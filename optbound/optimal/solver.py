"""Running a cached cvxpy problem: solver choice, version check, settings, retries, timing.

Clarabel settings, chosen on the benchmark's strip and Minkowski instances (condition numbers
up to 1e6; ``tests/optimal/test_hard_instances.py``):

- a fresh Clarabel solver for every solve (``warm_start=False``). cvxpy's warm start re-uses
  the previous solve's Clarabel object and only overwrites its data, which Clarabel scales with
  the *old* equilibration (Clarabel's ``data_updating.rs``), so an answer could depend on the
  instances solved before it.
- ``max_step_fraction=0.9`` (default 0.99): with full steps, 8 of 17,400 solves stalled
  ("InsufficientProgress" or "AlmostSolved", i.e. cvxpy's "solver_error" and
  "optimal_inaccurate"), mostly with the projection objective, whose optimal face is
  degenerate (only a Schur complement of M is determined). With shorter steps none of the
  17,400 (the full suite's instances for suite seeds 0, 1, 2) stalled, for about 4 % more time.

A solve whose status is not exactly "optimal" is retried once with a more conservative
setting (equilibration off, shorter steps, more iterations): our data are already normalised
in a whitened frame, so equilibration has nothing to fix. If the retry is not "optimal"
either, ``SolverError`` is raised; an inaccurate answer is never accepted.
"""

from __future__ import annotations

import time
import warnings
from functools import cache

import cvxpy as cp

from optbound.optimal.errors import SolverError

SOLVERS = ("CLARABEL", "SCS")
# Clarabel gained PSD cones in 0.5.0; log det needs them together with exponential cones.
_MIN_CLARABEL = (0, 5, 0)
# Clarabel's relative duality gap is taken relative to max(1, |objective|), so for the small
# objective values of narrow sets its default 1e-8 acts as an absolute tolerance: a min-trace
# reference came out 6.5e-4 above the analytic optimum (benchmark strip, seed 798589535).
# Tighter gaps bring every quick-suite reference within 1.1e-5 of it, for ~9 % more time.
_GAPS = {"tol_gap_abs": 1e-14, "tol_gap_rel": 1e-10}
ATTEMPTS = {
    "CLARABEL": (
        {"max_step_fraction": 0.9, **_GAPS},
        {"max_step_fraction": 0.8, "equilibrate_enable": False, "max_iter": 500, **_GAPS},
    ),
    "SCS": ({"eps_abs": 1e-9, "eps_rel": 1e-9, "max_iters": 200_000},),
}


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


def _status_of(problem: cp.Problem, name: str, options: dict) -> str:
    with warnings.catch_warnings():
        # cvxpy warns about inaccurate solutions; the status is checked (and refused) here.
        warnings.filterwarnings("ignore", message="Solution may be inaccurate")
        try:
            problem.solve(solver=name, warm_start=False, **options)
        except cp.error.SolverError:
            return "solver_error"
    return problem.status


def solve(problem: cp.Problem, solver: str) -> float:
    """Solve ``problem`` in place and return the wall time of all attempts in seconds.

    Raises
    ------
    SolverError
        Unless an attempt ends with status exactly "optimal" (inaccurate answers are
        refused); an infeasible problem is not retried.
    """
    name = check_solver(solver)
    statuses = []
    start = time.perf_counter()
    for options in ATTEMPTS[name]:
        status = _status_of(problem, name, options)
        if status == cp.OPTIMAL:
            return time.perf_counter() - start
        statuses.append(status)
        if status in (cp.INFEASIBLE, cp.UNBOUNDED):
            break
    detail = f"attempts gave {statuses}" if len(statuses) > 1 else ""
    raise SolverError(statuses[-1], detail)
