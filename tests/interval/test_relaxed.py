"""Relaxed intersection [KJWM00]: one outlier among range measurements."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from optbound import interval as iv
from optbound.interval.relaxed import FusedTests, relaxed_paving

LANDMARKS = np.array([[0.0, 0.0], [10.0, 0.0], [0.0, 10.0], [10.0, 10.0], [5.0, -4.0]])
TRUTH = np.array([3.0, 4.0])
REL_ERR = 0.02  # [d (1 - a), d (1 + a)] intervals as in KJWM00 Sect. 2.1
X0 = [[-5.0, 15.0], [-5.0, 15.0]]


def _range_tests(ranges):
    tests = []
    for (lx, ly), d in zip(LANDMARKS, ranges, strict=True):
        lo, hi = (d * (1 - REL_ERR)) ** 2, (d * (1 + REL_ERR)) ** 2
        tests.append(
            iv.constraint(lambda x, y, lx=lx, ly=ly: (x - lx) ** 2 + (y - ly) ** 2, [[lo, hi]])
        )
    return tests


def _measurements():
    ranges = np.linalg.norm(LANDMARKS - TRUTH, axis=1)
    ranges[2] *= 1.5  # sensor 2 is an outlier (e.g. a reflection)
    return ranges


def _covers(paving, point):
    boxes = paving.outer()
    return bool(np.any(np.all((boxes[:, :, 0] <= point) & (point <= boxes[:, :, 1]), axis=1)))


def test_one_outlier_breaks_the_intersection_but_not_the_relaxed_one():
    tests = _range_tests(_measurements())
    plain = iv.pave(iv.relaxed_test(tests, 0), X0, 0.05)
    assert plain.is_empty or not _covers(plain, TRUTH)
    relaxed = iv.pave(iv.relaxed_test(tests, 1), X0, 0.05)
    assert _covers(relaxed, TRUTH)
    # The q = 1 set is small: the four consistent ranges pin the position down.
    h = relaxed.components()[0].hull()
    assert h.contains(TRUTH) and np.all(h.widths < 1.0)


def test_min_outliers_raises_q_until_non_empty():
    q, paving = iv.min_outliers(_range_tests(_measurements()), X0, 0.05)
    assert q == 1 and _covers(paving, TRUTH)
    q0, _ = iv.min_outliers(_range_tests(np.linalg.norm(LANDMARKS - TRUTH, axis=1)), X0, 0.05)
    assert q0 == 0


def test_relaxed_tri_logic():
    T, U, F = iv.Tri.TRUE, iv.Tri.UNKNOWN, iv.Tri.FALSE
    values = np.array([[T, T, F, F], [T, U, F, U], [F, F, U, T]], dtype=np.int8)
    tests = [lambda row=row: row for row in values]
    assert iv.relaxed_test(tests, 0)().tolist() == [F, F, F, F]
    assert iv.relaxed_test(tests, 1)().tolist() == [T, U, F, U]
    assert iv.relaxed_test(tests, 2)().tolist() == [T, T, U, T]
    assert iv.relaxed_test(tests, 3)().tolist() == [T, T, T, T]


def test_bad_relaxed_input():
    tests = _range_tests(_measurements())
    with pytest.raises(ValueError, match="q must be"):
        iv.relaxed_test(tests, 6)
    with pytest.raises(ValueError, match="q must be"):
        iv.relaxed_test(tests, 1.5)
    with pytest.raises(ValueError, match="non-empty sequence"):
        iv.relaxed_test([], 0)
    with pytest.raises(ValueError, match="q_max"):
        iv.min_outliers(tests, X0, 0.1, q_max=-1)
    far = [iv.constraint(lambda x, y: x, [[100.0, 101.0]])] * 2
    with pytest.raises(ValueError, match="empty for every q"):
        iv.min_outliers(far, X0, 0.5, q_max=1)


@settings(max_examples=200, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), m=st.integers(1, 7), data=st.data())
def test_lazy_relaxed_test_equals_counting_every_test(seed, m, data):
    """Tests evaluated one by one on the undecided boxes give the all-tests verdict."""
    q = data.draw(st.integers(0, m))
    rng = np.random.default_rng(seed)
    table = rng.integers(0, 3, (m, 60)).astype(np.int8)
    seen = []

    def make(i):
        def test(x):
            seen.append(x.size)
            return table[i, x.astype(int)]

        return test

    got = iv.relaxed_test([make(i) for i in range(m)], q)(np.arange(60.0))
    n_true, n_false = (table == iv.Tri.TRUE).sum(0), (table == iv.Tri.FALSE).sum(0)
    want = np.where(
        n_true >= m - q, iv.Tri.TRUE, np.where(n_false > q, iv.Tri.FALSE, iv.Tri.UNKNOWN)
    )
    assert got.tolist() == want.tolist()
    assert sum(seen) <= 60 * m


def test_prior_is_required_whatever_q():
    tests = _range_tests(_measurements())
    prior = iv.constraint(lambda x, y: x, [[4.0, np.inf]])  # excludes the truth (x = 3)
    paving = relaxed_paving(tests, 5, X0, 0.2, prior=prior)
    assert not _covers(paving, TRUTH) and _covers(relaxed_paving(tests, 5, X0, 0.2), TRUTH)


def test_fused_tests_answer_for_one_box_per_entry_only():
    """A FusedTests list hands SIVIA's boxes to its fused test; other shapes get the plain one."""
    tests = _range_tests(_measurements())
    calls = []

    def fused(q):
        def test(*coords):
            calls.append(q)
            return iv.relaxed_test(tests, q)(*coords)

        return test

    bank = FusedTests(tests, fused)
    paving = relaxed_paving(bank, 1, X0, 0.5)
    assert calls and set(calls) == {1}
    reference = relaxed_paving(tests, 1, X0, 0.5)
    assert np.array_equal(paving.boundary, reference.boundary)
    calls.clear()
    grid = [iv.Interval(np.zeros((2, 2)), np.ones((2, 2)))] * 2  # not one box per entry
    assert iv.relaxed_test(bank, 1)(*grid).shape == (2, 2) and not calls


def test_deferral_changes_the_boxes_not_the_set():
    """Testing every level (defer_below=1) or deferring: the same outer set at sampled points."""
    tests = _range_tests(_measurements())
    rng = np.random.default_rng(0)
    points = rng.uniform(-5, 15, (4000, 2))
    covered = []
    for defer in (1, 64, 1024):
        paving = relaxed_paving(tests, 1, X0, 0.1, defer_below=defer)
        boxes = paving.outer()
        inside = (boxes[None, :, :, 0] <= points[:, None]) & (
            points[:, None] <= boxes[None, :, :, 1]
        )
        covered.append(np.any(np.all(inside, axis=-1), axis=1))
    assert covered[0].any() and all(np.array_equal(covered[0], c) for c in covered[1:])
    with pytest.raises(TypeError, match="defer_below"):
        relaxed_paving(tests, 1, X0, 0.1, defer_below=2.5)
