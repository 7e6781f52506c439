"""The rounding-mode guard: round-to-nearest inside, the caller's mode restored afterwards."""

import numpy as np
import pytest

from optbound.interval.fenv import FE_TONEAREST, get_rounding, round_to_nearest, set_rounding

pytestmark = pytest.mark.skipif(get_rounding() is None, reason="no C fenv on this platform")


def _upward_mode() -> int:
    """The mode in which 1 + 2^-60 rounds up (FE_UPWARD of this platform)."""
    for mode in (0x800, 0x400000, 0x0800):  # x86 glibc, aarch64 glibc
        try:
            set_rounding(mode)
        except ValueError:
            continue
        try:
            if (np.ones(1) + np.full(1, 2.0**-60))[0] > 1.0:
                return mode
        finally:
            set_rounding(FE_TONEAREST)
    pytest.skip("no round-upward mode found")


def test_guard_switches_to_nearest_and_restores_the_callers_mode():
    up = _upward_mode()
    set_rounding(up)
    try:
        with round_to_nearest():
            assert get_rounding() == FE_TONEAREST
            assert (np.ones(1) + np.full(1, 2.0**-60))[0] == 1.0
        assert get_rounding() == up
    finally:
        set_rounding(FE_TONEAREST)


def test_guard_restores_a_mode_changed_inside_the_block():
    up = _upward_mode()
    with round_to_nearest():
        set_rounding(up)  # as `import codac` does
    assert get_rounding() == FE_TONEAREST


def test_bad_mode_is_refused():
    with pytest.raises(ValueError, match="not a rounding mode"):
        set_rounding(12345)
    assert get_rounding() == FE_TONEAREST
