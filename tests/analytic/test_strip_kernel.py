"""The lane-parallel strip kernel: its lanes are independent of each other and of the block.

Every instance is computed in one lane of a block of ``W`` (``optbound.analytic._kernels.lanes``).
These tests check what that layout must not change: a lane's result (error code included)
is the single call's, bitwise, wherever the instance sits in the batch, whatever its
neighbours are (valid or not), for every criterion, strips and half-spaces.
"""

import numpy as np
import pytest

from optbound.analytic._kernels import strip_kernel as K
from optbound.analytic._kernels.lanes import W
from optbound.analytic._kernels.threads import ellipsoid_outputs
from optbound.bench.speed_analytic import batch_instances

MODES = (K.VOLUME, K.GIVEN, K.ROBUST, K.TRACE, K.PROJECTION, K.ROBUST_PROJECTION)


def _mixed_batch(seed: int, count: int, n: int):
    """Random instances (conditions up to 1e8, far centres) with invalid ones mixed in."""
    rng = np.random.default_rng(seed)
    parts = [batch_instances(rng, count, n, cond) for cond in (None, 1e3, 1e8)]
    c, C, a, b = (np.concatenate(x) for x in zip(*parts, strict=True))
    pick = rng.permutation(3 * count)[:count]
    c, C, a, b = c[pick].copy(), C[pick].copy(), a[pick].copy(), b[pick].copy()
    far = slice(0, None, 5)
    shift = 1.0e7 * rng.standard_normal(n)
    c[far] += shift
    b[far] += a[far] @ shift
    C[3::17, 0, 0] = np.nan  # not finite
    C[5::19] *= -1.0  # not positive definite
    a[7::23] = 0.0  # zero normal
    b[11::29] = np.inf
    b[13::31] += 1e3  # far from E: inconsistent
    lam = rng.uniform(0.0, 5.0, count)
    lam[::9] = 1e16
    lam[2::37] = -1.0  # invalid for the GIVEN mode
    return c, C, a, b, lam


def _batch(c, C, a, b, lam, halfspace, clip, mode, idx):
    n_batch, n = c.shape
    out = ellipsoid_outputs(n_batch, n, np.int8, np.int8, float, float, np.bool_, float)
    ws = K.workspace(n)
    first = K.fuse_range(c, C, a, b, halfspace, clip, mode, lam, idx, 10.0, 0.5, out, ws, 0,
                         n_batch)  # fmt: skip
    bad = np.flatnonzero(out[2])
    assert first == (bad[0] if bad.size else -1)
    return out


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("halfspace", [False, True])
def test_every_lane_is_the_single_call_bitwise(mode, halfspace):
    n, count = 3, 2 * W + 5  # two full blocks and a partial one
    c, C, a, b, lam = _mixed_batch(seed=mode + 10 * halfspace, count=count, n=n)
    idx = np.array([0, 1], np.int64)
    out = _batch(c, C, a, b, lam, halfspace, True, mode, idx)
    ws = K.workspace(n)
    codes = set()
    for k in range(count):
        oc, oC, _, _, r = K.fuse_single(
            c[k], C[k], a[k], b[k], halfspace, True, mode, lam[k], idx, 10.0, 0.5, ws
        )
        assert r[0] == out[2][k], k
        codes.add(int(r[0]))
        if r[0] != 0:
            continue  # an error: the batch raises, nothing else is defined
        assert r[1:] == tuple(out[q][k] for q in range(3, 8)), k
        assert np.array_equal(oc, out[0][k]) and np.array_equal(oC, out[1][k]), k
    assert {0, K.BAD_A, K.BAD_B} <= codes  # the neighbours really were mixed


@pytest.mark.parametrize("n", [2, 4])
def test_a_lane_does_not_depend_on_its_position(n):
    count = W + 9
    c, C, a, b, lam = _mixed_batch(seed=n, count=count, n=n)
    idx = np.array([0, 1], np.int64)
    out = _batch(c, C, a, b, lam, False, True, K.VOLUME, idx)
    pick = np.random.default_rng(n).permutation(count)
    again = _batch(c[pick], C[pick], a[pick], b[pick], lam[pick], False, True, K.VOLUME, idx)
    valid = out[2] == 0
    for q in range(8):
        assert np.array_equal(again[q][valid[pick]], out[q][pick][valid[pick]]), q
