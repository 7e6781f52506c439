"""Shared inputs for the interval tests: awkward floats and an mpmath enclosure check."""

from __future__ import annotations

import mpmath
import numpy as np

mpmath.mp.prec = 300  # far beyond double: the reference is exact for our purposes

TINY = 5e-324
MAX = np.finfo(float).max


def awkward_floats(rng: np.random.Generator, size: int) -> np.ndarray:
    """Floats mixing all magnitudes: subnormal, tiny, order one, huge, zeros and extremes."""
    kinds = rng.integers(0, 5, size)
    sign = rng.choice([-1.0, 1.0], size)
    out = np.empty(size)
    out[kinds == 0] = rng.integers(1, 2**52, np.sum(kinds == 0)) * TINY  # subnormal
    out[kinds == 1] = 10.0 ** rng.uniform(-307, 307, np.sum(kinds == 1))  # any magnitude
    out[kinds == 2] = rng.uniform(0, 4, np.sum(kinds == 2))  # order one
    out[kinds == 3] = 10.0 ** rng.uniform(-8, 8, np.sum(kinds == 3))
    out[kinds == 4] = rng.choice([0.0, TINY, 1.0, 2.0**-1022, MAX, 0.5], np.sum(kinds == 4))
    return sign * out


def random_intervals(rng: np.random.Generator, size: int) -> tuple[np.ndarray, np.ndarray]:
    """Bounds of random intervals; a quarter straddle zero, a few are points."""
    a, b = awkward_floats(rng, size), awkward_floats(rng, size)
    straddle = rng.random(size) < 0.25
    a = np.where(straddle, -np.abs(a), a)
    b = np.where(straddle, np.abs(b), b)
    point = rng.random(size) < 0.1
    b = np.where(point, a, b)
    return np.minimum(a, b), np.maximum(a, b)


def points_in(lo: np.ndarray, hi: np.ndarray, rng: np.random.Generator) -> list[np.ndarray]:
    """Endpoints and two interior points of each interval (finite bounds)."""
    t = rng.random((2, lo.size))
    inner = [np.clip(lo + ti * (hi - lo), lo, hi) for ti in t]
    inner = [np.where(np.isfinite(p), p, lo) for p in inner]  # hi - lo may overflow
    return [lo, hi, *inner]


def encloses(lo: float, hi: float, exact) -> bool:
    """Whether the float interval [lo, hi] contains the mpmath value ``exact``."""
    return mpmath.mpf(float(lo)) <= exact <= mpmath.mpf(float(hi))
