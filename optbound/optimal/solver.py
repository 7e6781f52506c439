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
The first solve also prepares, once per compiled program (``_FastProgram``), what every
re-solve shares: from cvxpy's compiled parameter map (``ParamConeProg``), Clarabel's ``A``
with its fixed sparsity pattern, the parameter columns, the zero ``P`` and the cones, and for
each variable the entries of Clarabel's ``x`` that form its value (read off cvxpy's own
inverse reductions once). A re-solve is then two sparse products with the parameter vector,
a fresh Clarabel solver with the first ``ATTEMPTS`` setting, and one selection per variable.
Dual values are not recovered (they keep those of an earlier solve), so only callers that read
primal values opt in. Any Clarabel status but "Solved" falls back to the full path with its
retries and refusals. ``tests/optimal/test_solver.py`` checks that both paths give the same
statuses, values and certified ellipsoids.

The fast path reads cvxpy's private compiled program (``Problem._cache``, ``ParamConeProg``,
``ReducedMat``, the inverse reductions), which cvxpy may change in any release: it is used
only under the cvxpy releases of :data:`FAST_PATH_CVXPY`, on which those tests passed; under
any other cvxpy every solve takes the public ``problem.solve`` path (same answers, slower).
"""

from __future__ import annotations

import re
import time
import warnings
from functools import cache

import cvxpy as cp
import numpy as np
import scipy.sparse as sp

from optbound.optimal.errors import SolverError

#: cvxpy releases (major, minor) on which the fast path was verified.
FAST_PATH_CVXPY = ((1, 9),)


def fast_path_supported(version: str) -> bool:
    """Whether cvxpy ``version`` (e.g. ``"1.9.3"``) is one of :data:`FAST_PATH_CVXPY`.

    Parameters
    ----------
    version : str
        A cvxpy version string.

    Returns
    -------
    bool
        True if its major.minor release is verified for the fast path.
    """
    match = re.match(r"(\d+)\.(\d+)", version)
    return match is not None and (int(match[1]), int(match[2])) in FAST_PATH_CVXPY


#: Whether ``solve(..., primal_only=True)`` may take the fast path under the installed cvxpy.
FAST_PATH = fast_path_supported(cp.__version__)

if FAST_PATH:  # private modules, imported only where their layout was verified
    from cvxpy.lin_ops.lin_op import CONSTANT_ID
    from cvxpy.reductions.solution import Solution
    from cvxpy.reductions.solvers.conic_solvers.clarabel_conif import (
        CLARABEL,
        dims_to_solver_cones,
    )

SOLVERS = ("CLARABEL", "SCS")
#: Clarabel's own solve time (its ``solve_time``, seconds) of the last fast-path solve in this
#: process, or None; ``optbound/bench/sdp_cache.py`` divides a whole call's time by it.
last_clarabel_seconds: float | None = None
# Clarabel gained PSD cones in 0.5.0; log det needs them together with exponential cones.
_MIN_CLARABEL = (0, 5, 0)
# Clarabel's relative duality gap is taken relative to max(1, |objective|), so for the small
# objective values of narrow sets its default 1e-8 acts as an absolute tolerance: a min-trace
# reference came out 6.5e-4 above the analytic optimum (benchmark strip, seed 798589535).
# Tighter gaps bring every quick-suite reference within 1.1e-5 of it, for ~9 % more time.
# Where they cannot be reached (e.g. an MVEE of hundreds of points), the default gaps follow.
_GAPS = {"tol_gap_abs": 1e-14, "tol_gap_rel": 1e-10}
# Parameter maps with at most this many entries are kept dense (32 kB at the most).
_DENSE_ENTRIES = 4096
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
    """Return the canonical solver name, or raise ``ValueError`` if it cannot do the job.

    Parameters
    ----------
    solver : str
        A solver name, any case.

    Returns
    -------
    str
        The upper-case name.

    Raises
    ------
    ValueError
        If the solver is unknown, not installed for cvxpy, or (Clarabel) too old for PSD and
        exponential cones together.
    """
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


class _FastProgram:
    """One compiled program, prepared for re-solves with Clarabel directly.

    Built once per program (on its first fast re-solve), it holds what does not change between
    re-solves: the sparsity pattern of ``A`` (cvxpy's ``ReducedMat``: the values of ``[A, b]``
    are one sparse product with the parameter vector), Clarabel's zero ``P`` and cone list, the
    parameter columns, and for each variable of the problem the entries of Clarabel's ``x`` that
    make up its value. The latter map is read off cvxpy's own inverse reductions, evaluated once
    at ``x = 1, 2, ..., N``; it is used only if every value is a plain selection of entries of
    ``x`` (symmetric variables are: cvxpy stores their upper triangle), checked again at a
    positive random ``x`` (positive because the inverses project onto the variables' domains,
    e.g. ``nonneg``, which ``unpack`` also does). Otherwise ``variables`` is None and the
    inverse reductions run per solve.
    """

    def __init__(self, problem: cp.Problem, program) -> None:
        # No reference back to ``program``, which holds this object: no cycle that only the
        # garbage collector could free when the template cache drops the problem.
        self.param_size = program.total_param_size
        self.q = _dense_if_small(program.q)
        # Parameters with attributes (e.g. PSD) are replaced by reduced copies in the compiled
        # program, whose values the reductions' ``update_parameters`` set on every solve.
        own = {param.id for param in problem.parameters()}
        self.reduced_params = any(
            key not in own for key in program.param_id_to_col if key != CONSTANT_ID
        )
        self.columns = [
            (program.id_to_param[key], col, program.param_id_to_size[key])
            for key, col in program.param_id_to_col.items()
            if key != CONSTANT_ID
        ]
        self.constant_col = program.param_id_to_col.get(CONSTANT_ID)
        program.reduced_A.cache()
        self.values_map = _dense_if_small(program.reduced_A.reduced_mat)
        indices, indptr, (rows, cols) = program.reduced_A.problem_data_index
        self.split = indptr[-2]
        self.b_rows = indices[self.split :]
        n = cols - 1
        self.A = sp.csc_array(
            (np.zeros(self.split), indices[: self.split], indptr[:-1]), shape=(rows, n)
        )
        self.P = sp.csc_array((n, n))
        self.cones = dims_to_solver_cones(program.cone_dims)
        self.variables = self._selections(problem, n)

    def parameter_vector(self, problem: cp.Problem) -> np.ndarray:
        """cvxpy's parameter vector (``canonInterface.get_parameter_vector``), column order."""
        if self.reduced_params:
            for reduction in problem._cache.solving_chain.reductions:
                reduction.update_parameters(problem)
        params = np.zeros(self.param_size + 1)
        for param, col, size in self.columns:
            params[col : col + size] = np.ravel(param.value, order="F")
        if self.constant_col is not None:
            params[self.constant_col] = 1.0
        return params

    def data(self, params: np.ndarray) -> tuple[np.ndarray, float, sp.csc_array, np.ndarray]:
        """``(c, d, A, b)`` for ``min c x + d, A x + s = b``, as cvxpy's ``ConicSolver.apply``.

        ``A`` is the one cached matrix with new values (Clarabel copies its data)."""
        q = self.q @ params
        values = self.values_map @ params
        self.A.data[:] = -values[: self.split]
        b = np.zeros(self.A.shape[0])
        b[self.b_rows] = values[self.split :]
        return np.ravel(q[:-1]), float(q[-1]), self.A, b

    @staticmethod
    def _invert(problem: cp.Problem, x: np.ndarray, objective: float) -> Solution:
        """Primal values of the problem's variables from Clarabel's ``x``, by cvxpy's own
        inverses of its reductions (skipping the solver's, which recovers duals)."""
        solution = Solution(cp.OPTIMAL, objective, {problem._cache.param_prog.x.id: x}, {}, {})
        chain = problem._cache.solving_chain.reductions[:-1]
        for reduction, inverse in reversed(
            list(zip(chain, problem._cache.inverse_data, strict=True))
        ):
            solution = reduction.invert(solution, inverse)
        return solution

    def _selections(self, problem: cp.Problem, n: int) -> list | None:
        coded = self._invert(problem, np.arange(1.0, n + 1.0), 0.0).primal_vars
        check = np.random.default_rng(0).uniform(1.0, 2.0, n)
        checked = self._invert(problem, check, 0.0).primal_vars
        selections = []
        for variable in problem.variables():
            code = np.asarray(coded[variable.id], dtype=float)
            index = np.rint(code).astype(np.intp) - 1
            valid = np.array_equal(code, index + 1.0) and np.all((index >= 0) & (index < n))
            recovered = variable.project(check[index])
            if not valid or not np.array_equal(recovered, checked[variable.id]):
                return None
            selections.append((variable, index, _projection(variable, index)))
        return selections

    def unpack(self, problem: cp.Problem, x: np.ndarray, objective: float) -> None:
        """Set the variables' values (and the problem's status) from Clarabel's ``x``."""
        if self.variables is None:
            problem.unpack(self._invert(problem, x, objective))
            return
        for variable, index, project in self.variables:
            value = x[index]
            variable.save_value(value if project is None else project(value))
        # What ``Problem.unpack`` sets, without re-evaluating the objective (e.g. a log det).
        problem._status = cp.OPTIMAL
        problem._value = -objective if isinstance(problem.objective, cp.Maximize) else objective


def _dense_if_small(matrix: sp.sparray | sp.spmatrix) -> sp.sparray | sp.spmatrix | np.ndarray:
    """A small parameter map as a dense array: scipy's sparse product costs microseconds of
    Python checks, a dense one of this size less than one."""
    return matrix.toarray() if np.prod(matrix.shape) <= _DENSE_ENTRIES else matrix


def _projection(variable: cp.Variable, index: np.ndarray):
    """What cvxpy's ``variable.project`` does to a selection ``x[index]``: nothing for a plain
    variable, or for a symmetric one whose selection is symmetric (cvxpy would average it with
    its transpose); the clipping at 0 for ``nonneg``; else ``project`` itself."""
    attributes = {name for name, value in variable.attributes.items() if value}
    if not attributes or (attributes == {"symmetric"} and np.array_equal(index, index.T)):
        return None
    if attributes == {"nonneg"}:
        return lambda value: np.maximum(value, 0.0)
    return variable.project


def _fast_program(problem: cp.Problem) -> _FastProgram | None:
    """The prepared compiled program of ``problem`` if the fast path can use it, else None."""
    program = _compiled(problem)
    if program is None:
        return None
    fast = getattr(program, "_optbound_fast", None)
    if fast is None:
        fast = _FastProgram(problem, program)
        program._optbound_fast = fast
    return fast


def _fast_solve(problem: cp.Problem) -> bool:
    """Re-solve a compiled ``problem`` with Clarabel directly; True if Clarabel "Solved" it."""
    import clarabel

    fast = _fast_program(problem)
    if fast is None:
        return False
    c, offset, A, b = fast.data(fast.parameter_vector(problem))
    settings = CLARABEL.parse_solver_opts(False, ATTEMPTS["CLARABEL"][0])
    result = clarabel.DefaultSolver(fast.P, c, A, b, fast.cones, settings).solve()
    global last_clarabel_seconds
    last_clarabel_seconds = float(result.solve_time)
    if str(result.status) != "Solved":
        return False
    fast.unpack(problem, np.asarray(result.x), result.obj_val + offset)
    return True


def solve(problem: cp.Problem, solver: str, primal_only: bool = False) -> float:
    """Solve ``problem`` in place and return the wall time of all attempts in seconds.

    With ``primal_only`` (the caller reads no dual values), re-solves with Clarabel take the
    fast path described in the module docstring (under a verified cvxpy, :data:`FAST_PATH`).

    Parameters
    ----------
    problem : cvxpy.Problem
        The problem, solved in place (its variables get their values).
    solver : {"CLARABEL", "SCS"}
        The conic solver.
    primal_only : bool, default False
        The caller reads no dual values (allows the fast path).

    Returns
    -------
    float
        Wall time of all attempts, in seconds.

    Raises
    ------
    SolverError
        Unless an attempt ends with status exactly "optimal" (inaccurate answers are
        refused); an infeasible problem is not retried.
    """
    name = check_solver(solver)
    fast = primal_only and name == "CLARABEL" and FAST_PATH
    statuses = []
    start = time.perf_counter()
    if fast and _fast_solve(problem):
        return time.perf_counter() - start
    for options in ATTEMPTS[name]:
        status = _status_of(problem, name, options)
        if status == cp.OPTIMAL:
            if fast:  # prepare the re-solves now, as part of the first (compiling) solve
                _fast_program(problem)
            return time.perf_counter() - start
        statuses.append(status)
        if status in (cp.INFEASIBLE, cp.UNBOUNDED):
            break
    detail = f"attempts gave {statuses}" if len(statuses) > 1 else ""
    raise SolverError(statuses[-1], detail)
