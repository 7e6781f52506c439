"""``optbound.optimal._cvx``: setting parameter values without cvxpy's checks only where they
cannot fire."""

import cvxpy as cp
import numpy as np
import pytest

from optbound.optimal._cvx import set_value


def test_a_finite_value_is_stored_as_given():
    param = cp.Parameter((3, 2))
    value = np.arange(6.0).reshape(3, 2)
    set_value(param, value)
    assert np.array_equal(param.value, value)


@pytest.mark.parametrize("value", [np.array([[np.nan, 0.0]]), np.zeros((2, 1))])
def test_bad_values_get_cvxpys_error(value):
    with pytest.raises(ValueError):
        set_value(cp.Parameter((1, 2)), value)


def test_parameters_with_attributes_keep_cvxpys_checks():
    with pytest.raises(ValueError):
        set_value(cp.Parameter((2, 2), PSD=True), np.array([[1.0, 0.0], [0.0, -1.0]]))
