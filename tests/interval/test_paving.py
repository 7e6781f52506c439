"""Paving: volume bracket, hull, connected components (touching boxes)."""

import numpy as np

from optbound import Box
from optbound import interval as iv
from optbound.interval.paving import Paving


def _two_discs(eps=0.05):
    # Discs of radius 0.5 centred at (-1, 0) and (1, 0): two components.
    def f(x, y):
        return np.minimum((x + 1) ** 2 + y**2, (x - 1) ** 2 + y**2)

    return iv.sivia(f, [[0.0, 0.25]], [[-2.0, 2.0], [-1.0, 1.0]], eps)


def test_components_of_two_discs():
    p = _two_discs()
    comps = p.components()
    assert len(comps) == 2
    hulls = sorted((c.hull().lo[0], c.hull().hi[0]) for c in comps)
    assert hulls[0][1] < 0.0 < hulls[1][0]  # one left of the y axis, one right
    for c in comps:
        h = c.hull()
        assert np.all(h.lo <= [-0.5, -0.5] + np.abs(h.center) * [1, 0])
        inner, outer = c.volume_bounds()
        assert inner <= np.pi / 4 <= outer
    total = sum(c.volume_bounds()[1] for c in comps)
    assert np.isclose(total, p.volume_bounds()[1])


def test_touching_boxes_are_connected():
    boxes = np.array(
        [
            [[0.0, 1.0], [0.0, 1.0]],
            [[1.0, 2.0], [1.0, 2.0]],  # touches the first only at the corner (1, 1)
            [[3.0, 4.0], [0.0, 1.0]],  # separate
        ]
    )
    none = np.empty((0, 2, 2))
    p = Paving(boxes[:1], boxes[1:], none, Box([0.0, 0.0], [4.0, 2.0]), 0.1)
    comps = p.components()
    assert [c.inner.shape[0] + c.boundary.shape[0] for c in comps] == [2, 1]
    assert comps[0].inner.shape[0] == 1 and comps[0].boundary.shape[0] == 1


def test_hull_and_outer():
    p = iv.sivia(lambda x, y: x**2 + y**2, [[0.0, 1.0]], [[-2.0, 2.0]] * 2, 0.05)
    h = p.hull()
    assert np.all(h.lo <= -1.0) and np.all(h.hi >= 1.0) and np.all(h.lo > -1.06)
    assert p.outer().shape[0] == p.inner.shape[0] + p.boundary.shape[0]
    assert "Paving(dim=2" in repr(p)
