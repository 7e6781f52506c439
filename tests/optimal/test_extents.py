"""Certified extents over ellipsoid ∩ polyhedron (clipping strips to the intersection)."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound import Ellipsoid, Strip
from optbound.optimal import EmptyIntersectionError, outer_ellipsoid
from optbound.optimal.extents import clip_to_intersection, extents_template
from optbound.optimal.lift import lift
from optbound.optimal.lower import sample_set
from tests.optimal.clip_effect import strip_instance


def _rows(sets: list) -> tuple[Ellipsoid, np.ndarray, np.ndarray, np.ndarray]:
    """The prior and its strips' rows, clipped to the prior's extents."""
    E, strips = sets[0], sets[1:]
    A = np.array([S.a for S in strips])
    extents = np.array([E.extent(a) for a in A])
    lo = np.maximum([S.b - 1.0 for S in strips], extents[:, 0])
    hi = np.minimum([S.b + 1.0 for S in strips], extents[:, 1])
    return E, A, lo, hi


@given(st.integers(0, 10_000), st.integers(2, 5), st.integers(1, 25))
def test_property_ranges_shrink_and_keep_every_point(seed, n, k):
    sets = strip_instance(n, k, seed)
    E, A, lo, hi = _rows(sets)
    new_lo, new_hi = clip_to_intersection(E, A, lo, hi)
    assert np.all(new_lo >= lo) and np.all(new_hi <= hi) and np.all(new_lo <= new_hi)
    # Points of the set climbed toward its vertices, where the extents are attained; the
    # sampler needs an outer ellipsoid close to the set (the reference without this clipping).
    outer = outer_ellipsoid(sets, clip="ellipsoids").ellipsoid
    X = sample_set(lift(sets, clip="ellipsoids"), outer, seed)
    values = X @ A.T
    assert np.all(values >= new_lo) and np.all(values <= new_hi)


def test_strips_cutting_a_square_are_clipped_to_it():
    # Disc of radius 2, the square |x1|, |x2| <= 1 and the diagonal strip |x1 + x2| <= 3:
    # over the square x1 + x2 ranges over [-2, 2].
    E = Ellipsoid([0.0, 0.0], 4.0 * np.eye(2))
    A = np.array([[1.0, 0.0], [0.0, 1.0], [1.0, 1.0]])
    lo, hi = clip_to_intersection(E, A, np.array([-1.0, -1.0, -3.0]), np.array([1.0, 1.0, 3.0]))
    np.testing.assert_allclose(lo, [-1.0, -1.0, -2.0], rtol=1e-7)
    np.testing.assert_allclose(hi, [1.0, 1.0, 2.0], rtol=1e-7)
    assert hi[2] >= 2.0 and lo[2] <= -2.0


def test_infeasible_polyhedron_is_certified_empty():
    E = Ellipsoid([0.0, 0.0], np.eye(2))
    A = np.array([[1.0, 0.0], [1.0, 0.0]])
    with pytest.raises(EmptyIntersectionError, match="weak duality"):
        clip_to_intersection(E, A, np.array([-1.0, 0.6]), np.array([0.5, 1.0]))


def test_template_is_cached_and_dpp():
    E, A, lo, hi = _rows([Ellipsoid([0.0, 0.0], np.eye(2)), *[Strip([1.0, 0.5], 0.2)] * 3])
    clip_to_intersection(E, A, lo, hi)
    before = extents_template.cache_info().hits
    clip_to_intersection(E, A, lo - 0.1, hi)
    assert extents_template.cache_info().hits == before + 1
    assert extents_template(2, 3).problem.is_dpp()
