"""Input validation shared by every package.

Every failure is a ``ValueError`` or ``TypeError`` that names the offending argument, so a user
who passes a NaN, a complex number or a non-PD matrix learns which argument was wrong instead
of getting a NaN bound later.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from optbound._core.domain import SYMMETRY_RTOL

# Smallest Cholesky pivot, relative to the largest diagonal entry, still counted as definite.
SINGULAR_RTOL = 1e-13


class NotRealError(TypeError, ValueError):
    """An argument that is not an array of real numbers (complex, text, ragged, objects).

    Both a ``TypeError`` (its values have the wrong type) and a ``ValueError`` (the argument
    has a wrong value), as numpy's ``AxisError`` is both an ``IndexError`` and a
    ``ValueError``: the set types document the first, the localization models the second.
    """


def real_array(name: str, value, what: str = "an array") -> np.ndarray:
    """``value`` as a float64 array (not copied if it is one); complex input is refused.

    Raises :class:`NotRealError` naming ``name`` for complex values (never silently truncated
    to their real part) and for anything numpy cannot read as real numbers (ragged rows, text,
    objects); ``what`` describes the expected array in that message, e.g. ``"an (N, 2) array"``.
    """
    if type(value) is np.ndarray and value.dtype == np.float64:
        return value  # the common case, without the checks' ~1 us
    try:
        arr = np.asarray(value)
        if not np.iscomplexobj(arr):
            return arr.astype(np.float64, copy=False)
    except (TypeError, ValueError):  # ragged, text, objects that are not numbers
        raise NotRealError(
            f"{name} must be {what} of real numbers, got {type(value).__name__}"
        ) from None
    raise NotRealError(f"{name} must be real, got complex values")


def finite_array(name: str, value) -> np.ndarray:
    """``value`` as a finite float64 array of any shape (see :func:`real_array`)."""
    arr = real_array(name, value)
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite")
    return arr


def finite_vector(name: str, value, dim: int | None = None) -> np.ndarray:
    """Return ``value`` as a finite float64 1-D array (a scalar becomes length 1)."""
    arr = np.atleast_1d(real_array(name, value))
    if arr.ndim != 1:
        raise ValueError(f"{name} must be a 1-D vector, got shape {arr.shape}")
    if arr.size == 0:
        raise ValueError(f"{name} must not be empty")
    if not np.isfinite(arr).all():
        raise ValueError(f"{name} must be finite, got {arr}")
    if dim is not None and arr.shape[0] != dim:
        raise ValueError(f"{name} must have length {dim}, got {arr.shape[0]}")
    return arr


def finite_scalar(name: str, value) -> float:
    """Return ``value`` as a finite Python float."""
    if type(value) is float or type(value) is np.float64:  # the common case, no array round trip
        if math.isfinite(value):
            return float(value)
        raise ValueError(f"{name} must be finite, got {float(value)}")
    arr = real_array(name, value)
    if arr.ndim != 0:
        raise ValueError(f"{name} must be a scalar, got shape {arr.shape}")
    if not np.isfinite(arr):
        raise ValueError(f"{name} must be finite, got {float(arr)}")
    return float(arr)


def finite_matrix(
    name: str, value, shape: tuple[int | None, int | None] = (None, None)
) -> np.ndarray:
    """Return ``value`` as a finite float64 2-D array, optionally of a given shape."""
    arr = real_array(name, value)
    if arr.ndim != 2:
        raise ValueError(f"{name} must be a 2-D matrix, got shape {arr.shape}")
    for axis, want in enumerate(shape):
        if want is not None and arr.shape[axis] != want:
            raise ValueError(f"{name} must have shape {shape}, got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite")
    return arr


def symmetric_matrix(name: str, value, dim: int | None = None) -> np.ndarray:
    """Validate a finite square symmetric matrix and return it exactly symmetrized.

    Asymmetry at rounding level (relative ``SYMMETRY_RTOL``) is removed by symmetrizing;
    larger asymmetry is an error, because it signals a wrong matrix rather than round-off.
    """
    arr = finite_matrix(name, value, (dim, dim))
    if arr.shape[0] != arr.shape[1]:
        raise ValueError(f"{name} must be square, got shape {arr.shape}")
    scale = np.max(np.abs(arr))
    if np.max(np.abs(arr - arr.T)) > SYMMETRY_RTOL * max(scale, np.finfo(float).tiny):
        raise ValueError(f"{name} must be symmetric")
    return 0.5 * (arr + arr.T)


def spd_matrix(name: str, value, dim: int | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Validate a symmetric positive-definite matrix; return it and its Cholesky factor.

    Symmetry is checked and enforced as in :func:`symmetric_matrix`.
    """
    arr = symmetric_matrix(name, value, dim)
    try:
        chol = np.linalg.cholesky(arr)
    except np.linalg.LinAlgError:
        raise ValueError(f"{name} must be positive definite") from None
    # A pivot at rounding level of the largest diagonal entry means singular, not PD.
    pivots = np.diag(chol) ** 2
    if not np.all(np.isfinite(chol)) or np.min(pivots) <= SINGULAR_RTOL * np.max(np.diag(arr)):
        raise ValueError(f"{name} must be positive definite (it is singular or nearly so)")
    return arr, chol


def points(name: str, value, dim: int) -> tuple[np.ndarray, bool]:
    """Return ``value`` as an (m, dim) array and whether a single point (dim,) was given."""
    arr = real_array(name, value)
    single = arr.ndim == 1
    arr = np.atleast_2d(arr)
    if arr.ndim != 2 or arr.shape[1] != dim:
        raise ValueError(f"{name} must have shape (m, {dim}) or ({dim},), got {np.shape(value)}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite")
    return arr, single


def dims_index(name: str, dims, dim: int) -> np.ndarray:
    """Validate a list of distinct coordinate indices into a ``dim``-dimensional space.

    The result is always a new read-only int64 array, whatever form ``dims`` came in (tuple,
    list, array of any integer type): the compiled kernels that take it then see one array
    type, and are compiled once for it rather than once per form. A tuple of Python ints (the
    common case, e.g. ``(0, 1)`` in a tracker's every update) is validated once and cached:
    the returned array is then shared.
    """
    if type(dims) is tuple and all(type(d) is int for d in dims):
        return _int_tuple_index(name, dims, dim)
    return _dims_index(name, dims, dim)


@functools.lru_cache(maxsize=256)
def _int_tuple_index(name: str, dims: tuple[int, ...], dim: int) -> np.ndarray:
    return _dims_index(name, dims, dim)


def _dims_index(name: str, dims, dim: int) -> np.ndarray:
    idx = np.atleast_1d(np.asarray(dims))
    if idx.ndim != 1 or idx.size == 0 or not np.issubdtype(idx.dtype, np.integer):
        raise ValueError(f"{name} must be a non-empty sequence of integer coordinates, got {dims}")
    if np.any(idx < 0) or np.any(idx >= dim) or len(set(idx.tolist())) != idx.size:
        raise ValueError(f"{name} must be distinct coordinates in [0, {dim}), got {dims}")
    idx = idx.astype(np.int64)  # a copy: the caller's array keeps its flags
    idx.flags.writeable = False
    return idx


def rng_of(rng) -> np.random.Generator:
    """Accept a Generator or a seed; refuse the implicit global state (results must be seeded)."""
    if isinstance(rng, np.random.Generator):
        return rng
    if rng is None:
        raise ValueError("rng must be a numpy Generator or an integer seed (seeded randomness)")
    return np.random.default_rng(rng)
