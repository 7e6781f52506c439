"""The BH Sect. V geometry and the random instances like it."""

import numpy as np

from optbound.localization import relative_bearing as rb
from optbound.scenarios import bh_geometry as bh


def test_sect5_instance_has_the_papers_noise_free_bearings():
    """[BH, Sect. V]: 90°, 45°, -135° for the pairs (3, 1), (1, 2), (2, 3); eps = 4°."""
    L, pairs, gammas, eps, x = bh.sect5_instance()
    assert np.array_equal(L, [[0.0, 1.0], [1.0, 1.0], [-1.0, 0.0]])
    assert pairs == [(2, 0), (0, 1), (1, 2)]
    assert np.allclose(np.degrees(gammas), [90.0, 45.0, -135.0])
    assert eps == np.radians(4.0) and np.array_equal(x, [0.0, 0.0])
    assert rb.in_exact_set(rb.measurements(L, pairs, gammas, eps), x[None]).all()


def test_sect5_instance_returns_copies():
    L, _, _, _, x = bh.sect5_instance()
    L[0, 0], x[0] = 99.0, 99.0
    assert bh.LANDMARKS[0, 0] == 0.0 and bh.VEHICLE[0] == 0.0


def test_random_instances_are_crescents_with_the_truth_in_the_exact_set():
    rng = np.random.default_rng(5)
    for _ in range(20):
        L, pairs, g, eps, x = bh.random_instance(rng)
        assert np.radians(1.0) <= eps <= np.radians(8.0)
        assert pairs == list(bh.PAIRS)
        margin = np.radians(3.0)
        assert np.all((np.abs(g) > eps + margin) & (np.abs(g) < np.pi - eps - margin))
        assert rb.in_exact_set(rb.measurements(L, pairs, g, eps), x[None]).all()


def test_random_instances_are_seeded():
    first = bh.random_instance(np.random.default_rng(11))
    second = bh.random_instance(np.random.default_rng(11))
    for a, b in zip(first, second, strict=True):
        assert np.array_equal(a, b)
