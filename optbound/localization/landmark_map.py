"""Map of indistinguishable point landmarks and partitioning walls [HS96, Sect. 2]."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from optbound.localization import geometry
from optbound.localization.landmarks import as_landmarks, as_shapes


@dataclass(frozen=True, init=False)
class LandmarkMap:
    """``M`` landmarks with error ellipses [HS96, eq. (2)] and occluding walls.

    Parameters
    ----------
    landmarks : array_like, shape (M, 2)
        Nominal landmark positions, ordered so that a robot scanning counter-clockwise sees the
        unoccluded ones in index order (cyclically) [HS96, Sect. 2].
    walls : array_like, shape (S, 2, 2), optional
        Partitioning walls as segments ``[[a_x, a_y], [b_x, b_y]]``; none by default.
    shapes : array_like, shape (M, 2, 2) or (2, 2), optional
        Landmark error ellipses ``C_i``; default exact landmarks.
    """

    landmarks: np.ndarray
    walls: np.ndarray
    shapes: np.ndarray

    def __init__(self, landmarks, walls=None, shapes=None):
        L = as_landmarks("landmarks", landmarks)
        W = np.empty((0, 2, 2)) if walls is None else geometry.as_segments(walls, "walls")
        C = as_shapes("shapes", shapes, L.shape[0])
        for arr in (L, W, C):
            arr.setflags(write=False)
        object.__setattr__(self, "landmarks", L)
        object.__setattr__(self, "walls", W)
        object.__setattr__(self, "shapes", C)

    @property
    def size(self) -> int:
        """Number of landmarks M."""
        return self.landmarks.shape[0]

    @property
    def radii(self) -> np.ndarray:
        """Radius of each landmark's error ellipse (sqrt of its largest eigenvalue), (M,)."""
        return np.sqrt(np.maximum(np.linalg.eigvalsh(self.shapes)[:, 1], 0.0))

    def visible(self, x, y) -> np.ndarray:
        """Tell which landmarks are unoccluded from the points ``(x, y)``.

        Parameters
        ----------
        x, y : array_like
            Coordinates of the points (broadcast together).

        Returns
        -------
        numpy.ndarray of bool, shape ``x.shape + (M,)``
            True where no wall meets the segment from the point to the landmark.
        """
        x, y = np.asarray(x, dtype=float)[..., None], np.asarray(y, dtype=float)[..., None]
        if self.walls.shape[0] == 0:
            return np.ones(np.broadcast(x, self.landmarks[:, 0]).shape, dtype=bool)
        hidden = geometry.occluded((x, y), (self.landmarks[:, 0], self.landmarks[:, 1]), self.walls)
        return ~hidden


__all__ = ["LandmarkMap"]
