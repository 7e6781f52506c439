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

A solve whose status is not exactly "optimal" is retried with Clarabel's default gap
tolerances, then with a more conservative setting (equilibration off, shorter steps, more
iterations): our data are already normalised in a whitened frame, so equilibration has
nothing to fix. If no attempt is "optimal", ``SolverError`` is raised; an inaccurate answer
is never accepted.

Fast re-solve (``primal_only=True``, Clarabel only): once a problem has been solved normally,
its later solves skip the parts of ``problem.solve`` that a cached template does not need.
cvxpy's compiled parameter map (``ParamConeProg``, built by the first solve) gives Clarabel's
data as one sparse product with the parameter vector, Clarabel is called directly with the
first ``ATTEMPTS`` setting, and only the primal values are mapped back, through cvxpy's own
inverses of its reductions (e.g. the packing of symmetric variables). Dual values are not
recovered (they keep those of an earlier solve), so only callers that read primal values opt
in. Any Clarabel status but "Solved" falls back to the full path with its retries and
refusals. ``tests/optimal/test_solver.py`` checks that both paths give the same statuses and
values.
"""

from __future__ import annotations

import time
import warnings
from functools import cache

import cvxpy as cp
import numpy as np
import scipy.sparse as sp
from cvxpy.cvxcore.python import canonInterface
from cvxpy.reductions.solution import Solution
from cvxpy.reductions.solvers.conic_solvers.clarabel_conif import CLARABEL, dims_to_solver_cones

from optbound.optimal.errors import SolverError

SOLVERS = ("CLARABEL", "SCS")
#: Clarabel's own solve time (its ``solve_time``, seconds) of the last fast-path solve in this
#: process, or None; ``benchmarks/sdp_cache.py`` divides a whole call's time by it.
last_clarabel_seconds: float | None = None
# Clarabel gained PSD cones in 0.5.0; log det needs them together with exponential cones.
_MIN_CLARABEL = (0, 5, 0)
# Clarabel's relative duality gap is taken relative to max(1, |objective|), so for the small
# objective values of narrow sets its default 1e-8 acts as an absolute tolerance: a min-trace
# reference came out 6.5e-4 above the analytic optimum (benchmark strip, seed 798589535).
# Tighter gaps bring every quick-suite reference within 1.1e-5 of it, for ~9 % more time.
# Where they cannot be reached (e.g. an MVEE of hundreds of points), the default gaps follow.
_GAPS = {"tol_gap_abs": 1e-14, "tol_gap_rel": 1e-10}
ATTEMPTS = {
    "CLARABEL": (
        {"max_step_fraction": 0.9, **_GAPS},
        {"max_step_fraction": 0.9},
        {"max_step_fraction": 0.8, "equilibrate_enable": False, "max_iter": 500},
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


def _compiled(problem: cp.Problem):
    """cvxpy's compiled Clarabel program of ``problem`` if the fast path can use it, else None."""
    cache = problem._cache  # filled by the first problem.solve with these arguments
    if cache.param_prog is None or cache.key != cache.make_key("CLARABEL", False, False, None):
        return None
    program = cache.param_prog
    # Our templates have parameters, and no quadratic objective or variable bounds, which are
    # not passed on here.
    unsupported = (program.P, program.lb_tensor, program.ub_tensor)
    if program.total_param_size == 0 or any(part is not None for part in unsupported):
        return None
    return program


def _clarabel_data(
    problem: cp.Problem, program
) -> tuple[np.ndarray, float, sp.csc_array, np.ndarray]:
    """``(c, d, A, b)`` for ``min c x + d, A x + s = b``, as cvxpy's ``ConicSolver.apply``."""
    for reduction in problem._cache.solving_chain.reductions:
        reduction.update_parameters(problem)
    params = canonInterface.get_parameter_vector(
        program.total_param_size,
        program.param_id_to_col,
        program.param_id_to_size,
        lambda key: np.asarray(program.id_to_param[key].value),
    )
    q = program.q @ params
    # [A, b] is a CSC matrix with a fixed pattern whose values are linear in the parameters
    # (cvxpy's ``ReducedMat``).
    program.reduced_A.cache()
    values = program.reduced_A.reduced_mat @ params
    indices, indptr, (rows, cols) = program.reduced_A.problem_data_index
    split = indptr[-2]
    A = sp.csc_array((-values[:split], indices[:split], indptr[:-1]), shape=(rows, cols - 1))
    b = np.zeros(rows)
    b[indices[split:]] = values[split:]
    return np.ravel(q[:-1]), float(q[-1]), A, b


def _fixed_parts(program, n: int):
    """Clarabel's zero quadratic term and cone list of a compiled program: the same for every
    re-solve, so built once per program. (The settings are parsed per solve: ``ATTEMPTS``
    may change.)"""
    parts = getattr(program, "_optbound_fixed", None)
    if parts is None:
        parts = (sp.csc_array((n, n)), dims_to_solver_cones(program.cone_dims))
        program._optbound_fixed = parts
    return parts


def _fast_solve(problem: cp.Problem) -> bool:
    """Re-solve a compiled ``problem`` with Clarabel directly; True if Clarabel "Solved" it."""
    import clarabel

    program = _compiled(problem)
    if program is None:
        return False
    c, offset, A, b = _clarabel_data(problem, program)
    P, cones = _fixed_parts(program, c.size)
    settings = CLARABEL.parse_solver_opts(False, ATTEMPTS["CLARABEL"][0])
    result = clarabel.DefaultSolver(P, c, A, b, cones, settings).solve()
    global last_clarabel_seconds
    last_clarabel_seconds = float(result.solve_time)
    if str(result.status) != "Solved":
        return False
    x = {program.x.id: np.asarray(result.x)}
    solution = Solution(cp.OPTIMAL, result.obj_val + offset, x, {}, {})
    # cvxpy's own inverses of its reductions (skipping the solver's, which recovers duals).
    chain = problem._cache.solving_chain.reductions[:-1]
    for reduction, inverse in reversed(list(zip(chain, problem._cache.inverse_data, strict=True))):
        solution = reduction.invert(solution, inverse)
    problem.unpack(solution)
    return True


def solve(problem: cp.Problem, solver: str, primal_only: bool = False) -> float:
    """Solve ``problem`` in place and return the wall time of all attempts in seconds.

    With ``primal_only`` (the caller reads no dual values), re-solves with Clarabel take the
    fast path described in the module docstring.

    Raises
    ------
    SolverError
        Unless an attempt ends with status exactly "optimal" (inaccurate answers are
        refused); an infeasible problem is not retried.
    """
    name = check_solver(solver)
    fast = primal_only and name == "CLARABEL"
    statuses = []
    start = time.perf_counter()
    if fast and _fast_solve(problem):
        return time.perf_counter() - start
    for options in ATTEMPTS[name]:
        status = _status_of(problem, name, options)
        if status == cp.OPTIMAL:
            return time.perf_counter() - start
        statuses.append(status)
        if status in (cp.INFEASIBLE, cp.UNBOUNDED):
            break
    detail = f"attempts gave {statuses}" if len(statuses) > 1 else ""
    raise SolverError(statuses[-1], detail)
