"""Certified volume brackets for zonotopes.

The volume of ``<c, G>`` in R^n is ``2^n sum_S |det G_S|`` over the n-subsets S of the
generators (Shephard 1974; McMullen 1984): in 2-D the area is ``4 sum_{i<j} |det(g_i, g_j)|``.
The sum is evaluated exactly in rational arithmetic and rounded outward, so the bracket is
the exact volume up to one float on each side. With more than ``max_subsets`` subsets the
lower bound is the exact volume of the sub-zonotope of the largest generators (which lies
in Z) and the upper bound the smaller of the interval hull's volume and the volume of the
Girard-reduced parallelotope (both contain Z).
"""

from __future__ import annotations

from fractions import Fraction
from itertools import combinations
from math import comb

import numpy as np

from optbound.sets.certified import row_sum_up
from optbound.sets.zonotope_reduction import reduce_generators


def _det(rows: list[list[Fraction]]) -> Fraction:
    """Exact determinant by fraction-valued Gaussian elimination."""
    a = [r[:] for r in rows]
    n, det = len(a), Fraction(1)
    for j in range(n):
        p = next((i for i in range(j, n) if a[i][j] != 0), None)
        if p is None:
            return Fraction(0)
        if p != j:
            a[j], a[p], det = a[p], a[j], -det
        det *= a[j][j]
        for i in range(j + 1, n):
            f = a[i][j] / a[j][j]
            if f:
                a[i] = [x - f * y for x, y in zip(a[i], a[j], strict=True)]
    return det


def exact_volume(G: np.ndarray) -> Fraction:
    """``2^n sum_S |det G_S|`` in exact arithmetic (the floats of G read exactly).

    Parameters
    ----------
    G : np.ndarray, shape (n, m)
        Generators.

    Returns
    -------
    Fraction
        The exact volume of ``<c, G>`` (Shephard 1974; McMullen 1984).
    """
    n, m = G.shape
    cols = [[Fraction(float(x)) for x in G[:, k]] for k in range(m)]
    total = sum(
        (
            abs(_det([list(r) for r in zip(*(cols[k] for k in S), strict=True)]))
            for S in combinations(range(m), n)
        ),
        Fraction(0),
    )
    return total * 2**n


def _down(x: Fraction) -> float:
    f = float(x)
    return float(np.nextafter(f, -np.inf)) if Fraction(f) > x else f


def _up(x: Fraction) -> float:
    f = float(x)
    return float(np.nextafter(f, np.inf)) if Fraction(f) < x else f


def volume_bounds(G: np.ndarray, max_subsets: int = 5000) -> tuple[float, float]:
    """Certified ``(lo, hi)`` with ``lo <= vol(<c, G>) <= hi`` (module docstring).

    Parameters
    ----------
    G : np.ndarray, shape (n, m)
        Generators (finite).
    max_subsets : int, default 5000
        Largest number of n-subsets summed exactly; above it, the sub-zonotope / hull bracket.

    Returns
    -------
    tuple of float
        ``(lo, hi)``; ``(0.0, 0.0)`` for a flat zonotope.
    """
    G = G[:, np.any(G != 0, axis=0)]
    n, m = G.shape
    if m < n:
        return 0.0, 0.0  # flat: it lies in the span of fewer than n vectors
    if comb(m, n) <= max_subsets:
        vol = exact_volume(G)
        return _down(vol), _up(vol)
    k = n
    while comb(k + 1, n) <= max_subsets:
        k += 1
    largest = np.sort(np.argsort(-np.linalg.norm(G, axis=0), kind="stable")[:k])
    lower = exact_volume(G[:, largest])
    box = Fraction(1)
    for r in row_sum_up(np.abs(G)):
        box *= 2 * Fraction(float(r))
    upper = min(box, exact_volume(reduce_generators(G, n, "girard")))
    return _down(lower), _up(upper)
