"""Three-valued logic: truth tables, booleans as TRUE/FALSE, bad values rejected."""

import numpy as np
import pytest

from optbound.interval import Tri, as_tri, tri_and, tri_not, tri_or

F, U, T = Tri.FALSE, Tri.UNKNOWN, Tri.TRUE


def test_truth_tables():
    a = np.array([F, F, F, U, U, U, T, T, T], dtype=np.int8)
    b = np.array([F, U, T, F, U, T, F, U, T], dtype=np.int8)
    assert tri_and(a, b).tolist() == [F, F, F, F, U, U, F, U, T]
    assert tri_or(a, b).tolist() == [F, U, T, U, U, T, T, T, T]
    assert tri_not(a).tolist() == [T, T, T, U, U, U, F, F, F]


def test_booleans_are_true_false():
    assert as_tri(np.array([True, False])).tolist() == [T, F]
    assert tri_and(np.array([True, True]), np.array([U, F], dtype=np.int8)).tolist() == [U, F]


def test_bad_values_raise():
    with pytest.raises(ValueError, match="Tri values"):
        as_tri(np.array([3]))
    with pytest.raises(ValueError, match="booleans or Tri"):
        as_tri(np.array([0.5]))
    with pytest.raises(ValueError, match="at least one"):
        tri_and()
