"""Batches split over threads give the same bits as one thread, also in a forked child; the
workers return their slices' results in order and raise their errors in the caller."""

import itertools
import multiprocessing
import os
import threading

import numpy as np
import pytest

from optbound import analytic
from optbound.analytic._kernels.threads import MIN_SLICE, run_sliced, slice_bounds
from optbound.bench.speed_analytic import batch_instances


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


@pytest.mark.parametrize("n_batch", [2 * MIN_SLICE, 1000, 10**6 + 7])
@pytest.mark.parametrize("slices", [2, 3, 8])
def test_slice_bounds_cover_the_batch_in_equal_slices(n_batch, slices):
    bounds = slice_bounds(n_batch, slices)
    assert bounds[0] == 0 and bounds[-1] == n_batch and len(bounds) == slices + 1
    sizes = np.diff(bounds)
    assert np.all(sizes > 0)
    assert np.ptp(sizes) <= 1


def test_run_sliced_returns_the_slices_in_order():
    n_batch = 4 * MIN_SLICE + 1
    slices = run_sliced(lambda start, stop: (start, stop, threading.get_ident()), n_batch)
    assert slices[0][0] == 0 and slices[-1][1] == n_batch
    assert all(a[1] == b[0] for a, b in itertools.pairwise(slices))
    assert slices[0][2] == threading.get_ident()  # the caller runs the first slice


CORES = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()


@pytest.mark.skipif((CORES or 1) < 2, reason="one core: no worker")
def test_an_error_in_a_worker_is_raised_in_the_caller_and_the_pool_survives():
    def call(start, stop):
        if start > 0:
            raise ArithmeticError(f"slice {start}")
        return stop

    n_batch = 2 * MIN_SLICE
    with pytest.raises(ArithmeticError, match="slice"):
        run_sliced(call, n_batch)
    assert len(run_sliced(lambda start, stop: stop - start, n_batch)) > 1


def test_concurrent_batches_agree_with_sequential_ones():
    """Batches started together share the workers, with the same bits."""
    c, C, a, b = _instances(4 * MIN_SLICE)
    expected = analytic.intersect_strip_batch(c, C, a, b).shapes
    got = [None] * 4

    def run(k):
        got[k] = analytic.intersect_strip_batch(c, C, a, b).shapes

    threads = [threading.Thread(target=run, args=(k,)) for k in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert all(np.array_equal(g, expected) for g in got)
