"""The seeded instance generators produce what the families claim to measure."""

import numpy as np
import pytest

from optbound.problems.generators import (
    STRIP_KINDS,
    random_ellipsoid,
    random_strip,
    strip_bounds,
    strips_around,
)


@pytest.mark.parametrize("dim", [2, 4, 6])
@pytest.mark.parametrize("cond", [1.0, 1e3, 1e6])
def test_random_ellipsoid_has_the_requested_condition_number(dim, cond):
    E = random_ellipsoid(np.random.default_rng(1), dim, cond, scale=2.0)
    eig = np.linalg.eigvalsh(E.shape)
    assert eig.max() / eig.min() == pytest.approx(cond, rel=1e-6)
    assert np.sqrt(eig.max()) == pytest.approx(2.0)


def test_random_ellipsoid_is_reproducible_from_its_seed():
    a = random_ellipsoid(np.random.default_rng(7), 3, 1e2)
    b = random_ellipsoid(np.random.default_rng(7), 3, 1e2)
    np.testing.assert_array_equal(a.shape, b.shape)
    np.testing.assert_array_equal(a.center, b.center)


def _cut_planes(E, S):
    """How many of the strip's two planes cross the ellipsoid's interior."""
    lo, hi = E.extent(S.a)
    return sum(lo < level < hi for level in (S.b - 1.0, S.b + 1.0))


@pytest.mark.parametrize("kind", STRIP_KINDS)
def test_strip_kinds_cut_the_ellipsoid_as_named(kind):
    rng = np.random.default_rng(3)
    for _ in range(50):
        E = random_ellipsoid(rng, 3, 1e4)
        S = random_strip(rng, E, kind)
        assert _cut_planes(E, S) == (1 if kind == "partial" else 2)
    lo, hi = strip_bounds(np.random.default_rng(0), kind)
    width = hi - lo
    if kind == "narrow":
        assert width <= 0.3
    elif kind == "wide":
        assert width >= 1.4


def test_unknown_strip_kind_is_refused():
    with pytest.raises(ValueError, match="kind"):
        strip_bounds(np.random.default_rng(0), "diagonal")


def test_strips_around_contain_the_true_point():
    rng = np.random.default_rng(5)
    E = random_ellipsoid(rng, 4, 1e2)
    point = E.sample(1, rng)[0]
    strips = strips_around(rng, E, point, 30, width=0.2)
    assert len(strips) == 30
    assert all(S.contains(point) for S in strips)
