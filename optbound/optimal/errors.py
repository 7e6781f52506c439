"""Exceptions of the SDP reference solvers, so callers can tell a bad instance from a bad solve."""

from __future__ import annotations

from optbound.sets.base import EmptySetError


class SolverError(RuntimeError):
    """The conic solver did not return an accurate optimum (``status`` says what it returned).

    "optimal_inaccurate" is refused too: an inaccurate optimum is not a reference.

    Parameters
    ----------
    status : str
        The status the solver returned (kept as ``self.status``).
    detail : str, optional
        More context for the message.
    """

    def __init__(self, status: str, detail: str = ""):
        self.status = status
        message = f"SDP solve failed with status {status!r}"
        super().__init__(f"{message}: {detail}" if detail else message)


class EmptyIntersectionError(EmptySetError):
    """The sets to be bounded have an empty intersection: no outer ellipsoid is defined.

    A ``ValueError`` (through ``optbound.sets.base.EmptySetError``).
    """


class CertificationError(RuntimeError):
    """A solver answer could not be certified as an outer bound, even after inflation."""
