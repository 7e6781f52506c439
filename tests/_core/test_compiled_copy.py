"""``copy_into``: the compiled kernels' array copy (element order, sizes, layout)."""

import numpy as np
import pytest

from optbound._core.compiled_copy import copy_into


@pytest.mark.parametrize("shape", [(5,), (3, 4), (2, 3, 2)])
def test_copies_every_element_in_place(shape):
    src = np.arange(np.prod(shape), dtype=float).reshape(shape) - 2.5
    dst = np.zeros(shape)
    copy_into(dst, src)
    assert np.array_equal(dst, src)


def test_copies_into_a_row_and_a_prefix():
    out = np.zeros((3, 2))
    copy_into(out[1], np.array([7.0, -1.0]))
    assert out.tolist() == [[0.0, 0.0], [7.0, -1.0], [0.0, 0.0]]
    flags = np.zeros(4, dtype=np.bool_)
    copy_into(flags[:2], np.array([True, True]))
    assert flags.tolist() == [True, True, False, False]


def test_different_sizes_raise():
    with pytest.raises(ValueError, match="differ in size"):
        copy_into(np.zeros(3), np.zeros(4))


def test_fortran_ordered_source_is_refused():
    # Copying in memory order would transpose it: numba's reshape refuses it instead.
    with pytest.raises(NotImplementedError):
        copy_into(np.zeros((2, 3)), np.asfortranarray(np.ones((2, 3))))
