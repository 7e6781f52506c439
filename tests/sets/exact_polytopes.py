"""Exact (fractions.Fraction) geometry of small zonotopes and constrained zonotopes.

The oracle of the soundness tests: points are the images of the vertices of the parameter
polytope ``{xi : A xi = b, |xi|_inf <= 1}`` (every vertex of the set is among them), computed
by enumerating bases and sign patterns in rational arithmetic, and 2-D membership is decided on
their exact convex hull. Floats enter as the exact rationals they denote; nothing is rounded.
"""

from __future__ import annotations

from fractions import Fraction
from itertools import combinations, product

import numpy as np

F = Fraction


def exact(a) -> list:
    """A float array as nested lists of Fractions (Fractions pass through)."""
    if isinstance(a, Fraction | int):
        return F(a)
    arr = np.asarray(a, dtype=object)
    if arr.ndim == 0:
        return F(float(arr)) if not isinstance(arr.item(), Fraction) else arr.item()
    return [exact(x) for x in arr]


def _solve(M: list[list[Fraction]], rhs: list[Fraction]) -> list[Fraction] | None:
    """Solve a square system exactly; None if singular."""
    n = len(M)
    a = [[*row, r] for row, r in zip(M, rhs, strict=True)]
    for j in range(n):
        p = next((i for i in range(j, n) if a[i][j] != 0), None)
        if p is None:
            return None
        a[j], a[p] = a[p], a[j]
        for i in range(n):
            if i != j and a[i][j] != 0:
                f = a[i][j] / a[j][j]
                a[i] = [x - f * y for x, y in zip(a[i], a[j], strict=True)]
    return [a[i][n] / a[i][i] for i in range(n)]


def _independent_rows(A: list, b: list) -> tuple[list, list] | None:
    """Exact row echelon reduction of ``A xi = b``; None if inconsistent."""
    rows = [[*r, bi] for r, bi in zip(A, b, strict=True)]
    out, m = [], len(A[0]) if A else 0
    col = 0
    while rows and col < m:
        p = next((i for i, r in enumerate(rows) if r[col] != 0), None)
        if p is None:
            col += 1
            continue
        piv = rows.pop(p)
        rows = [[x - r[col] / piv[col] * y for x, y in zip(r, piv, strict=True)] for r in rows]
        out.append(piv)
        col += 1
    if any(r[-1] != 0 for r in rows):  # 0 = nonzero left over
        return None
    return [r[:-1] for r in out], [r[-1] for r in out]


def parameter_vertices(A: list, b: list, m: int) -> list[list[Fraction]]:
    """All vertices of ``{xi in [-1, 1]^m : A xi = b}`` (exact)."""
    if not A:
        return [[F(s) for s in signs] for signs in product((-1, 1), repeat=m)]
    red = _independent_rows(A, b)
    if red is None:
        return []
    A, b = red
    r = len(A)
    found = set()
    for basis in combinations(range(m), r):
        others = [k for k in range(m) if k not in basis]
        M = [[row[k] for k in basis] for row in A]
        for signs in product((-1, 1), repeat=len(others)):
            rhs = [
                bi - sum(row[k] * s for k, s in zip(others, signs, strict=True))
                for row, bi in zip(A, b, strict=True)
            ]
            sol = _solve(M, rhs)
            if sol is None or any(abs(x) > 1 for x in sol):
                continue
            xi = [F(0)] * m
            for k, x in zip(basis, sol, strict=True):
                xi[k] = x
            for k, s in zip(others, signs, strict=True):
                xi[k] = F(s)
            found.add(tuple(xi))
    return [list(x) for x in found]


def points(c, G, A=None, b=None) -> list[tuple[Fraction, ...]]:
    """Exact images ``c + G xi`` of the parameter vertices (every vertex of the set)."""
    c, G = exact(c), exact(G)
    m = len(G[0]) if G else 0
    A = [] if A is None or len(A) == 0 else exact(A)
    b = [] if b is None or len(b) == 0 else exact(b)
    out = set()
    for xi in parameter_vertices(A, b, m):
        out.add(
            tuple(
                ci + sum(g * x for g, x in zip(row, xi, strict=True))
                for ci, row in zip(c, G, strict=True)
            )
        )
    return list(out)


def set_points(S) -> list[tuple[Fraction, ...]]:
    """Exact vertex candidates of an optbound Zonotope or ConstrainedZonotope."""
    A = getattr(S, "A", None)
    return points(S.center, S.generators, A, getattr(S, "b", None))


def _cross(o, a, b) -> Fraction:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def hull(pts) -> list[tuple[Fraction, Fraction]]:
    """Exact 2-D convex hull, counter-clockwise (monotone chain); collinear points dropped."""
    pts = sorted(set(pts))
    if len(pts) <= 2:
        return pts
    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and _cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and _cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def in_hull(H, x) -> bool:
    """Exact membership of the point x in the convex polygon H (any degenerate case)."""
    x = tuple(exact(x)) if not isinstance(x, tuple) else x
    if len(H) == 0:
        return False
    if len(H) == 1:
        return x == H[0]
    if len(H) == 2:
        p, q = H
        return _cross(p, q, x) == 0 and min(p, q) <= x <= max(p, q)
    return all(_cross(H[k], H[(k + 1) % len(H)], x) >= 0 for k in range(len(H)))


def contains_all(outer, pts) -> bool:
    """Whether every exact point lies in the 2-D optbound set ``outer`` (exactly)."""
    H = hull(set_points(outer))
    return all(in_hull(H, p) for p in pts)


def area(H) -> Fraction:
    """Exact area of a convex polygon (shoelace)."""
    if len(H) < 3:
        return F(0)
    return abs(sum(_cross(H[0], H[k], H[k + 1]) for k in range(1, len(H) - 1))) / 2


def disjoint(P, Q) -> bool:
    """Exact separating-axis test of two convex polygons (hulls, ccw)."""
    for poly in (P, Q):
        k = len(poly)
        axes = (
            [
                (poly[(i + 1) % k][1] - poly[i][1], poly[i][0] - poly[(i + 1) % k][0])
                for i in range(k)
            ]
            if k >= 2
            else []
        )
        if k == 2:
            axes.append((poly[1][0] - poly[0][0], poly[1][1] - poly[0][1]))
        for ax in axes:
            pp = [ax[0] * p[0] + ax[1] * p[1] for p in P]
            qq = [ax[0] * q[0] + ax[1] * q[1] for q in Q]
            if max(pp) < min(qq) or max(qq) < min(pp):
                return True
    if len(P) == 1 and len(Q) == 1:
        return P[0] != Q[0]
    return False


def box_corners(box) -> list[tuple[Fraction, Fraction]]:
    """Exact corners of a 2-D box given as its (2, 2) array of ``[lo, hi]`` rows."""
    return [(F(float(box[0][i])), F(float(box[1][j]))) for i in (0, 1) for j in (0, 1)]


def ellipsoid_level(center, shape, p) -> Fraction:
    """Exact ``(p - c)^T Q^{-1} (p - c)`` for float ``center``, ``shape`` read exactly (<= 1:
    the point p lies in the ellipsoid)."""
    c, Q = exact(center), exact(shape)
    d = [F(pi) - ci for pi, ci in zip(p, c, strict=True)]
    y = _solve(Q, d)
    return sum((di * yi for di, yi in zip(d, y, strict=True)), F(0))


def in_ellipsoid(E, pts) -> bool:
    """Whether every exact point lies in the optbound Ellipsoid E (exactly)."""
    return all(ellipsoid_level(E.center, E.shape, p) <= 1 for p in pts)
