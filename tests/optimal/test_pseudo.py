"""The optimal pseudo-ellipsoid reference: lower bracket by MVEE, upper certified by proofs."""

import numpy as np
import pytest

from optbound import optimal
from optbound.interval import sivia
from optbound.localization import relative_bearing as rb
from optbound.sets import PolynomialLifting


def test_identity_lifting_brackets_the_disc():
    # The smallest ellipse containing the unit disc is the disc: lower <= pi <= upper.
    paving = sivia(lambda x, y: x**2 + y**2, [[0.0, 1.0]], [[-1.5, 1.5], [-1.5, 1.5]], 0.02)
    lift = PolynomialLifting.from_components([{(1, 0): 1.0}, {(0, 1): 1.0}])
    ref = optimal.optimal_pseudo_ellipsoid(lift, paving.inner, paving.boundary)
    assert ref.lower <= np.pi <= ref.upper
    assert ref.upper / ref.lower < 1.1
    assert ref.bound.prove_covers(paving.outer()).proven


def test_sect5_l4_reference_is_below_the_filter_and_certified():
    L = np.array([[0.0, 1.0], [1.0, 1.0], [-1.0, 0.0]])
    pairs, g, eps = [(2, 0), (0, 1), (1, 2)], [np.pi / 2, np.pi / 4, -3 * np.pi / 4], np.radians(4)
    data = rb.measurements(L, pairs, g, eps)
    box = rb.prior_box(data)
    paving = rb.exact_paving(L, pairs, g, eps, np.stack([box.lo, box.hi], 1), 0.005)
    analytic = rb.localize(L, pairs, g, eps, order=1).bound
    ref = optimal.optimal_pseudo_ellipsoid(
        analytic.lift, paving.inner, paving.boundary, rb.exact_test(data)
    )
    assert ref.lower <= ref.sample_volume * (1 + 1e-6) <= ref.upper
    assert ref.upper < analytic.lifted.volume()
    assert ref.bound.prove_covers(paving.outer(), rb.exact_test(data)).proven


def test_bad_input():
    with pytest.raises(TypeError, match="lift"):
        optimal.optimal_pseudo_ellipsoid("bh4", np.zeros((3, 2, 2)), np.zeros((0, 2, 2)))
    with pytest.raises(ValueError, match="inner"):
        optimal.optimal_pseudo_ellipsoid(
            PolynomialLifting.bh4(), np.zeros((3, 3, 2)), np.zeros((0, 2, 2))
        )
