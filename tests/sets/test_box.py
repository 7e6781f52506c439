"""Tests for optbound.sets.Box."""

import numpy as np
import pytest

from optbound import Box


def test_box_geometry():
    B = Box([0.0, -1.0], [2.0, 3.0])
    assert B.volume() == pytest.approx(8.0)
    assert B.log_volume() == pytest.approx(np.log(8.0))
    np.testing.assert_allclose(B.center, [1.0, 1.0])
    assert B.support([1.0, -1.0]) == pytest.approx(3.0)
    assert B.project([1]).as_array().tolist() == [[-1.0, 3.0]]
    X = B.sample(1000, 0)
    assert B.contains(X).all()
    assert Box.from_array(B.as_array()).as_array().tolist() == B.as_array().tolist()


def test_unbounded_box():
    B = Box([-np.inf, 0.0], [np.inf, 1.0])
    assert not B.is_bounded
    assert B.support([0.0, 1.0]) == pytest.approx(1.0)
    assert B.support([1.0, 0.0]) == np.inf
    assert B.contains([1e300, 0.5])
    with pytest.raises(ValueError, match="unbounded"):
        B.sample(3, 0)


@pytest.mark.parametrize(
    ("lo", "hi", "word"),
    [
        ([0.0, 1.0], [1.0, 0.0], "lo must be <= hi"),
        ([0.0, np.nan], [1.0, 1.0], "NaN"),
        ([0.0], [1.0, 1.0], "same length"),
        ([np.inf], [np.inf], "inf"),
    ],
)
def test_bad_input(lo, hi, word):
    with pytest.raises(ValueError, match=word):
        Box(lo, hi)


def test_volume_of_an_unbounded_box_is_inf_not_nan():
    B = Box([-np.inf, 0.0], [np.inf, 0.0])
    assert B.volume() == np.inf and B.log_volume() == np.inf
    assert Box([0.0, 0.0], [1.0, 0.0]).volume() == 0.0
