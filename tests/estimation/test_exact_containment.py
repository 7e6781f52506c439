"""Exact containment of the exact set in every observer's set (2-D and 3-D), exact MVEEs.

Every check is in rational arithmetic at the exact vertices of ``X_k`` (no tolerance); the
constrained zonotopes' certificates are re-checked here independently of the code that found
them.
"""

from fractions import Fraction
from itertools import product

import numpy as np
import pytest

from optbound import Box, ConstrainedZonotope, Ellipsoid, Zonotope
from optbound import estimation as est
from optbound.estimation import references as ref
from optbound.estimation.exact_membership import max_level, parameter_certificate
from optbound.estimation.rational_polytope import convex_hull
from tests.estimation.test_exact_polytope import box_system
from tests.estimation.test_observers import box_noise
from tests.sets import exact_polytopes as X

F = Fraction


def _certified(Z: ConstrainedZonotope, p) -> bool:
    """The certificate of ``p in Z``, checked from its definition."""
    xi = parameter_certificate(Z, p)
    if xi is None:
        return False
    G, c, A, b = X.exact(Z.generators), X.exact(Z.center), X.exact(Z.A), X.exact(Z.b)
    image = [
        ci + sum(g * x for g, x in zip(row, xi, strict=True)) for ci, row in zip(c, G, strict=True)
    ]
    rows = [sum(a * x for a, x in zip(row, xi, strict=True)) for row in A]
    return all(abs(x) <= 1 for x in xi) and image == list(p) and rows == b


@pytest.mark.parametrize("case", ["2d-2", "3d"])
def test_every_method_contains_the_exact_set_at_every_step(case):
    if case == "3d":
        system, X0, ys = box_system(3, steps=2)
    else:
        system, X0, _, ys = box_noise(int(case[-1]))
    exact = est.exact_polytopes(system, X0, ys)
    for method in est.METHODS:
        for S, P in zip(est.observe(system, X0, ys, method=method), exact, strict=True):
            assert ref.proven_contains(S, P.vertices) is True, (method, case)
    for S, P in zip(est.exact_sets(system, X0, ys), exact, strict=True):
        assert all(_certified(S, v) for v in P.vertices)  # the unreduced sets too


def test_refutations_and_undecided():
    system, X0, ys = box_system(3, steps=1)
    P = est.exact_polytopes(system, X0, ys)[0]
    E = est.observe(system, X0, ys, method="ellipsoid_volume")[0]
    assert ref.proven_contains(E.scaled(0.9), P.vertices) is False
    lo, hi = P.as_array().min(axis=0), P.as_array().max(axis=0)
    assert ref.proven_contains(Box(lo - 0.01, hi - 0.01 * (hi - lo)), P.vertices) is False
    Z = est.observe(system, X0, ys, method="zonotope")[0]
    assert ref.proven_contains(Z.affine_map(0.9 * np.eye(3), 0.1 * Z.center), P.vertices) is False
    flat = Zonotope(np.zeros(3), [[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]])
    assert ref.proven_contains(flat, [(F(0), F(0), F(0))]) is None
    assert ref.proven_contains(flat, [(F(0), F(0), F(1))]) is False  # off its plane
    CZ = est.observe(system, X0, ys)[0]
    far = tuple(F(10) for _ in range(3))
    assert parameter_certificate(CZ, far) is None
    assert ref.proven_contains(CZ, [*P.vertices, far]) is None  # never refuted, undecided


def test_certificate_of_a_tight_vertex():
    # The unit square as the constrained zonotope <0, [I, e_1], [0 0 1], 0>: its corners need
    # the parameters exactly on their bounds.
    Z = ConstrainedZonotope(
        [0.0, 0.0], [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], [[0.0, 0.0, 1.0]], [0.0]
    )
    for corner in product((-1, 1), repeat=2):
        assert _certified(Z, tuple(F(c) for c in corner))
    assert parameter_certificate(Z, (F(1), F(1) + F(1, 2**60))) is None


@pytest.mark.parametrize("n", [3, 4])
def test_mvee_of_the_cube_is_the_circumscribed_ball(n):
    cube = convex_hull(list(product((-1, 1), repeat=n)), n)
    M = ref.polytope_mvee(cube)
    assert max_level(M.ellipsoid, cube.vertices) <= 1  # exact
    ball = Ellipsoid(np.zeros(n), n * np.eye(n))  # the MVEE of [-1, 1]^n (radius sqrt(n))
    assert M.ellipsoid.volume() == pytest.approx(ball.volume(), rel=1e-5)


def test_exact_mvee_bounds_the_ellipsoidal_observers():
    system, X0, ys = box_system(3, steps=2)
    P = est.exact_polytopes(system, X0, ys)[-1]
    M = ref.polytope_mvee(P)
    assert M.certified and max_level(M.ellipsoid, P.vertices) <= 1
    for method in ("ellipsoid_volume", "ellipsoid_trace"):
        E = est.observe(system, X0, ys, method=method)[-1]
        assert M.ellipsoid.volume() <= E.volume() * (1 + 1e-6)  # the MVEE is the smallest
    assert float(P.volume) <= M.ellipsoid.volume()
    with pytest.raises(ValueError, match="full-dimensional"):
        ref.polytope_mvee(convex_hull([(0, 0, 0), (1, 0, 0), (0, 1, 0)], 3))
