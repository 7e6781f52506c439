"""Lifting members to quadratic inequalities, with and without clipping."""

import numpy as np
import pytest

from optbound import Box, Ellipsoid, Halfspace, Strip
from optbound.optimal import EmptyIntersectionError
from optbound.optimal.lift import lift


def test_clipping_turns_the_far_plane_into_a_tangent():
    E = Ellipsoid([0.0, 0.0], np.eye(2))
    q = lift([E, Strip.from_bounds([1.0, 0.0], 0.3, 2.3)])[1]
    lo, hi = q.extent([1.0, 0.0])
    assert lo == pytest.approx(0.3) and hi == pytest.approx(1.0, abs=1e-11)
    assert hi >= 1.0  # widened outward, never inward


def test_no_clipping_keeps_the_raw_strip():
    E = Ellipsoid([0.0, 0.0], np.eye(2))
    q = lift([E, Strip.from_bounds([1.0, 0.0], 0.3, 2.3)], clip=False)[1]
    assert q.extent([1.0, 0.0]) == (pytest.approx(0.3), pytest.approx(2.3))


def test_clipped_halfspace_becomes_a_strip_and_box_gives_one_per_finite_coordinate():
    E = Ellipsoid([0.0, 0.0], np.eye(2))
    members = [E, Halfspace([0.0, 1.0], 0.5), Box([-np.inf, -3.0], [np.inf, 0.2])]
    quadratics = lift(members, clip="ellipsoids")
    assert len(quadratics) == 3
    assert quadratics[1].extent([0.0, 1.0]) == (pytest.approx(-1.0), pytest.approx(0.5))
    assert quadratics[2].extent([0.0, 1.0]) == (pytest.approx(-1.0), pytest.approx(0.2))
    # Clipped to the intersection, the half-space also meets the box's bound 0.2.
    clipped = lift(members, clip="intersection")
    assert clipped[1].extent([0.0, 1.0]) == (pytest.approx(-1.0), pytest.approx(0.2))
    assert clipped[1].extent([0.0, 1.0])[1] >= 0.2  # widened outward, never inward


def test_intersection_clipping_reaches_the_polygon_extents():
    # Unit disc cut by x1 <= 0.1 and x1 + x2 >= 0.5 (normalised): the second row's range
    # over the intersection is [0.5, (0.1 + sqrt(0.99)) / sqrt 2], attained at a corner.
    s = np.sqrt(0.5)
    members = [
        Ellipsoid([0.0, 0.0], np.eye(2)),
        Halfspace([1.0, 0.0], 0.1),
        Halfspace([-s, -s], -0.5 * s),
    ]
    lo, hi = lift(members)[2].extent([s, s])
    assert lo == pytest.approx(0.5 * s, rel=1e-8)
    assert hi == pytest.approx((0.1 + np.sqrt(0.99)) * s, rel=1e-7)
    assert hi >= (0.1 + np.sqrt(0.99)) * s  # certified: never clips a point of the set


def test_intersection_clipping_detects_an_empty_polyhedron():
    # Each half-space meets the disc, but not both together.
    members = [
        Ellipsoid([0.0, 0.0], np.eye(2)),
        Halfspace([1.0, 0.0], -0.5),
        Halfspace([-1.0, 0.0], -0.5),
    ]
    with pytest.raises(EmptyIntersectionError):
        lift(members)
    assert len(lift(members, clip="ellipsoids")) == 3


def test_clip_mode_is_checked():
    with pytest.raises(ValueError, match="clip"):
        lift([Ellipsoid([0.0, 0.0], np.eye(2))], clip="polytope")


def test_unclipped_halfspace_stays_affine():
    q = lift([Halfspace([0.0, 1.0], 0.5)], clip=False)[0]
    assert not np.any(q.A) and q.extent([0.0, 1.0])[1] == pytest.approx(0.5)


def test_strip_beyond_the_ellipsoid_is_empty():
    with pytest.raises(EmptyIntersectionError):
        lift([Ellipsoid([0.0, 0.0], np.eye(2)), Halfspace([1.0, 0.0], -1.5)])


def test_pair_products_hold_on_the_set():
    E = Ellipsoid([0.0, 0.0], np.eye(2))
    members = [E, Strip.from_bounds([1.0, 0.0], -0.5, 0.5), Strip.from_bounds([1.0, 1.0], 0, 2)]
    quadratics = lift(members, products=True)
    assert len(quadratics) == 3 + 4
    rng = np.random.default_rng(0)
    X = E.sample(20_000, rng)
    X = X[np.all([m.contains(X, tol=0.0) for m in members], axis=0)]
    assert X.shape[0] >= 1_000
    lifted = np.hstack([X, np.ones((X.shape[0], 1))])
    for q in quadratics[3:]:
        values = np.einsum("mi,ij,mj->m", lifted, q.F, lifted)
        assert np.all(values <= 1e-12)
        assert np.max(values) > -1e-2  # active somewhere on the set: not a redundant form


def test_empty_intersection_message_uses_the_users_numbers():
    E = Ellipsoid([1.0, 2.0], [[4.0, 0.0], [0.0, 1.0]])
    S = Strip.from_bounds([1.0, 0.0], 3.5, 7.25)  # x in [3.5, 7.25]; E has x in [-1, 3]
    with pytest.raises(EmptyIntersectionError) as exc:
        lift([E, S])
    text = str(exc.value)
    assert "allows u^T x in [3.5, 7.25] along its unit normal u = [1.0, 0.0]" in text
    assert "u^T x lies in [-1, 3]" in text
    assert repr(E) in text and repr(S) in text
