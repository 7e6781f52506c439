"""Membership tests shared by the zonotope types: float LPs for points, proofs for boxes.

:func:`tri_contains` proves a box inside or outside a zonotope with outward-rounded interval
arithmetic on slabs ``|d^T (x - c)| <= sum_j |d^T g_j|``, each of which contains the zonotope
for any direction ``d``:

- FALSE (disjoint) when one slab misses the box; the directions tried are the axes and the
  generators (and in 2-D the generator normals). By the separating-axis theorem these
  directions decide disjointness of a box and a full-dimensional 2-D zonotope exactly (up to
  the rounding margin); in higher dimensions a disjoint box may stay UNKNOWN;
- TRUE (inside) only in 1-D (one slab is the zonotope) and in 2-D when the generators span the
  plane: a 2-D zonotope is the intersection of the slabs of its generator normals
  ``(-g_2, g_1)``, and these normals are exact in floats (a swap and a negation). In 3-D and
  above the facet normals are rounded cross products, their slabs only contain the zonotope,
  and no box is reported inside (UNKNOWN).
"""

from __future__ import annotations

import numpy as np

from optbound._core import box_array
from optbound._core.linear_program import least_inf_norm
from optbound.interval import Interval
from optbound.interval.tribool import from_masks
from optbound.sets.certified import matmul, point


def min_norm_parameters(
    c: np.ndarray, G: np.ndarray, A: np.ndarray, b: np.ndarray, x: np.ndarray
) -> np.ndarray | None:
    """A float minimiser ``(xi, t)`` of ``t s.t. |xi| <= t, G xi = x - c, A xi = b`` (HiGHS),
    shape (m + 1,), or None if the LP reports no solution; ``G`` has at least one column.

    Parameters
    ----------
    c : np.ndarray, shape (n,)
        Centre.
    G : np.ndarray, shape (n, m)
        Generators.
    A : np.ndarray, shape (nc, m)
        Constraint matrix (nc = 0 for a zonotope).
    b : np.ndarray, shape (nc,)
        Constraint right-hand side.
    x : np.ndarray, shape (n,)
        The point.

    Returns
    -------
    np.ndarray, shape (m + 1,), or None
        ``(xi, t)``, or None if the LP fails (e.g. infeasible).
    """
    return least_inf_norm(np.vstack([G, A]), np.concatenate([x - c, b])).x


def lp_contains(
    c: np.ndarray, G: np.ndarray, A: np.ndarray, b: np.ndarray, pts: np.ndarray, tol: float
) -> np.ndarray:
    """Float test per point: ``min ||xi||_inf s.t. G xi = x - c, A xi = b`` is ``<= 1 + tol``.

    Parameters
    ----------
    c : np.ndarray, shape (n,)
        Centre.
    G : np.ndarray, shape (n, m)
        Generators.
    A : np.ndarray, shape (nc, m)
        Constraint matrix (nc = 0 for a zonotope).
    b : np.ndarray, shape (nc,)
        Constraint right-hand side.
    pts : np.ndarray, shape (k, n)
        Finite points, one per row.
    tol : float
        Relative slack on the defining inequality.

    Returns
    -------
    np.ndarray of bool, shape (k,)
        True where the point is inside (up to ``tol``).
    """
    if G.shape[1] == 0:
        return np.all(np.abs(pts - c) <= tol * np.maximum(1.0, np.abs(c)), axis=1)
    inside = np.zeros(pts.shape[0], dtype=bool)
    for k, x in enumerate(pts):
        sol = min_norm_parameters(c, G, A, b, x)
        inside[k] = sol is not None and sol[-1] <= 1.0 + tol
    return inside


def slab_contains(c: np.ndarray, G: np.ndarray, pts: np.ndarray, tol: float) -> np.ndarray | None:
    """Float 2-D test on the facet slabs of the generator normals; None unless the zonotope
    is a full-dimensional 2-D one (where the slabs intersect to exactly the zonotope).

    Parameters
    ----------
    c : np.ndarray, shape (n,)
        Centre.
    G : np.ndarray, shape (n, m)
        Generators.
    pts : np.ndarray, shape (k, n)
        Finite points, one per row.
    tol : float
        Relative slack on the defining inequality.

    Returns
    -------
    np.ndarray of bool, shape (k,), or None
        True where the point is inside; None if the test does not apply.
    """
    if G.shape[0] != 2:
        return None
    N, spans = _normals_2d(G)
    if not spans:
        return None
    h = np.abs(N @ G).sum(axis=1)
    return np.all(np.abs((pts - c) @ N.T) <= (1.0 + tol) * h, axis=1)


def _abs_sum(p: Interval) -> Interval:
    """Enclosure of ``sum_k |p_k|`` for a 1-D Interval."""
    acc = point(0.0)
    for k in range(p.shape[0]):
        acc = acc + abs(p[k])
    return acc


def _normals_2d(G: np.ndarray) -> tuple[np.ndarray, bool]:
    """Normals ``(-g_2, g_1)`` of the non-zero generators (exact in floats) and whether the
    generators span the plane."""
    G = G[:, np.any(G != 0, axis=0)]
    spans = G.shape[1] >= 2 and np.linalg.matrix_rank(G) == 2
    return np.column_stack([-G[1], G[0]]), bool(spans)


def _directions(G: np.ndarray) -> tuple[list[np.ndarray], bool]:
    """Slab directions and whether their slabs intersect to exactly the zonotope."""
    n = G.shape[0]
    nonzero = G[:, np.any(G != 0, axis=0)]
    dirs = [np.eye(n)[j] for j in range(n)] + list(nonzero.T)
    if n == 1:
        return dirs, True
    if n == 2:
        normals, spans = _normals_2d(G)
        return dirs + list(normals), spans
    return dirs, False


def tri_contains(Z, boxes) -> np.ndarray:
    """Tri values of ``box subset Z`` (TRUE), ``box ∩ Z = ∅`` (FALSE) per box (module doc).

    Parameters
    ----------
    Z : Zonotope
        The zonotope.
    boxes : array_like, shape (m, n, 2)
        Boxes as ``[lo, hi]`` rows per coordinate.

    Returns
    -------
    np.ndarray of int8, shape (m,)
        ``Tri`` value per box.

    Raises
    ------
    ValueError
        If ``boxes`` is mis-shaped, non-finite or has ``lo > hi``.
    """
    n = Z.dim
    B = box_array("boxes", boxes, n)
    X = [Interval(B[:, j, 0], B[:, j, 1]) - Z.center[j] for j in range(n)]
    dirs, exact = _directions(Z.generators)
    inside = np.full(B.shape[0], exact)
    outside = np.zeros(B.shape[0], dtype=bool)
    for d in dirs:
        s = point(0.0)
        for j in range(n):
            if d[j] != 0.0:
                s = s + d[j] * X[j]
        h = _abs_sum(matmul(d[None, :], Z.generators)[0])
        outside |= (s.lo > h.hi) | (s.hi < -h.hi)
        inside &= (s.hi <= h.lo) & (s.lo >= -h.lo)
    return from_masks(inside & ~outside, outside)
