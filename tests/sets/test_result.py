"""The result base: every bound result reads ``set``, ``certified`` and ``margin``."""

from dataclasses import dataclass

import numpy as np
import pytest

from optbound import Ellipsoid, Strip, analytic, optimal
from optbound.sets.result import BoundResult


def test_analytic_results_share_the_base():
    E = Ellipsoid([0.0, 0.0], [[2.0, 0.3], [0.3, 1.0]])
    results = [
        analytic.minkowski_sum(E, Ellipsoid([1.0, 0.0], np.eye(2))),
        analytic.intersect_strip(E, Strip([1.0, 0.2], 0.4)),
        analytic.bounding_update(E, np.array([[1.0, 0.2]]), np.array([0.4]), np.eye(1)),
    ]
    for r in results:
        assert isinstance(r, BoundResult)
        assert r.set is r.ellipsoid and r.certified
        assert 0.0 <= r.margin < 1e-10


def test_optimal_result_margin_is_the_inflation():
    r = optimal.mvee(Ellipsoid([0.0, 0.0], np.eye(2)).sample(20, 0))
    assert isinstance(r, BoundResult)
    assert r.set is r.ellipsoid and r.certified is True
    assert r.margin == r.inflation - 1.0 >= 0.0


def test_empty_result_has_no_set():
    E = Ellipsoid([0.0, 0.0], np.eye(2))
    r = analytic.intersect_strip(E, Strip.from_bounds([1.0, 0.0], 2.0, 3.0))
    assert r.set is None and r.ellipsoid is None


def test_a_subclass_must_state_the_shared_names():
    with pytest.raises(TypeError, match="must define set_attribute, certified"):

        @dataclass(frozen=True)
        class Incomplete(BoundResult):
            margin: float = 0.0

    @dataclass(frozen=True)
    class Complete(BoundResult):
        set_attribute = "box"
        certified = False

        box: object
        margin: float = 0.0

    c = Complete("the box")
    assert c.set == "the box" and not c.certified and c.margin == 0.0
