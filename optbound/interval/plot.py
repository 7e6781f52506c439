"""Matplotlib drawing of pavings: 2-D, or the 2-D projection of a higher-dimensional paving."""

from __future__ import annotations

import numpy as np

#: Colours in the usual SIVIA figures [LJMW97, Fig. 6]: inner, boundary, outside.
COLORS = {"inner": "#d62728", "boundary": "#ffd92f", "outside": "#9ecae1"}


def _rectangles(boxes: np.ndarray, dims) -> np.ndarray:
    """Corner polygons ``(m, 4, 2)`` of the boxes projected on ``dims``."""
    (x0, x1), (y0, y1) = boxes[:, dims[0]].T, boxes[:, dims[1]].T
    return np.stack(
        [
            np.stack([x0, y0], -1),
            np.stack([x1, y0], -1),
            np.stack([x1, y1], -1),
            np.stack([x0, y1], -1),
        ],
        axis=1,
    )


def plot_paving(paving, ax=None, dims: tuple[int, int] = (0, 1), show_outside: bool | None = None):
    """Draw inner (red), boundary (yellow) and, in 2-D, outside (blue) boxes.

    For ``n > 2`` the boxes are projected on ``dims``; projected outside boxes may overlap the
    projection of the set, so they are hidden by default there.

    Parameters
    ----------
    paving : Paving
        The paving drawn.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure if None.
    dims : tuple of int
        The two axes drawn (projection for ``n > 2``).
    show_outside : bool, optional
        Draw the outside boxes; default only in 2-D.

    Returns
    -------
    matplotlib.axes.Axes
        The axes drawn on.

    Raises
    ------
    ValueError
        If ``dims`` is not two distinct axes of the paving.
    """
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection

    dims = tuple(int(d) for d in dims)
    if len(dims) != 2 or dims[0] == dims[1] or not all(0 <= d < paving.dim for d in dims):
        raise ValueError(f"dims must be two distinct axes in [0, {paving.dim}), got {dims}")
    if show_outside is None:
        show_outside = paving.dim == 2
    if ax is None:
        _, ax = plt.subplots()
    layers = [("outside", paving.outside)] if show_outside else []
    layers += [("boundary", paving.boundary), ("inner", paving.inner)]
    for name, boxes in layers:
        if boxes.shape[0]:
            ax.add_collection(
                PolyCollection(
                    _rectangles(boxes, dims),
                    facecolors=COLORS[name],
                    edgecolors="k",
                    linewidths=0.2,
                    label=name,
                )
            )
    x0 = paving.X0.as_array()
    ax.set_xlim(x0[dims[0]])
    ax.set_ylim(x0[dims[1]])
    ax.set_xlabel(f"x{dims[0]}")
    ax.set_ylabel(f"x{dims[1]}")
    return ax
