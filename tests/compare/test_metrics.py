"""Size ratios between bounds."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound import Ellipsoid
from optbound.compare import (
    log_volume_ratio,
    projection_volume_ratio,
    trace_ratio,
    volume_ratio,
)


def test_scaled_ellipsoid_ratios():
    E = Ellipsoid([1.0, 2.0, 3.0], np.diag([1.0, 4.0, 9.0]))
    big = E.scaled(2.0)
    assert volume_ratio(big, E) == pytest.approx(8.0)
    assert log_volume_ratio(big, E) == pytest.approx(3 * np.log(2.0))
    assert trace_ratio(big, E) == pytest.approx(4.0)
    assert projection_volume_ratio(big, E, (0, 2)) == pytest.approx(4.0)


def test_projection_ratio_uses_only_the_chosen_coordinates():
    A = Ellipsoid([0.0, 0.0], np.diag([1.0, 100.0]))
    B = Ellipsoid([5.0, 5.0], np.diag([4.0, 1.0]))
    assert projection_volume_ratio(A, B, (0,)) == pytest.approx(0.5)


@given(st.integers(0, 10_000), st.integers(2, 8))
def test_volume_ratio_is_stable_in_high_dimension(seed, n):
    rng = np.random.default_rng(seed)
    A = rng.standard_normal((n, n))
    E = Ellipsoid(np.zeros(n), 1e-6 * (A @ A.T + np.eye(n)))
    assert volume_ratio(E.scaled(1.5), E) == pytest.approx(1.5**n, rel=1e-10)


def test_accepts_results_and_refuses_other_objects():
    class Result:
        ellipsoid = Ellipsoid([0.0], [[4.0]])

    assert volume_ratio(Result(), Ellipsoid([0.0], [[1.0]])) == pytest.approx(2.0)
    with pytest.raises(ValueError, match="A must be"):
        volume_ratio(np.eye(2), Ellipsoid([0.0], [[1.0]]))
    with pytest.raises(ValueError, match="dimensions"):
        trace_ratio(Ellipsoid([0.0], [[1.0]]), Ellipsoid([0.0, 0.0], np.eye(2)))
