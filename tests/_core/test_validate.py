"""Tests for optbound._core.validate: one real_array for every package."""

import numpy as np
import pytest

from optbound._core import NotRealError, real_array
from optbound._core import validate as v


def test_real_array_passes_float_arrays_through_and_converts_the_rest():
    x = np.arange(3.0)
    assert real_array("x", x) is x
    assert real_array("x", [1, 2]).dtype == np.float64
    assert real_array("x", 3).shape == ()
    assert real_array("x", np.array([1, 2], dtype=np.float32)).dtype == np.float64


@pytest.mark.parametrize(
    ("value", "word"),
    [
        ([1.0, 1j], "x must be real, got complex values"),
        (np.array([1.0 + 0j]), "x must be real, got complex values"),  # even with zero imag
        ([[1.0, 2.0], [3.0]], "x must be an array of real numbers, got list"),
        ("abc", "x must be an array of real numbers, got str"),
        ({"a": 1}, "x must be an array of real numbers, got dict"),
    ],
)
def test_non_real_input_is_a_type_and_a_value_error_naming_the_argument(value, word):
    # The set types document TypeError, the localization models ValueError: both hold.
    for error in (NotRealError, TypeError, ValueError):
        with pytest.raises(error, match=word):
            real_array("x", value)


def test_finite_array_keeps_the_shape_and_refuses_non_finite_values():
    assert v.finite_array("r", [[1.0, 2.0]]).shape == (1, 2)
    for bad in ([1.0, np.nan], [np.inf], -np.inf):
        with pytest.raises(ValueError, match="r must be finite"):
            v.finite_array("r", bad)
    with pytest.raises(ValueError, match="r must be real"):
        v.finite_array("r", [1j])


def test_the_message_describes_the_expected_array():
    message = r"^L must be an \(N, 2\) array of real numbers, got list$"
    with pytest.raises(NotRealError, match=message):
        real_array("L", [[0.0, 1.0], [1.0]], "an (N, 2) array")
