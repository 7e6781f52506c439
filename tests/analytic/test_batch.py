"""Batched inputs reach the compiled kernels with one array type, whatever their form."""

import numpy as np

from optbound.analytic._kernels import batch


def test_per_instance_is_contiguous_and_writable():
    shared = batch.per_instance("a", [1.0, 2.0], 1, (2,))  # a broadcast view before
    assert shared.flags.c_contiguous and shared.flags.writeable
    np.testing.assert_array_equal(shared, [[1.0, 2.0]])
