"""Tests for optbound._core.box: Box (public as optbound.Box, optbound.sets.Box), box arrays."""

import numpy as np
import pytest

from optbound import Box
from optbound._core import as_box, box_array, box_rows


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


def test_box_is_one_class_under_its_public_names():
    import optbound.sets

    assert Box is optbound.sets.Box is optbound._core.Box


@pytest.mark.parametrize(
    ("boxes", "dim", "error", "word"),
    [
        (np.zeros((2, 2)), None, ValueError, r"boxes must have shape \(m, n, 2\)"),
        (np.zeros((2, 3, 2)), 2, ValueError, r"boxes must have shape \(m, 2, 2\)"),
        (np.zeros((1, 2, 3)), 2, ValueError, "shape"),
        ([[[0.0, np.inf], [0.0, 1.0]]], 2, ValueError, "boxes must be finite"),
        ([[[0.0, np.nan], [0.0, 1.0]]], 2, ValueError, "boxes must be finite"),
        ([[[1.0, 0.0], [0.0, 1.0]]], 2, ValueError, "boxes must have lo <= hi"),
        ([[[1j, 2.0], [0.0, 1.0]]], 2, TypeError, "boxes must be real"),
        ([[[1j, 2.0], [0.0, 1.0]]], 2, ValueError, "boxes must be real"),
        ([[["a", "b"], [0.0, 1.0]]], 2, TypeError, "boxes must be an array of real numbers"),
    ],
)
def test_box_array_refuses_bad_boxes_naming_the_argument(boxes, dim, error, word):
    with pytest.raises(error, match=word):
        box_array("boxes", boxes, dim)


def test_box_array_volume_names_the_flat_boxes():
    flat = [[[0.0, 1.0], [0.0, 1.0]], [[0.0, 1.0], [2.0, 2.0]], [[3.0, 3.0], [0.0, 1.0]]]
    assert box_array("boxes", flat, 2).shape == (3, 2, 2)  # flat boxes are boxes
    with pytest.raises(ValueError, match=r"boxes: box\(es\) \[1, 2\] have no volume"):
        box_array("boxes", flat, 2, volume=True)


def test_box_array_accepts_no_boxes_and_returns_contiguous_floats():
    assert box_array("boxes", np.zeros((0, 3, 2)), 3).shape == (0, 3, 2)
    B = box_array("boxes", [[[0, 1], [2, 3]]])
    assert B.dtype == np.float64 and B.flags.c_contiguous
    assert B.tolist() == [[[0.0, 1.0], [2.0, 3.0]]]
    strided = np.zeros((2, 2, 4))[:, :, ::2]
    assert box_array("boxes", strided, 2).flags.c_contiguous


def test_as_box_and_box_rows():
    B = Box([0.0, 1.0], [2.0, 3.0])
    assert as_box("X0", B) is B
    assert as_box("X0", [[0.0, 2.0], [1.0, 3.0]]).as_array().tolist() == B.as_array().tolist()
    lo, hi = box_rows("X0", B, allow_infinite=False)
    lo[0] = -5.0  # fresh copies: the (immutable) box is untouched
    assert B.lo.tolist() == [0.0, 1.0] and hi.tolist() == [2.0, 3.0]
    unbounded = [[-np.inf, np.inf]]
    assert box_rows("Y", unbounded, allow_infinite=True)[0].tolist() == [-np.inf]
    with pytest.raises(ValueError, match="X0 must be a bounded box"):
        as_box("X0", unbounded, bounded=True)
    with pytest.raises(ValueError, match=r"X0: rows must have shape \(n, 2\)"):
        as_box("X0", [0.0, 1.0])
    with pytest.raises(ValueError, match="X0: lo must be <= hi"):
        box_rows("X0", [[1.0, 0.0]], allow_infinite=True)
