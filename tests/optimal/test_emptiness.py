"""Emptiness certificates: sum tau_i F_i positive definite, and the fallback SDP."""

import numpy as np
import pytest

from optbound import Ellipsoid, QuadraticSet
from optbound.optimal import EmptyIntersectionError, SolverError
from optbound.optimal.emptiness import explain_failure, refuse_empty


def _balls(offset: float) -> list[np.ndarray]:
    e = np.array([1.0, 0.0])
    return [
        QuadraticSet.from_ellipsoid(Ellipsoid(offset * e, np.eye(2))).F,
        QuadraticSet.from_ellipsoid(Ellipsoid(-offset * e, np.eye(2))).F,
    ]


def test_disjoint_balls_are_certified_by_equal_multipliers():
    # q1 + q2 = 2 |x|^2 + 2 offset^2 - 2 > 0 for offset > 1.
    with pytest.raises(EmptyIntersectionError):
        refuse_empty(_balls(2.0), np.zeros(2), np.array([1.0, 1.0]))


def test_overlapping_balls_are_never_certified():
    for tau in ([1.0, 1.0], [5.0, 0.1], [0.0, 1.0]):
        refuse_empty(_balls(0.5), np.zeros(2), np.array(tau))


def test_fallback_sdp_certifies_or_reraises():
    err = SolverError("solver_error")
    with pytest.raises(EmptyIntersectionError):
        explain_failure(_balls(2.0), np.zeros(2), "CLARABEL", err)
    with pytest.raises(SolverError) as raised:
        explain_failure(_balls(0.5), np.zeros(2), "CLARABEL", err)
    assert raised.value is err
