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
    quadratics = lift([E, Halfspace([0.0, 1.0], 0.5), Box([-np.inf, -3.0], [np.inf, 0.2])])
    assert len(quadratics) == 3
    assert quadratics[1].extent([0.0, 1.0]) == (pytest.approx(-1.0), pytest.approx(0.5))
    assert quadratics[2].extent([0.0, 1.0]) == (pytest.approx(-1.0), pytest.approx(0.2))


def test_unclipped_halfspace_stays_affine():
    q = lift([Halfspace([0.0, 1.0], 0.5)], clip=False)[0]
    assert not np.any(q.A) and q.extent([0.0, 1.0])[1] == pytest.approx(0.5)


def test_strip_beyond_the_ellipsoid_is_empty():
    with pytest.raises(EmptyIntersectionError):
        lift([Ellipsoid([0.0, 0.0], np.eye(2)), Halfspace([1.0, 0.0], -1.5)])
