"""Compiled scalar interval operations: the numpy kernels' bounds bit for bit, exact enclosure."""

from fractions import Fraction

import numpy as np
import pytest

from optbound.interval import _arith, _transcendental
from optbound.interval.compiled import iadd, idiv, imul, isqr, isqrt, isub

SPECIAL = [0.0, -0.0, 1.0, -1.0, 0.5, -3.0, 1e-300, -1e-300, 5e-324, 1e300, -1e300]


def _pairs(rng, n):
    """Intervals [lo, hi]: random magnitudes and signs, with special end points mixed in."""
    x = rng.choice([-1.0, 1.0], (n, 2)) * 10.0 ** rng.uniform(-8, 8, (n, 2))
    x = np.where(rng.uniform(size=(n, 2)) < 0.2, rng.choice(SPECIAL, (n, 2)), x)
    return np.sort(x, axis=1)


def _encloses(lo: float, hi: float, value: Fraction) -> bool:
    """``lo <= value <= hi`` in exact arithmetic (infinite bounds allowed)."""
    return (lo == -np.inf or Fraction(lo) <= value) and (hi == np.inf or value <= Fraction(hi))


def _apply(op, *cols):
    return np.array([op(*row) for row in zip(*cols, strict=True)]).T


@pytest.mark.parametrize(
    ("compiled", "numpy_kernel"),
    [(iadd, _arith.add), (isub, _arith.sub), (imul, _arith.mul), (idiv, _arith.div)],
)
def test_binary_operations_equal_the_numpy_kernels(compiled, numpy_kernel):
    rng = np.random.default_rng(0)
    a, b = _pairs(rng, 600), _pairs(rng, 600)
    b[:40] = [[0.0, 0.0], [0.0, 2.0], [-2.0, 0.0], [-1.0, 1.0]] * 10  # divisors holding 0
    with np.errstate(all="ignore"):
        ref = numpy_kernel(a[:, 0], a[:, 1], b[:, 0], b[:, 1])
    got = _apply(compiled, a[:, 0], a[:, 1], b[:, 0], b[:, 1])
    assert np.array_equal(got[0], ref[0]) and np.array_equal(got[1], ref[1])


@pytest.mark.parametrize(
    ("compiled", "numpy_kernel"), [(isqr, _arith.sqr), (isqrt, _transcendental.sqrt)]
)
def test_unary_operations_equal_the_numpy_kernels(compiled, numpy_kernel):
    a = _pairs(np.random.default_rng(1), 600)
    with np.errstate(all="ignore"):
        ref = numpy_kernel(a[:, 0], a[:, 1])
    got = _apply(compiled, a[:, 0], a[:, 1])
    assert np.array_equal(got[0], ref[0]) and np.array_equal(got[1], ref[1])


def test_results_contain_the_exact_values():
    """Corners of the operands, combined exactly in Fractions, lie inside the results."""
    rng = np.random.default_rng(2)
    a, b = _pairs(rng, 300), _pairs(rng, 300)
    b = np.where(np.abs(b) < 1e-200, 1.0, b)
    b = np.where((b[:, :1] < 0) & (b[:, 1:] > 0), np.abs(b), b)  # divisors without 0
    b = np.sort(b, axis=1)
    for (al, ah), (bl, bh) in zip(a, b, strict=True):
        for op, exact in (
            (iadd, lambda x, y: x + y),
            (isub, lambda x, y: x - y),
            (imul, lambda x, y: x * y),
            (idiv, lambda x, y: x / y),
        ):
            lo, hi = op(al, ah, bl, bh)
            for x in (al, ah):
                for y in (bl, bh):
                    assert _encloses(lo, hi, exact(Fraction(x), Fraction(y)))
        lo, hi = isqr(al, ah)
        assert _encloses(lo, hi, Fraction(al) ** 2) and _encloses(lo, hi, Fraction(ah) ** 2)
