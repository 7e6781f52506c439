"""Zonotopes ``{c + G xi : ||xi||_inf <= 1}`` (Kühn 1998; Girard 2005; Alamo et al. 2005).

Every operation that returns a set is *guaranteed*: its floats, read as exact numbers, give a
set containing the exact result. Rounding errors of products and sums are moved into extra
axis-aligned generators (see ``optbound.sets.certified``); the support function and the
bounding box are outward-rounded. ``contains`` is a float test (a linear program per point,
with the relative slack ``tol``); :meth:`Zonotope.tri_contains` is the proven one.
"""

from __future__ import annotations

import numpy as np

from optbound._core import Box, real_array
from optbound._core import validate as v
from optbound.sets.base import ConvexSet
from optbound.sets.certified import (
    affine_image,
    compact,
    magnitude,
    matmul,
    point,
    row_sum_up,
    split,
    sum_centers,
)
from optbound.sets.zonotope_reduction import generator_budget, reduce_generators


def center_generators(c, G, c_name: str = "c", G_name: str = "G") -> tuple[np.ndarray, np.ndarray]:
    """Validate a centre (n,) and generators (n, m), both finite; return float64 copies."""
    c = real_array(c_name, c)
    if c.ndim != 1 or c.size == 0:
        raise ValueError(f"{c_name} must be a non-empty 1-D vector, got shape {c.shape}")
    n = c.shape[0]
    G = real_array(G_name, G)
    if G.ndim != 2 or G.shape[0] != n:
        raise ValueError(f"{G_name} must have shape ({n}, m) (n = len({c_name})), got {G.shape}")
    if not np.isfinite(c).all():
        raise ValueError(f"{c_name} must be finite")
    if not np.isfinite(G).all():
        raise ValueError(f"{G_name} must be finite")
    return c.copy(), G.copy()


class Zonotope(ConvexSet):
    """Zonotope ``Z = <c, G> = {c + G xi : ||xi||_inf <= 1}``.

    Parameters
    ----------
    c : array_like, shape (n,)
        Centre.
    G : array_like, shape (n, m)
        Generators, one per column; ``m = 0`` (a point) is allowed.

    Raises
    ------
    ValueError
        If an argument is non-finite or the shapes disagree.
    TypeError
        If an argument is complex or not numeric.
    """

    def __init__(self, c, G):
        self._c, self._G = center_generators(c, G)
        self._c.setflags(write=False)
        self._G.setflags(write=False)

    # ----------------------------------------------------------------- attributes
    @property
    def center(self) -> np.ndarray:
        return self._c

    @property
    def generators(self) -> np.ndarray:
        return self._G

    @property
    def dim(self) -> int:
        return self._c.shape[0]

    @property
    def n_generators(self) -> int:
        return self._G.shape[1]

    @property
    def order(self) -> float:
        """``m / n``, generators per dimension."""
        return self.n_generators / self.dim

    def __repr__(self) -> str:
        return f"Zonotope(c={self._c.tolist()}, G={self._G.tolist()})"

    # ------------------------------------------------------------- construction
    @classmethod
    def _compacted(cls, c: np.ndarray, G: np.ndarray) -> Zonotope:
        """An operation's result, its free axis-aligned generators merged (``compact``)."""
        return cls(c, compact(G, np.zeros((0, G.shape[1])))[0])

    @classmethod
    def from_box(cls, box: Box) -> Zonotope:
        """The zonotope ``<mid, diag(rad)>`` of a bounded box (radii rounded up: it contains
        the box exactly)."""
        if not isinstance(box, Box):
            raise TypeError(f"box must be a Box, got {type(box).__name__}")
        if not box.is_bounded:
            raise ValueError("box must be bounded to be a zonotope")
        from optbound.interval import Interval

        c, r = split(Interval(box.lo, box.hi))
        return cls(c, np.diag(r))

    @classmethod
    def from_ellipsoid(cls, E) -> Zonotope:
        """A parallelotope containing the ellipsoid ``E`` (certified; see
        :func:`~optbound.sets.zonotope_conversions.ellipsoid_generators`)."""
        from optbound.sets.zonotope_conversions import ellipsoid_generators

        return cls(E.center, ellipsoid_generators(E))

    def outer_ellipsoid(self, weights: str = "norms"):
        """An ellipsoid containing the zonotope (certified; ``weights`` ``"norms"``: the
        trace-minimal member, ``"unit"``: ``m G G^T``, the minimum-volume one for a
        parallelotope; see :func:`~optbound.sets.zonotope_conversions.zonotope_ellipsoid_shape`)."""
        from optbound.sets.ellipsoid import Ellipsoid
        from optbound.sets.zonotope_conversions import zonotope_ellipsoid_shape

        return Ellipsoid(self._c, zonotope_ellipsoid_shape(self._G, weights))

    # ----------------------------------------------------------------- membership
    def contains(self, X, tol: float = 1e-9) -> np.ndarray | bool:
        """Float test of ``x in Z`` per row of ``X`` (use :meth:`tri_contains` for a proof).

        In 2-D with spanning generators: ``|n_k^T (x - c)| <= (1 + tol) sum_j |n_k^T g_j|``
        for every generator normal ``n_k`` (the zonotope's facets), vectorized. Otherwise
        ``min ||xi||_inf s.t. G xi = x - c`` is at most ``1 + tol`` (one LP per point).
        """
        from optbound.sets.zonotope_membership import lp_contains, slab_contains

        pts, single = v.points("X", X, self.dim)
        inside = slab_contains(self._c, self._G, pts, tol)
        if inside is None:
            inside = lp_contains(
                self._c, self._G, np.zeros((0, self.n_generators)), np.zeros(0), pts, tol
            )
        return bool(inside[0]) if single else inside

    def tri_contains(self, boxes) -> np.ndarray:
        """Three-valued membership of boxes (m, n, 2): TRUE (box inside), FALSE (disjoint),
        UNKNOWN; proven with outward rounding, see
        :func:`~optbound.sets.zonotope_membership.tri_contains`."""
        from optbound.sets.zonotope_membership import tri_contains

        return tri_contains(self, boxes)

    def support(self, d) -> np.ndarray | float:
        """Upper bound of ``max d^T x`` per row of ``d``: ``d^T c + ||G^T d||_1`` rounded up."""
        dirs, single = v.points("d", d, self.dim)
        h = matmul(dirs, self._c[:, None]).hi[:, 0]
        h = (point(h) + row_sum_up(magnitude(matmul(dirs, self._G)))).hi
        return float(h[0]) if single else h

    def bounding_box(self) -> Box:
        """The interval hull ``c -+ |G| 1``, rounded outward."""
        from optbound.interval import Interval

        rad = row_sum_up(np.abs(self._G))
        hull = point(self._c) + Interval(-rad, rad)
        return Box(hull.lo, hull.hi)

    # ----------------------------------------------------------------- operations
    def affine_map(self, A, t=None) -> Zonotope:
        """``{A x + t : x in Z}``, any A of shape (p, n); rounding errors become extra
        axis-aligned generators."""
        A = v.finite_matrix("A", A, (None, self.dim))
        t = None if t is None else v.finite_vector("t", t, A.shape[0])
        c, G, _ = affine_image(self._c, self._G, A, t)
        return Zonotope._compacted(c, G)

    def project(self, dims) -> Zonotope:
        """Coordinates ``dims`` of the zonotope (exact: rows are selected, nothing rounds)."""
        idx = v.dims_index("dims", dims, self.dim)
        return Zonotope(self._c[idx], self._G[idx])

    def minkowski_sum(self, other):
        """``Z + Y`` for a Zonotope, Box or ConstrainedZonotope ``Y``: generators concatenated
        (a constrained zonotope if ``Y`` is one)."""
        from optbound.sets.constrained_zonotope import ConstrainedZonotope

        if isinstance(other, ConstrainedZonotope):
            return ConstrainedZonotope.from_zonotope(self).minkowski_sum(other)
        other = as_zonotope("other", other, self.dim)
        c, extra = sum_centers(self._c, other.center)
        return Zonotope._compacted(c, np.hstack([self._G, other.generators, extra]))

    def intersect_strip(self, a, lo, hi):
        """``Z ∩ {x : lo <= a^T x <= hi}`` as a ConstrainedZonotope (see
        :meth:`ConstrainedZonotope.intersect_strip`)."""
        from optbound.sets.constrained_zonotope import ConstrainedZonotope

        return ConstrainedZonotope.from_zonotope(self).intersect_strip(a, lo, hi)

    def reduce_order(self, order: float, method: str = "girard") -> Zonotope:
        """A zonotope containing Z with at most ``floor(order * n)`` generators (see
        ``optbound.sets.zonotope_reduction``)."""
        budget = generator_budget(order, self.dim)
        return Zonotope(self._c, reduce_generators(self._G, budget, method))

    # --------------------------------------------------------------------- size
    def volume_bounds(
        self, eps: float | None = None, max_subsets: int = 5000
    ) -> tuple[float, float]:
        """Certified bracket ``lo <= volume <= hi`` (see
        :func:`~optbound.sets.zonotope_volume.volume_bounds`).

        ``eps`` (the ``VolumeBracket`` protocol's resolution) is unused: the bracket is exact
        to one float each side when at most ``max_subsets`` n-subsets of generators exist,
        else the stated sub-zonotope / parallelotope bracket.
        """
        from optbound.sets.zonotope_volume import volume_bounds

        if isinstance(max_subsets, bool) or not isinstance(max_subsets, int) or max_subsets < 1:
            raise ValueError(f"max_subsets must be a positive integer, got {max_subsets!r}")
        return volume_bounds(self._G, max_subsets)

    # ----------------------------------------------------------------- plotting
    def vertices(self) -> np.ndarray:
        """Vertices of a 2-D zonotope in counter-clockwise order (float, for plotting).

        The polygon's edges are the generators sorted by angle, each used twice.
        """
        if self.dim != 2:
            raise ValueError(f"vertices() is for 2-D zonotopes, this one has dim {self.dim}")
        G = self._G[:, np.any(self._G != 0, axis=0)]
        if G.shape[1] == 0:
            return self._c[None, :].copy()
        G = np.where((G[1] < 0) | ((G[1] == 0) & (G[0] < 0)), -G, G)  # angles in [0, pi)
        G = G[:, np.argsort(np.arctan2(G[1], G[0]), kind="stable")]
        start = self._c - G.sum(axis=1)
        edges = np.hstack([G, -G]) * 2.0
        return start + np.vstack([np.zeros(2), np.cumsum(edges.T, axis=0)[:-1]])

    def boundary(self, resolution: int = 0) -> np.ndarray:
        """The closed polygon of :meth:`vertices` (first vertex repeated), for the plots'
        ``Outlined`` protocol; ``resolution`` is unused (the outline is the exact polygon)."""
        V = self.vertices()
        return np.vstack([V, V[:1]])

    def plot(self, ax=None, dims: tuple[int, int] = (0, 1), **kwargs):
        """Draw the projection on ``dims`` as a polygon outline (matplotlib ``ax.fill``
        keywords; ``fill=False`` unless given)."""
        from optbound.sets.zonotope_membership import plot_polygon

        return plot_polygon(self.project(dims).vertices(), ax, kwargs)


def as_zonotope(name: str, Y, dim: int) -> Zonotope:
    """``Y`` (a Zonotope or a bounded Box) as a Zonotope of dimension ``dim``."""
    if isinstance(Y, Box):
        Y = Zonotope.from_box(Y)
    if not isinstance(Y, Zonotope):
        raise TypeError(f"{name} must be a Zonotope or a Box, got {type(Y).__name__}")
    if Y.dim != dim:
        raise ValueError(f"{name} must have dimension {dim}, got {Y.dim}")
    return Y
