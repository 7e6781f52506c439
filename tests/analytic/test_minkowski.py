"""Tests of the Schweppe outer ellipsoids of a Minkowski sum [HS96, eqs. (14)-(17)]."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy.optimize import minimize_scalar

from optbound import Ellipsoid, analytic
from optbound.analytic._kernels.lanes import W
from tests.analytic.instances import ellipsoid_pair, random_ellipsoid, sample_sum

CONTAIN_TOL = 1e-9


def _xy_psi_size(C, planar=(0, 1), heading=(2,)):
    """tr(proj_xy C) * tr(proj_psi C) [HS96, eq. (15)], log-scaled."""
    p, h = list(planar), list(heading)
    return np.log(np.trace(C[np.ix_(p, p)]) * np.trace(C[np.ix_(h, h)]))


SIZES = {
    "volume": lambda C: np.linalg.slogdet(C)[1],
    "trace": lambda C: np.log(np.trace(C)),
    "size_xy_psi": _xy_psi_size,
}


@pytest.mark.parametrize(
    ("criterion", "kw"),
    [
        ("volume", {}),
        ("trace", {}),
        ("size_xy_psi", {}),
        ("volume", {"kappa": 0.2}),
    ],
)
@given(pair=ellipsoid_pair(), seed=st.integers(0, 1000))
def test_result_contains_the_sum(criterion, kw, pair, seed):
    E1, E2 = pair
    if criterion == "size_xy_psi":  # planar (0, 1) and heading 2, or (0,) and (1,) in 2-D
        kw = {"dims": ((0, 1), (2,)) if E1.dim > 2 else ((0,), (1,))}
    out = analytic.minkowski_sum(E1, E2, criterion, **kw)
    assert 0 < out.kappa < 1
    pts = sample_sum(E1, E2, 10_000, np.random.default_rng(seed))
    assert np.all(out.ellipsoid.contains(pts, tol=CONTAIN_TOL))
    np.testing.assert_allclose(out.ellipsoid.center, E1.center + E2.center)


def _numeric_min(E1, E2, size):
    """Brute-force minimum of ``size`` over kappa: dense grid, then bounded refinement."""

    def f(k):
        return size(E1.shape / (1 - k) + E2.shape / k)

    grid = np.linspace(1e-4, 1 - 1e-4, 2000)
    values = np.array([f(k) for k in grid])
    i = int(np.argmin(values))
    res = minimize_scalar(
        f,
        bounds=(grid[max(i - 1, 0)], grid[min(i + 1, len(grid) - 1)]),
        method="bounded",
        options={"xatol": 1e-13},
    )
    return min(res.fun, values[i])


@pytest.mark.parametrize("criterion", ["volume", "trace", "size_xy_psi"])
@given(pair=ellipsoid_pair(min_dim=3, max_dim=5))
def test_closed_form_kappa_matches_numeric_minimum(criterion, pair):
    E1, E2 = pair
    size = SIZES[criterion]
    kw = {"dims": ((0, 1), (2,))} if criterion == "size_xy_psi" else {}
    closed = size(analytic.minkowski_sum(E1, E2, criterion, **kw).ellipsoid.shape)
    numeric = _numeric_min(E1, E2, size)
    assert closed <= numeric + 1e-10
    assert closed >= numeric - 1e-8


@pytest.mark.parametrize(("r1", "r2"), [(1.0, 1.0), (2.0, 0.5), (0.1, 30.0)])
@pytest.mark.parametrize("criterion", ["volume", "trace"])
def test_balls_anchor(r1, r2, criterion):
    """Balls of radii r1, r2: kappa = r2 / (r1 + r2), C = (r1 + r2)^2 I."""
    out = analytic.minkowski_sum(
        Ellipsoid(np.zeros(3), r1**2 * np.eye(3)),
        Ellipsoid(np.ones(3), r2**2 * np.eye(3)),
        criterion,
    )
    assert out.kappa == pytest.approx(r2 / (r1 + r2), rel=1e-14)
    np.testing.assert_allclose(out.ellipsoid.shape, (r1 + r2) ** 2 * np.eye(3), rtol=1e-14)


def test_diag41_anchor():
    """C1 = diag(4, 1), C2 = I (Known facts): p = root of 2p^3 + 5p^2 - 5p - 8."""
    E1, E2 = Ellipsoid([0, 0], np.diag([4.0, 1.0])), Ellipsoid([0, 0], np.eye(2))
    vol = analytic.minkowski_sum(E1, E2)
    p = (1 - vol.kappa) / vol.kappa
    assert 2 * p**3 + 5 * p**2 - 5 * p - 8 == pytest.approx(0.0, abs=1e-13)
    assert p == pytest.approx(1.3860009363, abs=1e-10)
    assert vol.kappa == pytest.approx(0.4191113192, abs=1e-10)
    np.testing.assert_allclose(
        np.diag(vol.ellipsoid.shape), [9.2720018727, 4.1075011704], atol=1e-9
    )
    tr = analytic.minkowski_sum(E1, E2, "trace")
    assert tr.kappa == pytest.approx(0.387426, abs=1e-6)
    assert np.trace(tr.ellipsoid.shape) == pytest.approx(7 + 2 * np.sqrt(10), rel=1e-14)


def test_size_xy_psi_uses_the_dims_convention():
    """Permuting coordinates and dims accordingly gives the same kappa."""
    rng = np.random.default_rng(5)
    A, B = rng.standard_normal((3, 3)), rng.standard_normal((3, 3))
    C1, C2 = A @ A.T + np.eye(3), B @ B.T + 0.1 * np.eye(3)
    perm = [2, 0, 1]  # heading first
    default = analytic.minkowski_sum(
        Ellipsoid(np.zeros(3), C1), Ellipsoid(np.zeros(3), C2), "size_xy_psi"
    )
    permuted = analytic.minkowski_sum(
        Ellipsoid(np.zeros(3), C1[np.ix_(perm, perm)]),
        Ellipsoid(np.zeros(3), C2[np.ix_(perm, perm)]),
        "size_xy_psi",
        dims=((1, 2), (0,)),
    )
    assert permuted.kappa == pytest.approx(default.kappa, rel=1e-12)


@pytest.mark.parametrize("criterion", ["volume", "trace", "size_xy_psi", "kappa"])
@given(pair=ellipsoid_pair())
def test_batch_matches_single_calls(criterion, pair):
    """Every criterion: one compiled pass over the batch gives the bits of single calls."""
    E1, E2 = pair
    kw = {"kappa": 0.3} if criterion == "kappa" else {"criterion": criterion}
    if criterion == "size_xy_psi":
        kw["dims"] = ((0, 1), (2,)) if E1.dim > 2 else ((1,), (0,))
    out = analytic.minkowski_sum_batch(
        np.stack([E1.center, E2.center]),
        np.stack([E1.shape, E2.shape]),
        np.stack([E2.center, E1.center]),
        np.stack([E2.shape, E1.shape]),
        **kw,
    )
    for i, (X, Y) in enumerate([(E1, E2), (E2, E1)]):
        single = analytic.minkowski_sum(X, Y, **kw)
        assert out.kappa[i] == single.kappa and out.margin[i] == single.margin
        np.testing.assert_array_equal(out.shapes[i], single.ellipsoid.shape)
        np.testing.assert_array_equal(out.centers[i], single.ellipsoid.center)


E2D = Ellipsoid([0.0, 0.0], np.eye(2))


@pytest.mark.parametrize(
    ("args", "kwargs", "match"),
    [
        ((E2D, Ellipsoid(np.zeros(3), np.eye(3))), {}, "same dimension"),
        ((E2D, E2D), {"criterion": "diameter"}, "criterion"),
        ((E2D, E2D), {"kappa": 1.0}, "kappa"),
        ((E2D, E2D), {"kappa": 0.0}, "kappa"),
        ((E2D, E2D), {"kappa": float("nan")}, "kappa must be finite"),
        ((E2D, E2D), {"criterion": "size_xy_psi"}, "dims=\\(planar, heading\\) is required"),
        ((E2D, E2D), {"criterion": "size_xy_psi", "dims": ((0,), (0,))}, "disjoint"),
        ((E2D, E2D), {"criterion": "size_xy_psi", "dims": ((0,), (5,))}, "dims"),
    ],
)
def test_bad_inputs_raise(args, kwargs, match):
    with pytest.raises(ValueError, match=match):
        analytic.minkowski_sum(*args, **kwargs)


def test_batch_bad_inputs_raise():
    with pytest.raises(ValueError, match="shapes2 must be positive definite"):
        analytic.minkowski_sum_batch(
            np.zeros((2, 2)),
            np.stack([np.eye(2)] * 2),
            np.zeros((2, 2)),
            np.stack([np.eye(2), -np.eye(2)]),
        )


@pytest.mark.parametrize("criterion", ["volume", "trace", "size_xy_psi", "kappa"])
def test_full_blocks_match_single_calls(criterion):
    """Two full blocks of lanes (vectorized loops) and a remainder against single calls
    (a block of one): the same bits, whatever the neighbouring instances."""
    rng = np.random.default_rng(5)
    B = 2 * W + 3
    pairs = [(random_ellipsoid(rng, 3, 4.0), random_ellipsoid(rng, 3, 0.5)) for _ in range(B)]
    kw = {"kappa": rng.uniform(0.05, 0.95, B)} if criterion == "kappa" else {}
    out = analytic.minkowski_sum_batch(
        *(np.stack([getattr(E, a) for E in Es]) for Es in zip(*pairs, strict=True)
          for a in ("center", "shape")),
        **({"criterion": criterion} if criterion != "kappa" else kw),
    )  # fmt: skip
    for i, (E1, E2) in enumerate(pairs):
        k = {"kappa": kw["kappa"][i]} if kw else {"criterion": criterion}
        single = analytic.minkowski_sum(E1, E2, **k)
        assert out.kappa[i] == single.kappa and out.margin[i] == single.margin, i
        assert np.array_equal(out.shapes[i], single.ellipsoid.shape), i
        assert np.array_equal(out.centers[i], single.ellipsoid.center), i
