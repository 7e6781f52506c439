"""``Paving``: the result of SIVIA, three arrays of boxes bracketing a set.

``inner ⊂ X ⊂ inner ∪ boundary`` [LJMW97, eq. (11)]; ``outside`` holds the boxes proven
disjoint from X. Boxes are ``(m, n, 2)`` arrays of ``[lo, hi]`` rows.
"""

from __future__ import annotations

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from optbound._core import Box

#: Candidate box pairs examined at once by :meth:`Paving.components` (bounds memory).
_PAIR_CHUNK = 4_000_000


def box_volumes(boxes: np.ndarray) -> np.ndarray:
    """Compute the volume of each box of an ``(m, n, 2)`` array.

    Parameters
    ----------
    boxes : numpy.ndarray, shape (m, n, 2)
        Rows ``[lo, hi]`` of each box.

    Returns
    -------
    numpy.ndarray, shape (m,)
        ``prod(hi - lo)`` of each box, in floating point (not rounded outward).
    """
    return np.prod(boxes[:, :, 1] - boxes[:, :, 0], axis=1)


class Paving:
    """Inner, boundary and outside boxes of a set within the initial box ``X0``.

    Parameters
    ----------
    inner : numpy.ndarray, shape (m1, n, 2)
        Boxes proven inside the set.
    boundary : numpy.ndarray, shape (m2, n, 2)
        Undetermined boxes (widest side at most ``eps``).
    outside : numpy.ndarray, shape (m3, n, 2)
        Boxes proven disjoint from the set.
    X0 : Box
        The initial box.
    eps : float
        The bisection threshold.

    Attributes
    ----------
    inner, boundary, outside
        ``(m, n, 2)`` box arrays: proven inside, undetermined (width <= eps), proven outside.
        codac calls them ``inner``, ``bound`` and ``outer_complem``; codac's ``outer`` is
        ``inner ∪ boundary``.
    X0
        The initial box; ``eps`` the bisection threshold.

    Notes
    -----
    ``inner ⊂ X ⊂ inner ∪ boundary`` [LJMW97, eq. (11)].
    """

    def __init__(self, inner, boundary, outside, X0: Box, eps: float):
        self.inner, self.boundary, self.outside = inner, boundary, outside
        self.X0, self.eps = X0, eps

    @property
    def dim(self) -> int:
        return self.X0.dim

    @property
    def is_empty(self) -> bool:
        """True when the set is proven empty (no inner and no boundary box)."""
        return self.inner.shape[0] == 0 and self.boundary.shape[0] == 0

    def outer(self) -> np.ndarray:
        """Return ``inner ∪ boundary``: boxes whose union contains the set (codac's ``outer``).

        Returns
        -------
        numpy.ndarray, shape (m, n, 2)
            The inner boxes followed by the boundary boxes.
        """
        return np.concatenate([self.inner, self.boundary])

    def volume_bounds(self) -> tuple[float, float]:
        """Bracket the set's volume by ``(vol(inner), vol(inner) + vol(boundary))``.

        Returns
        -------
        lower, upper : float
            Total volume of the inner boxes, and of the inner and boundary boxes.
        """
        v_in = float(box_volumes(self.inner).sum())
        return v_in, v_in + float(box_volumes(self.boundary).sum())

    def hull(self) -> Box | None:
        """Return the smallest box containing ``inner ∪ boundary``.

        Returns
        -------
        Box or None
            The hull of the outer boxes; ``None`` if the set is proven empty.
        """
        if self.is_empty:
            return None
        boxes = self.outer()
        return Box(boxes[:, :, 0].min(axis=0), boxes[:, :, 1].max(axis=0))

    def components(self) -> list[Paving]:
        """Connected components of ``inner ∪ boundary``, largest outer volume first.

        Boxes that touch (share a face, edge or corner) are connected [LJMW97, Sect. 4: the
        components Q1, Q2 are the localization hypotheses]. Each component is a ``Paving``
        with its own inner and boundary boxes (and no outside boxes).

        Returns
        -------
        list of Paving
            One paving per component, sorted by decreasing outer volume.
        """
        boxes = self.outer()
        n_inner = self.inner.shape[0]
        n_comp, labels = connected_components(_touch_graph(boxes), directed=False)
        is_inner = np.arange(boxes.shape[0]) < n_inner
        none = np.empty((0, self.dim, 2))
        parts = [
            Paving(
                boxes[(labels == c) & is_inner],
                boxes[(labels == c) & ~is_inner],
                none,
                self.X0,
                self.eps,
            )
            for c in range(n_comp)
        ]
        return sorted(parts, key=lambda p: -p.volume_bounds()[1])

    def plot(self, ax=None, dims: tuple[int, int] = (0, 1), **kwargs):
        """Draw the paving (or its projection on ``dims``); see :func:`plot_paving`.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; a new figure if None.
        dims : tuple of int
            The two axes drawn.
        **kwargs
            Passed to :func:`~optbound.interval.plot.plot_paving` (``show_outside``).

        Returns
        -------
        matplotlib.axes.Axes
            The axes drawn on.
        """
        from optbound.interval.plot import plot_paving

        return plot_paving(self, ax=ax, dims=dims, **kwargs)

    def __repr__(self) -> str:
        return (
            f"Paving(dim={self.dim}, eps={self.eps}, inner={self.inner.shape[0]}, "
            f"boundary={self.boundary.shape[0]}, outside={self.outside.shape[0]})"
        )


def _touch_graph(boxes: np.ndarray) -> coo_matrix:
    """Sparse adjacency of closed boxes that intersect, by a sweep along the first axis.

    After sorting by lower bound on axis 0, the boxes that can touch box i are the next ones
    whose lower bound does not exceed i's upper bound: a contiguous run found by searchsorted.
    Only those candidate pairs are tested on the other axes.
    """
    m = boxes.shape[0]
    order = np.argsort(boxes[:, 0, 0], kind="stable")
    sorted_boxes = boxes[order]
    starts = sorted_boxes[:, 0, 0]
    ends = np.searchsorted(starts, sorted_boxes[:, 0, 1], side="right")
    counts = np.maximum(ends - np.arange(m) - 1, 0)
    rows, cols = [], []
    first = 0
    while first < m:
        # Take boxes [first, last) whose candidate pairs fit in one chunk (at least one box).
        budget = np.cumsum(counts[first:])
        last = first + max(1, int(np.searchsorted(budget, _PAIR_CHUNK, side="right")))
        i = np.repeat(np.arange(first, last), counts[first:last])
        offsets = np.arange(i.size) - np.repeat(
            np.cumsum(counts[first:last]) - counts[first:last], counts[first:last]
        )
        j = i + 1 + offsets
        a, b = sorted_boxes[i], sorted_boxes[j]
        touch = np.all((b[:, 1:, 0] <= a[:, 1:, 1]) & (a[:, 1:, 0] <= b[:, 1:, 1]), axis=1)
        rows.append(order[i[touch]])
        cols.append(order[j[touch]])
        first = last
    r = np.concatenate(rows) if rows else np.empty(0, int)
    c = np.concatenate(cols) if cols else np.empty(0, int)
    return coo_matrix((np.ones(r.size, dtype=np.int8), (r, c)), shape=(m, m))
