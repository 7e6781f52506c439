"""Validation of batched inputs: stacks of centres (B, n) and shape matrices (B, n, n).

The single-instance functions receive already validated ``Ellipsoid`` objects; the batched
functions receive raw arrays and check them here once, vectorized, with ``ValueError`` messages
that name the argument and the first offending instance.
"""

from __future__ import annotations

import numpy as np

from optbound.sets._validate import SINGULAR_RTOL, SYMMETRY_RTOL


def finite_array(name: str, value, ndim: int) -> np.ndarray:
    """Return ``value`` as a finite float64 array with ``ndim`` dimensions."""
    arr = np.asarray(value, dtype=float)
    if arr.ndim != ndim:
        raise ValueError(f"{name} must have {ndim} dimensions, got shape {arr.shape}")
    if arr.size == 0:
        raise ValueError(f"{name} must not be empty")
    bad = ~np.isfinite(arr.reshape(arr.shape[0], -1)).all(axis=1)
    if bad.any():
        raise ValueError(f"{name} must be finite (instance {int(np.argmax(bad))} is not)")
    return arr


def ellipsoid_stack(
    centers_name: str, centers, shapes_name: str, shapes
) -> tuple[np.ndarray, np.ndarray]:
    """Validate centres (B, n) and symmetric positive-definite shapes (B, n, n)."""
    c = finite_array(centers_name, centers, 2)
    C = finite_array(shapes_name, shapes, 3)
    n_batch, n = c.shape
    if C.shape != (n_batch, n, n):
        raise ValueError(f"{shapes_name} must have shape {(n_batch, n, n)}, got {C.shape}")
    scale = np.max(np.abs(C), axis=(1, 2))
    asym = np.max(np.abs(C - C.transpose(0, 2, 1)), axis=(1, 2))
    if np.any(asym > SYMMETRY_RTOL * scale):
        first = int(np.argmax(asym > SYMMETRY_RTOL * scale))
        raise ValueError(f"{shapes_name} must be symmetric (instance {first} is not)")
    C = 0.5 * (C + C.transpose(0, 2, 1))
    # The same criterion as a single Ellipsoid (``_validate.spd_matrix``): Cholesky must succeed
    # and no pivot may be at rounding level of the largest diagonal entry.
    try:
        pivots = np.diagonal(np.linalg.cholesky(C), axis1=1, axis2=2) ** 2
        singular = pivots.min(axis=1) <= SINGULAR_RTOL * np.diagonal(C, axis1=1, axis2=2).max(
            axis=1
        )
    except np.linalg.LinAlgError:
        # Cholesky is the cheap test; the eigenvalues only locate the culprit for the message.
        singular = np.linalg.eigvalsh(C)[:, 0] <= 0
    if singular.any():
        raise ValueError(
            f"{shapes_name} must be positive definite (instance {int(np.argmax(singular))} is "
            "singular or nearly so)"
        )
    return c, C


def per_instance(name: str, value, n_batch: int, trailing: tuple[int, ...]) -> np.ndarray:
    """Broadcast a shared value (shape ``trailing``) or a per-instance one to (B, *trailing)."""
    arr = np.asarray(value, dtype=float)
    if arr.shape == trailing:
        arr = np.broadcast_to(arr, (n_batch, *trailing))
    if arr.shape != (n_batch, *trailing):
        raise ValueError(
            f"{name} must have shape {trailing} or {(n_batch, *trailing)}, got {arr.shape}"
        )
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite")
    return arr
