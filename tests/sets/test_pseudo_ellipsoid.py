"""PseudoEllipsoid [BH, eq. (10)]: float membership, proven box membership, area bracket."""

import mpmath
import numpy as np
import pytest

import optbound as ob
from optbound.sets import Ellipsoid, PolynomialLifting, PseudoEllipsoid

mpmath.mp.prec = 200


def exact_level(P: PseudoEllipsoid, x, C_inv=None) -> mpmath.mpf:
    """The quadratic form at a float point, in 200-bit arithmetic (floats read as exact)."""
    lift = P.lift
    u = [
        (mpmath.mpf(x[j]) - mpmath.mpf(lift.offset[j])) / mpmath.mpf(lift.scale)
        for j in range(lift.dim)
    ]
    T = []
    for row in lift.coefficients:
        acc = mpmath.mpf(0)
        for c, e in zip(row, lift.exponents, strict=True):
            term = mpmath.mpf(c)
            for j, p in enumerate(e):
                term *= u[j] ** int(p)
            acc += term
        T.append(acc)
    y = mpmath.matrix([T[k] - mpmath.mpf(P.center[k]) for k in range(lift.size)])
    C_inv = mpmath.inverse(mpmath.matrix(P.shape.tolist())) if C_inv is None else C_inv
    return (y.T * C_inv * y)[0]


def random_pseudo(seed: int, order: int = 2) -> PseudoEllipsoid:
    rng = np.random.default_rng(seed)
    lift = PolynomialLifting.bh8([0.1, -0.1], 1.3) if order == 2 else PolynomialLifting.bh4()
    A = rng.normal(size=(lift.size, lift.size))
    return PseudoEllipsoid(
        lift, 0.3 * rng.normal(size=lift.size), A @ A.T + 0.3 * np.eye(lift.size)
    )


def test_exported_at_top_level():
    assert ob.PseudoEllipsoid is PseudoEllipsoid


def test_identity_lifting_is_the_ellipse():
    lift = PolynomialLifting.from_components([{(1, 0): 1.0}, {(0, 1): 1.0}])
    E = Ellipsoid([0.3, -0.2], [[4.0, 1.0], [1.0, 1.0]])
    P = PseudoEllipsoid.from_ellipsoid(lift, E)
    X = np.random.default_rng(0).normal(size=(100, 2)) * 2
    np.testing.assert_allclose(P.level(X), E.level(X), rtol=1e-12)
    np.testing.assert_array_equal(P.contains(X), E.level(X) <= 1)
    lo, hi = P.area_bounds(0.01)
    assert lo <= E.volume() <= hi and hi - lo < 0.03 * hi
    assert P.lifted.volume() == pytest.approx(E.volume())


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_tri_contains_is_proven_in_exact_arithmetic(seed):
    P = random_pseudo(seed)
    rng = np.random.default_rng(seed)
    box = P.bounding_box()
    lo = rng.uniform(box.lo, box.hi, (150, 2))
    boxes = np.stack([lo, lo + rng.uniform(0.0, 0.05, (150, 2))], axis=-1)
    t = P.tri_contains(boxes)
    assert np.sum(t == 2) >= 5 and np.sum(t == 0) >= 5
    C_inv = mpmath.inverse(mpmath.matrix(P.shape.tolist()))
    for b, ti in zip(boxes, t, strict=True):
        if ti == 1:
            continue
        corners = [b[np.arange(2), [i, j]] for i in (0, 1) for j in (0, 1)]
        for x in [*corners, b.mean(axis=1)]:
            assert (exact_level(P, x, C_inv) <= 1) == (ti == 2)


def test_tri_contains_decides_small_boxes_and_agrees_with_points():
    P = random_pseudo(5)
    pav = P.paving(0.02)
    inner, bound = pav.volume_bounds()
    assert 0 < inner <= P.grid_area(400) <= bound
    # Boxes of the paving at most eps wide: the undecided ones are a thin layer.
    assert bound - inner < 0.25 * bound


def test_bounding_box_contains_the_set():
    P = random_pseudo(3)
    box = P.bounding_box()
    rng = np.random.default_rng(3)
    X = rng.uniform(box.lo - 1, box.hi + 1, (20000, 2))
    inside = X[P.contains(X)]
    assert inside.shape[0] > 100
    assert np.all((inside >= box.lo) & (inside <= box.hi))


def test_boundary_traces_level_one():
    P = random_pseudo(4, order=1)
    lines = P.boundary(300)
    assert lines
    pts = np.concatenate(lines)
    np.testing.assert_allclose(P.level(pts), 1.0, atol=0.05)


def test_prove_covers_proves_subsets_and_refuses_supersets():
    P = random_pseudo(6)
    own = P.paving(0.05)
    assert P.prove_covers(own.inner).proven
    bigger = PseudoEllipsoid(P.lift, P.center, P.shape * 1.5**2)
    # Boundary boxes stick out of P; with P's own test the parts outside P are dropped.
    assert bigger.prove_covers(own.outer(), P.tri_test).proven
    proof = P.prove_covers(bigger.paving(0.05).inner, bigger.tri_test, rounds=2)
    assert not proof.proven and proof.refuted


def test_bad_input():
    lift = PolynomialLifting.bh4()
    with pytest.raises(TypeError, match="lift"):
        PseudoEllipsoid("bh4", np.zeros(4), np.eye(4))
    with pytest.raises(ValueError, match="center"):
        PseudoEllipsoid(lift, np.zeros(3), np.eye(4))
    with pytest.raises(ValueError, match="positive definite"):
        PseudoEllipsoid(lift, np.zeros(4), -np.eye(4))
    with pytest.raises(ValueError, match="finite"):
        PseudoEllipsoid(lift, [0, 0, np.nan, 0], np.eye(4))
    P = PseudoEllipsoid(lift, np.zeros(4), np.eye(4))
    with pytest.raises(ValueError, match="boxes"):
        P.tri_contains(np.zeros((3, 2)))
    with pytest.raises(ValueError, match="X"):
        P.level(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="eps"):
        P.area_bounds(0.0)
    no_id = PolynomialLifting.from_components([{(2, 0): 1.0}, {(0, 2): 1.0}, {(1, 1): 1.0}])
    with pytest.raises(ValueError, match="bounding_box"):
        PseudoEllipsoid(no_id, np.zeros(3), np.eye(3)).bounding_box()
