"""Size ratios between two bounds of one set (``A`` relative to ``B``; > 1 means A is larger).

Volumes are compared through log volumes, so the ratio stays accurate for very small or very
large ellipsoids in high dimension.
"""

from __future__ import annotations

from collections.abc import Sequence
from math import exp

import numpy as np

from optbound.compare._ellipsoid import as_ellipsoid, same_dim


def log_volume_ratio(A, B) -> float:
    """``log(vol A / vol B)``."""
    A, B = as_ellipsoid("A", A), as_ellipsoid("B", B)
    same_dim(A, B)
    return A.log_volume() - B.log_volume()


def volume_ratio(A, B) -> float:
    """``vol A / vol B``."""
    return exp(log_volume_ratio(A, B))


def trace_ratio(A, B) -> float:
    """``tr C_A / tr C_B`` (sum of squared semi-axes, the HS96 trace criterion)."""
    A, B = as_ellipsoid("A", A), as_ellipsoid("B", B)
    same_dim(A, B)
    return float(np.trace(A.shape) / np.trace(B.shape))


def projection_volume_ratio(A, B, dims: Sequence[int]) -> float:
    """Volume ratio of the projections onto the coordinates ``dims`` [HS96, eq. (27)]."""
    A, B = as_ellipsoid("A", A), as_ellipsoid("B", B)
    same_dim(A, B)
    return volume_ratio(A.project(dims), B.project(dims))
