"""The set protocol of ``optbound.sets.base``: the built-in types have the capabilities that
``docs/extending.md`` lists, and their quadratic descriptions describe exactly the set."""

from __future__ import annotations

import numpy as np
import pytest

from optbound import Box, Ellipsoid, Halfspace, PseudoEllipsoid, QuadraticSet, Strip
from optbound.sets import PolynomialLifting
from optbound.sets.base import (
    BoxProver,
    ConvexSet,
    EmptySetError,
    Outlined,
    QuadraticallyDescribed,
    VolumeBracket,
)

E = Ellipsoid([0.5, -0.2], [[2.0, 0.4], [0.4, 0.5]])
BUILT_IN = {
    "ellipsoid": E,
    "strip": Strip([1.0, -0.5], 0.3),
    "halfspace": Halfspace([0.2, 1.0], 0.4),
    "box": Box([-1.0, -np.inf], [0.5, 0.7]),
    "ring_outside": QuadraticSet.from_parts(-np.eye(2), np.zeros(2), 0.25),
}


def test_capabilities_of_the_built_in_types():
    for S in BUILT_IN.values():
        assert isinstance(S, QuadraticallyDescribed)
    for S in (E, BUILT_IN["strip"], BUILT_IN["box"]):
        assert isinstance(S, ConvexSet)
    assert isinstance(E, Outlined) and not isinstance(E, BoxProver)
    P = PseudoEllipsoid(PolynomialLifting.bh4(), np.zeros(4), np.eye(4))
    assert isinstance(P, BoxProver) and isinstance(P, VolumeBracket) and isinstance(P, Outlined)
    assert not isinstance(P, QuadraticallyDescribed)


@pytest.mark.parametrize("name", sorted(BUILT_IN))
def test_description_is_exactly_the_set(name):
    S = BUILT_IN[name]
    d = S.quadratic_description()
    X = np.random.default_rng(0).uniform(-3.0, 3.0, (4000, 2))
    lifted = np.column_stack([X, np.ones(len(X))])
    inside = np.ones(len(X), dtype=bool)
    for q in d.forms:
        inside &= np.einsum("mi,ij,mj->m", lifted, q.F, lifted) <= 0.0
    for a, lo, hi in d.ranges:
        inside &= (lo <= X @ a) & (X @ a <= hi)
    np.testing.assert_array_equal(inside, S.contains(X, tol=0.0))
    assert 0.0 < inside.mean() < 1.0  # the sample sees both sides


def test_enclosing_ellipsoids():
    assert E.enclosing_ellipsoid() is E
    assert BUILT_IN["strip"].enclosing_ellipsoid() is None
    assert BUILT_IN["box"].enclosing_ellipsoid() is None
    q = QuadraticSet.from_ellipsoid(E)
    assert q.enclosing_ellipsoid() is E
    assert BUILT_IN["ring_outside"].enclosing_ellipsoid() is None  # unbounded
    empty = QuadraticSet.from_parts(np.eye(2), np.zeros(2), 1.0)  # |x|^2 + 1 <= 0
    with pytest.raises(EmptySetError, match="empty"):
        empty.enclosing_ellipsoid()
