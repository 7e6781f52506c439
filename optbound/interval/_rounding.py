"""Outward rounding: move computed bounds away from the exact result by a few ulps.

numpy evaluates in round-to-nearest. IEEE 754 requires +, -, *, / and sqrt to be correctly
rounded, so the exact result lies within half an ulp of the computed one and **one** ulp
outward encloses it. The transcendental functions (exp, log, sin, cos, atan2, pow) are not
correctly rounded: glibc documents errors of at most 1-2 ulp for them, and numpy's own accuracy
suite accepts at most 2 ulp for its AVX-512/SVML kernels. We step **four** ulps outward for
them, twice the largest documented error; the mpmath tests in ``tests/interval`` check the
enclosure on random, tiny, huge and subnormal inputs.

A step of ``k`` ulps is done in one pass, ``x * (1 -+ k 2^-52) -+ k 2^-1074``, which is several
times faster than ``k`` calls of ``np.nextafter`` (the hot path of SIVIA) and provably at least
as far: with ``c = k 2^-52`` a power of two, the exact ``x (1 - c) <= x - k ulp(x)`` is at or
below the k-th float under ``x``, and rounding to nearest is monotone, so the rounded product
is too; the ``k 2^-1074`` term supplies the k ulps when ``x`` is subnormal or zero. A computed
``+inf`` lower bound (overflow) becomes the k-th float below the largest float.
"""

from __future__ import annotations

import numpy as np

#: ulps stepped outward after a correctly rounded operation (+, -, *, /, sqrt).
BASIC_ULPS = 1
#: ulps stepped outward after a libm/SVML transcendental (exp, log, sin, cos, atan2, pow).
TRANSCENDENTAL_ULPS = 4

# Constants from hex literals, not ``2.0**-52``: pow() is only accurate in round-to-nearest,
# and this module may be imported after another library changed the mode.
_EPS = float.fromhex("0x1p-52")
# 1 + 2^-60, -1 - 2^-60 and 1 + (2^-53 + 2^-60) round to these only in round-to-nearest.
_PROBE = (
    np.array([1.0, -1.0, 1.0]),
    np.array([float.fromhex("0x1p-60"), -float.fromhex("0x1p-60"), float.fromhex("0x1.02p-53")]),
)
_NEAREST = np.array([1.0, -1.0, float.fromhex("0x1.0000000000001p0")])
_TINY = float.fromhex("0x1p-1074")


def _kth_below_max(k: int) -> float:
    x = np.finfo(float).max
    for _ in range(k):
        x = np.nextafter(x, -np.inf)
    return float(x)


# Both step sizes are powers of two, so k * 2^-52 and 1 -+ k 2^-52 are exact.
_CAP = {k: _kth_below_max(k) for k in (BASIC_ULPS, TRANSCENDENTAL_ULPS)}


def check_round_to_nearest() -> None:
    """Raise ``RuntimeError`` unless numpy computes in round-to-nearest, the IEEE default.

    The outward steps assume it: in round-upward, for instance, ``-MAX * (1 + 2^-52)`` rounds
    back to ``-MAX`` instead of ``-inf``. Some libraries change the mode process-wide (codac's
    interval backend gaol sets round-upward when it is imported).
    """
    if not np.array_equal(_PROBE[0] + _PROBE[1], _NEAREST):
        raise RuntimeError(
            "the floating-point rounding mode is not round-to-nearest (was codac/gaol imported?); "
            "outward rounding would not be guaranteed. Restore it with fesetround(FE_TONEAREST)."
        )


def down(x, ulps: int = BASIC_ULPS) -> np.ndarray:
    """``x`` moved at least ``ulps`` floats towards -inf (``-inf`` stays ``-inf``)."""
    return np.fmin(x * (1.0 - np.copysign(ulps * _EPS, x)) - ulps * _TINY, _CAP[ulps])


def up(x, ulps: int = BASIC_ULPS) -> np.ndarray:
    """``x`` moved at least ``ulps`` floats towards +inf (``+inf`` stays ``+inf``)."""
    return np.fmax(x * (1.0 + np.copysign(ulps * _EPS, x)) + ulps * _TINY, -_CAP[ulps])


def down_nonneg(x, ulps: int = BASIC_ULPS) -> np.ndarray:
    """:func:`down` for ``x >= 0`` (known sign: no copysign), clamped at 0."""
    return np.maximum(np.fmin(x * (1.0 - ulps * _EPS) - ulps * _TINY, _CAP[ulps]), 0.0)


def up_nonneg(x, ulps: int = BASIC_ULPS) -> np.ndarray:
    """:func:`up` for ``x >= 0`` (known sign: no copysign, and never -inf)."""
    return x * (1.0 + ulps * _EPS) + ulps * _TINY
