"""The result object every reference solver returns, and the objective values it reports."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from optbound.sets import Ellipsoid
from optbound.sets.result import BoundResult


@dataclass(frozen=True)
class OuterResult(BoundResult):
    """A certified outer ellipsoid and how it was obtained (a ``BoundResult``: ``set`` is
    ``ellipsoid``, ``margin`` is ``inflation - 1``).

    Parameters
    ----------
    ellipsoid : Ellipsoid
        The outer bound, certified in float64 (already inflated by ``inflation``).
    objective : float
        The objective evaluated on ``ellipsoid``: volume, trace of the shape matrix, or
        volume of the projection onto ``dims``, depending on the objective asked for.
    status : str
        The solver status (always "optimal": anything else raises ``SolverError``).
    solve_time : float
        Wall time of the conic solve in seconds (cvxpy parameter update + solver).
    multipliers : np.ndarray
        The S-procedure multipliers, one per quadratic inequality used (empty for ``mvee``).
    certified : bool
        True: the float64 certificate holds (results that fail are never returned).
    inflation : float
        Factor >= 1 applied to the solver's semi-axes to make the certificate hold.
    lower_bound : float or None
        When requested, a lower bound on the true minimum of the objective over *all*
        ellipsoids containing the set (so the reference's own gap is known).

    Attributes
    ----------
    accuracy : float
        Class constant 1e-5: how far (as a relative level, ``compare.max_level - 1``) the
        ellipsoid may lie from the true optimum in either direction. The conic solvers stop at
        relative gaps near 1e-8, which leaves the optimal shape itself accurate to a few 1e-6
        (2.9e-6 with Clarabel on the user guide's ellipse ∩ strip); ``compare.contains`` uses it
        as its default tolerance when this result is one of its arguments.
    """

    set_attribute = "ellipsoid"
    accuracy: ClassVar[float] = 1e-5

    ellipsoid: Ellipsoid
    objective: float
    status: str
    solve_time: float
    multipliers: np.ndarray
    certified: bool
    inflation: float
    lower_bound: float | None = None

    @property
    def margin(self) -> float:
        """Relative enlargement of the semi-axes, ``inflation - 1``."""
        return self.inflation - 1.0


def objective_value(ellipsoid: Ellipsoid, objective: str, dims: tuple[int, ...] | None) -> float:
    """Volume, trace of the shape, or volume of the projection on ``dims``.

    Parameters
    ----------
    ellipsoid : Ellipsoid
        The ellipsoid.
    objective : {"volume", "trace", "projection"}
        The objective.
    dims : tuple of int or None
        Coordinates of the projection objective.

    Returns
    -------
    float
        The objective's value on ``ellipsoid``.
    """
    if objective == "volume":
        return ellipsoid.volume()
    if objective == "trace":
        return float(np.trace(ellipsoid.shape))
    return ellipsoid.project(dims).volume()
