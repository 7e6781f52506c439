"""Batches split over threads give the same bits as one thread, also in a forked child."""

import multiprocessing

import numpy as np

from benchmarks.speed_analytic import batch_instances
from optbound import analytic
from optbound.analytic._threads import MIN_SLICE


def _instances(count: int):
    return batch_instances(np.random.default_rng(0), count, 3)


def test_sliced_batch_equals_small_batches():
    c, C, a, b = _instances(2 * MIN_SLICE + 3)
    whole = analytic.intersect_strip_batch(c, C, a, b)
    step = MIN_SLICE // 2  # each piece runs on one thread
    for start in range(0, len(b), step):
        part = analytic.intersect_strip_batch(
            c[start : start + step], C[start : start + step], a[start : start + step],
            b[start : start + step],
        )  # fmt: skip
        assert np.array_equal(part.shapes, whole.shapes[start : start + step])
        assert np.array_equal(part.centers, whole.centers[start : start + step])


def test_sliced_minkowski_batch_equals_small_batches():
    c, C, _, _ = _instances(2 * MIN_SLICE + 3)
    c2, C2 = c[::-1].copy(), C[::-1].copy()
    whole = analytic.minkowski_sum_batch(c, C, c2, C2)
    step = MIN_SLICE // 2  # each piece runs on one thread
    for start in range(0, len(c), step):
        part = analytic.minkowski_sum_batch(*(x[start : start + step] for x in (c, C, c2, C2)))
        assert np.array_equal(part.shapes, whole.shapes[start : start + step])
        assert np.array_equal(part.centers, whole.centers[start : start + step])
        assert np.array_equal(part.kappa, whole.kappa[start : start + step])


def _child_sum(queue):
    c, C, a, b = _instances(2 * MIN_SLICE)
    queue.put(float(analytic.intersect_strip_batch(c, C, a, b).shapes.sum()))


def test_a_forked_child_runs_sliced_batches():
    c, C, a, b = _instances(2 * MIN_SLICE)
    expected = float(analytic.intersect_strip_batch(c, C, a, b).shapes.sum())  # pool exists
    ctx = multiprocessing.get_context("fork")
    queue = ctx.Queue()
    child = ctx.Process(target=_child_sum, args=(queue,))
    child.start()
    got = queue.get(timeout=120)
    child.join(timeout=60)
    assert got == expected
