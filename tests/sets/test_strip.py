"""Tests for optbound.sets.Strip and Halfspace."""

import numpy as np
import pytest

from optbound import Halfspace, Strip


def test_from_bounds_round_trips_to_the_same_slab():
    S = Strip.from_bounds([2.0, 0.0], -1.0, 3.0)
    assert S.extent([2.0, 0.0]) == pytest.approx((-1.0, 3.0))
    assert S.width == pytest.approx(2.0)
    np.testing.assert_array_equal(S.contains([[1.5, 7.0], [1.6, 0.0], [-0.5, 0.0]]), [1, 0, 1])


def test_strip_support_is_finite_only_along_its_normal():
    S = Strip([1.0, 1.0], 0.5)
    assert S.support([2.0, 2.0]) == pytest.approx(2 * 1.5)
    assert S.support([-1.0, -1.0]) == pytest.approx(0.5)
    assert S.support([1.0, 0.0]) == np.inf


def test_halfspace_contains_and_support():
    H = Halfspace([0.0, 1.0], 2.0)
    np.testing.assert_array_equal(H.contains([[5.0, 2.0], [0.0, 2.1]]), [True, False])
    assert H.support([0.0, 3.0]) == pytest.approx(6.0)
    assert H.support([0.0, -1.0]) == np.inf
    assert H.support([1.0, 1.0]) == np.inf


@pytest.mark.parametrize(
    ("make", "word"),
    [
        (lambda: Strip([0.0, 0.0], 1.0), "non-zero"),
        (lambda: Strip([1.0, np.nan], 1.0), "a"),
        (lambda: Strip([1.0, 0.0], np.inf), "b"),
        (lambda: Strip.from_bounds([1.0, 0.0], 2.0, 2.0), "lo must be smaller"),
        (lambda: Halfspace([0.0, 0.0], 1.0), "non-zero"),
        (lambda: Strip([1.0, 0.0], [1.0, 2.0]), "scalar"),
    ],
)
def test_bad_input(make, word):
    with pytest.raises(ValueError, match=word):
        make()


@pytest.mark.parametrize("a", [[5e-324, 0.0], [1e61, 0.0], [0.0, 1e-61]])
def test_normals_outside_the_domain_are_refused_not_a_zero_division(a):
    with pytest.raises(ValueError, match="norm in"):
        Strip(a, 0.0)
    with pytest.raises(ValueError, match="norm in"):
        Halfspace(a, 0.0)


def test_complex_input_is_refused():
    with pytest.raises(TypeError, match="a must be real"):
        Strip([1.0 + 1e-3j, 0.0], 0.0)
    with pytest.raises(TypeError, match="b must be real"):
        Strip([1.0, 0.0], 1j)
