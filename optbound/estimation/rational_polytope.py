"""Convex hulls of rational points in R^n (small n), exact: vertices, edges and volume.

:func:`convex_hull` builds the *placing triangulation* of the points (Lee, *Regular
triangulations of convex polytopes*, 1991; the beneath-beyond method of Edelsbrunner,
*Algorithms in Combinatorial Geometry*, 1987, Sect. 8.4): starting from a simplex, each point
strictly beyond some boundary facet is joined to the visible facets, and the horizon ridges
(those of exactly one visible facet) spawn the new boundary facets. Every predicate is a sign
of a ``fractions.Fraction`` expression, so the result is exact, degenerate inputs included
(coplanar and repeated points, flat point sets: a set of affine dimension d < n is hulled in
its own affine coordinates and has volume 0).

From the triangulated boundary, oriented outward from an interior point ``o``:

- the volume is ``sum_F |det(q_1 - o, ..., q_n - o)| / n!`` over the boundary simplices
  ``F = (q_1, ..., q_n)`` (the cone decomposition, i.e. the divergence theorem);
- a boundary point is a vertex iff the normals of the boundary simplices through it span R^n
  (a point inside a face of dimension >= 1 has all its facet normals orthogonal to that face);
- every edge of the polytope is a union of boundary-simplex edges, so those edges (a
  superset) are all a hyperplane cut needs (:meth:`RationalPolytope.cut`).

Cost: ``O(N F n^2)`` rational operations for N points and F boundary simplices; meant for
n <= 4 and a few hundred points.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cached_property
from itertools import combinations
from math import factorial, lcm
from operator import mul

import numpy as np

Point = tuple[Fraction, ...]

# The float filter's relative and absolute error bounds (see _Placing).
_FILTER = 1e-12
_TINY = 1e-280


def dot(a, p):
    """Exact ``a^T p`` (ints or Fractions of equal length).

    Parameters
    ----------
    a, p : sequence of int or Fraction
        Two vectors of equal length.

    Returns
    -------
    int or Fraction
        ``sum_i a_i p_i``, exact.
    """
    return sum(map(mul, a, p))


def integer_determinant(M: list[list[int]]) -> int:
    """Exact determinant of an integer matrix (Bareiss' fraction-free elimination).

    Parameters
    ----------
    M : list of list of int
        A square integer matrix.

    Returns
    -------
    int
        ``det M`` (1 for the empty matrix).
    """
    a = [list(r) for r in M]
    n, sign, prev = len(a), 1, 1
    for k in range(n - 1):
        p = next((i for i in range(k, n) if a[i][k] != 0), None)
        if p is None:
            return 0
        if p != k:
            a[k], a[p], sign = a[p], a[k], -sign
        for i in range(k + 1, n):
            for j in range(k + 1, n):
                a[i][j] = (a[i][j] * a[k][k] - a[i][k] * a[k][j]) // prev
        prev = a[k][k]
    return sign * a[n - 1][n - 1] if n else 1


def normal(vectors: list[list[int]]) -> list[int]:
    """An integer vector orthogonal to n - 1 integer vectors of R^n (the generalized cross
    product: entry i is the signed minor without column i; zero iff the vectors are
    dependent).

    Parameters
    ----------
    vectors : list of list of int
        The n - 1 integer vectors, each of length n.

    Returns
    -------
    list of int
        The vector ``((-1)^i det V_i)_i``, ``V_i`` the vectors without their i-th entry.
    """
    n = len(vectors) + 1
    return [
        (-1) ** i * integer_determinant([[v[j] for j in range(n) if j != i] for v in vectors])
        for i in range(n)
    ]


def homogeneous(p) -> list[int]:
    """The rational point p as integers ``[d p_1, ..., d p_n, d]``, d > 0 the least common
    denominator (a point's own scale: hulls of points with unrelated denominators stay small).

    Parameters
    ----------
    p : sequence of Fraction
        A rational point.

    Returns
    -------
    list of int
        ``[d p_1, ..., d p_n, d]``.
    """
    d = lcm(*(x.denominator for x in p))
    return [int(x * d) for x in p] + [d]


def _rank(rows: list[list[int]]) -> int:
    """Exact rank of an integer matrix (fraction-free row echelon form)."""
    rows = [list(r) for r in rows if any(r)]
    rank, col, width = 0, 0, len(rows[0]) if rows else 0
    while rows and col < width:
        p = next((i for i, r in enumerate(rows) if r[col] != 0), None)
        if p is None:
            col += 1
            continue
        piv = rows.pop(p)
        rows = [[piv[col] * x - r[col] * y for x, y in zip(r, piv, strict=True)] for r in rows]
        rows = [r for r in rows if any(r)]
        rank, col = rank + 1, col + 1
    return rank


def _independent(vectors: list[list[int]]) -> list[int]:
    """Indices of a maximal linearly independent subset (greedy, exact), first vector first.

    Points are affinely independent iff their homogeneous vectors are linearly independent."""
    basis: list[int] = []
    for k, v in enumerate(vectors):
        if _rank([*(vectors[i] for i in basis), v]) > len(basis):
            basis.append(k)
            if len(basis) == len(v):
                break
    return basis


class _Placing:
    """The boundary of the placing triangulation of full-dimensional points, in homogeneous
    integer coordinates (module docstring). A facet is ``h`` with ``h^T X = 0`` at its points,
    oriented so that ``h^T X_o < 0`` at the interior point X_o (the first simplex's centroid);
    a point X is beyond it iff ``h^T X > 0``.

    A floating-point filter decides most of these signs: with ``h / max|h|`` and the point
    rounded to floats, ``s = h^T x`` is within ``_FILTER * sum |h_i x_i|`` (far above the
    rounding error of 2n + 4 roundings) of the exact value scaled alike, so ``|s|`` above that
    bound fixes the sign; only the others are computed in integers.
    """

    def __init__(self, points: list[list[int]], approx: np.ndarray, simplex: list[int], interior):
        self.points, self.approx, self.interior = points, approx, interior
        self.keys: list[frozenset[int]] = []
        self.exact: list[list[int]] = []
        self.floats = np.zeros((16, approx.shape[1]))
        self.alive = np.zeros(16, dtype=bool)
        for k in range(len(simplex)):
            self._add(frozenset(simplex[:k] + simplex[k + 1 :]))
        spread = np.linalg.norm(approx - approx.mean(axis=0), axis=1)
        for i in np.argsort(-spread, kind="stable"):  # far points first: fewer passing facets
            if i not in simplex:
                self._place(int(i))

    @property
    def facets(self) -> dict[frozenset[int], list[int]]:
        return {self.keys[k]: self.exact[k] for k in np.flatnonzero(self.alive)}

    def _add(self, facet: frozenset[int]) -> None:
        h = normal([self.points[i] for i in sorted(facet)])
        if dot(h, self.interior) > 0:
            h = [-x for x in h]
        k = len(self.keys)
        if k == len(self.alive):
            self.floats = np.vstack([self.floats, np.zeros_like(self.floats)])
            self.alive = np.concatenate([self.alive, np.zeros_like(self.alive)])
        top = max(abs(x) for x in h)
        self.floats[k] = [x / top for x in h]
        self.alive[k] = True
        self.keys.append(facet)
        self.exact.append(h)

    def _place(self, i: int) -> None:
        k = len(self.keys)
        H, x = self.floats[:k], self.approx[i]
        s = H @ x
        bound = _FILTER * (np.abs(H) @ np.abs(x)) + _TINY
        p = self.points[i]
        visible = [
            f
            for f in np.flatnonzero(self.alive[:k] & (s > -bound))
            if s[f] > bound[f] or dot(self.exact[f], p) > 0
        ]
        if not visible:
            return
        ridges = Counter(
            r for f in visible for r in combinations(sorted(self.keys[f]), len(self.keys[f]) - 1)
        )
        self.alive[visible] = False
        for ridge, count in ridges.items():
            if count == 1:
                self._add(frozenset((*ridge, i)))


@dataclass(frozen=True)
class RationalPolytope:
    """The convex hull of finitely many rational points of R^n, exact (module docstring).

    Attributes
    ----------
    dim : int
        Ambient dimension n.
    vertices : tuple of tuple of Fraction
        The extreme points, sorted (empty for the empty set).
    edges : tuple of (Point, Point)
        Pairs of hull points whose segments cover every edge of the polytope.
    volume : Fraction
        The exact n-dimensional volume (0 for a flat or empty set), computed on first use
        from the boundary simplices and the interior point (the cone formula).

    Parameters
    ----------
    dim : int
        Ambient dimension n.
    vertices : tuple of tuple of Fraction
        The extreme points, sorted.
    edges : tuple of (Point, Point)
        Segments covering every edge of the polytope.
    simplices : tuple of tuple of Point
        The boundary simplices of the triangulation (for the volume).
    interior : tuple of Fraction or None
        A point interior to the polytope (None for a flat or empty one).

    Notes
    -----
    Built by :func:`convex_hull`, not by hand. The volume is the cone formula
    ``sum_F |det(q_1 - o, ..., q_n - o)| / n!`` over the boundary simplices F (module
    docstring).
    """

    dim: int
    vertices: tuple[Point, ...]
    edges: tuple[tuple[Point, Point], ...]
    simplices: tuple[tuple[Point, ...], ...] = field(default=(), repr=False)
    interior: Point | None = field(default=None, repr=False)

    @cached_property
    def volume(self) -> Fraction:
        if self.interior is not None:
            cones = (abs(_det_of_differences(list(q), self.interior)) for q in self.simplices)
            return sum(cones, Fraction(0)) / factorial(self.dim)
        if self.dim == 1 and len(self.vertices) == 2:  # a segment of the line
            return self.vertices[1][0] - self.vertices[0][0]
        return Fraction(0)  # flat, a point or empty

    @property
    def is_empty(self) -> bool:
        """Whether the polytope has no point."""
        return not self.vertices

    def as_array(self) -> np.ndarray:
        """The vertices as floats (nearest), shape (V, n).

        Returns
        -------
        numpy.ndarray, shape (V, n)
            Each vertex coordinate rounded to the nearest float.
        """
        return np.array([[float(x) for x in p] for p in self.vertices]).reshape(-1, self.dim)

    def volume_bounds(self) -> tuple[float, float]:
        """``(lo, hi)`` floats with ``lo <= volume <= hi`` (the exact volume rounded outward).

        Returns
        -------
        tuple of float
            ``(lo, hi)``, equal when the volume is a float.
        """
        f = float(self.volume)
        lo = f if Fraction(f) <= self.volume else float(np.nextafter(f, -np.inf))
        hi = f if Fraction(f) >= self.volume else float(np.nextafter(f, np.inf))
        return lo, hi

    def cut(self, a, beta: Fraction) -> RationalPolytope:
        """``P ∩ {x : a^T x <= beta}``, exact: the hull of the vertices inside and of the
        crossings of the edges with the hyperplane ``a^T x = beta``.

        Parameters
        ----------
        a : sequence of Fraction or int
            The half-space's normal.
        beta : Fraction
            Its offset.

        Returns
        -------
        RationalPolytope
            The cut polytope (empty if no point remains).
        """
        f = {p: dot(a, p) - beta for p in {q for e in self.edges for q in e} | set(self.vertices)}
        pts = [p for p in self.vertices if f[p] <= 0]
        for p, q in self.edges:
            if (f[p] < 0 < f[q]) or (f[q] < 0 < f[p]):
                t = f[p] / (f[p] - f[q])
                pts.append(tuple(x + t * (y - x) for x, y in zip(p, q, strict=True)))
        return convex_hull(pts, self.dim)

    def minkowski_segment(self, g) -> RationalPolytope:
        """``P + {s g : |s| <= 1}``, exact (the hull of ``P - g`` and ``P + g``).

        Parameters
        ----------
        g : sequence of Fraction
            The segment's half-vector.

        Returns
        -------
        RationalPolytope
            The Minkowski sum (``P`` itself for a zero ``g``).
        """
        if not any(g):
            return self
        return convex_hull(
            [
                tuple(x + s * y for x, y in zip(p, g, strict=True))
                for p in self.vertices
                for s in (-1, 1)
            ],
            self.dim,
        )


def convex_hull(points, dim: int) -> RationalPolytope:
    """The exact convex hull of rational (or float, read exactly) points in R^dim.

    Parameters
    ----------
    points : iterable of sequences of length dim
        Fractions, ints or floats (a float is the rational it denotes).
    dim : int
        The ambient dimension (needed for an empty input).

    Returns
    -------
    RationalPolytope
        The hull: its vertices, covering edges and boundary triangulation, all exact.
    """
    pts = sorted({tuple(Fraction(x) for x in p) for p in points})
    if any(len(p) != dim for p in pts):
        raise ValueError(f"points must have {dim} coordinates each")
    if not pts:
        return RationalPolytope(dim, (), ())
    hom = [homogeneous(p) for p in pts]
    basis = _independent(hom)
    if len(basis) == 1:
        return RationalPolytope(dim, (pts[0],), ())
    if dim == 1:
        return _segment(pts)
    if len(basis) <= dim:
        return _flat_hull(pts, basis, dim)
    o = tuple(sum(pts[i][j] for i in basis) / (dim + 1) for j in range(dim))
    approx = np.array([[float(x) for x in p] + [1.0] for p in pts])
    facets = _Placing(hom, approx, basis, homogeneous(o)).facets
    normals: dict[int, list[list[int]]] = {}
    for f, h in facets.items():
        for i in f:
            normals.setdefault(i, []).append(h[:dim])
    vertices = tuple(sorted(pts[i] for i, rows in normals.items() if _rank(rows) == dim))
    edges = {(pts[i], pts[j]) for f in facets for i, j in combinations(sorted(f), 2)}
    simplices = tuple(tuple(pts[i] for i in sorted(f)) for f in facets)
    return RationalPolytope(dim, vertices, tuple(sorted(edges)), simplices, o)


def _det_of_differences(q: list[Point], o: Point) -> Fraction:
    """Exact ``det(q_1 - o, ..., q_n - o)`` (each row scaled to integers, then unscaled)."""
    rows, scale = [], 1
    for p in q:
        r = [x - y for x, y in zip(p, o, strict=True)]
        d = lcm(*(x.denominator for x in r))
        rows.append([int(x * d) for x in r])
        scale *= d
    return Fraction(integer_determinant(rows), scale)


def _flat_hull(pts: list[Point], basis: list[int], dim: int) -> RationalPolytope:
    """The hull of points spanning an affine subspace of dimension d < dim: hulled in d
    coordinates on which the spanning directions are independent (an exact projection,
    one-to-one on the subspace), mapped back; volume 0."""
    dirs = [[x - y for x, y in zip(pts[k], pts[basis[0]], strict=True)] for k in basis[1:]]
    rows: list[int] = []
    for j in range(dim):
        cols = [*rows, j]
        if _rank([homogeneous([v[r] for r in cols])[:-1] for v in dirs]) > len(rows):
            rows.append(j)
    low = [tuple(p[j] for j in rows) for p in pts]
    back = dict(zip(low, pts, strict=True))
    sub = convex_hull(low, len(rows))
    return RationalPolytope(
        dim,
        tuple(sorted(back[p] for p in sub.vertices)),
        tuple(sorted((back[p], back[q]) for p, q in sub.edges)),
    )


def _segment(pts: list[Point]) -> RationalPolytope:
    """The hull of distinct points on a line, in one coordinate."""
    a, b = min(pts), max(pts)
    return RationalPolytope(1, (a, b), ((a, b),))
