"""Outline and drawing of a set whose projections are exact convex polygons.

A set type that defines ``vertices()`` (the exact polygon of a 2-D set, in order) and
``project(dims)`` gets :class:`PolygonOutline`'s ``boundary`` (the closed polygon, for the
plots' ``Outlined`` protocol) and ``plot`` for free: the zonotopes and constrained zonotopes.
"""

from __future__ import annotations

import numpy as np


class PolygonOutline:
    """Mixin: ``boundary`` and ``plot`` from the set's ``vertices()`` and ``project(dims)``."""

    def boundary(self, resolution: int = 0) -> np.ndarray:
        """The closed polygon of :meth:`vertices` (first vertex repeated), for the plots'
        ``Outlined`` protocol; ``resolution`` is unused (the outline is the exact polygon).

        Parameters
        ----------
        resolution : int, default 0
            Unused (protocol compatibility).

        Returns
        -------
        ndarray, shape (k + 1, 2)
            The closed polygon.

        Raises
        ------
        ValueError
            If the set is not 2-D.
        """
        V = self.vertices()
        return np.vstack([V, V[:1]])

    def plot(self, ax=None, dims: tuple[int, int] = (0, 1), **kwargs):
        """Draw the projection on ``dims`` as a polygon outline (matplotlib ``ax.fill``
        keywords; ``fill=False`` unless given).

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Target axes (the current axes if None).
        dims : tuple of int, default (0, 1)
            The two coordinates shown.
        **kwargs
            Passed to ``ax.fill``.

        Returns
        -------
        list of matplotlib.patches.Polygon
            What ``ax.fill`` returns.
        """
        vertices = self.project(dims).vertices()
        if ax is None:
            import matplotlib.pyplot as plt

            ax = plt.gca()
        return ax.fill(vertices[:, 0], vertices[:, 1], **{"fill": False, **kwargs})
