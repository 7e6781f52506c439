"""Ellipsoidal observers: every step's ellipsoid contains the exact polygon (Fraction check)."""

from fractions import Fraction

import numpy as np
import pytest

from optbound import Box, Ellipsoid, Zonotope
from optbound import estimation as est
from optbound.estimation.ellipsoidal import measurement_strip
from optbound.estimation.noise import FLAT_INFLATION, coordinate_bounds, ellipsoid_of
from optbound.sets.base import EmptySetError
from tests.estimation.test_observers import ALAMO_YS, alamo, box_noise
from tests.sets import exact_polytopes as X

F = Fraction
ELLIPSOIDAL = ("ellipsoid_volume", "ellipsoid_trace")


@pytest.mark.parametrize("method", ELLIPSOIDAL)
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_ellipsoids_contain_the_exact_set(method, seed):
    system, X0, polys, ys = box_noise(seed)
    sets = est.observe(system, X0, ys, method=method)
    assert len(sets) == len(ys)
    for E, P in zip(sets, polys, strict=True):
        assert isinstance(E, Ellipsoid)
        assert X.in_ellipsoid(E, P)


@pytest.mark.parametrize("method", ELLIPSOIDAL)
def test_alamo_example_flat_noise(method):
    system, X0, polys = alamo()
    sets = est.observe(system, X0, ALAMO_YS, method=method)
    for E, P in zip(sets, polys, strict=True):
        assert X.in_ellipsoid(E, P)
    # No ellipsoid holds the exact polygon with less area than its own; this one is bigger.
    assert X.area(polys[-1]) < F(sets[-1].volume())


def test_the_criteria_choose_their_own_size():
    system, X0, _, ys = box_noise(0)
    vol = est.observe(system, X0, ys, method="ellipsoid_volume")
    tr = est.observe(system, X0, ys, method="ellipsoid_trace")
    # One step from the same prior: each criterion wins its own measure.
    E_v = est.observe(system, vol[-2], ys[-1:], method="ellipsoid_volume")[0]
    E_t = est.observe(system, vol[-2], ys[-1:], method="ellipsoid_trace")[0]
    assert E_v.volume() <= E_t.volume() * (1 + 1e-9)
    assert np.trace(E_t.shape) <= np.trace(E_v.shape) * (1 + 1e-9)
    assert len(tr) == len(vol)


def test_flat_noise_is_thickened_by_the_stated_amount():
    W = Zonotope([0.5, -0.5], [[-0.12], [0.02]])
    E = ellipsoid_of(W)
    ends = X.set_points(W)
    assert X.in_ellipsoid(E, ends)
    g = np.hypot(0.12, 0.02)
    small, large = E.semi_axes()
    assert large == pytest.approx(np.sqrt(2) * g, rel=1e-6)  # m G G^T with m = 2 generators
    # (the certified diagonal raise is ~1e-17 absolute: relative 1e-5 on this semi-axis)
    assert small == pytest.approx(np.sqrt(2) * FLAT_INFLATION * g, rel=1e-4)


def test_box_noise_ellipsoid_is_the_box_mvee():
    B = Box([-1.0, -0.25], [1.0, 0.25])
    E = ellipsoid_of(B)
    assert X.in_ellipsoid(E, X.box_corners(B.as_array()))
    assert np.allclose(E.shape, np.diag([2.0, 0.125]), rtol=1e-12)


@pytest.mark.parametrize("seed", range(4))
def test_measurement_strip_holds_the_exact_strip_inside_the_ellipsoid(seed):
    rng = np.random.default_rng(seed)
    L = np.tril(rng.normal(size=(2, 2))) + 2.0 * np.eye(2)
    E = Ellipsoid(rng.normal(size=2) * 100.0, L @ L.T)
    a = rng.normal(size=2)
    mid = float(a @ E.center) + rng.normal()
    lo, hi = mid - 0.3, mid + 0.1 * (seed == 0) + 0.2
    S = measurement_strip(a, lo, hi, E)
    aa, sa, sb = X.exact(a), X.exact(S.a), F(S.b)
    n2 = aa[0] ** 2 + aa[1] ** 2
    for bound in (F(lo), F(hi)):
        base = [bound * ai / n2 for ai in aa]  # a^T base = bound exactly
        for t in range(-40, 41):
            p = (base[0] - F(t, 4) * aa[1], base[1] + F(t, 4) * aa[0])
            if X.ellipsoid_level(E.center, E.shape, p) <= 1:
                assert abs(sa[0] * p[0] + sa[1] * p[1] - sb) <= 1


def test_ellipsoidal_noise():
    rng = np.random.default_rng(5)
    A = np.array([[0.8, 0.3], [-0.2, 0.7]])
    W, V = Ellipsoid([0.0, 0.0], np.diag([0.01, 0.02])), Ellipsoid([0.05], [[0.04]])
    system = est.LinearSystem(A, [[1.0, 0.5]], W, V)
    assert not system.polytopic
    X0 = Ellipsoid([0.0, 0.0], np.eye(2))
    x, xs, ys = X0.sample(1, rng)[0], [], []
    for _ in range(8):
        x = A @ x + W.sample(1, rng)[0]
        xs.append(x)
        ys.append(float(system.C[0] @ x + V.sample(1, rng)[0, 0]))
    with pytest.raises(ValueError, match="not a polytope"):
        est.exact_sets(system, X0, ys)
    for method in est.METHODS:
        sets = est.observe(system, X0, ys, method=method)
        for S, x in zip(sets, xs, strict=True):
            assert S.contains(x, tol=0.0)
    Vb = coordinate_bounds(V)
    assert Vb.lo[0] <= 0.05 - 0.2 and Vb.hi[0] >= 0.05 + 0.2


def test_inconsistent_measurement_is_reported():
    system = est.LinearSystem(np.eye(2), [1.0, 0.0], Box([-0.1] * 2, [0.1] * 2), Box([-0.1], [0.1]))
    with pytest.raises(EmptySetError):
        est.observe(system, Box([0.0, 0.0], [1.0, 1.0]), [50.0], method="ellipsoid_trace")
