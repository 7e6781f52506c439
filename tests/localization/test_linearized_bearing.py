"""HS96-style linearized fusion of relative bearings: what it computes, and that it can fail."""

import numpy as np
import pytest

from optbound.localization import relative_bearing as rb
from optbound.localization.linearized_bearing import (
    box_ellipse,
    linearized_localize,
    linearized_strip,
)
from optbound.scenarios import bh_geometry as bh
from optbound.sets import Box

LANDMARKS, PAIRS = bh.LANDMARKS, bh.PAIRS  # [BH, Sect. V]
EPS = np.radians(bh.EPS_DEG)
GAMMAS = rb.bearings(np.zeros(2), LANDMARKS, PAIRS)


def test_box_ellipse_passes_through_the_corners():
    E = box_ellipse(Box([-1.0, 2.0], [3.0, 3.0]))
    corners = np.array([[-1.0, 2.0], [-1.0, 3.0], [3.0, 2.0], [3.0, 3.0]])
    d = corners - E.center
    assert np.allclose(np.einsum("ki,ij,kj->k", d, np.linalg.inv(E.shape), d), 1.0)


def test_strip_is_the_tangent_of_the_bearing():
    """At the linearization point the strip's centre value is the measured residual."""
    li, lj = LANDMARKS[2], LANDMARKS[0]
    about = np.array([0.1, -0.05])
    S = linearized_strip(li, lj, GAMMAS[0], EPS, about)
    gamma_at = rb.bearings(about, LANDMARKS, PAIRS)[0]
    # a^T x - b = (g^T x - g^T c - (gamma_hat - gamma(c))) / eps
    assert S.a @ about - S.b == pytest.approx((gamma_at - GAMMAS[0]) / EPS, rel=1e-12)
    h = 1e-6
    for k in range(2):  # the normal is the bearing's gradient / eps
        step = np.eye(2)[k] * h
        num = (
            rb.bearings(about + step, LANDMARKS, PAIRS)[0]
            - rb.bearings(about - step, LANDMARKS, PAIRS)[0]
        )
        assert S.a[k] * EPS == pytest.approx(num / (2 * h), rel=1e-6)


def test_bh_geometry_contains_the_truth_but_not_the_whole_exact_set():
    res = linearized_localize(LANDMARKS, PAIRS, GAMMAS, EPS)
    assert res.rejected == 0 and res.ellipse.contains(np.zeros(2))
    paving = rb.exact_paving(LANDMARKS, PAIRS, GAMMAS, EPS, [[-0.3, 0.3], [-0.3, 0.3]], 0.01)
    centres = paving.inner.mean(axis=2)
    assert rb.in_exact_set(rb.measurements(LANDMARKS, PAIRS, GAMMAS, EPS), centres).all()
    assert not np.all(res.ellipse.contains(centres))  # not guaranteed: points of the set missed


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"relinearize": -1}, "relinearize"),
        ({"relinearize": 0.5}, "relinearize"),
        ({"criterion": "projection"}, "criterion"),
        ({"prior": [[0, 1], [0, 1]]}, "prior"),
    ],
)
def test_bad_arguments(kwargs, match):
    with pytest.raises(ValueError, match=match):
        linearized_localize(LANDMARKS, PAIRS, GAMMAS, EPS, **kwargs)


def test_linearizing_at_a_landmark_is_refused():
    with pytest.raises(ValueError, match="landmark"):
        linearized_strip(LANDMARKS[0], LANDMARKS[1], GAMMAS[1], EPS, LANDMARKS[0])
