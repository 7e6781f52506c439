"""LandmarkMap: validation, error radii, visibility through walls."""

import numpy as np
import pytest

from optbound.localization.landmark_map import LandmarkMap


def test_visibility_radii_and_defaults():
    m = LandmarkMap([[0, 5], [5, 0], [0, -5]], walls=[[[2, -1], [2, 1]]], shapes=np.eye(2) * 4e-4)
    assert m.visible([0, 3], [0, 0]).tolist() == [[True, False, True], [True, True, True]]
    assert np.allclose(m.radii, 0.02)
    free = LandmarkMap([[0, 5], [5, 0]])
    assert free.visible(0.0, 0.0).tolist() == [True, True] and np.all(free.radii == 0)
    with pytest.raises(ValueError):
        m.landmarks[0, 0] = 1.0  # read-only


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"landmarks": [[0, 1, 2]]}, "shape"),
        ({"landmarks": [[0, 1]], "walls": [[[0, 0], [0, 0]]]}, "zero length"),
        ({"landmarks": [[0, 1]], "shapes": [[1, 2], [0, 1]]}, "symmetric"),
        ({"landmarks": [[0, 1]], "shapes": -np.eye(2)}, "semi-definite"),
        ({"landmarks": [[0, 1]], "shapes": np.ones((3, 2, 2))}, "shape"),
    ],
)
def test_bad_maps(kwargs, match):
    with pytest.raises(ValueError, match=match):
        LandmarkMap(**kwargs)
