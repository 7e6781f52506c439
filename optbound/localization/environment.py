"""An environment known by an inner and an outer characterization, E⁻ ⊂ E ⊂ E⁺ [GLH12, Fig. 2].

The obstacles are closed solid polygons. The visibility test uses E⁻ when a measurement says
"visible" and E⁺ when it says "not visible" [GLH12, Props. 15-16]; both inclusions are checked
in certified arithmetic when the environment is built, so a wrong map cannot silently break
the guarantee.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from optbound.localization.geometry import as_polygons, pack_polygons, polygon_inside

Packed = tuple[np.ndarray, np.ndarray, np.ndarray]


def _contained(small: list[np.ndarray], big: list[np.ndarray], what: str) -> None:
    for j, poly in enumerate(small):
        if not any(polygon_inside(poly, other) for other in big):
            raise ValueError(
                f"{what}: polygon {j} is not (provably) inside the interior of any polygon of "
                "the larger set; E⁻ ⊂ E ⊂ E⁺ must hold polygon by polygon"
            )


@dataclass(frozen=True)
class Environment:
    """Inner and outer characterizations ``inner`` = E⁻ and ``outer`` = E⁺ of the obstacles.

    Parameters
    ----------
    inner, outer
        Lists of polygons ((k, 2) vertex arrays). ``inner`` may be empty [GLH12, Fig. 2];
        each inner polygon must lie in the interior of an outer one.
    exact
        Optional exact map E (used by simulations to generate measurements); when given, each
        inner polygon must lie inside an exact one and each exact one inside an outer one.

    Raises
    ------
    ValueError
        If a polygon is malformed or an inclusion E⁻ ⊂ E⁺ (E⁻ ⊂ E ⊂ E⁺) cannot be proven.
    """

    inner: list[np.ndarray]
    outer: list[np.ndarray]
    exact: list[np.ndarray] | None = None
    packed_inner: Packed = field(init=False, repr=False)
    packed_outer: Packed = field(init=False, repr=False)

    def __post_init__(self) -> None:
        inner, outer = as_polygons(self.inner, "inner"), as_polygons(self.outer, "outer")
        object.__setattr__(self, "inner", inner)
        object.__setattr__(self, "outer", outer)
        if self.exact is None:
            _contained(inner, outer, "E⁻ ⊄ E⁺")
        else:
            exact = as_polygons(self.exact, "exact")
            object.__setattr__(self, "exact", exact)
            _contained(inner, exact, "E⁻ ⊄ E")
            _contained(exact, outer, "E ⊄ E⁺")
        object.__setattr__(self, "packed_inner", pack_polygons(inner))
        object.__setattr__(self, "packed_outer", pack_polygons(outer))

    @classmethod
    def from_polygons(cls, polygons, margin: float) -> Environment:
        """Build E⁻ and E⁺ of an exact map of convex polygons, shrunk and grown by ``margin``.

        Each edge line is moved by ``margin`` (outward for E⁺, inward for E⁻) and consecutive
        lines are intersected, so E⁺ contains every point within ``margin`` of E. E⁻ is the
        erosion of E by a disc of radius ``margin`` (the intersection of the inward-moved
        half-planes, edges that vanish dropped), so it contains every point at depth
        ``margin`` in E. An obstacle whose erosion is empty, or too thin to certify inside E,
        is left out of E⁻ (E⁻ may be empty [GLH12, Fig. 2]; a smaller inner set is the safe
        side). The inclusions are then checked exactly.

        Parameters
        ----------
        polygons : list of array_like
            The exact obstacles E, convex polygons ((k, 2) vertex arrays, either orientation).
        margin : float
            Distance (> 0) by which E is grown into E⁺ and shrunk into E⁻.

        Returns
        -------
        Environment
            ``inner`` = E⁻, ``outer`` = E⁺ and ``exact`` = E (counter-clockwise).

        Raises
        ------
        ValueError
            For a non-positive or non-finite ``margin``, a malformed or non-convex polygon, or
            an inclusion E⁻ ⊂ E ⊂ E⁺ that cannot be proven.
        TypeError
            If ``polygons`` is not a list or tuple.
        """
        if not isinstance(margin, int | float) or not np.isfinite(margin) or margin <= 0:
            raise ValueError(f"margin must be a positive finite number, got {margin!r}")
        exact = [_counter_clockwise(p, j) for j, p in enumerate(as_polygons(polygons))]
        inner = [q for q in (_erode(p, float(margin)) for p in exact) if q is not None]
        return cls(inner, [_offset(p, float(margin)) for p in exact], exact)


def _cross(poly: np.ndarray) -> np.ndarray:
    """z-component of consecutive edge cross products (positive at a left turn)."""
    d = np.roll(poly, -1, axis=0) - poly
    return d[:, 0] * np.roll(d[:, 1], -1) - d[:, 1] * np.roll(d[:, 0], -1)


def _counter_clockwise(poly: np.ndarray, j: int) -> np.ndarray:
    turns = _cross(poly)
    if np.all(turns < 0):
        return poly[::-1].copy()
    if not np.all(turns > 0):
        raise ValueError(f"polygons[{j}] must be strictly convex (Environment.from_polygons)")
    return poly


def _offset(poly: np.ndarray, d: float) -> np.ndarray:
    """Move each edge line of a counter-clockwise convex polygon outward by ``d`` > 0."""
    n, c = _edge_lines(poly, d)
    n0, c0 = np.roll(n, 1, axis=0), np.roll(c, 1, axis=0)  # previous edge's line
    det = n0[:, 0] * n[:, 1] - n0[:, 1] * n[:, 0]
    x = (c0 * n[:, 1] - n0[:, 1] * c) / det
    y = (n0[:, 0] * c - c0 * n[:, 0]) / det
    return np.column_stack([x, y])


def _edge_lines(poly: np.ndarray, d: float) -> tuple[np.ndarray, np.ndarray]:
    """Unit outward normals ``n`` and offsets ``c`` of the edge lines n . x = c moved by ``d``."""
    a, b = poly, np.roll(poly, -1, axis=0)
    t = (b - a) / np.linalg.norm(b - a, axis=1)[:, None]
    n = np.column_stack([t[:, 1], -t[:, 0]])  # outward normal of a CCW polygon
    return n, np.einsum("ij,ij->i", n, a) + d


def _erode(poly: np.ndarray, r: float) -> np.ndarray | None:
    """The points at depth >= ``r`` in a counter-clockwise convex polygon, or None.

    That set is the intersection of the half-planes n_i . x <= c_i - r. Each moved edge line
    is clipped by all the other half-planes; an edge survives if a piece of positive length
    is left, and the surviving edges' start points, in edge order, are the vertices. None when
    nothing (or no polygon that is certainly inside ``poly``) is left: leaving an obstacle out
    of the inner set E⁻ is the safe side.
    """
    n, c = _edge_lines(poly, -r)
    t = np.column_stack([-n[:, 1], n[:, 0]])  # edge directions
    p = poly - r * n  # a point on each moved line
    slack = c[None, :] - p @ n.T  # slack[i, j]: constraint j at line i's point
    rate = t @ n.T  # rate[i, j]: d(n_j . x)/ds along line i
    np.fill_diagonal(rate, 0.0)
    np.fill_diagonal(slack, 0.0)
    if np.any((rate == 0) & (slack < 0)):
        return None  # a parallel opposite side is nearer than 2 r
    with np.errstate(divide="ignore", invalid="ignore"):
        bound = slack / rate
    s_lo = np.max(np.where(rate < 0, bound, -np.inf), axis=1)
    s_hi = np.min(np.where(rate > 0, bound, np.inf), axis=1)
    scale = np.abs(poly).max() + r
    keep = s_hi - s_lo > 1e-9 * scale
    if np.count_nonzero(keep) < 3:
        return None
    out = p[keep] + s_lo[keep, None] * t[keep]
    if not np.all(_cross(out) > 0) or not polygon_inside(out, poly):
        return None
    return out


__all__ = ["Environment"]
