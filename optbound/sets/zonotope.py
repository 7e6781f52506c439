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
from optbound.sets.polygon_outline import PolygonOutline
from optbound.sets.zonotope_reduction import generator_budget, reduce_generators


def center_generators(c, G, c_name: str = "c", G_name: str = "G") -> tuple[np.ndarray, np.ndarray]:
    """Validate a centre (n,) and generators (n, m), both finite; return float64 copies.

    Parameters
    ----------
    c : array_like, shape (n,)
        Centre.
    G : array_like, shape (n, m)
        Generators, one per column.
    c_name, G_name : str
        The argument names used in error messages.

    Returns
    -------
    c : np.ndarray, shape (n,)
        Float64 copy of the centre.
    G : np.ndarray, shape (n, m)
        Float64 copy of the generators.

    Raises
    ------
    ValueError
        If an argument is non-finite, empty or the shapes disagree.
    TypeError
        If an argument is complex or not numeric.
    """
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


class Zonotope(PolygonOutline, ConvexSet):
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

    Examples
    --------
    >>> from optbound.interval.tribool import Tri
    >>> from optbound.sets import Zonotope
    >>> Z = Zonotope([0.0, 0.0], [[1.0, 1.0], [0.0, 1.0]])
    >>> Z.contains([[1.5, 0.5], [0.0, 1.5]]).tolist()
    [True, False]
    >>> boxes = [[[0.0, 0.1], [0.0, 0.1]], [[3.0, 4.0], [0.0, 1.0]], [[1.5, 2.5], [0.0, 1.0]]]
    >>> [Tri(t).name for t in Z.tri_contains(boxes)]  # proven inside, disjoint, undecided
    ['TRUE', 'FALSE', 'UNKNOWN']
    >>> Z.volume_bounds()
    (4.0, 4.0)
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
        the box exactly).

        Parameters
        ----------
        box : Box
            A bounded box.

        Returns
        -------
        Zonotope
            An axis-aligned zonotope containing the box.

        Raises
        ------
        TypeError
            If ``box`` is not a Box.
        ValueError
            If ``box`` is unbounded.
        """
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
        :func:`~optbound.sets.zonotope_conversions.ellipsoid_generators`).

        Parameters
        ----------
        E : Ellipsoid
            The ellipsoid enclosed.

        Returns
        -------
        Zonotope
            A parallelotope with E's centre containing E.

        Raises
        ------
        ValueError
            If E is too ill-conditioned for the containment to be proven.
        """
        from optbound.sets.zonotope_conversions import ellipsoid_generators

        return cls(E.center, ellipsoid_generators(E))

    def outer_ellipsoid(self, weights: str = "norms"):
        """An ellipsoid containing the zonotope (certified; ``weights`` ``"norms"``: the
        trace-minimal member, ``"unit"``: ``m G G^T``, the minimum-volume one for a
        parallelotope; see :func:`~optbound.sets.zonotope_conversions.zonotope_ellipsoid_shape`).

        Parameters
        ----------
        weights : {"norms", "unit"}, default "norms"
            The Cauchy-Schwarz weights ``w_i`` of the shape ``(sum w_i) sum g_i g_i^T / w_i``.

        Returns
        -------
        Ellipsoid
            An ellipsoid with the zonotope's centre containing it.

        Raises
        ------
        ValueError
            If the zonotope is flat (generators of rank < n) or ``weights`` is unknown.
        """
        from optbound.sets.ellipsoid import Ellipsoid
        from optbound.sets.zonotope_conversions import zonotope_ellipsoid_shape

        return Ellipsoid(self._c, zonotope_ellipsoid_shape(self._G, weights))

    # ----------------------------------------------------------------- membership
    def contains(self, X, tol: float = 1e-9) -> np.ndarray | bool:
        """Float test of ``x in Z`` per row of ``X`` (use :meth:`tri_contains` for a proof).

        In 2-D with spanning generators: ``|n_k^T (x - c)| <= (1 + tol) sum_j |n_k^T g_j|``
        for every generator normal ``n_k`` (the zonotope's facets), vectorized. Otherwise
        ``min ||xi||_inf s.t. G xi = x - c`` is at most ``1 + tol`` (one LP per point).

        Parameters
        ----------
        X : array_like, shape (m, n) or (n,)
            Points, one per row; a single point gives a bool.
        tol : float, default 1e-9
            Relative slack on the defining inequality.

        Returns
        -------
        ndarray of bool, shape (m,), or bool
            True where the point is inside (up to ``tol``).

        Raises
        ------
        ValueError
            If ``X`` is non-finite or its dimension is not ``dim``.
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
        :func:`~optbound.sets.zonotope_membership.tri_contains`.

        Parameters
        ----------
        boxes : array_like, shape (m, n, 2)
            Boxes as ``[lo, hi]`` rows per coordinate.

        Returns
        -------
        ndarray of int8, shape (m,)
            ``Tri`` value per box.

        Raises
        ------
        ValueError
            If ``boxes`` is mis-shaped, non-finite or has ``lo > hi``.
        """
        from optbound.sets.zonotope_membership import tri_contains

        return tri_contains(self, boxes)

    def support(self, d) -> np.ndarray | float:
        """Upper bound of ``max d^T x`` per row of ``d``: ``d^T c + ||G^T d||_1`` rounded up.

        Parameters
        ----------
        d : array_like, shape (m, n) or (n,)
            Directions, one per row; a single direction gives a float.

        Returns
        -------
        ndarray, shape (m,), or float
            An upper bound of the support function per direction.

        Raises
        ------
        ValueError
            If ``d`` is non-finite or its dimension is not ``dim``.
        """
        dirs, single = v.points("d", d, self.dim)
        h = matmul(dirs, self._c[:, None]).hi[:, 0]
        h = (point(h) + row_sum_up(magnitude(matmul(dirs, self._G)))).hi
        return float(h[0]) if single else h

    def bounding_box(self) -> Box:
        """The interval hull ``c -+ |G| 1``, rounded outward.

        Returns
        -------
        Box
            A box containing the zonotope.
        """
        from optbound.interval import Interval

        rad = row_sum_up(np.abs(self._G))
        hull = point(self._c) + Interval(-rad, rad)
        return Box(hull.lo, hull.hi)

    # ----------------------------------------------------------------- operations
    def affine_map(self, A, t=None) -> Zonotope:
        """``{A x + t : x in Z}``, any A of shape (p, n); rounding errors become extra
        axis-aligned generators.

        Parameters
        ----------
        A : array_like, shape (p, n)
            Linear map.
        t : array_like, shape (p,), optional
            Translation (zero if omitted).

        Returns
        -------
        Zonotope
            A zonotope containing the exact image.

        Raises
        ------
        ValueError
            If ``A`` or ``t`` is non-finite or mis-shaped.
        """
        A = v.finite_matrix("A", A, (None, self.dim))
        t = None if t is None else v.finite_vector("t", t, A.shape[0])
        c, G, _ = affine_image(self._c, self._G, A, t)
        return Zonotope._compacted(c, G)

    def project(self, dims) -> Zonotope:
        """Coordinates ``dims`` of the zonotope (exact: rows are selected, nothing rounds).

        Parameters
        ----------
        dims : sequence of int
            Distinct coordinate indices to keep.

        Returns
        -------
        Zonotope
            The projection, of dimension ``len(dims)``.

        Raises
        ------
        ValueError
            If ``dims`` is empty, repeats an index or indexes outside ``range(dim)``.
        """
        idx = v.dims_index("dims", dims, self.dim)
        return Zonotope(self._c[idx], self._G[idx])

    def minkowski_sum(self, other):
        """``Z + Y`` for a Zonotope, Box or ConstrainedZonotope ``Y``: generators concatenated
        (a constrained zonotope if ``Y`` is one).

        Parameters
        ----------
        other : Zonotope, Box or ConstrainedZonotope
            The set added, of dimension ``dim`` (a Box must be bounded).

        Returns
        -------
        Zonotope or ConstrainedZonotope
            A set containing the exact sum (the centres' rounding error is an extra generator).

        Raises
        ------
        TypeError
            If ``other`` is of another type.
        ValueError
            If ``other`` has another dimension or is an unbounded Box.
        """
        from optbound.sets.constrained_zonotope import ConstrainedZonotope

        if isinstance(other, ConstrainedZonotope):
            return ConstrainedZonotope.from_zonotope(self).minkowski_sum(other)
        other = as_zonotope("other", other, self.dim)
        c, extra = sum_centers(self._c, other.center)
        return Zonotope._compacted(c, np.hstack([self._G, other.generators, extra]))

    def intersect_strip(self, a, lo, hi):
        """``Z ∩ {x : lo <= a^T x <= hi}`` as a ConstrainedZonotope (see
        :meth:`ConstrainedZonotope.intersect_strip`).

        Parameters
        ----------
        a : array_like, shape (n,)
            Normal of the strip.
        lo, hi : float
            Bounds of ``a^T x``.

        Returns
        -------
        ConstrainedZonotope
            A constrained zonotope containing the exact intersection.

        Raises
        ------
        ValueError
            As :meth:`ConstrainedZonotope.intersect_strip`.
        """
        from optbound.sets.constrained_zonotope import ConstrainedZonotope

        return ConstrainedZonotope.from_zonotope(self).intersect_strip(a, lo, hi)

    def reduce_order(self, order: float, method: str = "girard") -> Zonotope:
        """A zonotope containing Z with at most ``floor(order * n)`` generators (see
        ``optbound.sets.zonotope_reduction``).

        Parameters
        ----------
        order : float
            Generators per dimension allowed, at least 1.
        method : {"girard", "combastel"}, default "girard"
            Which generators are boxed.

        Returns
        -------
        Zonotope
            A zonotope containing Z (Z itself if it already fits).

        Raises
        ------
        ValueError
            If ``order`` is not a finite number >= 1 or ``method`` is unknown.
        """
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

        Parameters
        ----------
        eps : float, optional
            Unused (protocol compatibility).
        max_subsets : int, default 5000
            Largest number of n-subsets of generators summed exactly.

        Returns
        -------
        tuple of float
            ``(lo, hi)`` with ``lo <= volume <= hi``.

        Raises
        ------
        ValueError
            If ``max_subsets`` is not a positive integer.
        """
        from optbound.sets.zonotope_volume import volume_bounds

        if isinstance(max_subsets, bool) or not isinstance(max_subsets, int) or max_subsets < 1:
            raise ValueError(f"max_subsets must be a positive integer, got {max_subsets!r}")
        return volume_bounds(self._G, max_subsets)

    # ----------------------------------------------------------------- plotting
    def vertices(self) -> np.ndarray:
        """Vertices of a 2-D zonotope in counter-clockwise order (float, for plotting).

        The polygon's edges are the generators sorted by angle, each used twice.

        Returns
        -------
        ndarray, shape (k, 2)
            The vertices (the centre alone if there is no non-zero generator).

        Raises
        ------
        ValueError
            If the zonotope is not 2-D.
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


def as_zonotope(name: str, Y, dim: int) -> Zonotope:
    """``Y`` (a Zonotope or a bounded Box) as a Zonotope of dimension ``dim``.

    Parameters
    ----------
    name : str
        The argument name used in error messages.
    Y : Zonotope or Box
        The set converted.
    dim : int
        The dimension required.

    Returns
    -------
    Zonotope
        ``Y`` itself, or the zonotope of the box.

    Raises
    ------
    TypeError
        If ``Y`` is neither a Zonotope nor a Box.
    ValueError
        If ``Y`` has another dimension or is an unbounded Box.
    """
    if isinstance(Y, Box):
        Y = Zonotope.from_box(Y)
    if not isinstance(Y, Zonotope):
        raise TypeError(f"{name} must be a Zonotope or a Box, got {type(Y).__name__}")
    if Y.dim != dim:
        raise ValueError(f"{name} must have dimension {dim}, got {Y.dim}")
    return Y
