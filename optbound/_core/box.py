"""Axis-aligned boxes: the ``Box`` set and validated ``(m, n, 2)`` arrays of boxes.

A ``Box`` is ``{x : lo <= x <= hi}``; its bounds may be infinite (e.g. SIVIA's Y). A box array
holds m boxes of dimension n as ``[lo, hi]`` rows, ``B[k, j] = [lo_j, hi_j]`` of box k: the
currency of interval pavings, ``tri_contains`` and the localization models.
"""

from __future__ import annotations

import numpy as np

from optbound._core import validate as v
from optbound._core.convex import ConvexSet, QuadraticDescription
from optbound._core.validate import real_array


class Box(ConvexSet):
    """Axis-aligned box with lower corner ``lo`` and upper corner ``hi`` (``lo <= hi``).

    Infinite bounds are allowed (an unbounded box); NaN is not.
    """

    def __init__(self, lo, hi):
        lo = np.atleast_1d(real_array("lo", lo)).copy()
        hi = np.atleast_1d(real_array("hi", hi)).copy()
        for name, arr in (("lo", lo), ("hi", hi)):
            if arr.ndim != 1 or arr.size == 0:
                raise ValueError(f"{name} must be a non-empty 1-D vector, got shape {arr.shape}")
            if np.any(np.isnan(arr)):
                raise ValueError(f"{name} must not contain NaN")
        if lo.shape != hi.shape:
            raise ValueError(f"lo and hi must have the same length, got {lo.shape} and {hi.shape}")
        if np.any(lo > hi):
            raise ValueError(f"lo must be <= hi componentwise, got lo={lo}, hi={hi}")
        if np.any(lo == np.inf) or np.any(hi == -np.inf):
            raise ValueError("lo must not be +inf and hi must not be -inf")
        self._lo, self._hi = lo, hi
        lo.setflags(write=False)
        hi.setflags(write=False)

    @classmethod
    def from_array(cls, rows) -> Box:
        """Build from an (n, 2) array of ``[lo, hi]`` rows."""
        arr = real_array("rows", rows)
        if arr.ndim != 2 or arr.shape[1] != 2:
            raise ValueError(f"rows must have shape (n, 2), got {arr.shape}")
        return cls(arr[:, 0], arr[:, 1])

    @property
    def lo(self) -> np.ndarray:
        return self._lo

    @property
    def hi(self) -> np.ndarray:
        return self._hi

    @property
    def dim(self) -> int:
        return self._lo.shape[0]

    @property
    def is_bounded(self) -> bool:
        return bool(np.all(np.isfinite(self._lo)) and np.all(np.isfinite(self._hi)))

    @property
    def center(self) -> np.ndarray:
        return 0.5 * (self._lo + self._hi)

    @property
    def widths(self) -> np.ndarray:
        return self._hi - self._lo

    def as_array(self) -> np.ndarray:
        """The (n, 2) array of ``[lo, hi]`` rows."""
        return np.column_stack([self._lo, self._hi])

    def __repr__(self) -> str:
        return f"Box(lo={self._lo.tolist()}, hi={self._hi.tolist()})"

    def volume(self) -> float:
        """Product of the widths; ``inf`` for an unbounded box (even if another width is 0)."""
        if not self.is_bounded:
            return np.inf
        return float(np.prod(self.widths))

    def log_volume(self) -> float:
        """Sum of the log-widths; ``inf`` for an unbounded box, ``-inf`` for a flat one."""
        if not self.is_bounded:
            return np.inf
        with np.errstate(divide="ignore"):
            return float(np.sum(np.log(self.widths)))

    def contains(self, X, tol: float = 1e-9) -> np.ndarray | bool:
        pts, single = v.points("X", X, self.dim)
        slack = tol * np.maximum(1.0, np.where(np.isfinite(self.widths), self.widths, 1.0))
        inside = np.all((pts >= self._lo - slack) & (pts <= self._hi + slack), axis=1)
        return bool(inside[0]) if single else inside

    def support(self, d) -> np.ndarray | float:
        dirs, single = v.points("d", d, self.dim)
        # Pick the corner coordinate that maximises each term; 0 * inf counts as 0.
        corner = np.where(dirs >= 0, self._hi, self._lo)
        with np.errstate(invalid="ignore"):
            terms = np.where(dirs == 0, 0.0, dirs * corner)
        h = terms.sum(axis=1)
        return float(h[0]) if single else h

    def quadratic_description(self) -> QuadraticDescription:
        """One range ``lo_i <= x_i <= hi_i`` per coordinate with a finite bound."""
        eye = np.eye(self.dim)
        finite = np.isfinite(self._lo) | np.isfinite(self._hi)
        return QuadraticDescription(
            ranges=tuple((eye[i], self._lo[i], self._hi[i]) for i in np.flatnonzero(finite))
        )

    def enclosing_ellipsoid(self) -> None:
        """None: a box's own bounds enter the SDP layer as ranges, tighter than any ellipsoid
        around it."""
        return None

    def project(self, dims) -> Box:
        idx = v.dims_index("dims", dims, self.dim)
        return Box(self._lo[idx], self._hi[idx])

    def sample(self, m: int, rng) -> np.ndarray:
        """``m`` points uniform in the box (bounded boxes only)."""
        if not self.is_bounded:
            raise ValueError("cannot sample an unbounded box")
        gen = v.rng_of(rng)
        return self._lo + gen.random((m, self.dim)) * self.widths


def box_array(name: str, boxes, dim: int | None = None, *, volume: bool = False) -> np.ndarray:
    """Validate an ``(m, dim, 2)`` array of finite ``[lo, hi]`` boxes with ``lo <= hi``.

    Parameters
    ----------
    name
        The argument's name, used in every error message.
    boxes : array_like, shape (m, dim, 2)
        ``boxes[k, j] = [lo, hi]``: side j of box k. ``m = 0`` is allowed.
    dim
        The required dimension n of the boxes (any n if ``None``).
    volume
        Also require ``lo < hi`` on every side (a box with interior, e.g. a robot's position).

    Returns
    -------
    numpy.ndarray
        The boxes as a C-contiguous float64 array (``boxes`` itself if it is one).
    """
    B = np.ascontiguousarray(real_array(name, boxes))
    if B.ndim != 3 or B.shape[2] != 2 or (dim is not None and B.shape[1] != dim):
        n = "n" if dim is None else dim
        raise ValueError(f"{name} must have shape (m, {n}, 2) ([lo, hi] rows), got {B.shape}")
    if not np.all(np.isfinite(B)):
        raise ValueError(f"{name} must be finite")
    if np.any(B[:, :, 0] > B[:, :, 1]):
        raise ValueError(f"{name} must have lo <= hi (a lower bound exceeds its upper bound)")
    if volume:
        flat = np.any(B[:, :, 0] >= B[:, :, 1], axis=1)
        if np.any(flat):
            bad = np.flatnonzero(flat).tolist()
            raise ValueError(f"{name}: box(es) {bad} have no volume (lo >= hi on a side)")
    return B


def as_box(name: str, value, *, bounded: bool = False) -> Box:
    """``value`` (a :class:`Box` or ``(n, 2)`` ``[lo, hi]`` rows) as a ``Box``.

    ``bounded=True`` refuses an unbounded box. Errors are ``ValueError`` naming ``name``.
    """
    try:
        box = value if isinstance(value, Box) else Box.from_array(value)
    except ValueError as err:
        raise ValueError(f"{name}: {err}") from None
    if bounded and not box.is_bounded:
        raise ValueError(f"{name} must be a bounded box, got {box}")
    return box


def box_rows(name: str, value, allow_infinite: bool) -> tuple[np.ndarray, np.ndarray]:
    """:func:`as_box`, returned as fresh (writable) copies of the lower and upper corners."""
    box = as_box(name, value, bounded=not allow_infinite)
    return np.array(box.lo), np.array(box.hi)
