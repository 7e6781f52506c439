"""mvee: anchors, agreement with Khachiyan's algorithm, certification, bad input."""

import numpy as np
import pytest

from optbound.optimal import mvee
from optbound.optimal.khachiyan import khachiyan_mvee


def test_cube_vertices_give_the_circumscribed_ball():
    corners = np.array(np.meshgrid(*[[-1.0, 1.0]] * 3)).reshape(3, -1).T
    r = mvee(corners)
    assert r.objective == pytest.approx(4.0 / 3.0 * np.pi * 3.0**1.5, rel=1e-7)
    assert r.multipliers.size == 0


@pytest.mark.parametrize("m, n", [(50, 2), (200, 3), (300, 5)])
def test_agrees_with_khachiyan(m, n):
    X = np.random.default_rng(m + n).standard_normal((m, n)) @ np.diag(np.arange(1.0, n + 1))
    r = mvee(X)
    K = khachiyan_mvee(X, tol=1e-7)
    # Khachiyan's (scaled) ellipsoid is feasible, so it cannot beat the optimum.
    assert r.objective <= K.volume() * (1 + 1e-7)
    assert r.objective == pytest.approx(K.volume(), rel=1e-5)
    assert np.all(r.ellipsoid.contains(X, tol=0.0))
    assert r.certified and 1.0 <= r.inflation < 1.0 + 1e-6


@pytest.mark.parametrize(
    "points, word",
    [
        (np.zeros((2, 2)), "at least"),
        (np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [3.0, 3.0]]), "lower-dimensional"),
        (np.array([[0.0, np.nan], [1.0, 0.0], [0.0, 1.0]]), "finite"),
        (np.ones(4), "2-D"),
        # Issue 8: 1e-9 from a line, and magnitudes 1e+-200: a clear message, never NaN.
        (np.column_stack([np.linspace(0.0, 1.0, 10), 1e-9 * np.sin(np.arange(10.0))]), "thickness"),
        (1e200 * np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]), "coordinates <="),
        (1e-200 * np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]), "spread"),
    ],
)
def test_bad_points(points, word):
    with pytest.raises(ValueError, match=word):
        mvee(points)
