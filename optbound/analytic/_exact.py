"""Exact rational evaluation of a family member, and its certified float enclosure.

Used where speed does not matter and the formula involves a matrix inverse (the m-row
bounding update [BH, eq. (7)]): every float input is read as the exact rational it is, the
member is computed in ``fractions.Fraction`` without any rounding, and only the final rounding
to floats is bounded and absorbed by ``midrad.inflate``.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from optbound._core import check_ellipsoid
from optbound.analytic._kernels.midrad import inflate
from optbound.sets.ellipsoid import Ellipsoid

Matrix = list[list[Fraction]]


def rational(A) -> Matrix:
    """A float array (1-D or 2-D) as exact rationals (a 1-D array becomes a column)."""
    A = np.asarray(A, dtype=float)
    rows = A.reshape(A.shape[0], -1)
    return [[Fraction(float(x)) for x in row] for row in rows]


def matmul(A: Matrix, B: Matrix) -> Matrix:
    return [
        [
            sum((a * b for a, b in zip(row, col, strict=True)), Fraction(0))
            for col in zip(*B, strict=True)
        ]
        for row in A
    ]


def transpose(A: Matrix) -> Matrix:
    return [list(col) for col in zip(*A, strict=True)]


def solve(A: Matrix, B: Matrix) -> Matrix:
    """A^{-1} B by Gaussian elimination (exact; A must be non-singular)."""
    m = len(A)
    M = [list(A[i]) + list(B[i]) for i in range(m)]
    for k in range(m):
        p = next(i for i in range(k, m) if M[i][k] != 0)
        M[k], M[p] = M[p], M[k]
        for i in range(m):
            if i != k and M[i][k] != 0:
                f = M[i][k] / M[k][k]
                M[i] = [x - f * y for x, y in zip(M[i], M[k], strict=True)]
    return [[x / M[i][i] for x in M[i][m:]] for i in range(m)]


def _upper(x: Fraction) -> float:
    """A float >= |x|."""
    x = abs(x)
    f = float(x)
    return f if Fraction(f) >= x else math.nextafter(f, math.inf)


def enclose(center: Matrix, shape: Matrix) -> tuple[Ellipsoid | None, float]:
    """Floats that contain the exact ellipsoid E(center, shape): the rounded member inflated by
    the certified margin; (None, -1) if the result is outside the domain."""
    n = len(shape)
    c = np.array([float(row[0]) for row in center])
    S = np.array([[float(x) for x in row] for row in shape])
    S = np.tril(S) + np.tril(S, -1).T  # the exact shape is symmetric; keep S exactly so
    D = np.array([[_upper(shape[i][j] - Fraction(S[i, j])) for j in range(n)] for i in range(n)])
    d = np.array([_upper(center[i][0] - Fraction(c[i])) for i in range(n)])
    T = np.empty((n, n))
    L = np.empty((n, n))
    margin = inflate(S, D, c, d, T, L)
    if margin < 0 or check_ellipsoid(c, T, L) != 0:
        return None, -1.0
    return Ellipsoid._trusted(c, T, L), float(margin)
