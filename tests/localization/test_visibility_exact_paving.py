"""The exact consistent set of one LUVIA step, paved: sound against exact rational checks."""

import numpy as np
import pytest

from optbound.localization import visibility as v
from optbound.localization.environment import Environment
from tests.localization import exact_visibility as ex

POLYS = [
    np.array([[2.0, 2.0], [3.0, 2.0], [3.0, 4.5], [2.0, 4.5]]),
    np.array([[6.5, 5.0], [8.5, 5.5], [7.0, 7.0]]),
    np.array([[4.3, 4.3], [5.3, 4.8], [5.0, 5.6], [4.0, 5.1]]),
]
ENV = Environment.from_polygons(POLYS, 0.05)


def _instance(rng, m=5, half=0.6):
    """True positions off the obstacles, boxes around them, exact measurements on E."""
    while True:
        truth = rng.uniform(0.5, 9.5, (m, 2))
        if not any(ex.inside(p, ex.rational(q)) for p in ex.rational(truth) for q in ENV.outer):
            break
    lo = truth - rng.uniform(0.05, 2 * half - 0.05, (m, 2))
    boxes = np.stack([lo, lo + 2 * half], -1)
    y = np.array([[ex.visible(a, b, ENV.exact) for b in truth] for a in truth])
    return truth, boxes, y


def _consistent_with(x, xl, visible) -> bool:
    """Exact: is the pair (x, xl) consistent with the measurement (E⁻ if visible, else E⁺)?"""
    if visible:
        return ex.visible(x, xl, ENV.inner)
    return not ex.visible(x, xl, ENV.outer)


def test_truth_kept_inner_inside_luvia_and_outside_refuted_exactly():
    rng = np.random.default_rng(3)
    refuted_checked = 0
    for _ in range(6):
        truth, boxes, y = _instance(rng)
        for i in range(len(truth)):
            p = v.exact_paving(i, y[i], boxes, ENV, 0.1, split=4)
            outer = p.outer()
            assert np.any(np.all((outer[:, :, 0] <= truth[i]) & (truth[i] <= outer[:, :, 1]), 1))
            hull = v.luvia(i, y[i], boxes, ENV, 0.01)  # contains S_i, hence every inner box
            assert np.all(hull[:, 0] <= p.inner[:, :, 0]) and np.all(p.inner[:, :, 1] <= hull[:, 1])
            # A point of an outside box: some other robot has no witness among its box's
            # corners and samples (exact rational visibility on E⁻ / E⁺).
            for box in p.outside[rng.permutation(len(p.outside))[:3]]:
                x = box[:, 0] + rng.uniform(size=2) * (box[:, 1] - box[:, 0])
                found = False
                for j in range(len(truth)):
                    if j == i:
                        continue
                    b = boxes[j]
                    cand = [b[:, 0] + t * (b[:, 1] - b[:, 0]) for t in rng.uniform(size=(12, 2))]
                    cand += [np.array([b[0, a], b[1, c]]) for a in (0, 1) for c in (0, 1)]
                    if not any(_consistent_with(x, c, y[i, j]) for c in cand):
                        found = True
                        break
                assert found
                refuted_checked += 1
    assert refuted_checked >= 5


def test_finer_splits_refute_no_less():
    """Each outer box of a finer split lies in an outer box of split 1 (Algorithm 2's test)."""
    rng = np.random.default_rng(4)
    truth, boxes, y = _instance(rng, half=0.9)
    shrank = 0
    for i in range(len(truth)):
        one = v.exact_paving(i, y[i], boxes, ENV, 0.1, split=1).outer()
        fine = v.exact_paving(i, y[i], boxes, ENV, 0.1, split=6).outer()
        for box in fine:
            assert np.any(np.all((one[:, :, 0] <= box[:, 0]) & (box[:, 1] <= one[:, :, 1]), 1))
        shrank += len(fine) < len(one)
    assert shrank >= 1


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"robot": 5}, ValueError, "robot"),
        ({"y": np.ones(2, dtype=bool)}, ValueError, "one entry per robot"),
        ({"env": None}, TypeError, "Environment"),
        ({"split": 0}, ValueError, "split"),
    ],
)
def test_bad_input(kwargs, error, match):
    _, boxes, y = _instance(np.random.default_rng(0), m=3)
    args = {"robot": 0, "y": y[0], "boxes": boxes, "env": ENV, "eps": 0.1, **kwargs}
    with pytest.raises(error, match=match):
        v.exact_paving(
            args.pop("robot"),
            args.pop("y"),
            args.pop("boxes"),
            args.pop("env"),
            args.pop("eps"),
            **args,
        )
