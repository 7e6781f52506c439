"""A certified inner and outer polygon of a 2-D constrained zonotope: its area bracket and a
fast three-valued box test.

A 2-D constrained zonotope ``CZ = {c + G xi : ||xi||_inf <= 1, A xi = b}`` is a convex
polygon, found by float LPs (:meth:`ConstrainedZonotope.vertices`). Neither float polygon is
proven, so two proven ones are built around it:

- **outer**: the half-planes ``n_i^T x <= h_i`` with ``n_i`` the axes and the float vertex
  polygon's edge normals and ``h_i`` the certified support values
  (:meth:`ConstrainedZonotope.support`, LP duals checked with outward rounding); the bounding
  box is clipped by each edge half-plane in exact rational arithmetic;
- **inner**: the convex hull of points *proven* in the set: each support LP's solution
  ``xi`` of the vertex search is made to satisfy ``A xi = b`` exactly
  (``xi + A^T (A A^T)^{-1} (b - A xi)`` in integer arithmetic on the floats' common power
  of two), then pulled towards an interior
  ``xi_0`` (the least-infinity-norm solution, repaired the same way) until ``|xi| <= 1``
  holds exactly; the point ``c + G xi`` is then in the set with every float read as exact.

``area = (inner area, outer area)`` rounded outward is a certified bracket; a box is FALSE if
it lies beyond one outer half-plane and TRUE if its corners satisfy every inner edge. The two
box tests run vectorised in float64 and count only with a margin of ``1e-12`` times the sum
of the magnitudes of the terms, far above the rounding error of the few float operations
(at most ``4 u`` times that sum, ``u = 2^-53``), so each verdict holds for the exact numbers.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from optbound._core.linear_program import least_inf_norm

Point = tuple[Fraction, Fraction]
#: Relative margin of the float box tests (module docstring).
MARGIN = 1e-12


@dataclass(frozen=True)
class CertifiedPolygons:
    """``inner`` (ccw exact points proven in the set, possibly fewer than 3), ``outer`` (ccw
    exact corners of a polygon proven to contain it) and the outer half-planes ``normals``
    (m, 2), ``h`` (m,) with ``CZ ⊆ {x : normals @ x <= h}``.

    Parameters
    ----------
    inner : list of tuple of Fraction
        Counter-clockwise exact points proven in the set (possibly fewer than 3).
    outer : list of tuple of Fraction
        Counter-clockwise exact corners of a polygon proven to contain the set.
    normals : np.ndarray, shape (m, 2)
        Outer half-plane normals.
    h : np.ndarray, shape (m,)
        Outer half-plane offsets.
    """

    inner: list[Point]
    outer: list[Point]
    normals: np.ndarray
    h: np.ndarray

    def area_bracket(self) -> tuple[float, float]:
        """``(lo, hi)`` with ``lo <= area(CZ) <= hi`` (floats rounded outward).

        Returns
        -------
        tuple of float
            The inner polygon's area rounded down (0 if it has fewer than 3 points) and the outer
            one's rounded up.
        """
        lo = polygon_area(self.inner) if len(self.inner) >= 3 else Fraction(0)
        return round_down(lo), round_up(polygon_area(self.outer))

    def tri(self, B: np.ndarray) -> np.ndarray:
        """Tri values (int8) of the boxes ``B`` (m, 2, 2) (module docstring).

        Parameters
        ----------
        B : np.ndarray, shape (m, 2, 2)
            Boxes as ``[lo, hi]`` rows per coordinate.

        Returns
        -------
        np.ndarray of int8, shape (m,)
            ``Tri`` value per box.
        """
        from optbound.interval.tribool import Tri

        out = np.full(B.shape[0], Tri.UNKNOWN, dtype=np.int8)
        low, _, scale = _box_range(B, self.normals, self.h)
        apart = np.any(low > self.h + MARGIN * scale, axis=1)  # beyond one outer half-plane
        out[apart] = Tri.FALSE
        if len(self.inner) >= 3:
            inside = polygon_box_test(self.inner)(B) == Tri.TRUE
            out[inside & ~apart] = Tri.TRUE
        return out


def half_planes(P: list[Point]) -> list[tuple[Fraction, Fraction, Fraction]]:
    """``(a, b, h)`` per edge of the ccw convex polygon ``P``: ``P = {a x + b y <= h}``.

    Parameters
    ----------
    P : list of tuple of Fraction
        Counter-clockwise convex polygon.

    Returns
    -------
    list of tuple of Fraction
        One exact ``(a, b, h)`` per edge, edge k from ``P[k]`` to ``P[k + 1]``.
    """
    out = []
    for k in range(len(P)):
        (px, py), (qx, qy) = P[k], P[(k + 1) % len(P)]
        a, b = qy - py, px - qx
        out.append((a, b, a * px + b * py))
    return out


def polygon_box_test(P: list[Point]):
    """The exact three-valued test ``boxes (m, 2, 2) -> Tri`` of the ccw convex polygon ``P``
    (exact points): TRUE when every corner satisfies every edge's half-plane, FALSE when the
    whole box violates one, for the floats of the box read as exact numbers.

    Decided in float64 with the margin of the module docstring where that suffices, else in
    ``Fraction`` arithmetic (boxes within the margin of an edge).

    Parameters
    ----------
    P : list of tuple of Fraction
        Counter-clockwise convex polygon (exact points).

    Returns
    -------
    callable
        ``test(B)`` mapping boxes (m, 2, 2) to an int8 array of ``Tri`` values.
    """
    from optbound.interval.tribool import Tri

    planes = half_planes(P)
    N = np.array([[float(a), float(b)] for a, b, _ in planes])
    h = np.array([float(c) for _, _, c in planes])

    def test(B: np.ndarray) -> np.ndarray:
        low, high, scale = _box_range(B, N, h)
        out = np.full(B.shape[0], Tri.UNKNOWN, dtype=np.int8)
        apart = np.any(low > h + MARGIN * scale, axis=1)
        inside = np.all(high < h - MARGIN * scale, axis=1)
        out[apart], out[inside & ~apart] = Tri.FALSE, Tri.TRUE
        # Only a box with an end within the margin of an edge can have another exact verdict.
        close = (np.abs(high - h) <= MARGIN * scale) | (np.abs(low - h) <= MARGIN * scale)
        for i in np.flatnonzero(~apart & ~inside & np.any(close, axis=1)):
            out[i] = _exact_verdict(planes, B[i])
        return out

    return test


def _exact_verdict(planes, box: np.ndarray) -> int:
    from optbound.interval.tribool import Tri

    X = (Fraction(float(box[0, 0])), Fraction(float(box[0, 1])))
    Y = (Fraction(float(box[1, 0])), Fraction(float(box[1, 1])))
    verdict = Tri.TRUE
    for a, b, h in planes:
        ax, by = sorted((a * X[0], a * X[1])), sorted((b * Y[0], b * Y[1]))
        if ax[0] + by[0] > h:
            return Tri.FALSE
        if ax[1] + by[1] > h:
            verdict = Tri.UNKNOWN
    return verdict


def _box_range(B: np.ndarray, N: np.ndarray, h: np.ndarray):
    """Float ``min`` and ``max`` of ``N_i^T x`` over each box (m, k) and the magnitude sum
    ``sum_j |N_ij| max|x_j| + |h_i|`` that bounds their rounding error (module docstring)."""
    a, b = N[None] * B[:, None, :, 0], N[None] * B[:, None, :, 1]
    scale = np.maximum(np.abs(a), np.abs(b)).sum(axis=2) + np.abs(h)[None]
    return np.minimum(a, b).sum(axis=2), np.maximum(a, b).sum(axis=2), scale


def certified_polygons(cz) -> CertifiedPolygons:
    """The certified polygons of the 2-D constrained zonotope ``cz`` (module docstring).

    Parameters
    ----------
    cz : ConstrainedZonotope
        A 2-D constrained zonotope.

    Returns
    -------
    CertifiedPolygons
        Its inner and outer polygons.

    Raises
    ------
    ValueError
        If ``cz`` is not 2-D, or its LP vertex polygon is flat or empty.
    """
    _check_planar(cz)
    V, xis = cz._vertex_search()
    outer, normals, h = _outer(cz, V)
    return CertifiedPolygons(_inner(cz, xis), outer, normals, h)


def outer_polygon(cz) -> tuple[np.ndarray, list[Point]]:
    """Compute the certified outer polygon of a 2-D constrained zonotope.

    The float LP vertex polygon (ccw) of ``cz`` and the certified outer polygon of
    :func:`certified_polygons` built from it, without the inner one (whose exact repairs cost
    far more than the LPs).

    Parameters
    ----------
    cz : ConstrainedZonotope
        A 2-D constrained zonotope.

    Returns
    -------
    V : ndarray, shape (m, 2)
        The LP vertices (floats, counter-clockwise; not certified).
    outer : list of tuple of Fraction
        Vertices of a polygon proven to contain ``cz``.

    Raises
    ------
    ValueError
        If ``cz`` is not 2-D, or its LP vertex polygon is flat or empty.
    """
    _check_planar(cz)
    V = cz.vertices()
    return V, _outer(cz, V)[0]


def _check_planar(cz) -> None:
    if cz.dim != 2:
        raise ValueError(f"certified polygons are for 2-D sets, got dimension {cz.dim}")


def _outer(cz, V: np.ndarray) -> tuple[list[Point], np.ndarray, np.ndarray]:
    """The outer polygon, its normals and certified support values (module docstring)."""
    if len(V) < 3:
        raise ValueError("the set is flat or empty: it has no polygon")
    edges = np.array(
        [[q[1] - p[1], p[0] - q[0]] for p, q in zip(V, np.roll(V, -1, 0), strict=True)]
    )
    normals = np.vstack([np.eye(2), -np.eye(2), edges])
    h = cz.support(normals)
    # The certified bounding box clipped by every edge half-plane, in exact arithmetic (no
    # reliance on the float edges' order: nearly collinear vertices may turn the wrong way).
    (x0, y0), (x1, y1) = [
        [Fraction(float(-v)) for v in h[2:4]],
        [Fraction(float(v)) for v in h[:2]],
    ]
    outer = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    for (a, b), hk in zip(edges, h[4:], strict=True):
        outer = clip(outer, Fraction(float(a)), Fraction(float(b)), Fraction(float(hk)))
    return outer, normals, h


def clip(P: list[Point], a: Fraction, b: Fraction, h: Fraction) -> list[Point]:
    """The convex polygon ``P ∩ {a x + b y <= h}`` (exact; Sutherland-Hodgman, one plane).

    Parameters
    ----------
    P : list of tuple of Fraction
        Convex polygon, vertices in order.
    a, b, h : Fraction
        The half-plane ``a x + b y <= h``.

    Returns
    -------
    list of tuple of Fraction
        The clipped polygon (empty if nothing remains).
    """
    out: list[Point] = []
    for k in range(len(P)):
        p, q = P[k], P[(k + 1) % len(P)]
        fp, fq = a * p[0] + b * p[1] - h, a * q[0] + b * q[1] - h
        if fp <= 0:
            out.append(p)
        if (fp < 0 < fq) or (fq < 0 < fp):
            t = fp / (fp - fq)
            out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    return out


def _inner(cz, xis: list[np.ndarray]) -> list[Point]:
    """Points proven in ``cz`` from the LP solutions ``xis`` (module docstring); their hull.

    The exact arithmetic runs on integers (:func:`_dyadic`): each repaired ``xi`` is a list
    of numerators over one denominator, and the point ``c + G z`` with
    ``z = xi_0 + t (xi - xi_0)`` is evaluated as ``c + G xi_0 + t G (xi - xi_0)``, the same
    rational numbers.
    """
    m = cz.n_generators
    # xi_0: min t s.t. A xi = b, |xi_j| <= t (the least-infinity-norm solution).
    res = least_inf_norm(cz.A, cz.b)
    if not res.optimal:
        return []
    project = _projector(cz.A, cz.b)
    start = _repair(project, res.x[:m])
    if start is None or max(abs(x) for x in start[0]) >= start[1]:
        return []  # no interior point proven
    n0, d0 = start
    c = [Fraction(float(x)) for x in cz.center]
    G, eg = _dyadic_rows(cz.generators)
    base = [ci + Fraction(_dot(row, n0), d0 << eg) for ci, row in zip(c, G, strict=True)]
    points = []
    for xi in xis:
        repaired = _repair(project, xi)
        if repaired is None:
            continue
        n, d = repaired
        step = [nj * d0 - n0j * d for nj, n0j in zip(n, n0, strict=True)]  # over d d0
        t = min(
            [Fraction(1)]
            + [Fraction(((1 if s > 0 else -1) * d0 - n0j) * d, s)
               for s, n0j in zip(step, n0, strict=True) if s]
        )  # fmt: skip
        points.append(
            tuple(
                bk + t * Fraction(_dot(row, step), (d * d0) << eg)
                for bk, row in zip(base, G, strict=True)
            )
        )
    return convex_hull(points)


def _dyadic(values) -> tuple[list[int], int]:
    """Floats as integers over one power of two: ``values[k] == ints[k] / 2**e`` exactly."""
    ratios = [float(v).as_integer_ratio() for v in values]
    e = max((d.bit_length() - 1 for _, d in ratios), default=0)
    return [n << (e - d.bit_length() + 1) for n, d in ratios], e


def _dyadic_rows(M: np.ndarray) -> tuple[list[list[int]], int]:
    """A float matrix as integer rows over one power of two (:func:`_dyadic`)."""
    ints, e = _dyadic(np.ravel(M))
    cols = M.shape[1] if M.ndim == 2 else 0
    return [ints[k * cols : (k + 1) * cols] for k in range(M.shape[0])], e


def _dot(u: list[int], v: list[int]) -> int:
    return sum(a * b for a, b in zip(u, v, strict=True))


@dataclass(frozen=True)
class _Projector:
    """``xi -> xi + A^T (A A^T)^{-1} (b - A xi)`` on integers: ``A = rows / 2**ea``,
    ``b = b_ints / 2**eb`` and ``Q = rows^T adj``, where ``adj = L (rows rows^T)^{-1}`` is an
    integer matrix and ``L > 0``."""

    rows: list[list[int]]
    ea: int
    b_ints: list[int]
    eb: int
    Q: list[list[int]]
    L: int


def _projector(A: np.ndarray, b: np.ndarray) -> _Projector | None:
    """The exact projector onto ``A xi = b`` (:class:`_Projector`); None if ``A A^T`` is
    singular (the repair then fails for every ``xi``)."""
    rows, ea = _dyadic_rows(A)
    b_ints, eb = _dyadic(b)
    inverse = _scaled_inverse([[_dot(ri, rj) for rj in rows] for ri in rows])
    if inverse is None:
        return None
    adj, L = inverse
    n, cols = len(rows), (len(rows[0]) if rows else 0)
    Q = [[sum(rows[k][j] * adj[k][i] for k in range(n)) for i in range(n)] for j in range(cols)]
    return _Projector(rows, ea, b_ints, eb, Q, L)


def _scaled_inverse(M: list[list[int]]) -> tuple[list[list[int]], int] | None:
    """``(X, L)`` with ``M X = L I``, ``L > 0``, for an integer matrix ``M``; None if singular.

    Fraction-free Gauss-Jordan elimination (Bareiss): every division is exact, so the
    numbers stay integers of the size of ``M``'s minors; at the end the left block is
    ``d I`` with ``d = ±det M`` and the right block ``d M^{-1}``.
    """
    n = len(M)
    aug = [[*row, *(int(i == j) for j in range(n))] for i, row in enumerate(M)]
    prev = 1
    for k in range(n):
        piv = next((i for i in range(k, n) if aug[i][k] != 0), None)
        if piv is None:
            return None
        aug[k], aug[piv] = aug[piv], aug[k]
        pk = aug[k]
        for i in range(n):
            if i != k:
                ri, f = aug[i], aug[i][k]
                aug[i] = [(pk[k] * x - f * y) // prev for x, y in zip(ri, pk, strict=True)]
        prev = pk[k]
    sign = 1 if prev > 0 else -1
    return [[sign * x for x in row[n:]] for row in aug], sign * prev


def _repair(project: _Projector | None, xi: np.ndarray) -> tuple[list[int], int] | None:
    """``xi + A^T (A A^T)^{-1} (b - A xi)`` in exact arithmetic (solves ``A xi = b``) as
    integer numerators over one positive denominator; None if ``A A^T`` is singular."""
    if project is None:
        return None
    x, ex = _dyadic(xi)
    if not project.rows:
        return x, 1 << ex
    # r = b - A x = r_ints / 2**e
    e = max(project.eb, project.ea + ex)
    r = [
        (bi << (e - project.eb)) - (_dot(row, x) << (e - project.ea - ex))
        for row, bi in zip(project.rows, project.b_ints, strict=True)
    ]
    # A^T y = 2**ea Q r / (L 2**e); over the denominator L 2**(e + ex):
    scale, shift = project.L << e, project.ea + ex
    return [xj * scale + (_dot(q, r) << shift) for xj, q in zip(x, project.Q, strict=True)], (
        scale << ex
    )


def convex_hull(points: list[Point]) -> list[Point]:
    """Convex hull, counter-clockwise (Andrew's monotone chain, exact).

    Parameters
    ----------
    points : list of tuple of Fraction
        Exact points.

    Returns
    -------
    list of tuple of Fraction
        Hull vertices, counter-clockwise, no collinear points.
    """
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts

    def cross(o, p, q):
        return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])

    lower: list[Point] = []
    upper: list[Point] = []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def polygon_area(P: list[Point]) -> Fraction:
    """Exact area of the polygon ``P`` (shoelace; vertices in order).

    Parameters
    ----------
    P : list of tuple of Fraction
        Polygon, vertices in order.

    Returns
    -------
    Fraction
        The exact area; 0 for fewer than three vertices.
    """
    n = len(P)
    if n < 3:
        return Fraction(0)
    return abs(sum(P[k][0] * P[(k + 1) % n][1] - P[(k + 1) % n][0] * P[k][1] for k in range(n))) / 2


def round_down(x: Fraction) -> float:
    """The largest float ``<= x``.

    Parameters
    ----------
    x : Fraction
        Exact value.

    Returns
    -------
    float
        ``x`` rounded toward -inf.
    """
    f = float(x)
    return f if Fraction(f) <= x else float(np.nextafter(f, -np.inf))


def round_up(x: Fraction) -> float:
    """The smallest float ``>= x``.

    Parameters
    ----------
    x : Fraction
        Exact value.

    Returns
    -------
    float
        ``x`` rounded toward +inf.
    """
    f = float(x)
    return f if Fraction(f) >= x else float(np.nextafter(f, np.inf))
