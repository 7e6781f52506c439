"""Cached SDP templates: a cvxpy problem built once per shape with Parameters, then re-solved.

Building and compiling a cvxpy problem costs far more than solving a small one, so every
reference solver writes its problem once per *shape key* (dimension, number of members,
objective, ...) with the data as ``cp.Parameter`` s (DPP, so that a re-solve only updates the
parameters), keeps it in an LRU cache, and per call sets the parameters and solves.

A builder decorated with :func:`cached_template` returns a :class:`Template`: the problem and
named handles to the parameters it sets, the variables it reads and the constraints whose dual
values it reads. The decorated builder keeps ``functools.lru_cache``'s ``cache_info`` and
``cache_clear``.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import lru_cache
from typing import Any

import cvxpy as cp
import numpy as np

from optbound.optimal import _cvx
from optbound.optimal.solver import solve


class Template:
    """A DPP cvxpy problem and its named handles (parameters, variables, constraints).

    Parameters
    ----------
    problem : cp.Problem
        Must be DPP (checked: otherwise a re-solve would recompile from scratch).
    **handles
        The problem's parts by name, read back as attributes (``template.tau.value``).
    """

    __slots__ = ("_handles", "problem")

    def __init__(self, problem: cp.Problem, **handles: Any) -> None:
        self.problem = _cvx.require_dpp(problem)
        self._handles = handles

    def __getattr__(self, name: str) -> Any:
        try:
            return self._handles[name]
        except KeyError:
            raise AttributeError(f"the template has no handle {name!r}") from None

    def set(self, **values: np.ndarray) -> None:
        """Set the named parameters (``_cvx.set_value``: cvxpy's checks only where needed).

        Parameters
        ----------
        **values
            Parameter name to value (array_like of the parameter's shape).
        """
        for name, value in values.items():
            _cvx.set_value(self._handles[name], np.asarray(value, dtype=float))

    def solve(self, solver: str, primal_only: bool = False) -> float:
        """Solve in place (``optbound.optimal.solver.solve``); the wall time in seconds.

        Parameters
        ----------
        solver : {"CLARABEL", "SCS"}
            The conic solver.
        primal_only : bool, default False
            The caller reads no dual values (allows the fast path).

        Returns
        -------
        float
            Wall time of the solve, in seconds.

        Raises
        ------
        SolverError
            Unless the solve ends with status "optimal".
        """
        return solve(self.problem, solver, primal_only=primal_only)


def cached_template(maxsize: int) -> Callable[[Callable[..., Template]], Callable[..., Template]]:
    """Cache a template builder per shape key (its hashable arguments), ``maxsize`` shapes.

    Parameters
    ----------
    maxsize : int
        Number of shapes kept (least recently used dropped first).

    Returns
    -------
    callable
        A decorator: the builder wrapped by ``functools.lru_cache``.
    """
    return lru_cache(maxsize=maxsize)
