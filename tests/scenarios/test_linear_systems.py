"""Random linear systems: seeded, stable, and every observer's sets hold the true states."""

import numpy as np
import pytest

from optbound import Ellipsoid
from optbound import estimation as est
from optbound.scenarios.linear_systems import RHO, random_system


@pytest.mark.parametrize("noise", ["box", "ellipsoid"])
@pytest.mark.parametrize("n", [2, 4, 6])
def test_seeded_stable_and_consistent(n, noise):
    a, b = random_system(n, 3, noise, steps=12), random_system(n, 3, noise, steps=12)
    assert np.array_equal(a.ys, b.ys) and np.array_equal(a.system.A, b.system.A)
    assert max(abs(np.linalg.eigvals(a.system.A))) == pytest.approx(RHO)
    assert a.ys.shape == (12, max(1, n // 2)) and a.states.shape == (12, n)
    assert isinstance(a.system.W, Ellipsoid) == (noise == "ellipsoid")
    methods = [m for m in est.METHODS if not (m == "zonotope_volume" and n > 2)]
    for method in methods:
        sets = est.observe(a.system, a.X0, a.ys, method=method, order=4.0)
        for S, x in zip(sets, a.states, strict=True):
            assert S.contains(x, tol=0.0), (method, n, noise)


def test_bad_arguments():
    with pytest.raises(ValueError, match="noise must be one of"):
        random_system(2, 0, "gauss")
    with pytest.raises(ValueError, match="n must be"):
        random_system(0, 0)
