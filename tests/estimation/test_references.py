"""References: exact area against the exact polygon, MVEE, and the optimal one-step ellipsoid."""

from fractions import Fraction

import numpy as np
import pytest

from optbound import estimation as est
from optbound.estimation import references as ref
from tests.estimation.test_observers import box_noise
from tests.sets import exact_polytopes as X


@pytest.mark.parametrize("seed", [0, 1])
def test_exact_area_brackets_the_exact_polygon(seed):
    system, X0, polys, ys = box_noise(seed)
    for S, P in zip(est.exact_sets(system, X0, ys), polys, strict=True):
        area, upper = ref.exact_area(S)
        exact = X.area(P)
        assert exact <= Fraction(upper)  # certified
        assert area == pytest.approx(float(exact), rel=1e-7)  # LP vertices
        assert upper == pytest.approx(float(exact), rel=1e-6)
        assert ref.interval_hull(S).volume() >= float(exact)


def test_mvee_and_one_step_optimal():
    system, X0, polys, ys = box_noise(2)
    exact = est.exact_sets(system, X0, ys)
    M = ref.exact_mvee(exact[-1])
    assert M.certified
    assert np.all(M.ellipsoid.level(np.array(polys[-1], dtype=float)) <= 1 + 1e-9)
    for method in ("ellipsoid_volume", "ellipsoid_trace"):
        E = est.observe(system, X0, ys, method=method)
        opt = ref.one_step_optimal(system, E[-2], ys[-1], method)
        assert opt.certified
        assert X.in_ellipsoid(opt.ellipsoid, polys[-1])  # it bounds a superset of X_k
        size = (
            (lambda e: e.volume())
            if method == "ellipsoid_volume"
            else (lambda e: np.trace(e.shape))
        )
        # optimal over all ellipsoids of the same set: never larger than the analytic step
        assert size(opt.ellipsoid) <= size(E[-1]) * (1 + 1e-6)
        assert M.ellipsoid.volume() <= E[-1].volume()
    with pytest.raises(ValueError, match="2-D"):
        ref.exact_area(est.exact_sets(*_three_d())[0])


def _three_d():
    from optbound import Box

    system = est.LinearSystem(
        np.eye(3) * 0.5, np.ones(3), Box([-0.1] * 3, [0.1] * 3), Box([-1.0], [1.0])
    )
    return system, Box([-1.0] * 3, [1.0] * 3), [0.0]


def test_proven_contains():
    from optbound import Box
    from optbound.estimation.exact_polygon import exact_polygons

    system, X0, polys, ys = box_noise(1)
    exact = exact_polygons(system, X0, ys)[-1]
    assert sorted(exact) == sorted(polys[-1])  # the test oracle's polygon, exactly
    for method in ("interval", "zonotope", "zonotope_volume", "ellipsoid_volume"):
        S = est.observe(system, X0, ys, method=method)[-1]
        assert ref.proven_contains(S, exact) is True
    E = est.observe(system, X0, ys, method="ellipsoid_trace")[-1]
    assert ref.proven_contains(E.scaled(0.5), exact) is False
    hull = ref.interval_hull(est.exact_sets(system, X0, ys)[-1])
    assert ref.proven_contains(hull, exact) is True
    assert ref.proven_contains(Box(hull.lo + 0.01 * hull.widths, hull.hi), exact) is False
    Z = est.observe(system, X0, ys, method="zonotope")[-1]
    assert ref.proven_contains(Z.affine_map(0.5 * np.eye(2), Z.center * 0.5), exact) is False
    assert ref.proven_contains(est.observe(system, X0, ys)[-1], exact) is True


@pytest.mark.parametrize("seed", [0, 2])
def test_exact_polygons_match_the_oracle(seed):
    from optbound.estimation.exact_polygon import exact_polygons
    from optbound.sets.constrained_zonotope_polygon import polygon_area as area

    system, X0, polys, ys = box_noise(seed)
    for P, Q in zip(exact_polygons(system, X0, ys), polys, strict=True):
        assert sorted(P) == sorted(Q)
        assert area(P) == X.area(Q)
