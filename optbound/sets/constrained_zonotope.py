"""Constrained zonotopes ``{c + G xi : ||xi||_inf <= 1, A xi = b}``.

Scott, Raimondo, Marseglia & Braatz, *Constrained zonotopes: a new tool for set-based
estimation and fault detection*, Automatica 69 (2016) — "[SRMB]" below (Def. 1). Every
convex polytope is one, and the operations an observer needs (affine maps, Minkowski sums,
intersections with strips and with the preimage of another set) are exact in this
representation, so the exact set of a linear system with polytopic noise is a constrained
zonotope.

As for :class:`~optbound.sets.Zonotope`, every returned set is *guaranteed* in floating
point: products and sums are enclosed in interval arithmetic, centre/generator errors become
extra axis-aligned generators, constraint errors become slack generators (one per affected
row), see ``optbound.sets.certified``. Support values and the bounding box come from HiGHS
LPs certified by weak duality (:func:`~optbound.sets.certified.max_bound`).
"""

from __future__ import annotations

import numpy as np

from optbound._core import Box, box_array, real_array
from optbound._core import validate as v
from optbound._core.linear_program import solve_lp
from optbound.sets.base import ConvexSet, EmptySetError
from optbound.sets.certified import (
    affine_image,
    compact,
    enclose,
    error_generators,
    matmul,
    max_bound,
    point,
    proven_empty,
    relax_rows,
    split,
    sum_centers,
)
from optbound.sets.polygon_outline import PolygonOutline
from optbound.sets.zonotope import Zonotope, as_zonotope, center_generators
from optbound.sets.zonotope_reduction import generator_budget, reduce_generators


def _constraints(A, b, m: int) -> tuple[np.ndarray, np.ndarray]:
    A = real_array("A", A)
    b = np.atleast_1d(real_array("b", b)) if np.ndim(b) == 0 else real_array("b", b)
    if A.ndim != 2 or A.shape[1] != m:
        raise ValueError(f"A must have shape (nc, {m}) (m = number of generators), got {A.shape}")
    if b.shape != (A.shape[0],):
        raise ValueError(
            f"b must have shape ({A.shape[0]},) (one entry per row of A), got {b.shape}"
        )
    if not np.isfinite(A).all():
        raise ValueError("A must be finite")
    if not np.isfinite(b).all():
        raise ValueError("b must be finite")
    return A.copy(), b.copy()


def _zeros(rows: int, cols: int) -> np.ndarray:
    return np.zeros((rows, cols))


class ConstrainedZonotope(PolygonOutline, ConvexSet):
    """Constrained zonotope ``{c + G xi : ||xi||_inf <= 1, A xi = b}`` [SRMB, Def. 1].

    Parameters
    ----------
    c : array_like, shape (n,)
        Centre.
    G : array_like, shape (n, m)
        Generators.
    A : array_like, shape (nc, m)
        Constraint matrix (``nc = 0``, shape (0, m), is a zonotope).
    b : array_like, shape (nc,)
        Constraint right-hand side.

    Raises
    ------
    ValueError
        If an argument is non-finite or the shapes disagree (the message names it).
    TypeError
        If an argument is complex or not numeric.

    Examples
    --------
    The diagonal segment of the square ``[-1, 1]^2`` (constraint ``xi_1 + xi_2 = 0``), then
    the square cut by the strip ``|x_1 + x_2| <= 1``:

    >>> from optbound.sets import ConstrainedZonotope, Zonotope
    >>> S = ConstrainedZonotope([0.0, 0.0], [[1.0, 0.0], [0.0, 1.0]], [[1.0, 1.0]], [0.0])
    >>> S.contains([[0.5, -0.5], [0.5, 0.5]]).tolist()
    [True, False]
    >>> square = ConstrainedZonotope.from_zonotope(Zonotope([0.0, 0.0], [[1.0, 0.0], [0.0, 1.0]]))
    >>> cut = square.intersect_strip([1.0, 1.0], -1.0, 1.0)
    >>> cut.n_constraints
    1
    >>> cut.contains([[0.5, 0.4], [0.9, 0.9]]).tolist()
    [True, False]
    """

    def __init__(self, c, G, A, b):
        self._c, self._G = center_generators(c, G)
        self._A, self._b = _constraints(A, b, self._G.shape[1])
        for arr in (self._c, self._G, self._A, self._b):
            arr.setflags(write=False)
        self._polygons = None  # 2-D certified polygons, built on first use
        self._vertex_cache = None  # 2-D vertex search (vertices, LP solutions), on first use

    @classmethod
    def _compacted(cls, c, G, A, b) -> ConstrainedZonotope:
        """An operation's result, its free axis-aligned generators merged (``compact``)."""
        return cls(c, *compact(G, A), b)

    @classmethod
    def from_zonotope(cls, Z: Zonotope) -> ConstrainedZonotope:
        """The zonotope ``Z`` without constraints (a Box is converted first).

        Parameters
        ----------
        Z : Zonotope or Box
            The set (a Box must be bounded).

        Returns
        -------
        ConstrainedZonotope
            The same set with no constraint rows.

        Raises
        ------
        TypeError
            If ``Z`` is neither a Zonotope nor a Box.
        ValueError
            If ``Z`` is an unbounded Box.
        """
        if isinstance(Z, Box):
            Z = Zonotope.from_box(Z)
        if not isinstance(Z, Zonotope):
            raise TypeError(f"Z must be a Zonotope or a Box, got {type(Z).__name__}")
        return cls(Z.center, Z.generators, _zeros(0, Z.n_generators), np.zeros(0))

    # ----------------------------------------------------------------- attributes
    @property
    def center(self) -> np.ndarray:
        return self._c

    @property
    def generators(self) -> np.ndarray:
        return self._G

    @property
    def A(self) -> np.ndarray:
        return self._A

    @property
    def b(self) -> np.ndarray:
        return self._b

    @property
    def dim(self) -> int:
        return self._c.shape[0]

    @property
    def n_generators(self) -> int:
        return self._G.shape[1]

    @property
    def n_constraints(self) -> int:
        return self._A.shape[0]

    def __repr__(self) -> str:
        return (
            f"ConstrainedZonotope(c={self._c.tolist()}, G={self._G.tolist()}, "
            f"A={self._A.tolist()}, b={self._b.tolist()})"
        )

    # ----------------------------------------------------------------- membership
    def contains(self, X, tol: float = 1e-9) -> np.ndarray | bool:
        """Float test per row of ``X``: ``min ||xi||_inf s.t. G xi = x - c, A xi = b`` is at
        most ``1 + tol`` (one LP per point). In 2-D a point inside the certified inner polygon
        (:meth:`tri_contains`) is answered True without an LP, and with ``tol == 0`` a point
        beyond the certified outer polygon False.

        Parameters
        ----------
        X : array_like, shape (m, n) or (n,)
            Points, one per row; a single point gives a bool.
        tol : float, default 1e-9
            Relative slack on the LP's optimum.

        Returns
        -------
        ndarray of bool, shape (m,), or bool
            True where the point is inside (up to ``tol``).

        Raises
        ------
        ValueError
            If ``X`` is non-finite or its dimension is not ``dim``.
        """
        from optbound.interval.tribool import Tri
        from optbound.sets.zonotope_membership import lp_contains

        pts, single = v.points("X", X, self.dim)
        inside = np.zeros(pts.shape[0], dtype=bool)
        todo = np.ones(pts.shape[0], dtype=bool)
        if self.dim == 2 and (polygons := self._certified_polygons()) is not None:
            tri = polygons.tri(np.stack([pts, pts], axis=2))
            inside = tri == Tri.TRUE
            todo = (tri == Tri.UNKNOWN) if tol == 0 else ~inside
        if todo.any():
            inside[todo] = lp_contains(self._c, self._G, self._A, self._b, pts[todo], tol)
        return bool(inside[0]) if single else inside

    def is_empty(self) -> bool:
        """True only if the set is *proven* empty (a Farkas certificate checked with outward
        rounding, see :func:`~optbound.sets.certified.proven_empty`); False means "not
        proven empty", the safe answer for an outer bound.

        Returns
        -------
        bool
            True if emptiness is proven.
        """
        return proven_empty(self._A, self._b)

    def support(self, d) -> np.ndarray | float:
        """Certified upper bound of ``max d^T x`` per row of ``d`` (``-inf`` if proven
        empty): ``d^T c`` plus the LP bound of :func:`~optbound.sets.certified.max_bound`.

        Parameters
        ----------
        d : array_like, shape (m, n) or (n,)
            Directions, one per row; a single direction gives a float.

        Returns
        -------
        ndarray, shape (m,), or float
            An upper bound of the support function per direction (``-inf`` if proven empty).

        Raises
        ------
        ValueError
            If ``d`` is non-finite or its dimension is not ``dim``.
        """
        dirs, single = v.points("d", d, self.dim)
        h = np.empty(dirs.shape[0])
        for k, dk in enumerate(dirs):
            f_iv = matmul(dk[None, :], self._G)[0]
            bound = max_bound(f_iv, self._A, self._b)
            center = matmul(dk[None, :], self._c[:, None]).hi[0, 0]
            h[k] = bound if bound == -np.inf else float((point(center) + bound).hi)
        return float(h[0]) if single else h

    def bounding_box(self) -> Box:
        """Guaranteed interval hull from 2n certified LP bounds.

        Returns
        -------
        Box
            A box containing the set.

        Raises
        ------
        EmptySetError
            If the set is proven empty (it has no bounding box).
        """
        eye = np.eye(self.dim)
        hi = self.support(eye)
        lo = -self.support(-eye)
        if np.any(hi == -np.inf) or np.any(lo == np.inf):
            raise EmptySetError("the constrained zonotope is empty: it has no bounding box")
        return Box(np.minimum(lo, hi), np.maximum(lo, hi))

    def tri_contains(self, boxes) -> np.ndarray:
        """Tri values per box (m, n, 2).

        In 2-D, from the certified inner and outer polygons
        (:mod:`optbound.sets.constrained_zonotope_polygon`, built once per set): TRUE when
        the box is inside the inner one, FALSE when it is beyond an edge of the outer one.
        Otherwise FALSE when ``box ∩ CZ`` is proven empty (the box's bounding-box test, else
        a Farkas certificate of the generalized intersection, one LP per box); TRUE is not
        proven there, so the others are UNKNOWN.

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
        from optbound.interval.tribool import Tri

        B = box_array("boxes", boxes, self.dim)
        if self.dim == 2 and (polygons := self._certified_polygons()) is not None:
            return polygons.tri(B)
        out = np.full(B.shape[0], Tri.UNKNOWN, dtype=np.int8)
        try:
            hull = self.bounding_box()
        except EmptySetError:
            return np.full(B.shape[0], Tri.FALSE, dtype=np.int8)
        apart = np.any((B[:, :, 1] < hull.lo) | (B[:, :, 0] > hull.hi), axis=1)
        out[apart] = Tri.FALSE
        for k in np.flatnonzero(~apart):
            if self.generalized_intersection(Box(B[k, :, 0], B[k, :, 1])).is_empty():
                out[k] = Tri.FALSE
        return out

    def volume_bounds(self, eps: float | None = None) -> tuple[float, float]:
        """Certified bracket ``lo <= volume <= hi``.

        In 2-D the areas of the certified inner and outer polygons
        (:mod:`optbound.sets.constrained_zonotope_polygon`); a flat or empty 2-D set gives
        ``(0, outer area)`` or ``(0, 0)``. In other dimensions ``(0, volume of the certified
        interval hull)``: a valid but loose bracket. ``eps`` (the ``VolumeBracket``
        protocol's resolution) is unused.

        Parameters
        ----------
        eps : float, optional
            Unused (protocol compatibility).

        Returns
        -------
        tuple of float
            ``(lo, hi)`` with ``lo <= volume <= hi``.
        """
        from fractions import Fraction

        from optbound.sets.constrained_zonotope_polygon import round_up

        if self.dim == 2:
            polygons = self._certified_polygons()
            if polygons is not None:
                return polygons.area_bracket()
        try:
            hull = self.bounding_box()
        except EmptySetError:
            return 0.0, 0.0
        volume = Fraction(1)
        for lo, hi in zip(hull.lo, hull.hi, strict=True):
            volume *= Fraction(float(hi)) - Fraction(float(lo))
        return 0.0, round_up(volume)

    def _certified_polygons(self):
        """The 2-D certified polygons (cached), or None for a flat or empty set."""
        from optbound.sets.constrained_zonotope_polygon import certified_polygons

        if self._polygons is None:
            try:
                self._polygons = certified_polygons(self)
            except ValueError:  # flat or empty: the LP tests remain
                self._polygons = False
        return self._polygons or None

    # ----------------------------------------------------------------- operations
    def affine_map(self, A, t=None) -> ConstrainedZonotope:
        """``{A x + t : x in CZ}`` [SRMB, Prop. 1, eq. (5)] for any A of shape (p, n).

        Parameters
        ----------
        A : array_like, shape (p, n)
            Linear map.
        t : array_like, shape (p,), optional
            Translation (zero if omitted).

        Returns
        -------
        ConstrainedZonotope
            A set containing the exact image.

        Raises
        ------
        ValueError
            If ``A`` or ``t`` is non-finite or mis-shaped.
        """
        A = v.finite_matrix("A", A, (None, self.dim))
        t = None if t is None else v.finite_vector("t", t, A.shape[0])
        c, G, extra = affine_image(self._c, self._G, A, t)
        return ConstrainedZonotope._compacted(
            c, G, np.hstack([self._A, _zeros(self.n_constraints, extra)]), self._b
        )

    def project(self, dims) -> ConstrainedZonotope:
        """Coordinates ``dims`` (exact: rows of c and G are selected).

        Parameters
        ----------
        dims : sequence of int
            Distinct coordinate indices to keep.

        Returns
        -------
        ConstrainedZonotope
            The projection, of dimension ``len(dims)``.

        Raises
        ------
        ValueError
            If ``dims`` is empty, repeats an index or indexes outside ``range(dim)``.
        """
        idx = v.dims_index("dims", dims, self.dim)
        return ConstrainedZonotope(self._c[idx], self._G[idx], self._A, self._b)

    def minkowski_sum(self, other) -> ConstrainedZonotope:
        """``CZ + Y`` for a ConstrainedZonotope, Zonotope or Box Y [SRMB, Prop. 1, eq. (6)].

        Parameters
        ----------
        other : ConstrainedZonotope, Zonotope or Box
            The set added, of dimension ``dim`` (a Box must be bounded).

        Returns
        -------
        ConstrainedZonotope
            A set containing the exact sum.

        Raises
        ------
        TypeError
            If ``other`` is of another type.
        ValueError
            If ``other`` has another dimension or is an unbounded Box.
        """
        from scipy.linalg import block_diag

        Y = _as_cz("other", other, self.dim)
        c, extra = sum_centers(self._c, Y.center)
        k = extra.shape[1]
        return ConstrainedZonotope._compacted(
            c,
            np.hstack([self._G, Y.generators, extra]),
            np.hstack([block_diag(self._A, Y.A), _zeros(self.n_constraints + Y.n_constraints, k)]),
            np.concatenate([self._b, Y.b]),
        )

    def generalized_intersection(self, Y, R=None) -> ConstrainedZonotope:
        """``CZ ∩_R Y = {x in CZ : R x in Y}`` [SRMB, Prop. 1, eq. (7)]; ``R`` defaults to I.

        New constraint rows ``R G xi - G_Y xi_Y = c_Y - R c`` are computed in interval
        arithmetic; a row that rounds gets a slack generator of the rounding's size, so the
        result contains the exact intersection.

        Parameters
        ----------
        Y : ConstrainedZonotope, Zonotope or Box
            The set ``R x`` must lie in (a Box must be bounded).
        R : array_like, shape (p, n), optional
            Linear map (the identity if omitted).

        Returns
        -------
        ConstrainedZonotope
            A set containing the exact generalized intersection.

        Raises
        ------
        TypeError
            If ``Y`` is of another type.
        ValueError
            If ``R`` is non-finite or mis-shaped, or ``Y`` has not ``R.shape[0]`` dimensions.
        """
        from optbound.interval import Interval

        R = np.eye(self.dim) if R is None else v.finite_matrix("R", R, (None, self.dim))
        Y = _as_cz("Y", Y, R.shape[0])
        RG = matmul(R, self._G)
        rows = Interval(np.hstack([RG.lo, -Y.generators]), np.hstack([RG.hi, -Y.generators]))
        rhs = point(Y.center) - matmul(R, self._c[:, None])[:, 0]
        A_new, b_new, E = relax_rows(rows, rhs)
        slack = -error_generators(E)
        m, my, k = self.n_generators, Y.n_generators, slack.shape[1]
        A = np.vstack(
            [
                np.hstack([self._A, _zeros(self.n_constraints, my + k)]),
                np.hstack([_zeros(Y.n_constraints, m), Y.A, _zeros(Y.n_constraints, k)]),
                np.hstack([A_new, slack]),
            ]
        )
        G = np.hstack([self._G, _zeros(self.dim, my + k)])
        return ConstrainedZonotope._compacted(self._c, G, A, np.concatenate([self._b, Y.b, b_new]))

    def intersect_strip(self, a, lo, hi) -> ConstrainedZonotope:
        """``CZ ∩ {x : lo <= a^T x <= hi}``: the generalized intersection with ``R = a^T``
        and the 1-D zonotope ``<mid, rad>`` of ``[lo, hi]`` (radius rounded up).

        Parameters
        ----------
        a : array_like, shape (n,)
            Normal of the strip.
        lo, hi : float
            Bounds of ``a^T x``, ``lo <= hi``.

        Returns
        -------
        ConstrainedZonotope
            A set containing the exact intersection (one more constraint).

        Raises
        ------
        ValueError
            If an argument is non-finite or mis-shaped, or ``lo > hi``.
        """
        from optbound.interval import Interval

        a = v.finite_vector("a", a, self.dim)
        lo, hi = v.finite_scalar("lo", lo), v.finite_scalar("hi", hi)
        if lo > hi:
            raise ValueError(f"lo must be <= hi, got lo={lo}, hi={hi}")
        mid, rad = split(Interval(lo, hi))
        return self.generalized_intersection(Zonotope([mid], [[rad]]), a[None, :])

    def reduce_order(self, order: float, method: str = "girard") -> ConstrainedZonotope:
        """At most ``floor(order * n)`` generators by reducing the lifted zonotope
        ``<(c, -b), (G; A)>`` [SRMB, Sect. 4.2] (Girard or Combastel, see
        ``optbound.sets.zonotope_reduction``).

        ``{x : (x, 0) in lifted}`` is the set, and any lifted superset gives a superset.
        The budget must be at least ``n + nc`` (the lifted box alone).

        Parameters
        ----------
        order : float
            Generators per dimension allowed, at least 1.
        method : {"girard", "combastel"}, default "girard"
            Which generators are boxed.

        Returns
        -------
        ConstrainedZonotope
            A set containing CZ.

        Raises
        ------
        ValueError
            If ``order`` is not finite, is below 1 or gives fewer than ``n + nc`` generators,
            or ``method`` is unknown.
        """
        budget = generator_budget(order, self.dim)
        if budget < self.dim + self.n_constraints:
            raise ValueError(
                f"order must give at least n + nc = {self.dim + self.n_constraints} generators "
                f"(the lifted box), got order={order} -> {budget}; eliminate constraints first"
            )
        lifted = reduce_generators(np.vstack([self._G, self._A]), budget, method)
        return ConstrainedZonotope._compacted(
            self._c, lifted[: self.dim], lifted[self.dim :], self._b
        )

    def eliminate_constraints(self, count: int = 1) -> ConstrainedZonotope:
        """Remove ``count`` constraints (and one generator each), an outer approximation.

        Constraint i is solved for ``xi_j = (b_i - sum_{k != j} a_ik xi_k) / a_ij`` and
        substituted [SRMB, Sect. 4.2, Prop. 5]; dropping ``|xi_j| <= 1`` enlarges the set
        unless the implied range of ``xi_j`` lies in [-1, 1]. The pair (i, j) minimises
        ``||(g_j; a_j)||_2 * max(0, rho_ij - 1)``, ``rho_ij = (|b_i| + sum_{k != j} |a_ik|) /
        |a_ij|`` the range of ``xi_j`` implied by row i alone (the cost is 0 when the
        elimination is exact by that row) and ``(g_j; a_j)`` the column of the lifted zonotope
        of :meth:`reduce_order` whose bound is dropped; ties go to the larger ``|a_ij|``.
        Substituted data are enclosed as in the
        other operations (error and slack generators), so the result contains the input.

        Parameters
        ----------
        count : int, default 1
            Number of constraints removed, at most ``n_constraints``.

        Returns
        -------
        ConstrainedZonotope
            A set containing CZ with ``count`` fewer constraints.

        Raises
        ------
        ValueError
            If ``count`` is not an integer in ``[0, n_constraints]``.
        """
        if isinstance(count, bool) or not isinstance(count, int | np.integer) or count < 0:
            raise ValueError(f"count must be a non-negative integer, got {count!r}")
        if count > self.n_constraints:
            raise ValueError(
                f"count must be <= {self.n_constraints} (the constraints), got {count}"
            )
        Z = self
        for _ in range(count):
            Z = Z._eliminate_one()
        return Z

    def _pivot(self) -> tuple[int, int] | None:
        """The pair (i, j) of :meth:`eliminate_constraints` (vectorised; ties: larger
        ``|a_ij|``, then the first in row-major order), None if ``A`` is all zero."""
        A, b = np.abs(self._A), np.abs(self._b)
        rows, cols = np.nonzero(A)
        if rows.size == 0:
            return None
        G = np.linalg.norm(np.vstack([self._G, self._A]), axis=0)
        a = A[rows, cols]
        rho = (b[rows] + A.sum(axis=1)[rows] - a) / a
        cost = G[cols] * np.maximum(0.0, rho - 1.0)
        best = np.lexsort((np.arange(rows.size), -a, cost))[0]
        return int(rows[best]), int(cols[best])

    def _eliminate_one(self) -> ConstrainedZonotope:
        pivot = self._pivot()
        if pivot is None:  # a zero row: 0 = b_i, dropped (an outer approximation if b_i != 0)
            i = int(np.argmin(np.abs(self._b)))
            keep = np.arange(self.n_constraints) != i
            return ConstrainedZonotope(self._c, self._G, self._A[keep], self._b[keep])
        i, j = pivot
        a_row, b_i, a_ij = self._A[i], self._b[i], self._A[i, j]
        others = np.arange(self.n_generators) != j
        rows = np.arange(self.n_constraints) != i
        # x = c + g_j b_i / a_ij + (G - g_j a_i^T / a_ij) xi  (column j becomes zero, dropped)
        fG = point(self._G[:, j]) / a_ij
        c_iv = fG * b_i + self._c
        G_iv = point(self._G[:, others]) - matmul(fG[:, None], point(a_row[None, others]))
        c, G, r = enclose(c_iv, G_iv)
        fA = point(self._A[rows, j]) / a_ij
        A_iv = point(self._A[np.ix_(rows, others)]) - matmul(
            fA[:, None], point(a_row[None, others])
        )
        A_new, b_new, E = relax_rows(A_iv, point(self._b[rows]) - fA * b_i)
        gens, slack = error_generators(r), -error_generators(E)
        nr = A_new.shape[0]
        return ConstrainedZonotope._compacted(
            c,
            np.hstack([G, gens, _zeros(self.dim, slack.shape[1])]),
            np.hstack([A_new, _zeros(nr, gens.shape[1]), slack]),
            b_new,
        )

    # ----------------------------------------------------------------- plotting
    def vertices(self) -> np.ndarray:
        """Vertices of a 2-D constrained zonotope, counter-clockwise (float LPs, for
        plotting); shape (0, 2) if the LP finds it empty.

        Support points in eight directions, then for each edge the support point along its
        outward normal is inserted until no edge moves (the polygon is then the set, up to
        the LP tolerance). An edge that did not move is never asked again, so the cost is
        about two LPs per vertex.

        Returns
        -------
        ndarray, shape (k, 2)
            The vertices.

        Raises
        ------
        ValueError
            If the set is not 2-D.
        """
        return self._vertex_search()[0].copy()

    def _vertex_search(self) -> tuple[np.ndarray, list[np.ndarray]]:
        """:meth:`vertices` and, per vertex, the LP solution ``xi`` it came from (a point
        of the set up to the LP tolerance; the certified inner polygon starts from them).
        Searched once per set (the set is immutable)."""
        if self._vertex_cache is None:
            self._vertex_cache = self._search_vertices()
        return self._vertex_cache

    def _search_vertices(self) -> tuple[np.ndarray, list[np.ndarray]]:
        """The LP search of :meth:`_vertex_search` (:meth:`vertices` describes it)."""
        if self.dim != 2:
            raise ValueError(f"vertices() is for 2-D sets, this one has dim {self.dim}")
        xis: dict[tuple, np.ndarray] = {}  # the rounded point (as _ccw_unique rounds) -> xi

        def support_point(d: np.ndarray) -> np.ndarray | None:
            xi = self._support_xi(d)
            if xi is None:
                return None
            point = self._c + self._G @ xi
            xis[tuple(np.round(point, 12))] = xi
            return point

        angles = np.linspace(0.0, 2.0 * np.pi, 8, endpoint=False)
        pts = [support_point(np.array([np.cos(t), np.sin(t)])) for t in angles]
        if any(p is None for p in pts):
            return np.zeros((0, 2)), []
        poly = _ccw_unique(np.array(pts))
        scale = 1e-9 * max(1.0, float(np.abs(self._G).sum() + np.abs(self._c).sum()))
        final: set[tuple] = set()  # edges (p, q) whose outward support point is on them
        for _ in range(200):
            grown = False
            out = [poly[0]]
            for p, q in zip(poly, np.roll(poly, -1, axis=0), strict=True):
                edge = (*p, *q)
                normal = np.array([q[1] - p[1], p[0] - q[0]])
                if edge not in final and np.any(normal != 0):
                    s = support_point(normal)
                    if s is not None and normal @ (s - p) > scale * np.linalg.norm(normal):
                        out.append(s)
                        grown = True
                    else:
                        final.add(edge)
                out.append(q)
            poly = _ccw_unique(np.array(out[:-1]))
            if not grown:
                break
        return poly, [xis[key] for p in poly if (key := tuple(p)) in xis]

    def _support_xi(self, d: np.ndarray) -> np.ndarray | None:
        """The LP's ``xi`` maximising ``d^T G xi`` (float, not certified); None if it fails."""
        res = solve_lp(
            -(self._G.T @ d),
            A_eq=self._A if self.n_constraints else None,
            b_eq=self._b if self.n_constraints else None,
            lower=-1.0,
            upper=1.0,
        )
        return res.x


def _ccw_unique(pts: np.ndarray) -> np.ndarray:
    """Distinct points sorted counter-clockwise around their mean (a convex polygon)."""
    pts = np.unique(np.round(pts, 12), axis=0) if pts.shape[0] else pts
    mean = pts.mean(axis=0)
    return pts[np.argsort(np.arctan2(pts[:, 1] - mean[1], pts[:, 0] - mean[0]), kind="stable")]


def _as_cz(name: str, Y, dim: int) -> ConstrainedZonotope:
    """``Y`` (a ConstrainedZonotope, Zonotope or bounded Box) as a ConstrainedZonotope."""
    if isinstance(Y, ConstrainedZonotope):
        if Y.dim != dim:
            raise ValueError(f"{name} must have dimension {dim}, got {Y.dim}")
        return Y
    if not isinstance(Y, Zonotope | Box):
        raise TypeError(
            f"{name} must be a ConstrainedZonotope, Zonotope or Box, got {type(Y).__name__}"
        )
    return ConstrainedZonotope.from_zonotope(as_zonotope(name, Y, dim))
