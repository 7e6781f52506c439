"""Exact containment checks in 60-digit arithmetic (mpmath), with no tolerance.

The returned floats of a bound are read as exact numbers (``mpf(float)`` is exact); points of
the true set are computed from the float inputs at 60 digits. A true set is an intersection of
quadratic constraints ``q_i(x) <= 1``; its boundary points are found by casting rays from an
interior point and stopping at the first constraint (the root of a quadratic in the ray
parameter, taken a relative 1e-40 inside, far below any float's resolution but far above the
60-digit rounding).
"""

from __future__ import annotations

import mpmath as mp
import numpy as np

DPS = 60
INSIDE = mp.mpf("1e-40")


def _vec(x) -> mp.matrix:
    return mp.matrix([mp.mpf(float(t)) for t in np.ravel(x)])


def _mat(A) -> mp.matrix:
    A = np.asarray(A, dtype=float)
    return mp.matrix([[mp.mpf(float(t)) for t in row] for row in A])


class Quadric:
    """``(x - c)^T M (x - c) <= 1`` with M = C^{-1} (ellipsoid) or a given PSD M (cylinder)."""

    def __init__(self, center: mp.matrix, M: mp.matrix):
        self.c, self.M = center, M

    @classmethod
    def ellipsoid(cls, center, shape) -> Quadric:
        with mp.workdps(DPS):
            return cls(_vec(center), mp.inverse(_mat(shape)))

    @classmethod
    def slab(cls, a, lo, hi) -> Quadric:
        """``lo <= a^T x <= hi`` written as ``(a^T x - m)^2 / h^2 <= 1`` (lo, hi read exactly)."""
        with mp.workdps(DPS):
            av = _vec(a)
            m = (mp.mpf(lo) + mp.mpf(hi)) / 2
            h = (mp.mpf(hi) - mp.mpf(lo)) / 2
            x0 = av * (m / (av.T * av)[0])  # a point with a^T x0 = m
            return cls(x0, (av * av.T) / h**2)

    def value(self, x: mp.matrix) -> mp.mpf:
        d = x - self.c
        return (d.T * self.M * d)[0]

    def ray(self, x0: mp.matrix, d: mp.matrix) -> mp.mpf:
        """Largest t with q(x0 + t d) <= 1 (inf if unbounded along d)."""
        e = x0 - self.c
        qa = (d.T * self.M * d)[0]
        qb = 2 * (d.T * self.M * e)[0]
        qc = (e.T * self.M * e)[0] - 1
        if qa <= 0:
            return mp.inf if qb <= 0 else -qc / qb
        return (-qb + mp.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)


class Halfplane:
    """``a^T x <= b`` (read exactly)."""

    def __init__(self, a, b):
        self.a, self.b = _vec(a), mp.mpf(float(b))

    def value(self, x: mp.matrix) -> mp.mpf:
        return (self.a.T * x)[0] - self.b + 1  # <= 1 inside, like the quadrics

    def ray(self, x0: mp.matrix, d: mp.matrix) -> mp.mpf:
        slope = (self.a.T * d)[0]
        return mp.inf if slope <= 0 else (self.b - (self.a.T * x0)[0]) / slope


def boundary_points(constraints, x0, directions) -> list[mp.matrix]:
    """Points of ``{x : every constraint <= 1}`` on rays from the interior point ``x0``.

    Each returned point is verified (at 60 digits) to satisfy every constraint.
    """
    out = []
    with mp.workdps(DPS):
        x0 = x0 if isinstance(x0, mp.matrix) else _vec(x0)
        assert all(q.value(x0) <= 1 for q in constraints), "x0 must be in the set"
        out.append(x0)
        for d in directions:
            dv = _vec(d)
            t = min(q.ray(x0, dv) for q in constraints)
            if t == mp.inf:
                continue
            x = x0 + dv * (t * (1 - INSIDE))
            if all(q.value(x) <= 1 for q in constraints):
                out.append(x)
    return out


def ellipsoid_strip_interior(center, shape, a, lo, hi) -> mp.matrix:
    """A point of E ∩ {lo <= a^T x <= hi}: the middle of the feasible part of the chord of E
    through its centre along C a (the direction of E's extent in a)."""
    with mp.workdps(DPS):
        c, C, av = _vec(center), _mat(shape), _vec(a)
        w = C * av
        g = mp.sqrt((av.T * w)[0])
        ac = (av.T * c)[0]
        # x = c + s w / g has a^T x = ac + s g, s in [-1, 1].
        s_lo = max(mp.mpf(-1), (mp.mpf(lo) - ac) / g) if lo != -np.inf else mp.mpf(-1)
        s_hi = min(mp.mpf(1), (mp.mpf(hi) - ac) / g) if hi != np.inf else mp.mpf(1)
        assert s_lo <= s_hi, "the intersection is empty"
        return c + w * ((s_lo + s_hi) / 2 / g)


def strip_set(center, shape, a, b, halfspace: bool = False):
    """Constraints of E ∩ S for ``S = {|a^T x - b| <= 1}`` (or ``{a^T x <= b}``) and an
    interior point. The strip bounds b -+ 1 are formed at 60 digits, not in floats."""
    with mp.workdps(DPS):
        E = Quadric.ellipsoid(center, shape)
        bb = mp.mpf(float(b))
        if halfspace:
            S = Halfplane(a, b)
            x0 = ellipsoid_strip_interior(center, shape, a, -np.inf, bb)
        else:
            S = Quadric.slab(a, bb - 1, bb + 1)
            x0 = ellipsoid_strip_interior(center, shape, a, bb - 1, bb + 1)
    return [E, S], x0


def plane_points(center, shape, a, levels, x0, directions) -> list[mp.matrix]:
    """Points of E's boundary on the planes ``a^T x = t`` (t in ``levels``, read exactly): the
    corners of E ∩ S, where an outer bound is tightest. Each is pulled a relative 1e-40
    towards the interior point ``x0``; callers keep only the verified ones."""
    out = []
    with mp.workdps(DPS):
        c, C, av = _vec(center), _mat(shape), _vec(a)
        L = mp.cholesky(C)
        g = L.T * av  # strip normal in the whitened frame y = L^{-1} (x - c)
        gg = (g.T * g)[0]
        ac = (av.T * c)[0]
        for t in levels:
            s = (mp.mpf(t) - ac) / gg  # y = s g + r e with e orthogonal to g
            r2 = 1 - s * s * gg
            if r2 < 0:
                continue
            for d in directions:
                e = _vec(d)
                e = e - g * ((g.T * e)[0] / gg)
                ne = mp.sqrt((e.T * e)[0])
                if ne == 0:
                    continue
                x = c + L * (g * s + e * (mp.sqrt(r2) / ne))
                out.append(x + (x0 - x) * INSIDE)
    return out


def strip_points(center, shape, a, b, rng, count: int = 40, halfspace: bool = False):
    """Verified points of E ∩ S (S a strip ``|a^T x - b| <= 1`` or half-space ``a^T x <= b``):
    the interior point, ray-cast boundary points and the corners on each cutting plane."""
    constraints, x0 = strip_set(center, shape, a, b, halfspace)
    n = len(np.ravel(center))
    w = np.asarray(shape) @ np.asarray(a)
    dirs = directions(rng, n, count, [a, -np.asarray(a), w, -w])
    pts = boundary_points(constraints, x0, dirs)
    with mp.workdps(DPS):
        bb = mp.mpf(float(b))
        levels = [bb] if halfspace else [bb - 1, bb + 1]
        corners = plane_points(center, shape, a, levels, x0, directions(rng, n, count))
        pts += [x for x in corners if all(q.value(x) <= 1 for q in constraints)]
    return pts


def disjoint(center, shape, a, b, halfspace: bool = False) -> bool:
    """E ∩ S = {} exactly: E's exact extent along a misses ``|a^T x - b| <= 1`` (or a^T x <= b)."""
    with mp.workdps(DPS):
        av, c, C = _vec(a), _vec(center), _mat(shape)
        g = mp.sqrt((av.T * C * av)[0])
        ac = (av.T * c)[0]
        bb = mp.mpf(float(b))
        if halfspace:
            return bb < ac - g
        return bb - 1 > ac + g or bb + 1 < ac - g


def max_level(center, shape, points) -> mp.mpf:
    """Largest ``(x - c)^T C^{-1} (x - c)`` over the points, with c, C read exactly."""
    with mp.workdps(DPS):
        q = Quadric.ellipsoid(center, shape)
        return max(q.value(x) for x in points)


def sum_points(E1, E2, directions) -> list[mp.matrix]:
    """Support points of E1 + E2: ``s1(d) + s2(d)`` with ``s(d) = c + C d / sqrt(d^T C d)``.

    Each support point is pulled a relative 1e-40 towards its centre so that rounding of the
    square root cannot place it outside.
    """
    out = []
    with mp.workdps(DPS):
        parts = [(_vec(E.center), _mat(E.shape)) for E in (E1, E2)]
        for d in directions:
            dv = _vec(d)
            x = mp.matrix(len(dv), 1)
            for c, C in parts:
                Cd = C * dv
                x += c + Cd * ((1 - INSIDE) / mp.sqrt((dv.T * Cd)[0]))
            out.append(x)
    return out


def directions(rng: np.random.Generator, n: int, count: int, extra=()) -> list[np.ndarray]:
    """Random unit directions plus the given ones (e.g. +-a, +-C a)."""
    d = rng.standard_normal((count, n))
    return [*d, *[np.asarray(e, dtype=float) for e in extra]]
