"""Tests for optbound.sets.Zonotope: every outer operation checked in exact arithmetic."""

from fractions import Fraction

import matplotlib.pyplot as plt
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound import Box, ConstrainedZonotope, Ellipsoid, Zonotope
from optbound.interval.tribool import Tri
from tests.sets import exact_polytopes as X

seeds = st.integers(0, 2**32 - 1)


def random_zonotope(rng, n: int = 2, m: int | None = None) -> Zonotope:
    m = int(rng.integers(1, 5)) if m is None else m
    return Zonotope(rng.normal(size=n) * 3.0, rng.normal(size=(n, m)) / 3.0)


def exact_support(pts, d) -> Fraction:
    d = X.exact(d)
    return max(sum(di * xi for di, xi in zip(d, p, strict=True)) for p in pts)


# ----------------------------------------------------------------------------- validation
@pytest.mark.parametrize(
    ("c", "G", "err", "match"),
    [
        ([0.0, np.nan], np.eye(2), ValueError, "c must be finite"),
        ([0.0, 0.0], [[1.0, np.inf], [0.0, 1.0]], ValueError, "G must be finite"),
        ([0.0, 0.0], np.eye(3), ValueError, "G must have shape"),
        ([0.0, 0.0], [1.0, 2.0], ValueError, "G must have shape"),
        ([], np.zeros((0, 1)), ValueError, "c must be a non-empty"),
        ([1j, 0.0], np.eye(2), TypeError, "c must be real"),
        ([0.0, 0.0], "ab", TypeError, "G must be an array"),
    ],
)
def test_bad_input_names_the_argument(c, G, err, match):
    with pytest.raises(err, match=match):
        Zonotope(c, G)


def test_operation_arguments_are_validated():
    Z = Zonotope([0.0, 0.0], np.eye(2))
    with pytest.raises(ValueError, match="A must have shape"):
        Z.affine_map(np.eye(3))
    with pytest.raises(ValueError, match="t must have length"):
        Z.affine_map(np.eye(2), [1.0])
    with pytest.raises(ValueError, match="order must be >= 1"):
        Z.reduce_order(0.5)
    with pytest.raises(ValueError, match="method must be one of"):
        Z.reduce_order(1, method="pca")
    with pytest.raises(ValueError, match="other must have dimension 2"):
        Z.minkowski_sum(Zonotope([0.0], [[1.0]]))
    with pytest.raises(TypeError, match="other must be a Zonotope or a Box"):
        Z.minkowski_sum(Ellipsoid([0.0, 0.0], np.eye(2)))
    with pytest.raises(ValueError, match="X must have shape"):
        Z.contains([1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="boxes must have shape"):
        Z.tri_contains(np.zeros((1, 3, 2)))
    with pytest.raises(ValueError, match="box must be bounded"):
        Zonotope.from_box(Box([0.0, -np.inf], [1.0, 1.0]))


# ------------------------------------------------------------------- hull and support
@given(seeds)
def test_support_and_bounding_box_are_sound_and_tight(seed):
    rng = np.random.default_rng(seed)
    Z = random_zonotope(rng, n=int(rng.integers(1, 4)))
    pts = X.set_points(Z)
    dirs = rng.normal(size=(4, Z.dim))
    for d, h in zip(dirs, Z.support(dirs), strict=True):
        exact = exact_support(pts, d)
        assert Fraction(h) >= exact
        assert h - float(exact) <= 1e-12 * (1.0 + abs(h))
    box = Z.bounding_box()
    for p in pts:
        assert all(
            Fraction(lo) <= x <= Fraction(hi) for lo, x, hi in zip(box.lo, p, box.hi, strict=True)
        )
    assert np.allclose(box.lo, Z.center - np.abs(Z.generators).sum(axis=1))


@given(seeds)
def test_contains_points(seed):
    rng = np.random.default_rng(seed)
    Z = random_zonotope(rng, n=int(rng.integers(1, 4)))
    xi = rng.uniform(-1.0, 1.0, size=(5, Z.n_generators)) * 0.99
    assert Z.contains(Z.center + xi @ Z.generators.T).all()
    d = rng.normal(size=Z.dim)
    far = Z.center + d * 1.01 * (Z.support(d) - d @ Z.center) / (d @ d)
    assert not Z.contains(far)
    assert Z.contains(Z.center) is True


# --------------------------------------------------------------------------- operations
@given(seeds)
def test_affine_map_contains_exact_image(seed):
    rng = np.random.default_rng(seed)
    Z = random_zonotope(rng, n=int(rng.integers(1, 4)))
    M, t = rng.normal(size=(2, Z.dim)), rng.normal(size=2)
    image = Z.affine_map(M, t)
    Me, te = X.exact(M), X.exact(t)
    exact = [
        tuple(
            sum(a * x for a, x in zip(row, p, strict=True)) + ti
            for row, ti in zip(Me, te, strict=True)
        )
        for p in X.set_points(Z)
    ]
    assert X.contains_all(image, exact)


@given(seeds)
def test_minkowski_sum_contains_exact_sum(seed):
    rng = np.random.default_rng(seed)
    Z1, Z2 = random_zonotope(rng), random_zonotope(rng)
    S = Z1.minkowski_sum(Z2)
    exact = [
        tuple(a + b for a, b in zip(p, q, strict=True))
        for p in X.set_points(Z1)
        for q in X.set_points(Z2)
    ]
    assert X.contains_all(S, exact)
    assert S.n_generators >= Z1.n_generators + Z2.n_generators


def test_minkowski_sum_with_box_and_constrained_zonotope():
    Z = Zonotope([0.1, 0.2], [[1.0, 0.3], [0.0, 1.0]])
    S = Z.minkowski_sum(Box([0.0, 0.0], [0.1, 0.3]))
    assert isinstance(S, Zonotope)
    assert S.contains([1.3 + 0.1 + 0.1, 1.2 + 0.3])
    C = ConstrainedZonotope([0.0, 0.0], np.eye(2), [[1.0, 1.0]], [0.0])
    assert isinstance(Z.minkowski_sum(C), ConstrainedZonotope)


@pytest.mark.parametrize("method", ["girard", "combastel"])
@given(seed=seeds)
def test_reduce_order_contains_exact_zonotope(method, seed):
    rng = np.random.default_rng(seed)
    Z = random_zonotope(rng, m=int(rng.integers(3, 8)))
    R = Z.reduce_order(1.5, method)
    assert R.n_generators <= 3
    assert X.contains_all(R, X.set_points(Z))
    assert (
        Z.reduce_order(10, method) is not Z
        and Z.reduce_order(10, method).n_generators == Z.n_generators
    )


def test_reduction_methods_choose_different_generators():
    # Girard keeps the largest ||g||_1 - ||g||_inf (the diagonal generator; axis-aligned ones
    # score 0), Combastel the largest Euclidean norm (the long axis-aligned one).
    G = np.array([[0.0, 0.3, 5.0, 0.1], [1.0, 0.3, 0.0, 0.0]])
    girard = Zonotope([0.0, 0.0], G).reduce_order(1.5, "girard").generators
    combastel = Zonotope([0.0, 0.0], G).reduce_order(1.5, "combastel").generators
    assert girard[:, 0].tolist() == [0.3, 0.3]
    assert np.allclose(girard[:, 1:], np.diag([5.1, 1.0]))
    assert combastel[:, 0].tolist() == [5.0, 0.0]
    assert np.allclose(combastel[:, 1:], np.diag([0.4, 1.3]))


def test_project_selects_rows():
    Z = Zonotope([1.0, 2.0, 3.0], [[1.0, 0.0], [0.0, 2.0], [1.0, 1.0]])
    P = Z.project([2, 0])
    assert P.center.tolist() == [3.0, 1.0]
    assert P.generators.tolist() == [[1.0, 1.0], [1.0, 0.0]]


# -------------------------------------------------------------------------- conversions
@given(seeds)
def test_from_box_contains_the_box(seed):
    rng = np.random.default_rng(seed)
    lo = rng.normal(size=2)
    B = Box(lo, lo + rng.uniform(0.0, 2.0, size=2))
    Z = Zonotope.from_box(B)
    assert X.contains_all(Z, X.box_corners(B.as_array()))


def _exact_quadratic(c, Q, p) -> Fraction:
    """(p - c)^T Q^{-1} (p - c) for a 2x2 Q, exactly."""
    (a, b), (_, d) = X.exact(Q)
    u, w = (p[0] - X.exact(c[0]), p[1] - X.exact(c[1]))
    det = a * d - b * b
    return (d * u * u - 2 * b * u * w + a * w * w) / det


@given(seeds)
def test_outer_ellipsoid_contains_exact_zonotope(seed):
    rng = np.random.default_rng(seed)
    Z = random_zonotope(rng, m=int(rng.integers(2, 6)))
    E = Z.outer_ellipsoid()
    assert all(_exact_quadratic(E.center, E.shape, p) <= 1 for p in X.set_points(Z))
    # The trace-minimal member (sum ||g||)^2 of the family, inflated by rounding only; its
    # trace is at most that of m G G^T (Cauchy-Schwarz).
    G = Z.generators
    w = np.linalg.norm(G, axis=0)
    assert np.allclose(E.shape, w.sum() * (G / w) @ G.T, rtol=1e-12, atol=0.0)
    assert np.trace(E.shape) <= (1 + 1e-12) * Z.n_generators * np.trace(G @ G.T)


@given(seeds)
def test_outer_ellipsoid_with_unit_weights_contains_exact_zonotope(seed):
    rng = np.random.default_rng(seed)
    Z = random_zonotope(rng, m=int(rng.integers(2, 6)))
    E = Z.outer_ellipsoid(weights="unit")
    assert all(_exact_quadratic(E.center, E.shape, p) <= 1 for p in X.set_points(Z))
    G = Z.generators
    assert np.allclose(E.shape, Z.n_generators * G @ G.T, rtol=1e-12, atol=0.0)
    with pytest.raises(ValueError, match="weights must be"):
        Z.outer_ellipsoid(weights="volume")


def test_outer_ellipsoid_of_a_flat_zonotope_is_refused():
    with pytest.raises(ValueError, match="flat"):
        Zonotope([0.0, 0.0], [[1.0, 2.0], [1.0, 2.0]]).outer_ellipsoid()


@given(seeds)
def test_from_ellipsoid_contains_the_ellipsoid(seed):
    rng = np.random.default_rng(seed)
    L = np.tril(rng.normal(size=(2, 2))) + 2.0 * np.eye(2)
    E = Ellipsoid(rng.normal(size=2), L @ L.T)
    Z = Zonotope.from_ellipsoid(E)
    assert Z.n_generators == 2 and np.allclose(Z.generators, E.chol, rtol=1e-12)
    # Same centre: E subset Z iff h_E <= h_Z along every facet normal of the parallelogram,
    # i.e. d^T Q d <= (sum_j |d^T g_j|)^2 with exact normals d = (-g_2, g_1).
    G, Q = X.exact(Z.generators), X.exact(E.shape)
    assert Z.center.tolist() == E.center.tolist()
    for k in range(2):
        d = (-G[1][k], G[0][k])
        quad = sum(d[i] * Q[i][j] * d[j] for i in range(2) for j in range(2))
        h = sum(abs(d[0] * G[0][j] + d[1] * G[1][j]) for j in range(2))
        assert quad <= h * h


# ----------------------------------------------------------------------------- volume
@given(seeds)
def test_area_bracket_is_exact_in_2d(seed):
    rng = np.random.default_rng(seed)
    Z = random_zonotope(rng, m=int(rng.integers(1, 7)))
    lo, hi = Z.volume_bounds()
    exact = X.area(X.hull(X.set_points(Z)))
    assert Fraction(lo) <= exact <= Fraction(hi)
    assert hi <= np.nextafter(np.nextafter(lo, np.inf), np.inf)
    coarse = Z.volume_bounds(max_subsets=2)
    assert Fraction(coarse[0]) <= exact <= Fraction(coarse[1])


def test_volume_in_3d_and_flat_cases():
    cube = Zonotope([0.0, 0.0, 0.0], np.diag([0.5, 1.0, 2.0]))
    assert cube.volume_bounds() == (8.0, 8.0)
    assert Zonotope([0.0, 0.0, 0.0], np.ones((3, 2))).volume_bounds() == (0.0, 0.0)
    skew = Zonotope([0.0] * 3, [[1.0, 0.5, 0.0, 0.2], [0.0, 1.0, 0.1, 0.3], [0.0, 0.0, 1.0, 0.4]])
    lo, hi = skew.volume_bounds()
    coarse_lo, coarse_hi = skew.volume_bounds(max_subsets=1)
    assert coarse_lo <= lo <= hi <= coarse_hi and coarse_lo < coarse_hi
    assert skew.bounding_box().volume() >= hi


# ------------------------------------------------------------------------ tri_contains
@given(seeds)
def test_tri_contains_is_proven(seed):
    rng = np.random.default_rng(seed)
    Z = random_zonotope(rng, m=int(rng.integers(2, 5)))
    hull_box = Z.bounding_box()
    lo = rng.uniform(hull_box.lo - 0.5, hull_box.hi + 0.5, size=(40, 2))
    boxes = np.stack([lo, lo + rng.uniform(0.0, 0.3, size=(40, 2))], axis=2)
    tri = Z.tri_contains(boxes)
    H = X.hull(X.set_points(Z))
    for box, t in zip(boxes, tri, strict=True):
        corners = X.box_corners(box)
        if t == Tri.TRUE:
            assert all(X.in_hull(H, p) for p in corners)
        elif t == Tri.FALSE:
            assert X.disjoint(H, X.hull(corners))
    # Decisive where it should be: a tiny box at the centre, a box far away.
    c = Z.center
    probe = np.array([np.column_stack([c - 1e-9, c + 1e-9]), np.column_stack([c + 50, c + 51])])
    assert Z.tri_contains(probe).tolist() == [Tri.TRUE, Tri.FALSE]


def test_tri_contains_in_3d_proves_only_disjointness():
    Z = Zonotope([0.0, 0.0, 0.0], np.eye(3))
    boxes = np.array([[[-0.1, 0.1]] * 3, [[2.0, 3.0]] * 3])
    assert Z.tri_contains(boxes).tolist() == [Tri.UNKNOWN, Tri.FALSE]
    line = Zonotope([0.0], [[1.0, 0.5]])
    assert line.tri_contains(np.array([[[-1.0, 1.0]], [[1.6, 2.0]]])).tolist() == [
        Tri.TRUE,
        Tri.FALSE,
    ]


# ------------------------------------------------------------------------------ drawing
@given(seeds)
def test_vertices_are_the_exact_polygon(seed):
    rng = np.random.default_rng(seed)
    Z = random_zonotope(rng, m=int(rng.integers(1, 6)))
    H = X.hull(X.set_points(Z))
    V = Z.vertices()
    exact = np.array([[float(a), float(b)] for a, b in H])
    for v in exact:
        assert np.min(np.linalg.norm(V - v, axis=1)) <= 1e-12 * (1 + np.abs(v).max())
    area = 0.5 * abs(np.sum(V[:, 0] * np.roll(V[:, 1], -1) - np.roll(V[:, 0], -1) * V[:, 1]))
    assert area == pytest.approx(float(X.area(H)), rel=1e-9, abs=1e-12)


def test_plot_draws_the_outline():
    fig, ax = plt.subplots()
    patches = Zonotope([0.0, 0.0, 5.0], [[1.0, 0.5], [0.0, 1.0], [3.0, 3.0]]).plot(ax, color="k")
    assert len(patches) == 1 and patches[0].get_xy().shape[0] == 5  # 4 vertices, closed
    plt.close(fig)


def test_protocol_capabilities():
    from optbound.sets.base import BoxProver, Outlined, VolumeBracket

    Z = Zonotope([0.0, 0.0], [[1.0, 0.5], [0.0, 1.0]])
    C = ConstrainedZonotope.from_zonotope(Z)
    for S in (Z, C):
        assert isinstance(S, BoxProver) and isinstance(S, Outlined)
        ring = S.boundary(100)
        assert ring.shape == (5, 2) and ring[0].tolist() == ring[-1].tolist()
    assert isinstance(Z, VolumeBracket)
    assert Z.volume_bounds(0.01) == Z.volume_bounds() == (4.0, 4.0)
    with pytest.raises(ValueError, match="max_subsets must be a positive integer"):
        Z.volume_bounds(max_subsets=0)


@given(seeds)
def test_2d_slab_membership_agrees_with_the_lp(seed):
    from optbound.sets.zonotope_membership import lp_contains, slab_contains

    rng = np.random.default_rng(seed)
    Z = random_zonotope(rng, m=int(rng.integers(2, 6)))
    box = Z.bounding_box()
    pts = rng.uniform(box.lo, box.hi, size=(30, 2))
    H = X.hull(X.set_points(Z))
    exact = [X.in_hull(H, tuple(X.exact(p))) for p in pts]
    no_constraints = (np.zeros((0, Z.n_generators)), np.zeros(0))
    assert slab_contains(Z.center, Z.generators, pts, 0.0).tolist() == exact
    assert lp_contains(Z.center, Z.generators, *no_constraints, pts, 1e-7).tolist() == exact
