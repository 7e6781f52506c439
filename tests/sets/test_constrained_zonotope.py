"""Tests for optbound.sets.ConstrainedZonotope: soundness of every operation in exact arithmetic.

The true result of each operation is built from its definition [Scott et al. 2016, Prop. 1]
in ``fractions.Fraction`` (the inputs' floats read exactly), its vertices enumerated exactly,
and each must lie in the returned set's exact convex hull.
"""

from fractions import Fraction

import matplotlib.pyplot as plt
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from optbound import Box, ConstrainedZonotope, Zonotope
from optbound.interval.tribool import Tri
from tests.sets import exact_polytopes as X

seeds = st.integers(0, 2**32 - 1)
F = Fraction


def random_cz(rng, n: int = 2, nc: int = 1) -> ConstrainedZonotope:
    """A non-empty constrained zonotope: b = A xi0 for an interior xi0."""
    m = int(rng.integers(nc + 2, nc + 4))
    A = rng.normal(size=(nc, m))
    return ConstrainedZonotope(
        rng.normal(size=n), rng.normal(size=(n, m)) / 2.0, A, A @ rng.uniform(-0.5, 0.5, m)
    )


def mat(rows) -> list[list[Fraction]]:
    return [list(r) for r in rows]


def matmul(P, Q) -> list[list[Fraction]]:
    return [
        [sum(p * q for p, q in zip(row, col, strict=True)) for col in zip(*Q, strict=True)]
        for row in P
    ]


def exact_intersection(S, Y, R) -> list:
    """Exact vertices of ``S ∩_R Y`` from Scott's Prop. 1, eq. (7), in Fractions."""
    c, G = X.exact(S.center), X.exact(S.generators)
    A, b = X.exact(S.A) if S.n_constraints else [], X.exact(S.b) if S.n_constraints else []
    cy, Gy = X.exact(Y.center), X.exact(Y.generators)
    Ay = X.exact(Y.A) if getattr(Y, "n_constraints", 0) else []
    by = X.exact(Y.b) if getattr(Y, "n_constraints", 0) else []
    R = X.exact(R)
    m, my = len(G[0]), len(Gy[0])
    RG = matmul(R, G)
    Rc = [sum(r * x for r, x in zip(row, c, strict=True)) for row in R]
    rows = [list(row) + [F(0)] * my for row in A]
    rows += [[F(0)] * m + list(row) for row in Ay]
    rows += [RG[i] + [-g for g in Gy[i]] for i in range(len(R))]
    rhs = list(b) + list(by) + [cy[i] - Rc[i] for i in range(len(R))]
    G_full = [list(row) + [F(0)] * my for row in G]
    return X.points(c, G_full, rows, rhs)


# ----------------------------------------------------------------------------- validation
@pytest.mark.parametrize(
    ("A", "b", "match"),
    [
        ([[1.0, 0.0]], [0.0], "A must have shape \\(nc, 3\\)"),
        ([[1.0, 0.0, 0.0]], [0.0, 1.0], "b must have shape \\(1,\\)"),
        ([[1.0, np.nan, 0.0]], [0.0], "A must be finite"),
        ([[1.0, 0.0, 0.0]], [np.inf], "b must be finite"),
        ([1.0, 0.0, 0.0], [0.0], "A must have shape"),
    ],
)
def test_bad_constraints_name_the_argument(A, b, match):
    with pytest.raises(ValueError, match=match):
        ConstrainedZonotope([0.0, 0.0], np.ones((2, 3)), A, b)


def test_operation_arguments_are_validated():
    C = ConstrainedZonotope([0.0, 0.0], np.eye(2), [[1.0, 1.0]], [0.5])
    with pytest.raises(ValueError, match="lo must be <= hi"):
        C.intersect_strip([1.0, 0.0], 1.0, 0.0)
    with pytest.raises(ValueError, match="a must have length 2"):
        C.intersect_strip([1.0], 0.0, 1.0)
    with pytest.raises(ValueError, match="hi must be finite"):
        C.intersect_strip([1.0, 0.0], 0.0, np.inf)
    with pytest.raises(ValueError, match="R must have shape"):
        C.generalized_intersection(Zonotope([0.0], [[1.0]]), np.eye(3))
    with pytest.raises(ValueError, match="Y must have dimension 1"):
        C.generalized_intersection(Zonotope([0.0, 0.0], np.eye(2)), [[1.0, 0.0]])
    with pytest.raises(TypeError, match="other must be a ConstrainedZonotope, Zonotope or Box"):
        C.minkowski_sum(np.eye(2))
    with pytest.raises(ValueError, match="order must give at least n \\+ nc = 3"):
        C.reduce_order(1.0)
    with pytest.raises(ValueError, match="count must be <= 1"):
        C.eliminate_constraints(2)
    with pytest.raises(TypeError, match="Z must be a Zonotope or a Box"):
        ConstrainedZonotope.from_zonotope(C)


# ------------------------------------------------------------------- hull, support, empty
@given(seeds)
def test_support_and_bounding_box_are_sound_and_tight(seed):
    rng = np.random.default_rng(seed)
    C = random_cz(rng, n=int(rng.integers(2, 4)), nc=int(rng.integers(1, 3)))
    pts = X.set_points(C)
    assert pts
    for d in rng.normal(size=(4, C.dim)):
        exact = max(sum(F(float(di)) * x for di, x in zip(d, p, strict=True)) for p in pts)
        h = C.support(d)
        assert Fraction(h) >= exact
        assert h - float(exact) <= 1e-7 * (1.0 + np.abs(d).sum() * np.abs(C.generators).sum())
    box = C.bounding_box()
    for p in pts:
        assert all(F(lo) <= x <= F(hi) for lo, x, hi in zip(box.lo, p, box.hi, strict=True))


@given(seeds)
def test_emptiness_is_proven_only_when_empty(seed):
    rng = np.random.default_rng(seed)
    C = random_cz(rng)
    assert not C.is_empty()
    d = rng.normal(size=2)
    top = C.support(d)
    gap = float(rng.uniform(1e-6, 1.0))
    away = C.intersect_strip(d, top + gap, top + 2 * gap)
    assert away.is_empty()
    assert X.set_points(away) == []  # exactly empty
    with pytest.raises(ValueError, match="empty"):
        away.bounding_box()
    assert away.support(d) == -np.inf


@given(seeds)
def test_contains_points(seed):
    rng = np.random.default_rng(seed)
    C = random_cz(rng)
    V = np.array([[float(x) for x in p] for p in X.set_points(C)])
    w = rng.dirichlet(np.ones(V.shape[0]), size=5)
    assert C.contains(w @ V).all()
    mid = V.mean(axis=0)
    assert not C.contains(mid + 1.5 * (V - mid)[np.argmax(np.linalg.norm(V - mid, axis=1))])


# --------------------------------------------------------------------------- operations
@given(seeds)
def test_intersect_strip_contains_exact_intersection(seed):
    rng = np.random.default_rng(seed)
    C = (
        random_cz(rng)
        if seed % 2
        else ConstrainedZonotope.from_zonotope(
            Zonotope(rng.normal(size=2), rng.normal(size=(2, 3)))
        )
    )
    a = rng.normal(size=2)
    centre = float(a @ C.center)
    lo = centre + float(rng.uniform(-1.0, 0.2))
    hi = lo + float(rng.uniform(0.0, 1.0))
    out = C.intersect_strip(a, lo, hi)
    mid, rad = (F(lo) + F(hi)) / 2, (F(hi) - F(lo)) / 2
    true = exact_intersection(C, _OneDim(mid, rad), [list(a)])
    assert X.contains_all(out, true)
    # and it is not larger than the exact set beyond rounding
    assert float(X.area(X.hull(X.set_points(out)))) <= float(X.area(X.hull(true))) + 1e-12


class _OneDim:
    """The exact 1-D zonotope <mid, rad> (Fractions) for the oracle."""

    def __init__(self, mid, rad):
        self.center, self.generators, self.n_constraints = [mid], [[rad]], 0


@settings(max_examples=12)  # exact vertex enumeration of the larger outer sets
@given(seeds)
def test_generalized_intersection_contains_exact_one(seed):
    rng = np.random.default_rng(seed)
    C = random_cz(rng)
    p = int(rng.integers(1, 3))
    R = rng.normal(size=(p, 2))
    Y = Zonotope(R @ C.center + rng.normal(size=p) * 0.3, rng.normal(size=(p, 2)))
    out = C.generalized_intersection(Y, R)
    true = exact_intersection(C, Y, R)
    assert X.contains_all(out, true)
    if true:
        assert float(X.area(X.hull(X.set_points(out)))) <= float(X.area(X.hull(true))) + 1e-12


@given(seeds)
def test_affine_map_contains_exact_image(seed):
    rng = np.random.default_rng(seed)
    C = random_cz(rng, n=int(rng.integers(2, 4)))
    M, t = rng.normal(size=(2, C.dim)), rng.normal(size=2)
    out = C.affine_map(M, t)
    Me, te = X.exact(M), X.exact(t)
    true = [
        tuple(
            sum(a * x for a, x in zip(row, p, strict=True)) + ti
            for row, ti in zip(Me, te, strict=True)
        )
        for p in X.set_points(C)
    ]
    assert X.contains_all(out, true)


@settings(max_examples=12)  # exact vertex enumeration of the larger outer sets
@given(seeds)
def test_minkowski_sum_contains_exact_sum(seed):
    rng = np.random.default_rng(seed)
    C = random_cz(rng)
    Y = random_cz(rng) if seed % 2 else Zonotope(rng.normal(size=2), rng.normal(size=(2, 2)))
    out = C.minkowski_sum(Y)
    true = [
        tuple(a + b for a, b in zip(p, q, strict=True))
        for p in X.set_points(C)
        for q in X.set_points(Y)
    ]
    assert X.contains_all(out, true)
    assert out.n_constraints == C.n_constraints + getattr(Y, "n_constraints", 0)


def test_minkowski_sum_with_box():
    C = ConstrainedZonotope([0.0, 0.0], np.eye(2), [[1.0, -1.0]], [0.0])  # the diagonal segment
    S = C.minkowski_sum(Box([0.0, 0.0], [0.5, 0.0]))
    assert X.contains_all(S, [(F(3, 2), F(1)), (F(-1), F(-1))])
    assert not S.contains([1.0, -1.0])


@pytest.mark.parametrize("method", ["girard", "combastel"])
@settings(max_examples=12)  # exact vertex enumeration of the larger outer sets
@given(seed=seeds)
def test_reduce_order_contains_exact_set(method, seed):
    rng = np.random.default_rng(seed)
    C = random_cz(rng).minkowski_sum(Zonotope([0.0, 0.0], rng.normal(size=(2, 3))))
    out = C.reduce_order(2.0, method)
    assert out.n_generators <= 4 and out.n_constraints == C.n_constraints
    assert X.contains_all(out, X.set_points(C))


@settings(max_examples=12)  # exact vertex enumeration of the larger outer sets
@given(seeds)
def test_eliminate_constraints_contains_exact_set(seed):
    rng = np.random.default_rng(seed)
    C = random_cz(rng, nc=2)
    one = C.eliminate_constraints(1)
    assert one.n_constraints <= C.n_constraints - 1 + 1  # a rounding slack may replace a row
    assert X.contains_all(one, X.set_points(C))
    none = C.eliminate_constraints(2)
    assert X.contains_all(none, X.set_points(C))


def test_elimination_is_exact_when_a_row_implies_the_bound():
    # xi_1 = xi_2 / 2: row 0 implies |xi_1| <= 1/2, so dropping xi_1's bound loses nothing;
    # the pivot rule must pick it (cost 0) rather than xi_2 or xi_3.
    C = ConstrainedZonotope(
        [0.0, 0.0], [[1.0, 0.5, 0.0], [0.0, 1.0, 1.0]], [[1.0, -0.5, 0.0]], [0.0]
    )
    out = C.eliminate_constraints(1)
    assert out.n_constraints == 0
    exact = X.set_points(C)
    assert X.contains_all(out, exact)
    # equal up to the rounding generators (outward-rounded interval products are ~1 ulp wide)
    assert X.area(X.hull(X.set_points(out))) <= X.area(X.hull(exact)) * (1 + F(1, 10**12))


def test_strip_then_eliminate_keeps_the_strip_constraint_informative():
    Z = Zonotope([1.0, 2.0], [[1.0, 0.5, 0.1], [0.0, 1.0, -0.3]])
    C = Z.intersect_strip([1.0, 1.0], 3.0, 3.5)
    out = C.eliminate_constraints(1)
    assert X.contains_all(out, X.set_points(C))
    assert float(X.area(X.hull(X.set_points(out)))) < 0.9 * float(X.area(X.hull(X.set_points(Z))))


# ------------------------------------------------------------------ tri_contains, drawing
@settings(max_examples=12)  # exact vertex enumeration of the larger outer sets
@given(seeds)
def test_tri_contains_false_is_proven(seed):
    rng = np.random.default_rng(seed)
    C = random_cz(rng)
    hull_box = C.bounding_box()
    lo = rng.uniform(hull_box.lo - 0.3, hull_box.hi, size=(12, 2))
    boxes = np.stack([lo, lo + rng.uniform(0.0, 0.3, size=(12, 2))], axis=2)
    tri = C.tri_contains(boxes)
    H = X.hull(X.set_points(C))
    for box, t in zip(boxes, tri, strict=True):
        if t == Tri.FALSE:
            assert X.disjoint(H, X.hull(X.box_corners(box)))
        if t == Tri.TRUE:
            assert all(X.in_hull(H, p) for p in X.box_corners(box))
    far = np.array([np.column_stack([hull_box.hi + 1.0, hull_box.hi + 2.0])])
    assert C.tri_contains(far).tolist() == [Tri.FALSE]


@settings(max_examples=12)
@given(seeds)
def test_tri_contains_true_is_proven_and_found_in_2d(seed):
    # Small boxes around points of the set: inside ones are TRUE (the certified inner
    # polygon), each checked exactly against the exact vertex hull.
    rng = np.random.default_rng(seed)
    C = random_cz(rng)
    H = X.hull(X.set_points(C))
    V = np.array([[float(p[0]), float(p[1])] for p in H])
    centre = V.mean(axis=0)
    pts = centre + rng.uniform(0.0, 1.0, (40, 1)) * (V[rng.integers(0, len(V), 40)] - centre)
    half = 1e-3 * np.abs(V - centre).max()
    boxes = np.stack([pts - half, pts + half], axis=2)
    tri = C.tri_contains(boxes)
    assert np.sum(tri == Tri.TRUE) >= 10
    for box, t in zip(boxes, tri, strict=True):
        if t == Tri.TRUE:
            assert all(X.in_hull(H, p) for p in X.box_corners(box))
        if t == Tri.FALSE:
            assert X.disjoint(H, X.hull(X.box_corners(box)))


@settings(max_examples=15)
@given(seeds, st.integers(0, 2))
def test_volume_bounds_bracket_the_exact_area(seed, nc):
    rng = np.random.default_rng(seed)
    C = random_cz(rng, nc=nc)
    lo, hi = C.volume_bounds()
    exact = X.area(X.hull(X.set_points(C)))
    assert F(lo) <= exact <= F(hi)
    assert hi - lo <= 1e-6 * float(exact)  # the two polygons meet at the LP tolerance


def test_volume_bounds_beyond_2d_are_the_hull_volume():
    C = ConstrainedZonotope(np.zeros(3), np.eye(3), [[1.0, 1.0, 0.0]], [0.0])
    lo, hi = C.volume_bounds()  # the certified hull [-1, 1]^3, its LP bounds rounded outward
    assert lo == 0.0 and 8.0 <= hi <= 8.0 * (1 + 1e-12)


def test_polygon_box_test_is_exact_at_the_edges():
    from optbound.sets.constrained_zonotope_polygon import polygon_box_test

    # The triangle (0, 0), (1, 0), (0, 1); boxes touching the hypotenuse x + y = 1 from
    # either side by one ulp, and one corner exactly on it.
    P = [(F(0), F(0)), (F(1), F(0)), (F(0), F(1))]
    one_up, one_down = np.nextafter(1.0, 2.0), np.nextafter(1.0, 0.0)
    boxes = np.array(
        [
            [[0.25, 0.5], [0.25, 0.5]],  # corner (0.5, 0.5) on the edge: inside
            [[0.25, 0.5], [0.25, np.nextafter(0.5, 1.0)]],  # one ulp over it
            [[0.5, 0.6], [np.nextafter(0.5, 1.0), 0.6]],  # whole box one ulp beyond it
            [[0.5, 0.6], [0.5, 0.6]],  # touching it at (0.5, 0.5)
            [[0.1, 0.2], [0.1, 0.2]],
            [[one_down, one_down], [0.0, 0.0]],
            [[one_up, one_up], [0.0, 0.0]],
        ]
    )
    assert polygon_box_test(P)(boxes).tolist() == [
        Tri.TRUE,
        Tri.UNKNOWN,
        Tri.FALSE,
        Tri.UNKNOWN,
        Tri.TRUE,
        Tri.TRUE,
        Tri.FALSE,
    ]


def test_tri_contains_uses_the_constraints():
    # The diagonal segment x = y in [-1, 1]^2: a box at (0.5, -0.5) is inside the hull but off
    # the segment, proven only by the constraint.
    C = ConstrainedZonotope([0.0, 0.0], np.eye(2), [[1.0, -1.0]], [0.0])
    boxes = np.array([[[0.4, 0.6], [-0.6, -0.4]], [[-0.1, 0.1], [-0.1, 0.1]]])
    assert C.tri_contains(boxes).tolist() == [Tri.FALSE, Tri.UNKNOWN]


@given(seeds)
def test_vertices_match_the_exact_polygon(seed):
    rng = np.random.default_rng(seed)
    C = random_cz(rng)
    V = C.vertices()
    for h in X.hull(X.set_points(C)):
        v = np.array([float(h[0]), float(h[1])])
        assert np.min(np.linalg.norm(V - v, axis=1)) <= 1e-6 * (1.0 + np.abs(v).max())


def test_plot_and_conversions():
    Z = Zonotope([0.0, 0.0], [[1.0, 0.5], [0.0, 1.0]])
    C = ConstrainedZonotope.from_zonotope(Z)
    assert C.n_constraints == 0 and C.A.shape == (0, 2)
    B = ConstrainedZonotope.from_zonotope(Box([0.0, 0.0], [1.0, 2.0]))
    hull = B.bounding_box().as_array()
    assert np.all(hull[:, 0] <= [0.0, 0.0]) and np.all(hull[:, 1] >= [1.0, 2.0])
    assert np.allclose(hull, [[0.0, 1.0], [0.0, 2.0]], rtol=0.0, atol=1e-14)
    fig, ax = plt.subplots()
    patches = C.intersect_strip([1.0, 0.0], -0.5, 0.5).plot(ax)
    assert len(patches) == 1
    plt.close(fig)


def _exact_step(c, G, A, b, M, W, a, lo, hi):
    """One exact observer step (M X + W) ∩ {lo <= a^T x <= hi} on Fraction data."""
    M = X.exact(M)
    c = [
        sum(r * x for r, x in zip(row, c, strict=True)) + w
        for row, w in zip(M, X.exact(W.center), strict=True)
    ]
    G = [mg + list(wg) for mg, wg in zip(matmul(M, G), X.exact(W.generators), strict=True)]
    m = len(G[0])
    A = [row + [F(0)] * (m - len(row)) for row in A]
    a = X.exact(a)
    aG = [sum(ai * G[i][k] for i, ai in enumerate(a)) for k in range(m)]
    mid, rad = (F(lo) + F(hi)) / 2, (F(hi) - F(lo)) / 2
    ac = sum(ai * ci for ai, ci in zip(a, c, strict=True))
    G = [[*row, F(0)] for row in G]
    A = [[*row, F(0)] for row in A] + [[*aG, -rad]]
    return c, G, A, [*b, mid - ac]


def test_recursion_is_sound_and_rounding_generators_do_not_accumulate():
    M = np.array([[0.9, 0.3], [-0.2, 0.8]])
    W = Zonotope([0.01, 0.0], [[0.1, 0.0, 0.05], [0.0, 0.1, 0.05]])
    Z = Zonotope([0.3, 0.1], np.eye(2))
    C = ConstrainedZonotope.from_zonotope(Z)
    c, G, A, b = X.exact(Z.center), X.exact(Z.generators), [], []
    for lo, hi in ((-0.3, 0.4), (-0.1, 0.5)):
        C = C.affine_map(M).minkowski_sum(W).intersect_strip([1.0, -0.5], lo, hi)
        c, G, A, b = _exact_step(c, G, A, b, M, W, [1.0, -0.5], lo, hi)
    # exact: 2 + 2 * (3 noise + 1 strip) generators; the rounding ones merged into them
    assert (C.n_generators, C.n_constraints) == (10, 2)
    assert X.contains_all(C, X.points(c, G, A, b))
    for _ in range(10):
        Z = Z.affine_map(M).minkowski_sum(W)
    assert Z.n_generators == 2 + 10 * 3


def test_scaled_inverse_is_exact_and_finds_singular_matrices():
    """``M X = L I`` with ``L > 0`` in integers (the inner polygon's exact repairs use it)."""
    from optbound.sets.constrained_zonotope_polygon import _scaled_inverse

    rng = np.random.default_rng(3)
    for n in range(5):
        for _ in range(20):
            M = rng.integers(-6, 7, (n, n)).tolist()
            X_L = _scaled_inverse(M)
            if X_L is None:
                assert n > 0 and round(np.linalg.det(np.array(M, dtype=float))) == 0
                continue
            X, L = X_L
            assert L > 0
            for i in range(n):
                for j in range(n):
                    assert sum(M[i][k] * X[k][j] for k in range(n)) == (L if i == j else 0)
    big = [[2**60 + 1, 3], [5, 2**61]]  # entries far beyond float64 precision
    X, L = _scaled_inverse(big)
    assert [[sum(big[i][k] * X[k][j] for k in range(2)) for j in range(2)] for i in range(2)] == [
        [L, 0],
        [0, L],
    ]
    assert _scaled_inverse([[1, 2], [2, 4]]) is None
