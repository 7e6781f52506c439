"""Exact proofs that rational points lie in an observer's set (any dimension).

:func:`proven_inside` decides, with every float of the set read as the rational it is and no
tolerance, whether all given points (``fractions.Fraction`` coordinates, e.g. the exact
vertices of :mod:`optbound.estimation.exact_polytope`) lie in

- a Box: by its bounds;
- an Ellipsoid: ``(p - c)^T Q^{-1} (p - c) <= 1`` with ``Q^{-1}`` inverted exactly;
- a Zonotope spanning R^n: by its facet slabs ``|h^T (p - c)| <= sum_j |h^T g_j|``, ``h`` the
  exact normal of each n - 1 independent generators (a full-dimensional zonotope is the
  intersection of these slabs, so the test is exact both ways);
- a ConstrainedZonotope ``{c + G xi : |xi|_inf <= 1, A xi = b}`` (Scott, Raimondo, Marseglia &
  Braatz, Automatica 2016): by an exact certificate per point, a ``xi`` with ``|xi_i| <= 1``
  and ``G xi = p - c``, ``A xi = b`` holding in rational arithmetic
  (:func:`parameter_certificate`). A failed certificate leaves the answer undecided (None),
  never False.

Since the sets are convex, all vertices inside proves the whole polytope inside: this is the
exact containment check ``X_k ⊆ estimate`` of the observers.
"""

from __future__ import annotations

from fractions import Fraction
from itertools import combinations, islice

import numpy as np

from optbound._core import Box
from optbound._core.linear_program import solve_lp
from optbound.compare.exact import fractions, inverse
from optbound.estimation.rational_polytope import dot, homogeneous, normal
from optbound.sets.constrained_zonotope import ConstrainedZonotope
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.zonotope import Zonotope

Point = tuple[Fraction, ...]

# Snapping thresholds of the certificate: parameters within 1 - eps of a bound are set on it.
_SNAP = (1e-9, 1e-12, 0.0)
# At most this many subsets of snapped parameters are freed per try.
_MAX_SUBSETS = 512


def _solve_consistent(M: list[list[Fraction]], e: list[Fraction]) -> list[Fraction] | None:
    """A solution of ``M d = e`` (Gauss-Jordan with the columns as pivots in their given
    order, non-pivot unknowns 0), or None if the system is inconsistent."""
    rows = [[*r, x] for r, x in zip(M, e, strict=True)]
    m = len(M[0]) if M else 0
    d = [Fraction(0)] * m
    pivots: list[tuple[int, int]] = []
    r0 = 0
    for col in range(m):
        p = next((i for i in range(r0, len(rows)) if rows[i][col] != 0), None)
        if p is None:
            continue
        rows[r0], rows[p] = rows[p], rows[r0]
        piv = rows[r0]
        for i in range(len(rows)):
            if i != r0 and rows[i][col] != 0:
                f = rows[i][col] / piv[col]
                rows[i] = [x - f * y for x, y in zip(rows[i], piv, strict=True)]
        pivots.append((r0, col))
        r0 += 1
    if any(r[-1] != 0 for r in rows[r0:]):
        return None
    for r, col in pivots:
        d[col] = rows[r][-1] / rows[r][col]
    return d


def _float_parameters(Z: ConstrainedZonotope, x: np.ndarray) -> list[np.ndarray]:
    """Float candidates for ``xi``: the minimiser of ``|xi|_inf`` (interior when x is) and a
    basic feasible point of ``|xi| <= 1, G xi = x - c, A xi = b`` (dual simplex; at most
    n + nc parameters off the bounds)."""
    from optbound.sets.zonotope_membership import min_norm_parameters

    c, G, A, b = Z.center, Z.generators, Z.A, Z.b
    basic = solve_lp(
        np.zeros(Z.n_generators),
        A_eq=np.vstack([G, A]),
        b_eq=np.concatenate([x - c, b]),
        lower=-1.0,
        upper=1.0,
        dual_simplex=True,
    ).x
    sol = min_norm_parameters(c, G, A, b, x)
    return [y for y in (sol, basic) if y is not None]


def _pivot_order(Mf: np.ndarray, cols: list[int], weights: np.ndarray) -> list[int]:
    """``cols`` ordered by a column-pivoted QR of the weighted float columns: well-conditioned,
    heavily weighted columns first (the exact solve takes its pivots in this order)."""
    from scipy.linalg import qr

    _, _, perm = qr(Mf[:, cols] * weights, mode="economic", pivoting=True)
    return [cols[k] for k in perm]


def _direction_columns(
    Mf: np.ndarray, e: np.ndarray, signs: np.ndarray, near: list[int]
) -> list[int] | None:
    """The support of a least-``l_1`` direction ``d`` with ``M d = e / |e|`` that moves no
    snapped parameter outward (``sign_j d_j <= 0``), by a float LP (HiGHS), or None."""
    m = Mf.shape[1]
    up = [0.0 if j in near and signs[j] > 0 else np.inf for j in range(m)]
    down = [0.0 if j in near and signs[j] < 0 else np.inf for j in range(m)]
    res = solve_lp(
        np.ones(2 * m), A_eq=np.hstack([Mf, -Mf]), b_eq=e / np.max(np.abs(e)), upper=up + down
    )
    if not res.optimal:
        return None
    d = res.x[:m] - res.x[m:]
    return [j for j in np.argsort(-np.abs(d), kind="stable") if abs(d[j]) > 1e-9]


def _repair(
    M, Mf: np.ndarray, r, xi0: np.ndarray, eps: float, subsets: bool
) -> list[Fraction] | None:
    """``xi0`` with the parameters within ``1 - eps`` of a bound set on it, corrected exactly
    to ``M xi = r``; the result if it satisfies ``|xi| <= 1``, else None.

    The correction is solved exactly on a set of columns: the support of a float direction
    that moves no snapped parameter outward (:func:`_direction_columns`), or (``subsets``,
    the fallback) the parameters off the bounds (well-conditioned, far from the bounds first,
    :func:`_pivot_order`) with subsets of the snapped ones of increasing size (at most
    ``_MAX_SUBSETS``): a parameter the float LP put on a bound may lie just inside it in the
    exact solution.
    """
    slack = 1.0 - np.abs(xi0)
    near = [j for j in range(len(xi0)) if slack[j] <= eps]
    free = [j for j in range(len(xi0)) if slack[j] > eps]
    xi = [
        Fraction(int(np.sign(xi0[j]))) if j in near else Fraction(float(xi0[j]))
        for j in range(len(xi0))
    ]
    e = [ri - dot(row, xi) for row, ri in zip(M, r, strict=True)]
    if not any(e):
        return xi if all(abs(x) <= 1 for x in xi) else None
    e_float = np.array([float(x) for x in e])
    signs = np.sign(xi0)
    rank = np.linalg.matrix_rank(Mf)

    def bases():
        if not subsets:
            support = _direction_columns(Mf, e_float, signs, near) if np.any(e_float) else None
            if support is not None:
                yield support
            return
        snapped = (P for k in range(len(near) + 1) for P in combinations(near, k))
        for P in islice(snapped, _MAX_SUBSETS):
            cols = free + list(P)
            if len(cols) >= rank:
                weights = np.array([max(slack[j], 0.0) if j in free else 1e-6 for j in cols])
                yield _pivot_order(Mf, cols, weights)[:rank]

    xi_float = np.array([float(x) for x in xi])
    for basis in bases():
        d_float = np.linalg.lstsq(Mf[:, basis], e_float, rcond=None)[0]
        outward = (d_float * signs[basis])[[j in near for j in basis]]
        if np.any(np.abs(xi_float[basis] + d_float) > 1.0) or np.any(outward > 1e-20):
            continue  # a float preview: no parameter may leave [-1, 1]
        d = _solve_consistent([[row[j] for j in basis] for row in M], e)
        if d is None:
            continue
        cand = list(xi)
        for j, dj in zip(basis, d, strict=True):
            cand[j] += dj
        if all(abs(x) <= 1 for x in cand) and all(
            dot(row, cand) == ri for row, ri in zip(M, r, strict=True)
        ):
            return cand
    return None


def parameter_certificate(Z: ConstrainedZonotope, p) -> list[Fraction] | None:
    """An exact ``xi`` proving the rational point ``p`` in ``Z``, or None (undecided).

    Float parameters (a basic feasible point of the LP ``|xi| <= 1, G xi = p - c, A xi = b``
    and the minimiser of ``|xi|_inf``, HiGHS) are repaired in rational arithmetic: parameters
    within ``1 - eps`` of a bound are set on it, and the residual of the equalities is removed
    by an exact solve on chosen columns (:func:`_repair`). A result is accepted only if every
    ``|xi_i| <= 1`` and both equalities hold exactly (tried for eps in 1e-9, 1e-12, 0). Cost:
    a few float LPs and, typically, one exact ``(n + nc) x (n + nc)`` elimination.

    Parameters
    ----------
    Z : ConstrainedZonotope
        ``<c, G, A, b>`` (Scott et al. 2016's representation), its floats read exactly.
    p : sequence of Fraction (or float)
        The point.

    Returns
    -------
    list of Fraction or None
        ``xi`` with ``|xi_i| <= 1``, ``G xi = p - c`` and ``A xi = b`` exactly, proving
        ``p in Z``; None when no certificate was found (undecided, not a refutation).
    """
    p = [Fraction(x) for x in p]
    r = [x - y for x, y in zip(p, fractions(Z.center), strict=True)] + fractions(Z.b)
    if not Z.n_generators:
        return [] if not any(r) else None
    Mf = np.vstack([Z.generators, Z.A])
    M = fractions(Mf)
    candidates = _float_parameters(Z, np.array([float(x) for x in p]))
    for subsets in (False, True):
        for xi0 in candidates:
            for eps in _SNAP:
                xi = _repair(M, Mf, r, xi0[: Z.n_generators], eps, subsets)
                if xi is not None:
                    return xi
    return None


def _in_zonotope(Z: Zonotope, points: list[Point]) -> bool | None:
    """Facet-slab test; a slab missing a point refutes, all slabs of a spanning zonotope
    prove (a flat one is undecided)."""
    c, gens = fractions(Z.center), fractions(Z.generators.T) if Z.n_generators else []
    d = [[x - y for x, y in zip(p, c, strict=True)] for p in points]
    if Z.dim == 1:
        return all(abs(x[0]) <= sum(abs(g[0]) for g in gens) for x in d)
    spans = False
    for S in combinations([homogeneous(g)[:-1] for g in gens], Z.dim - 1):
        a = normal(list(S))
        h = sum(abs(dot(a, g)) for g in gens)
        spans = spans or h > 0  # a != 0 and a generator off its hyperplane: rank n
        if any(abs(dot(a, x)) > h for x in d):
            return False
    return True if spans else None


def max_level(E: Ellipsoid, points) -> Fraction:
    """The largest ``(p - c)^T Q^{-1} (p - c)`` over the rational points, exact (``Q^{-1}``
    inverted in rational arithmetic); ``<= 1`` iff every point lies in E.

    Parameters
    ----------
    E : Ellipsoid
        ``E(c, Q)``, its floats read exactly.
    points : iterable of sequences of Fraction (or float)
        The points.

    Returns
    -------
    Fraction
        ``max_p (p - c)^T Q^{-1} (p - c)`` (0 for no point).
    """
    Q_inv, c = inverse(fractions(E.shape)), fractions(E.center)
    worst = Fraction(0)
    for p in points:
        d = [Fraction(x) - y for x, y in zip(p, c, strict=True)]
        worst = max(worst, dot(d, [dot(row, d) for row in Q_inv]))
    return worst


def proven_inside(outer, points) -> bool | None:
    """Whether every rational point lies in ``outer``, decided exactly (module docstring).

    Parameters
    ----------
    outer : Box, Ellipsoid, Zonotope or ConstrainedZonotope
        The set, its floats read exactly.
    points : iterable of sequences of Fraction (or float)
        The points, e.g. the exact vertices of a polytope.

    Returns
    -------
    bool or None
        True: proven inside; False: a point is proven outside; None: undecided (a flat
        zonotope, a constrained zonotope whose certificate failed, another set type).
    """
    pts = [tuple(Fraction(x) for x in p) for p in points]
    if isinstance(outer, Box):
        lo, hi = fractions(outer.lo), fractions(outer.hi)
        return all(a <= x <= b for p in pts for a, x, b in zip(lo, p, hi, strict=True))
    if isinstance(outer, Ellipsoid):
        return max_level(outer, pts) <= 1
    if isinstance(outer, Zonotope):
        return _in_zonotope(outer, pts)
    if isinstance(outer, ConstrainedZonotope):
        ok = all(parameter_certificate(outer, p) is not None for p in pts)
        return True if ok else None
    return None
