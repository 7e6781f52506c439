"""The one-pass outward step moves at least k floats, never produces NaN, keeps infinities."""

import ctypes
import ctypes.util
import platform

import numpy as np
import pytest

from optbound import interval as iv
from optbound.interval._rounding import (
    BASIC_ULPS,
    TRANSCENDENTAL_ULPS,
    down,
    down_nonneg,
    up,
    up_nonneg,
)
from tests.interval._samples import MAX, TINY, awkward_floats

SPECIAL = np.array(
    [
        0.0,
        -0.0,
        TINY,
        -TINY,
        2.0**-1022,
        -(2.0**-1022),
        1.0,
        -1.0,
        2.0,
        -2.0,
        1.0 - 2.0**-53,
        MAX,
        -MAX,
        np.inf,
        -np.inf,
    ]
)


def _steps(x, k, direction):
    for _ in range(k):
        x = np.nextafter(x, direction)
    return x


@pytest.mark.parametrize("k", [BASIC_ULPS, TRANSCENDENTAL_ULPS])
def test_steps_at_least_k_ulps_outward(k):
    x = np.concatenate([awkward_floats(np.random.default_rng(3), 200_000), SPECIAL])
    with np.errstate(over="ignore"):
        d, u = down(x, k), up(x, k)
        assert not np.any(np.isnan(d)) and not np.any(np.isnan(u))
        finite_lo = x != np.inf  # +inf as a lower bound (overflow) is capped below MAX
        assert np.all(d[finite_lo] <= _steps(x, k, -np.inf)[finite_lo])
        assert np.all(u[x != -np.inf] >= _steps(x, k, np.inf)[x != -np.inf])
    assert down(np.array(np.inf), k) < MAX and up(np.array(-np.inf), k) > -MAX
    assert down(np.array(-np.inf), k) == -np.inf and up(np.array(np.inf), k) == np.inf


@pytest.mark.parametrize("k", [BASIC_ULPS, TRANSCENDENTAL_ULPS])
def test_nonneg_variants_agree_with_general_steps(k):
    x = np.abs(np.concatenate([awkward_floats(np.random.default_rng(6), 100_000), SPECIAL]))
    with np.errstate(over="ignore"):
        assert np.all(down_nonneg(x, k) <= np.maximum(down(x, k), 0.0))
        assert np.all(down_nonneg(x, k) >= 0.0)
        assert np.all(up_nonneg(x, k) >= up(x, k))


def test_step_is_small():
    # At most 2k ulps: outward rounding must not waste precision.
    x = np.random.default_rng(4).uniform(-1e6, 1e6, 10_000)
    assert np.all(x - down(x) <= 2 * np.spacing(np.abs(x)))
    assert np.all(up(x, 4) - x <= 8 * np.spacing(np.abs(x)))


def test_sivia_computes_in_round_to_nearest_and_restores_the_callers_mode():
    # codac/gaol switch the process to round-upward; the outward steps assume round-to-nearest.
    if platform.machine() != "x86_64":
        pytest.skip("fenv constants below are x86-64 glibc")
    libm = ctypes.CDLL(ctypes.util.find_library("m"))
    before = libm.fegetround()

    def run():
        return iv.sivia(
            lambda x, y: x * x + y / 3.0, [[0.0, 1.0]], [[-2.0, 2.0], [-1.0, 1.0]], 0.05
        )

    expected = run()
    try:
        libm.fesetround(0x800)  # FE_UPWARD
        got = run()
        assert libm.fegetround() == 0x800  # the caller's mode is back
    finally:
        libm.fesetround(before)
    assert np.array_equal(got.inner, expected.inner)
    assert np.array_equal(got.boundary, expected.boundary)
