"""Calls of a compiled step by its address (``optbound._core.native_call``)."""

import numpy as np
import pytest
from numba import njit
from numba.core.errors import TypingError

from optbound._core.native_call import address, caller


@njit
def _scale(x, m, factor):
    for k in range(m):
        x[k] *= factor


_call_scale = caller(_scale)


@njit
def _twice(entry, x, m):
    _call_scale(entry, (x, m, 2.0))
    _call_scale(entry, (x, m, 3.0))


def test_the_callee_runs_at_its_address():
    x = np.arange(5.0)
    _twice(address(_scale, x, 0, 0.0), x, 4)
    assert np.array_equal(x, [0.0, 6.0, 12.0, 18.0, 4.0])


def test_a_call_with_other_types_than_the_address_was_taken_for_is_refused():
    address(_scale, np.zeros(2), 0, 0.0)
    with pytest.raises(TypingError, match="_scale is not compiled for"):
        _twice(0, np.zeros(2, np.float32), 1)
