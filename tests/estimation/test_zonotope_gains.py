"""The volume-minimising zonotopic observer: the volume formula, its minimiser, soundness."""

from fractions import Fraction

import numpy as np
import pytest

from optbound import Box, Zonotope
from optbound import estimation as est
from optbound.estimation.observers import alamo_strip
from optbound.estimation.zonotope_gains import (
    frobenius_gain,
    volume_gain,
    volume_of_gain,
)
from tests.estimation.test_observers import ALAMO_YS, alamo, box_noise
from tests.sets import exact_polytopes as X

F = Fraction


def _generators(G, a, s, lam):
    n = G.shape[0]
    return np.hstack([(np.eye(n) - np.outer(lam, a)) @ G, s * lam[:, None]])


@pytest.mark.parametrize("n", [2, 3])
def test_volume_formula_matches_the_zonotope_volume(n):
    rng = np.random.default_rng(n)
    G, a, s = rng.normal(size=(n, 5)), rng.normal(size=n), 0.3
    for lam in (frobenius_gain(G, a, s), rng.normal(size=n), np.zeros(n)):
        lo, hi = Zonotope(np.zeros(n), _generators(G, a, s, lam)).volume_bounds()
        v = 2**n * volume_of_gain(G, a, s, lam)
        assert lo * (1 - 1e-9) <= v <= hi * (1 + 1e-9)


@pytest.mark.parametrize("seed", range(4))
def test_volume_gain_minimises_the_volume(seed):
    rng = np.random.default_rng(seed)
    n = 2 + seed % 2
    G, a, s = rng.normal(size=(n, 4)), rng.normal(size=n), 0.2
    lam = volume_gain(G, a, s)
    best = volume_of_gain(G, a, s, lam)
    assert best <= volume_of_gain(G, a, s, frobenius_gain(G, a, s)) * (1 + 1e-9)
    for d in rng.normal(size=(10, n)):
        assert best <= volume_of_gain(G, a, s, lam + 1e-3 * d) * (1 + 1e-9)


def test_alamo_strip_with_the_volume_gain_contains_the_exact_intersection():
    rng = np.random.default_rng(7)
    Z = Zonotope(rng.normal(size=2), rng.normal(size=(2, 4)))
    a = rng.normal(size=2)
    lo, hi = a @ Z.center - 0.4, a @ Z.center + 0.1
    out = alamo_strip(Z, a, lo, hi, gain="volume")
    # exact vertices of Z ∩ strip: a constrained zonotope with a slack generator
    from optbound import ConstrainedZonotope

    cut = ConstrainedZonotope.from_zonotope(Z).intersect_strip(a, lo, hi)
    assert X.contains_all(out, X.set_points(cut))
    assert out.volume_bounds()[1] <= alamo_strip(Z, a, lo, hi).volume_bounds()[1] * (1 + 1e-9)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_volume_observer_contains_the_exact_set(seed):
    system, X0, polys, ys = box_noise(seed)
    for Z, P in zip(est.observe(system, X0, ys, "zonotope_volume", order=4.0), polys, strict=True):
        assert Z.n_generators <= 8
        assert X.contains_all(Z, P)


def test_volume_observer_on_alamo_example():
    system, X0, polys = alamo()
    sets = est.observe(system, X0, ALAMO_YS, method="zonotope_volume")
    for Z, P in zip(sets, polys, strict=True):
        assert X.contains_all(Z, P)


def test_too_many_subsets_are_refused():
    W = Zonotope(np.zeros(6), np.random.default_rng(0).normal(size=(6, 12)) * 0.01)
    system = est.LinearSystem(np.eye(6) * 0.5, np.ones(6), W, Box([-1.0], [1.0]))
    with pytest.raises(ValueError, match="lower the order"):
        est.observe(system, Box([-1.0] * 6, [1.0] * 6), [0.0], "zonotope_volume")
