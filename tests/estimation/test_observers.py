"""Guaranteed observers and exact sets on 2-D systems, checked against an exact polygon oracle.

The oracle recomputes ``X_k = (A X_{k-1} + W) ∩ {x : y_k - C x in V}`` as a polygon in
``fractions.Fraction`` (vertex images, hull of vertex sums, Sutherland-Hodgman clipping), from
the floats of the data read exactly; no optbound code is involved.
"""

from fractions import Fraction

import numpy as np
import pytest

from optbound import Box, ConstrainedZonotope, Zonotope
from optbound import estimation as est
from optbound.sets.base import EmptySetError
from tests.sets import exact_polytopes as X

F = Fraction
ALAMO_YS = [0.79, 5.00, 4.35, 1.86, -0.11, -1.13]


def _clip(P, a, bound):
    """Exact clip of the convex polygon P (ccw list) to ``a^T x <= bound``."""
    out = []
    for k in range(len(P)):
        p, q = P[k], P[(k + 1) % len(P)]
        fp = a[0] * p[0] + a[1] * p[1] - bound
        fq = a[0] * q[0] + a[1] * q[1] - bound
        if fp <= 0:
            out.append(p)
        if (fp < 0 < fq) or (fq < 0 < fp):
            t = fp / (fp - fq)
            out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    return X.hull(out)


def oracle(A, C, W_pts, v_lo, v_hi, X0_pts, ys):
    """Exact polygons X_1..X_N (lists of Fraction vertices); C has one row."""
    A, c = X.exact(A), X.exact(C)
    P, out = X.hull(X0_pts), []
    for y in ys:
        mapped = [tuple(sum(a * x for a, x in zip(row, p, strict=True)) for row in A) for p in P]
        P = X.hull([(p[0] + w[0], p[1] + w[1]) for p in mapped for w in W_pts])
        y = F(float(y))
        P = _clip(P, c, y - v_lo)  # c^T x <= y - v_lo
        P = _clip(P, (-c[0], -c[1]), -(y - v_hi))  # c^T x >= y - v_hi
        out.append(P)
    return out


def alamo():
    """Alamo et al. (2005), Sect. 7.1, the first steps."""
    W = Zonotope([0.0, 0.0], [[-0.12], [0.02]])
    system = est.LinearSystem([[0.0, -0.5], [1.0, 1.0]], [-2.0, 1.0], W, Box([-0.2], [0.2]))
    X0 = Box([-3.0, -3.0], [3.0, 3.0])
    polys = oracle(
        system.A,
        system.C[0],
        X.set_points(W),
        F(-0.2),
        F(0.2),
        X.box_corners(X0.as_array()),
        ALAMO_YS,
    )
    return system, X0, polys


def box_noise(seed: int):
    """A random stable 2-D system with box noise and simulated measurements."""
    rng = np.random.default_rng(seed)
    A = rng.normal(size=(2, 2))
    A *= 0.9 / max(abs(np.linalg.eigvals(A)))
    C = rng.normal(size=2)
    W, V = Box([-0.1, -0.05], [0.1, 0.05]), Box([-0.2], [0.1])
    X0 = Box([-1.0, -1.0], [1.0, 1.0])
    x, ys = rng.uniform(-1, 1, 2), []
    for _ in range(5):
        x = A @ x + rng.uniform(W.lo, W.hi)
        ys.append(float(C @ x + rng.uniform(V.lo, V.hi)[0]))
    system = est.LinearSystem(A, C, W, V)
    polys = oracle(
        A, C, X.box_corners(W.as_array()), F(-0.2), F(0.1), X.box_corners(X0.as_array()), ys
    )
    return system, X0, polys, ys


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_exact_sets_match_an_independent_polygon_computation(seed):
    system, X0, polys, ys = box_noise(seed)
    sets = est.exact_sets(system, X0, ys)
    assert len(sets) == len(ys) and all(isinstance(S, ConstrainedZonotope) for S in sets)
    for k, (S, P) in enumerate(zip(sets, polys, strict=True)):
        if k < 2:  # exact containment (vertex enumeration of S is affordable)
            assert X.contains_all(S, P)
        V = S.vertices()
        for p in P:  # and equal up to rounding: every exact vertex is a computed one
            assert np.min(np.linalg.norm(V - np.array([float(p[0]), float(p[1])]), axis=1)) < 1e-7


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_observers_contain_the_exact_set(seed):
    system, X0, polys, ys = box_noise(seed)
    boxes = est.observe(system, X0, ys, method="interval")
    zonos = est.observe(system, X0, ys, method="zonotope", order=4.0)
    czs = est.observe(system, X0, ys, method="constrained_zonotope", order=4.0, max_constraints=2)
    for B, Z, C, P in zip(boxes, zonos, czs, polys, strict=True):
        assert all(F(B.lo[i]) <= p[i] <= F(B.hi[i]) for p in P for i in (0, 1))
        assert isinstance(Z, Zonotope) and Z.n_generators <= 8
        assert X.contains_all(Z, P)
        assert C.n_generators <= 8 and C.n_constraints <= 2
        assert X.contains_all(C, P)


def test_alamo_gain_is_the_f_radius_minimiser():
    # For one strip, Alamo's gain minimises ||[(I - lam a^T) G, -s lam]||_F; perturbing it
    # in any direction can only increase that radius.
    from optbound.estimation.observers import alamo_strip

    rng = np.random.default_rng(3)
    Z = Zonotope(rng.normal(size=2), rng.normal(size=(2, 4)))
    a = rng.normal(size=2)
    out = alamo_strip(Z, a, -0.3 + a @ Z.center, 0.2 + a @ Z.center)
    G, s = Z.generators, 0.25
    lam = out.center - Z.center  # = lam * (mid - a^T c) with mid - a^T c = -0.05
    lam = lam / -0.05

    def radius(g):
        return np.linalg.norm(np.hstack([(np.eye(2) - np.outer(g, a)) @ G, -s * g[:, None]]))

    assert np.linalg.norm(out.generators) == pytest.approx(radius(lam), rel=1e-9)
    for d in rng.normal(size=(8, 2)):
        assert radius(lam + 1e-3 * d) > radius(lam)


def test_alamo_example_first_steps():
    system, X0, polys = alamo()
    czs = est.observe(system, X0, ALAMO_YS, order=4.0)
    zonos = est.observe(system, X0, ALAMO_YS, method="zonotope", order=4.0)
    boxes = est.observe(system, X0, ALAMO_YS, method="interval")
    exact = est.exact_sets(system, X0, ALAMO_YS[:2])
    for k, P in enumerate(polys):
        assert X.contains_all(czs[k], P)
        assert X.contains_all(zonos[k], P)
        assert all(F(boxes[k].lo[i]) <= p[i] <= F(boxes[k].hi[i]) for p in P for i in (0, 1))
        if k < 2:
            assert X.contains_all(exact[k], P)
    # Ordered as containment and the methods' strength imply: exact <= zonotopic < boxes.
    area = X.area(polys[-1])
    for Z in (czs[-1], zonos[-1]):
        assert area <= X.area(X.hull(X.set_points(Z))) < F(boxes[-1].volume())
    assert F(zonos[-1].volume_bounds()[0]) <= X.area(X.hull(X.set_points(zonos[-1])))


def test_bad_input_is_refused():
    W, V = Box([-0.1, -0.1], [0.1, 0.1]), Box([-0.1], [0.1])
    with pytest.raises(ValueError, match="A must be square"):
        est.LinearSystem(np.ones((2, 3)), [1.0, 0.0], W, V)
    with pytest.raises(ValueError, match="C must have shape"):
        est.LinearSystem(np.eye(2), [1.0, 0.0, 0.0], W, V)
    with pytest.raises(ValueError, match="V must have dimension 1"):
        est.LinearSystem(np.eye(2), [1.0, 0.0], W, W)
    system = est.LinearSystem(np.eye(2), [1.0, 0.0], W, V)
    with pytest.raises(ValueError, match="ys must have shape"):
        est.exact_sets(system, Box([0.0, 0.0], [1.0, 1.0]), np.ones((3, 2)))
    with pytest.raises(ValueError, match="X0 must have dimension 2"):
        est.observe(system, Box([0.0], [1.0]), [0.0])
    with pytest.raises(ValueError, match="method must be one of"):
        est.observe(system, Box([0.0, 0.0], [1.0, 1.0]), [0.0], method="ellipsoid")


def test_inconsistent_measurements_are_reported():
    W, V = Box([-0.1, -0.1], [0.1, 0.1]), Box([-0.1], [0.1])
    system = est.LinearSystem(np.eye(2), [1.0, 0.0], W, V)
    X0 = Box([0.0, 0.0], [1.0, 1.0])
    for method in est.METHODS:
        with pytest.raises(EmptySetError):
            est.observe(system, X0, [50.0], method=method)
