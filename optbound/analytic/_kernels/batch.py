"""Conversion of batched inputs: stacks of centres (B, n), shape matrices (B, n, n), parameters.

Only types and array shapes are checked here; the values (finiteness, symmetry, definiteness,
the supported domain) are checked per instance inside the compiled kernels, in the same pass
that computes the result, and reported with the argument's name and the instance.
"""

from __future__ import annotations

import numpy as np

from optbound._core import real_array


def float_array(name: str, value, ndim: int) -> np.ndarray:
    """``value`` as a C-contiguous float64 array with ``ndim`` dimensions, not empty."""
    arr = np.ascontiguousarray(real_array(name, value))
    if arr.ndim != ndim:
        raise ValueError(f"{name} must have {ndim} dimensions, got shape {arr.shape}")
    if arr.size == 0:
        raise ValueError(f"{name} must not be empty")
    return arr


def per_instance(
    name: str, value, n_batch: int, trailing: tuple[int, ...], finite: bool = True
) -> np.ndarray:
    """Broadcast a shared value (shape ``trailing``) or a per-instance one to (B, *trailing),
    as a C-contiguous, writable array: always the same array type for the compiled kernels,
    whatever B (a broadcast of one instance would otherwise be a read-only view, a type of its
    own that numba compiles the whole kernel again for). ``finite=False`` leaves the
    finiteness check to a kernel that checks every instance anyway (and names it)."""
    arr = real_array(name, value)
    if arr.shape == trailing:
        arr = np.broadcast_to(arr, (n_batch, *trailing))
    if arr.shape != (n_batch, *trailing):
        raise ValueError(
            f"{name} must have shape {trailing} or {(n_batch, *trailing)}, got {arr.shape}"
        )
    if finite and not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite")
    if arr.flags.c_contiguous and arr.flags.writeable:
        return arr
    return np.require(arr, requirements="CW")
