"""The designed 10 x 10 m world of GLH12 Sect. 5 (Fig. 7 is lost)."""

import numpy as np
import pytest

from optbound.interval import Tri
from optbound.localization.geometry import point_in_polygon
from optbound.scenarios import arena


def test_obstacles_and_starts_fit_the_room():
    assert len(arena.OBSTACLES) == 11 and len(arena.STARTS) == 11
    for poly in arena.OBSTACLES:
        assert np.all((poly > 0) & (poly < arena.SIZE))
        assert not np.any(point_in_polygon(arena.STARTS, poly) != Tri.FALSE)
    env = arena.environment(11)
    assert len(env.inner) == len(env.outer) == 11


def test_simulate_follows_the_paper_sensing():
    run = arena.simulate(5, 6, 60, seed=3)
    steps = np.linalg.norm(np.diff(run.truth, axis=0), axis=-1)
    assert np.all((steps >= 0.099 - 1e-12) & (steps <= 0.101 + 1e-12))
    assert np.all((run.boxes0[..., 0] <= run.truth[0]) & (run.truth[0] <= run.boxes0[..., 1]))
    np.testing.assert_allclose(np.prod(np.diff(run.boxes0), axis=(1, 2)), 1.0)
    assert run.visibility.shape == (60, 5, 5)
    assert np.array_equal(run.visibility, np.swapaxes(run.visibility, 1, 2))
    assert 0.0 < run.visibility.mean() < 1.0
    for poly in run.env.exact:  # robots never enter an obstacle
        assert not np.any(point_in_polygon(run.truth.reshape(-1, 2), poly) != Tri.FALSE)


@pytest.mark.parametrize(
    ("robots", "obstacles", "match"),
    [(0, 3, "n_robots"), (12, 3, "n_robots"), (3, 12, "n_obstacles")],
)
def test_simulate_rejects_bad_counts(robots, obstacles, match):
    with pytest.raises(ValueError, match=match):
        arena.simulate(robots, obstacles, 5, 0)


def test_random_layouts_are_seeded_free_and_nested():
    a, b = arena.random_layout(4), arena.random_layout(4)
    assert all(np.array_equal(p, q) for p, q in zip(a[0], b[0], strict=True))
    assert np.array_equal(a[1], b[1])
    assert not np.array_equal(a[1], arena.random_layout(5)[1])
    obstacles, starts = a
    assert len(obstacles) == 11 and starts.shape == (11, 2)
    for poly in obstacles:
        assert np.all((poly > 0) & (poly < arena.SIZE))
        assert not np.any(point_in_polygon(starts, poly) != Tri.FALSE)
    arena.environment(11, obstacles)  # E⁻ ⊂ E ⊂ E⁺ provable for every drawn obstacle


def test_setting_factors_are_applied_and_runs_are_deterministic():
    setting = arena.Setting(layout="random", turn=0.0, heading_error=0.01, box_offset="centre")
    run, again = (arena.simulate(4, 5, 40, 9, setting) for _ in range(2))
    assert np.array_equal(run.truth, again.truth)
    assert np.array_equal(run.visibility, again.visibility)
    np.testing.assert_allclose(run.truth[0], arena.random_layout(9)[1][:4])
    np.testing.assert_allclose(run.boxes0.mean(axis=-1), run.truth[0])
    assert run.heading_error == 0.01
    for poly in run.env.exact:
        assert not np.any(point_in_polygon(run.truth.reshape(-1, 2), poly) != Tri.FALSE)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [({"layout": "x"}, "layout"), ({"box_offset": "x"}, "box_offset"), ({"turn": -1}, "turn")],
)
def test_setting_rejects_bad_factors(kwargs, match):
    with pytest.raises(ValueError, match=match):
        arena.Setting(**kwargs)
