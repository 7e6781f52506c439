"""The exact set LUVIA contracts towards, paved: a yardstick for [GLH12, Algorithm 2].

For robot ``i`` with measurements ``y`` and the other robots' boxes ``[x_l]``, the positions
consistent with one step's data are

    S_i = {x ∈ [x_i] : for every l ≠ i there is an x_l ∈ [x_l] with
           Seg(x, x_l) ∩ E⁻ = ∅ if y_il (visible), Seg(x, x_l) ∩ E⁺ ≠ ∅ if not}

(E⁻ for "visible" and E⁺ for "not visible", as in [GLH12, Props. 15-16]; the robots l are
distinct, so each measurement has its own witness x_l). Algorithm 2 bisects ``[x_i]`` only and
tests every sub-box against the *whole* box ``[x_l]``: a sub-box is refuted only when no
point of ``[x_l]`` is a witness for any of its points. :func:`consistent_paving` also splits
each ``[x_l]`` into a grid of sub-boxes, so it refutes a box as soon as every cell is refuted
and proves a box inner when one cell witnesses all its points. Its inner boxes lie in S_i and
its inner and boundary boxes cover S_i, which brackets the hull of S_i: the best any
contraction that uses only this step's measurements and boxes can return.
"""

from __future__ import annotations

import numpy as np

from optbound.interval import Paving, Tri, pave
from optbound.localization.environment import Environment
from optbound.localization.geometry import as_polygons, segments_meet_polygons
from optbound.localization.visibility import as_boxes


def _cells(box: np.ndarray, split: int) -> np.ndarray:
    """``box`` cut into a ``split`` x ``split`` grid of (split², 2, 2) cells covering it."""
    xs = np.linspace(box[0, 0], box[0, 1], split + 1)
    ys = np.linspace(box[1, 0], box[1, 1], split + 1)
    xs[[0, -1]], ys[[0, -1]] = box[0], box[1]  # the grid covers the box exactly
    gx, gy = np.meshgrid(np.arange(split), np.arange(split), indexing="ij")
    gx, gy = gx.ravel(), gy.ravel()
    return np.stack(
        [np.stack([xs[gx], xs[gx + 1]], -1), np.stack([ys[gy], ys[gy + 1]], -1)], axis=1
    )


def consistent_paving(
    robot: int, y, boxes, env: Environment, eps: float, *, split: int = 8
) -> Paving:
    """Pave the positions of ``robot`` consistent with its measurements (module docstring).

    Parameters
    ----------
    robot, y, boxes, env
        As for :func:`optbound.localization.visibility.luvia` (``y[robot]`` is ignored).
    eps
        Boxes whose widest side is at most ``eps`` (metres) are not bisected further.
    split
        Each other robot's box is cut into ``split`` x ``split`` cells (1: Algorithm 2's test).

    Returns
    -------
    Paving
        ``inner ⊂ S_i ⊂ inner ∪ boundary`` within ``boxes[robot]``.
    """
    b = as_boxes(boxes, "boxes", volume=True)
    m = len(b)
    if isinstance(robot, bool) or not isinstance(robot, int | np.integer) or not 0 <= robot < m:
        raise ValueError(f"robot must be an index in [0, {m}), got {robot!r}")
    y = np.asarray(y)
    if y.dtype != np.bool_ or y.shape != (m,):
        raise ValueError(f"y must be ({m},) booleans, got {y.dtype} {y.shape}")
    if not isinstance(env, Environment):
        raise TypeError(f"env must be an Environment, got {type(env).__name__}")
    if isinstance(split, bool) or not isinstance(split, int) or split < 1:
        raise ValueError(f"split must be a positive integer, got {split!r}")
    inner, outer = as_polygons(env.inner), as_polygons(env.outer)
    others = [(_cells(b[j], split), inner if y[j] else outer, bool(y[j])) for j in range(m)]
    others = [o for j, o in enumerate(others) if j != robot]

    def test(x, yy) -> np.ndarray:
        n = len(x.lo)
        xbox = np.stack([np.stack([x.lo, x.hi], -1), np.stack([yy.lo, yy.hi], -1)], axis=1)
        proven = np.ones(n, dtype=bool)
        refuted = np.zeros(n, dtype=bool)
        for cells, polygons, visible in others:
            c = len(cells)
            meets = segments_meet_polygons(
                np.repeat(xbox, c, axis=0), np.tile(cells, (n, 1, 1)), polygons
            ).reshape(n, c)
            good, bad = (Tri.FALSE, Tri.TRUE) if visible else (Tri.TRUE, Tri.FALSE)
            proven &= np.any(meets == good, axis=1)
            refuted |= np.all(meets == bad, axis=1)
        out = np.full(n, Tri.UNKNOWN, dtype=np.int8)
        out[proven] = Tri.TRUE
        out[refuted] = Tri.FALSE
        return out

    return pave(test, b[robot], eps)


__all__ = ["consistent_paving"]
