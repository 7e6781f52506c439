"""Tests of the bounding-ellipsoid measurement update [BH, eq. (7)]."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound import Ellipsoid, Strip, analytic
from tests.analytic.instances import ellipsoid_and_strip, random_ellipsoid

CONTAIN_TOL = 1e-9


def _feasible_points(E, H, z, V, rng, m=20_000):
    """Points of {x in E : (z - Hx)^T V^-1 (z - Hx) <= 1}: samples of E and of its boundary."""
    pts = np.vstack([E.sample(m, rng), E.sample_boundary(m, rng)])
    r = z - pts @ H.T
    level = np.einsum("ij,ij->i", r @ np.linalg.inv(V), r)
    return pts[level <= 1.0]


@st.composite
def measurement(draw):
    """Prior E (2-5-D) and z = H x + v with m <= n rows, z near or far from H E."""
    n = draw(st.integers(2, 5))
    m = draw(st.integers(1, n))
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    E = random_ellipsoid(rng, n)
    H = rng.standard_normal((m, n))
    B = rng.standard_normal((m, m))
    V = draw(st.floats(0.05, 2.0)) * (B @ B.T + 0.1 * np.eye(m))
    x = E.center + draw(st.floats(0.0, 1.5)) * E.chol @ rng.standard_normal(n) / np.sqrt(n)
    return E, H, H @ x + rng.standard_normal(m) * draw(st.floats(0.0, 1.0)), V


@pytest.mark.parametrize(("criterion", "lam"), [("volume", None), ("trace", None), ("volume", 0.3)])
@given(inst=measurement(), seed=st.integers(0, 1000))
def test_result_contains_the_feasible_set(criterion, lam, inst, seed):
    E, H, z, V = inst
    out = analytic.bounding_update(E, H, z, V, criterion, lam=lam)
    pts = _feasible_points(E, H, z, V, np.random.default_rng(seed))
    if out.ellipsoid is None:
        assert pts.shape[0] == 0
        return
    assert np.all(out.ellipsoid.contains(pts, tol=CONTAIN_TOL))


@given(inst=measurement())
def test_volume_lambda_is_not_worse_than_a_grid(inst):
    """The minimizer beats (or ties) every lambda of a dense grid."""
    E, H, z, V = inst
    best = analytic.bounding_update(E, H, z, V)
    if best.ellipsoid is None:
        return
    for lam in np.linspace(0.0, 5.0, 101):
        other = analytic.bounding_update(E, H, z, V, lam=lam).ellipsoid
        assert best.ellipsoid.log_volume() <= other.log_volume() + 1e-10


@given(inst=ellipsoid_and_strip())
def test_one_row_equals_strip_fusion_without_clipping(inst):
    """z = a^T x + v, |v| <= 1 is the strip |a^T x - b| <= 1: same ellipsoid as [HS96, eq. (24)]."""
    E, S = inst
    strip = analytic.intersect_strip(E, S, clip=False)
    scale = 2.5  # the strip written as |H x - z| <= sqrt(V) with V = scale^2
    bh = analytic.bounding_update(E, scale * S.a[None], [scale * S.b], [[scale**2]])
    if strip.case == "inconsistent":
        assert bh.ellipsoid is None
        return
    if strip.case == "no_reduction":  # strip returns E with lambda = 0 by definition
        assert bh.ellipsoid.volume() >= E.volume() * (1 - 1e-8)
        return
    assert bh.lam == pytest.approx(strip.lam, rel=1e-10, abs=1e-14)
    np.testing.assert_allclose(bh.ellipsoid.shape, strip.ellipsoid.shape, rtol=1e-10, atol=1e-14)
    np.testing.assert_allclose(bh.ellipsoid.center, strip.ellipsoid.center, rtol=1e-10, atol=1e-12)
    exact = analytic.bounding_update(E, scale * S.a[None], [scale * S.b], [[scale**2]], lam=0.4)
    same = analytic.intersect_strip(E, S, clip=False, lam=0.4)
    np.testing.assert_allclose(exact.ellipsoid.shape, same.ellipsoid.shape, rtol=1e-12, atol=1e-14)


def test_anchor_unit_ball_strip():
    out = analytic.bounding_update(Ellipsoid([0, 0], np.eye(2)), [[2.0, 0.0]], [0.0], 1.0)
    assert out.lam == pytest.approx(0.5, rel=1e-14)
    np.testing.assert_allclose(out.ellipsoid.shape, np.diag([0.5, 1.5]), rtol=1e-14)


def test_disjoint_measurement_is_empty():
    E = Ellipsoid([0, 0], np.eye(2))
    out = analytic.bounding_update(E, np.eye(2), [3.0, 0.0], np.eye(2))
    assert out.ellipsoid is None


def test_touching_measurement_falls_back_to_the_prior():
    """Unit ball and the unit ball around (2, 0) touch at (1, 0): E itself, which contains it."""
    E = Ellipsoid([0, 0], np.eye(2))
    out = analytic.bounding_update(E, np.eye(2), [2.0, 0.0], np.eye(2))
    assert out.ellipsoid is not None and out.ellipsoid.contains([1.0, 0.0])


E2 = Ellipsoid([0.0, 0.0], np.eye(2))


@pytest.mark.parametrize(
    ("H", "z", "V", "kwargs", "match"),
    [
        ([[1.0, 0.0, 0.0]], [0.0], [[1.0]], {}, "H must have shape"),
        ([[1.0, 0.0]], [0.0, 1.0], [[1.0]], {}, "z must have length"),
        ([[1.0, 0.0]], [np.nan], [[1.0]], {}, "z must be finite"),
        ([[1.0, 0.0]], [0.0], [[-1.0]], {}, "V must be positive definite"),
        ([[1.0, 0.0]], [0.0], [[1.0]], {"criterion": "det"}, "criterion"),
        ([[1.0, 0.0]], [0.0], [[1.0]], {"lam": -1.0}, "lam must be >= 0"),
    ],
)
def test_bad_inputs_raise(H, z, V, kwargs, match):
    with pytest.raises(ValueError, match=match):
        analytic.bounding_update(E2, H, z, V, **kwargs)


def test_strip_written_as_measurement_has_the_same_feasible_set():
    """Sanity check of the test's own conversion |Hx - z| <= sqrt(V) <=> |a^T x - b| <= 1."""
    S = Strip([0.4, -1.0], 0.3)
    x = np.random.default_rng(0).standard_normal((1000, 2))
    scale = 2.5
    in_measurement = np.abs(x @ (scale * S.a) - scale * S.b) <= scale
    np.testing.assert_array_equal(in_measurement, S.contains(x, tol=0.0))
