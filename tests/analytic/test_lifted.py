"""The lifted (pseudo-ellipsoid) update [BH, eqs. (15)-(16)]."""

import numpy as np
import pytest

from optbound import analytic
from optbound.sets import PolynomialLifting, PseudoEllipsoid, Strip

# One ring 0.8 <= |x - M| <= 1.0 around M = (0.3, -0.2) in the L = 4 lifting [BH, eq. (22)]:
# |x - M|^2 - |M|^2 = H [x, y, x^2, y^2].
M = np.array([0.3, -0.2])
H4 = np.array([[-2 * M[0], -2 * M[1], 1.0, 1.0]])
LO, HI = 0.8**2 - M @ M, 1.0**2 - M @ M


def prior(order: int = 1) -> PseudoEllipsoid:
    lift = PolynomialLifting.bh4() if order == 1 else PolynomialLifting.bh8()
    P = PseudoEllipsoid(lift, np.zeros(lift.size), 100.0 * np.eye(lift.size))
    assert np.all(P.contains(ring_points()))  # the prior contains the ring
    return P


def ring_points(n=2000, seed=0):
    rng = np.random.default_rng(seed)
    t = rng.uniform(0, 2 * np.pi, n)
    r = np.sqrt(rng.uniform(0.8**2, 1.0**2, n))
    return M + np.column_stack([r * np.cos(t), r * np.sin(t)])


def test_volume_criterion_is_bounding_update_in_the_lifted_space():
    P = prior()
    z, V = [0.5 * (LO + HI)], [[(0.5 * (HI - LO)) ** 2]]
    q = analytic.lifted_update(P, H4, z, V)
    ref = analytic.bounding_update(P.lifted, H4, z, V)
    np.testing.assert_array_equal(q.bound.center, ref.ellipsoid.center)
    np.testing.assert_array_equal(q.bound.shape, ref.ellipsoid.shape)
    assert q.lam == ref.lam
    assert q.margin == ref.margin > 0.0  # the lifted member's certified inflation
    assert q.set is q.bound and q.certified


def test_l4_strip_update_equals_intersect_strip():
    P = prior()
    mid, half = 0.5 * (LO + HI), 0.5 * (HI - LO)
    # v_center shifts the interval: z - v_center is the strip's centre.
    q = analytic.lifted_update(P, H4, [mid + 0.25], [[half**2]], v_center=[0.25])
    f = analytic.intersect_strip(P.lifted, Strip.from_bounds(H4[0], LO, HI))
    np.testing.assert_allclose(q.bound.center, f.ellipsoid.center, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(q.bound.shape, f.ellipsoid.shape, rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize("criterion", ["volume", "area"])
def test_contains_the_ring(criterion):
    P = prior()
    q = analytic.lifted_update(
        P, H4, [0.5 * (LO + HI)], [[(0.5 * (HI - LO)) ** 2]], criterion=criterion
    )
    X = ring_points()
    assert np.all(q.bound.contains(X))
    assert q.bound.grid_area(200, P.bounding_box()) < P.grid_area(200)


def test_area_criterion_is_not_worse_than_volume_on_its_own_objective():
    P = prior()
    args = (P, H4, [0.5 * (LO + HI)], [[(0.5 * (HI - LO)) ** 2]])
    window = P.bounding_box()
    a = analytic.lifted_update(*args, criterion="area").bound.grid_area(120, window)
    v = analytic.lifted_update(*args, criterion="volume").bound.grid_area(120, window)
    assert a <= v * 1.01


def test_two_row_update_with_the_arc_noise_l8():
    P = prior(order=2)
    m2 = M @ M
    H = np.array(
        [
            [-2 * M[0], -2 * M[1], 0, 1, 1, 0, 0, 0],
            [
                -4 * M[0] * m2,
                -4 * M[1] * m2,
                8 * M[0] * M[1],
                6 * M[0] ** 2 + 2 * M[1] ** 2,
                2 * M[0] ** 2 + 6 * M[1] ** 2,
                -4 * M[0],
                -4 * M[1],
                1,
            ],
        ]
    )
    v_hat, V = analytic.parabola_arc_ellipse(0.8**2, 1.0**2)
    q = analytic.lifted_update(P, H, -np.array([m2, m2 * m2]), V, v_center=-v_hat)
    X = ring_points()
    assert np.all(q.bound.contains(X))


def test_empty_measurement_gives_no_bound():
    P = prior()
    q = analytic.lifted_update(P, H4, [1e3], [[1.0]])
    assert q.bound is None


def test_bad_input():
    P = prior()
    with pytest.raises(TypeError, match="P"):
        analytic.lifted_update(P.lifted, H4, [0.0], [[1.0]])
    with pytest.raises(ValueError, match="criterion"):
        analytic.lifted_update(P, H4, [0.0], [[1.0]], criterion="trace-ish")
    with pytest.raises(ValueError, match="H"):
        analytic.lifted_update(P, H4[:, :3], [0.0], [[1.0]])
    with pytest.raises(ValueError, match="v_center"):
        analytic.lifted_update(P, H4, [0.0], [[1.0]], v_center=[np.nan])
    lift3 = PolynomialLifting.from_components(
        [{(1, 0, 0): 1.0}, {(0, 1, 0): 1.0}, {(0, 0, 1): 1.0}]
    )
    P3 = PseudoEllipsoid(lift3, np.zeros(3), np.eye(3))
    with pytest.raises(ValueError, match="area"):
        analytic.lifted_update(P3, [[1.0, 0, 0]], [0.0], [[0.25]], criterion="area")
