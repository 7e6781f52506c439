"""Exact polytopes (n <= 4): hull, volume and the exact sets, against independent formulas.

Every comparison is exact (``fractions.Fraction``, no tolerance): known volumes (cubes,
simplices, cross-polytopes), the zonotope volume ``2^n sum_S |det G_S|`` (Shephard 1974) and
vertex count ``2 sum_{i<n} C(m-1, i)`` of zonotopes in general position, the 2-D polygons,
and in 3-D the images of the vertices of the parameter polytope of ``X_k`` written directly
as a constrained zonotope in rational arithmetic (``tests.sets.exact_polytopes``).
"""

from fractions import Fraction
from itertools import product
from math import comb, factorial

import numpy as np
import pytest

from optbound import Box, Ellipsoid, Zonotope
from optbound import estimation as est
from optbound.estimation.exact_polygon import exact_polygons
from optbound.estimation.rational_polytope import convex_hull
from optbound.sets.constrained_zonotope_polygon import polygon_area as area
from tests.estimation.test_observers import box_noise
from tests.sets import exact_polytopes as X

F = Fraction


def _shephard(G) -> Fraction:
    """``2^n sum over n-subsets |det|`` with the test oracle's own exact solver."""
    from itertools import combinations

    n, m = len(G), len(G[0])
    total = F(0)
    for S in combinations(range(m), n):
        M = [[G[i][j] for j in S] for i in range(n)]
        total += abs(_det(M))
    return total * 2**n


def _det(M) -> Fraction:
    n = len(M)
    if n == 1:
        return M[0][0]
    return sum(
        (-1) ** j * M[0][j] * _det([row[:j] + row[j + 1 :] for row in M[1:]]) for j in range(n)
    )


@pytest.mark.parametrize("n", [2, 3, 4])
def test_known_volumes_with_interior_coplanar_and_repeated_points(n):
    cube = list(product((0, 1), repeat=n))
    extra = [tuple(F(1, 2) for _ in range(n)), (F(1, 2),) + (0,) * (n - 1), cube[0]]
    P = convex_hull(cube + extra, n)
    assert P.volume == 1 and sorted(P.vertices) == sorted(tuple(map(F, c)) for c in cube)
    simplex = [tuple(int(i == j) for j in range(n)) for i in range(n)] + [(0,) * n]
    assert convex_hull([*simplex, (F(1, 2 * n),) * n], n).volume == F(1, factorial(n))
    cross = [tuple(s * int(i == j) for j in range(n)) for i in range(n) for s in (-1, 1)]
    assert convex_hull([*cross, (0,) * n], n).volume == F(2**n, factorial(n))
    lo, hi = convex_hull(cross, n).volume_bounds()
    assert F(lo) <= F(2**n, factorial(n)) <= F(hi)


def test_flat_and_degenerate_sets():
    square = convex_hull([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), (F(1, 2), F(1, 2), 0)], 3)
    assert square.volume == 0 and len(square.vertices) == 4
    segment = convex_hull([(0, 0, 0), (1, 1, 1), (2, 2, 2)], 3)
    assert segment.vertices == ((0, 0, 0), (2, 2, 2)) and segment.volume == 0
    assert convex_hull([(1, 2, 3)], 3).vertices == ((1, 2, 3),)
    assert convex_hull([], 3).is_empty
    cut = convex_hull(list(product((0, 1), repeat=3)), 3).cut([1, 1, 1], F(1, 2))
    assert cut.volume == F(1, 48) and len(cut.vertices) == 4  # the corner simplex
    with pytest.raises(ValueError, match="3 coordinates"):
        convex_hull([(0, 0)], 3)


@pytest.mark.parametrize(("n", "m", "seed"), [(3, 5, 0), (3, 6, 1), (4, 5, 2)])
def test_zonotope_hull_matches_shephard_and_vertex_count(n, m, seed):
    G = X.exact(np.random.default_rng(seed).normal(size=(n, m)))
    pts = [
        tuple(sum(g * s for g, s in zip(row, signs, strict=True)) for row in G)
        for signs in product((-1, 1), repeat=m)
    ]
    P = convex_hull(pts, n)
    assert P.volume == _shephard(G)
    assert len(P.vertices) == 2 * sum(comb(m - 1, i) for i in range(n))


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_two_d_is_the_exact_polygon(seed):
    system, X0, polys, ys = box_noise(seed)
    for P, Q, R in zip(
        est.exact_polytopes(system, X0, ys), exact_polygons(system, X0, ys), polys, strict=True
    ):
        assert sorted(P.vertices) == sorted(Q) == sorted(R)
        assert P.volume == area(Q) == X.area(R)


def box_system(n: int = 3, steps: int = 2, seed: int = 0):
    """A random stable n-D system with box noise, one output, simulated measurements."""
    rng = np.random.default_rng(seed)
    A = rng.normal(size=(n, n))
    A *= 0.9 / max(abs(np.linalg.eigvals(A)))
    C = rng.normal(size=n)
    half = [0.1, 0.05, 0.1, 0.05][:n]
    W, V = Box([-h for h in half], half), Box([-0.2], [0.1])
    X0 = Box([-1.0] * n, [1.0] * n)
    x, ys = rng.uniform(-1, 1, n), []
    for _ in range(steps):
        x = A @ x + rng.uniform(W.lo, W.hi)
        ys.append(float(C @ x + rng.uniform(V.lo, V.hi)[0]))
    return est.LinearSystem(A, C, W, V), X0, ys


def parameter_oracle(system, X0, ys):
    """Exact vertex candidates of X_1..X_N from the rational constrained zonotope
    ``<c, G, A, b>``: ``x_k = A^k c_0 + ... ``, one slack generator and one constraint per
    measurement (``c^T x_k - y_k + mid_V = -rad_V s_k``), enumerated by the test oracle."""
    A, c = X.exact(system.A), X.exact(system.C[0])
    lo, hi = F(float(system.V.lo[0])), F(float(system.V.hi[0]))
    n = len(A)
    center = [F(0)] * n
    G = [[F(int(i == j)) for j in range(n)] for i in range(n)]  # X0 = [-1, 1]^n
    w = X.exact(system.W.widths / 2)
    rows, rhs, out = [], [], []
    for y in ys:
        center = [sum(a * x for a, x in zip(r, center, strict=True)) for r in A]
        G = [[sum(r[k] * G[k][j] for k in range(n)) for j in range(len(G[0]))] for r in A]
        G = [row + [w[i] if i == j else F(0) for j in range(n)] for i, row in enumerate(G)]
        rows = [r + [F(0)] * (n + 1) for r in rows]
        G = [[*row, F(0)] for row in G]
        cg = [sum(c[i] * G[i][j] for i in range(n)) for j in range(len(G[0]))]
        cg[-1] = (hi - lo) / 2  # c^T (c + G xi) + rad s = y - mid
        rows.append(cg)
        rhs.append(F(y) - (hi + lo) / 2 - sum(ci * x for ci, x in zip(c, center, strict=True)))
        out.append(X.points(center, G, rows, rhs))
    return out


@pytest.mark.parametrize(
    ("n", "steps"),
    [  # slow: 9 s (the 4-D hulls) and 18 s (the oracle's enumeration)
        (3, 1),
        pytest.param(4, 1, marks=pytest.mark.slow),
        pytest.param(3, 2, marks=pytest.mark.slow),
    ],
)
def test_exact_sets_match_the_parameter_oracle(n, steps):
    system, X0, ys = box_system(n, steps)
    for P, pts in zip(
        est.exact_polytopes(system, X0, ys), parameter_oracle(system, X0, ys), strict=True
    ):
        assert set(P.vertices) <= set(pts)  # every vertex is an exact point of the set
        assert sorted(convex_hull(pts, n).vertices) == sorted(P.vertices)
        assert P.volume > 0


def test_bad_input_is_refused():
    system, X0, ys = box_system(3, steps=1)
    with pytest.raises(TypeError, match="X0 must be a Box or Zonotope of dimension 3"):
        est.exact_polytopes(system, Ellipsoid(np.zeros(3), np.eye(3)), ys)
    big = est.LinearSystem(np.eye(5), np.ones(5), Box([-1.0] * 5, [1.0] * 5), Box([-1.0], [1.0]))
    with pytest.raises(ValueError, match="at most 4 states"):
        est.exact_polytopes(big, Box([-1.0] * 5, [1.0] * 5), [0.0])
    ell = est.LinearSystem(
        np.eye(3), np.ones(3), Ellipsoid(np.zeros(3), np.eye(3)), Box([-1.0], [1.0])
    )
    with pytest.raises(ValueError, match="Box or Zonotope noise"):
        est.exact_polytopes(ell, X0, ys)
    z = Zonotope([0.0, 0.0], [[1.0, 1.0], [0.0, 1.0]])
    two = est.LinearSystem(np.eye(3), np.ones((2, 3)), Box([-1.0] * 3, [1.0] * 3), z)
    with pytest.raises(ValueError, match="axis-aligned"):
        est.exact_polytopes(two, X0, [[0.0, 0.0]])
