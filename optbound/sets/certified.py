"""Outward-rounded linear algebra for the zonotope types (and the observers of ``estimation``).

A float operation on a generator representation (``M @ G``, ``c1 + c2``, a substituted
constraint row) rounds, and the rounded set is not in general a superset of the exact one.
Every operation of :class:`~optbound.sets.Zonotope` and
:class:`~optbound.sets.ConstrainedZonotope` therefore computes its new data as
:class:`~optbound.interval.Interval` enclosures, keeps the midpoints and moves the rounding
into the set itself:

- a centre/generator error of radius ``r_i`` in row ``i`` becomes an extra generator
  ``r_i e_i`` (with a zero column in the constraints): ``c + G xi`` for any exact ``c, G`` in
  the enclosures lies in ``c_mid + G_mid xi + diag(r) eta`` (:func:`enclose`);
- an equality constraint ``a^T xi = beta`` known only as enclosures becomes
  ``a_mid^T xi - E s = beta_mid`` with a new ``s in [-1, 1]``, ``E >= sum |a - a_mid| +
  |beta - beta_mid|`` (:func:`relax_rows`): every exact solution satisfies the relaxed row.

Linear programs are solved by HiGHS in floats and then *certified* by weak duality
(:func:`max_bound`), evaluated in outward-rounded arithmetic, so a bound returned here holds
for the exact set whatever the solver's accuracy. The interval package and HiGHS are
imported on first use, so that ``import optbound`` stays light.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from optbound.interval import Interval


def point(x) -> Interval:
    """A float array as a point interval.

    Parameters
    ----------
    x : array_like
        Float values.

    Returns
    -------
    Interval
        The degenerate intervals ``[x, x]``.
    """
    from optbound.interval import Interval

    return Interval(np.asarray(x, dtype=float))


#: Unit roundoff of float64, and the smallest normal float (bounds an underflow's error).
_U = 2.0**-53
_TINY = float(np.finfo(float).tiny)


def _gamma(q: int) -> float:
    """A float above ``gamma_q / (1 - gamma_q)`` (``gamma_q = q u / (1 - q u)``, Higham's
    bound of a length-q dot product's relative error) with room for the few roundings of the
    radius formula itself: ``3 (q + 2) u``."""
    return 3.0 * (q + 2) * _U


def _mid_rad(M) -> tuple[np.ndarray, np.ndarray | None]:
    """Midpoint and a radius rounded up of a float array (radius None) or an Interval."""
    from optbound.interval import Interval

    if not isinstance(M, Interval):
        return np.asarray(M, dtype=float), None
    mid = 0.5 * M.lo + 0.5 * M.hi
    rad = np.nextafter(np.maximum(M.hi - mid, mid - M.lo), np.inf)
    return mid, (rad if np.any(rad) else None)


def matmul(M, X) -> Interval:
    """Enclosure of the exact product ``M @ X`` of 2-D float arrays or Intervals.

    Midpoint-radius arithmetic (Rump, *Fast and parallel interval arithmetic*, BIT 39, 1999):
    ``[mM ± rM] [mX ± rX] ⊆ mM mX ± (|mM| rX + rM (|mX| + rX))``. The float product
    ``C = fl(mM mX)`` is within ``gamma_q |mM| |mX|`` of the exact one for any summation
    order (``q`` the inner dimension; Higham, *Accuracy and Stability of Numerical
    Algorithms*, Sect. 3.5), and ``|mM| |mX| <= fl(|mM| |mX|) / (1 - gamma_q)``; the radius
    terms computed in floats are enlarged by the same factor, underflow by ``(q + 2)`` times
    the smallest normal float, and the ends ``C ∓ rad`` rounded outward by one ulp. Two BLAS
    products instead of q interval operations.

    Parameters
    ----------
    M : np.ndarray or Interval, shape (p, q)
        Left factor.
    X : np.ndarray or Interval, shape (q, r)
        Right factor.

    Returns
    -------
    Interval, shape (p, r)
        An enclosure of every exact product of members of M and X.

    Raises
    ------
    ValueError
        If the product overflows.
    """
    from optbound.interval import Interval

    mM, rM = _mid_rad(M)
    mX, rX = _mid_rad(X)
    p, q = mM.shape
    r = mX.shape[1]
    if q == 0:
        return point(np.zeros((p, r)))
    g = _gamma(q)
    C = mM @ mX
    aM, aX = np.abs(mM), np.abs(mX)
    rad = g * (aM @ aX)
    if rX is not None:
        rad = rad + (1.0 + g) * (aM @ rX)
    if rM is not None:
        rad = rad + (1.0 + g) * (rM @ (aX if rX is None else aX + rX))
    rad = np.nextafter(rad * (1.0 + 4.0 * _U), np.inf) + (q + 2) * _TINY
    lo, hi = np.nextafter(C - rad, -np.inf), np.nextafter(C + rad, np.inf)
    if np.isnan(lo).any() or np.isnan(hi).any():
        raise ValueError("the product overflowed (its enclosure has NaN bounds)")
    return Interval._make(lo, hi)  # lo <= hi, no NaN: checked above


def magnitude(iv: Interval) -> np.ndarray:
    """``max |x|`` over each interval (exact: a bound is a float).

    Parameters
    ----------
    iv : Interval
        The intervals.

    Returns
    -------
    np.ndarray
        The magnitudes, of the shape of ``iv``.
    """
    return np.maximum(-iv.lo, iv.hi)


def row_sum_up(mat: np.ndarray) -> np.ndarray:
    """Upper bound of the exact row sums of a non-negative (p, q) float array: the float sum
    is at least ``(1 - gamma_q)`` times the exact one (any order), so ``fl(sum) (1 + 3 (q +
    2) u)`` rounded up, plus the underflow term, bounds it (:func:`matmul`).

    Parameters
    ----------
    mat : np.ndarray, shape (p, q)
        Non-negative floats.

    Returns
    -------
    np.ndarray, shape (p,)
        Upper bounds of the exact row sums.
    """
    q = mat.shape[1]
    total = mat.sum(axis=1)
    return np.nextafter(total * (1.0 + _gamma(q)), np.inf) + (q + 2) * _TINY * (q > 0)


def split(iv: Interval) -> tuple[np.ndarray, np.ndarray]:
    """Midpoints and radii ``r >= |x - mid|`` for every x in each interval.

    Parameters
    ----------
    iv : Interval
        The intervals.

    Returns
    -------
    mid : np.ndarray
        The midpoints.
    rad : np.ndarray
        Radii rounded up.
    """
    mid = iv.midpoint()
    return mid, magnitude(iv - mid)


def enclose(c_iv: Interval, G_iv: Interval) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Float ``c, G`` and radii ``r`` with ``c' + G' xi in c + G xi + diag(r) eta``.

    For every exact ``c' in c_iv``, ``G' in G_iv`` and ``|xi|, |eta| <= 1``: the row-``i``
    error ``(c' - c)_i + (G' - G)_i xi`` is at most ``r_i`` in magnitude.

    Parameters
    ----------
    c_iv : Interval, shape (n,)
        Enclosure of the centre.
    G_iv : Interval, shape (n, m)
        Enclosure of the generators.

    Returns
    -------
    c : np.ndarray, shape (n,)
        Float centre.
    G : np.ndarray, shape (n, m)
        Float generators.
    r : np.ndarray, shape (n,)
        Error radius per row.
    """
    c, rc = split(c_iv)
    G, rG = split(G_iv)
    return c, G, row_sum_up(np.column_stack([rc, rG]))


def error_generators(r: np.ndarray) -> np.ndarray:
    """The generators ``r_i e_i`` of the non-zero radii (shape (n, k)).

    Parameters
    ----------
    r : np.ndarray, shape (n,)
        Non-negative radii.

    Returns
    -------
    np.ndarray, shape (n, k)
        One axis-aligned column per non-zero radius.
    """
    return np.diag(r)[:, r > 0]


def relax_rows(A_iv: Interval, b_iv: Interval) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Float rows ``A, b`` and slack radii ``E`` for constraints known as enclosures.

    Every ``xi`` with ``|xi| <= 1`` and ``A' xi = b'`` for some exact ``A' in A_iv``,
    ``b' in b_iv`` satisfies ``|(A xi - b)_k| <= E_k``; the caller adds a slack generator
    ``-E_k`` to row k (only where ``E_k > 0``).

    Parameters
    ----------
    A_iv : Interval, shape (nc, m)
        Enclosure of the constraint rows.
    b_iv : Interval, shape (nc,)
        Enclosure of the right-hand side.

    Returns
    -------
    A : np.ndarray, shape (nc, m)
        Float rows.
    b : np.ndarray, shape (nc,)
        Float right-hand side.
    E : np.ndarray, shape (nc,)
        Slack radius per row.
    """
    b, A, E = enclose(b_iv, A_iv)
    return A, b, E


def lower_dot(lam: np.ndarray, b: np.ndarray) -> float:
    """A lower bound of the exact ``lam^T b``.

    Parameters
    ----------
    lam : np.ndarray, shape (k,)
        Multipliers.
    b : np.ndarray, shape (k,)
        Right-hand side.

    Returns
    -------
    float
        A lower bound.
    """
    return float(matmul(lam[None, :], b[:, None]).lo[0, 0])


def l1_upper(f_iv: Interval, A: np.ndarray, lam: np.ndarray) -> float:
    """An upper bound of ``||f - A^T lam||_1`` over the exact ``f in f_iv``.

    Parameters
    ----------
    f_iv : Interval, shape (m,)
        Enclosure of the objective.
    A : np.ndarray, shape (nc, m)
        Constraint matrix.
    lam : np.ndarray, shape (nc,)
        Multipliers.

    Returns
    -------
    float
        An upper bound.
    """
    r = f_iv - matmul(A.T, lam[:, None])[:, 0]
    return float(row_sum_up(magnitude(r)[None, :])[0])


def max_bound(f_iv: Interval, A: np.ndarray, b: np.ndarray) -> float:
    """Certified upper bound of ``max {f^T xi : A xi = b, |xi|_inf <= 1}`` (``-inf``: empty).

    Weak duality: for *any* multiplier ``lam``, ``f^T xi = lam^T b + (f - A^T lam)^T xi <=
    lam^T b + ||f - A^T lam||_1`` on the feasible set. ``lam`` is HiGHS's equality dual; the
    bound is evaluated in outward-rounded arithmetic, so it holds even if the LP answer is
    inaccurate (a poor ``lam`` only loosens the bound). ``-inf`` only if :func:`proven_empty`.

    Parameters
    ----------
    f_iv : Interval, shape (m,)
        Enclosure of the objective.
    A : np.ndarray, shape (nc, m)
        Constraint matrix.
    b : np.ndarray, shape (nc,)
        Constraint right-hand side.

    Returns
    -------
    float
        The certified upper bound (``-inf`` if proven empty).
    """
    from optbound._core.linear_program import solve_lp

    nc = A.shape[0]
    if nc == 0:
        return float(row_sum_up(magnitude(f_iv)[None, :])[0])
    f = split(f_iv)[0]
    res = solve_lp(-f, A_eq=A, b_eq=b, lower=-1.0, upper=1.0)
    if res.optimal:
        lam = -res.eq_duals
    elif proven_empty(A, b):
        return -np.inf
    else:
        lam = np.zeros(nc)
    if not np.all(np.isfinite(lam)):
        lam = np.zeros(nc)
    bound = point(-lower_dot(-lam, b)) + l1_upper(f_iv, A, lam)
    return float(bound.hi)


def proven_empty(A: np.ndarray, b: np.ndarray) -> bool:
    """Whether ``{xi : A xi = b, |xi|_inf <= 1}`` is *proven* empty (a Farkas certificate).

    If ``lam^T b > ||A^T lam||_1`` no ``|xi| <= 1`` solves ``A xi = b`` (``lam^T A xi <=
    ||A^T lam||_1``). ``lam`` is the dual of ``min t s.t. A xi = b, |xi_j| <= t`` (whose
    dual is ``max lam^T b s.t. ||A^T lam||_1 <= 1``) or, if that LP fails, the least-squares
    residual ``b - A A^+ b``. Both sides are evaluated with outward rounding.

    Parameters
    ----------
    A : np.ndarray, shape (nc, m)
        Constraint matrix.
    b : np.ndarray, shape (nc,)
        Right-hand side.

    Returns
    -------
    bool
        True if a Farkas certificate proves emptiness; False means not proven.
    """
    from optbound._core.linear_program import least_inf_norm

    nc, m = A.shape
    if nc == 0:
        return False
    res = least_inf_norm(A, b)
    candidates = []
    if res.optimal:
        candidates.append(res.eq_duals)
    candidates.append(b - A @ np.linalg.lstsq(A, b, rcond=None)[0])
    zero = point(np.zeros(m))
    for lam in candidates:
        if np.all(np.isfinite(lam)) and lower_dot(lam, b) > l1_upper(zero, A, lam):
            return True
    return False


def affine_image(
    c: np.ndarray, G: np.ndarray, M: np.ndarray, t: np.ndarray | None
) -> tuple[np.ndarray, np.ndarray, int]:
    """Float ``c', G'`` with ``{M (c + G xi) + t} subset {c' + G' (xi, eta)}``.

    ``G'`` is ``M G`` (rounded) followed by the error generators; returns also their number.

    Parameters
    ----------
    c : np.ndarray, shape (n,)
        Centre.
    G : np.ndarray, shape (n, m)
        Generators.
    M : np.ndarray, shape (p, n)
        Linear map.
    t : np.ndarray, shape (p,) or None
        Translation.

    Returns
    -------
    c : np.ndarray, shape (p,)
        Float centre of the image.
    G : np.ndarray, shape (p, m + k)
        ``fl(M G)`` followed by the k error generators.
    k : int
        Number of error generators.
    """
    c_iv = matmul(M, c[:, None])[:, 0]
    if t is not None:
        c_iv = c_iv + t
    c_new, G_new, r = enclose(c_iv, matmul(M, G))
    extra = error_generators(r)
    return c_new, np.hstack([G_new, extra]), extra.shape[1]


def sum_centers(c1: np.ndarray, c2: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Float centre of ``c1 + c2`` and the error generators of its rounding.

    Parameters
    ----------
    c1 : np.ndarray, shape (n,)
        First centre.
    c2 : np.ndarray, shape (n,)
        Second centre.

    Returns
    -------
    c : np.ndarray, shape (n,)
        Float centre.
    extra : np.ndarray, shape (n, k)
        Error generators.
    """
    c, r = split(point(c1) + c2)
    return c, error_generators(r)


def compact(G: np.ndarray, A: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Merge parallel axis-aligned columns of the lifted generators ``(G; A)`` (a superset).

    A constrained zonotope is the slice ``{x : (x, 0) in <(c, -b), (G; A)>}`` of its lifted
    zonotope [Scott et al. 2016, Sect. 4.2], and columns ``r_1 e_i, r_2 e_i, ...`` of the
    lifted generators along one lifted axis sum to the single segment ``(|r_1| + |r_2| +
    ...) e_i`` (rounded up): a free rounding generator of a state row, or a slack of a
    constraint row. All-zero columns contribute nothing and are dropped. This keeps the
    rounding generators of a recursion from accumulating (a map's errors merge into the next
    noise box's generators, a strip's rounding slack into its own slack).

    Parameters
    ----------
    G : np.ndarray, shape (n, m)
        Generators.
    A : np.ndarray, shape (nc, m)
        Constraint matrix.

    Returns
    -------
    G : np.ndarray, shape (n, k)
        Generators after merging (``G`` itself if nothing merges).
    A : np.ndarray, shape (nc, k)
        Constraint matrix after merging.
    """
    L = np.vstack([G, A])
    nonzero = L != 0
    counts = nonzero.sum(axis=0)
    rows = np.argmax(nonzero, axis=0)
    drop = counts == 0
    merged = []
    single = counts == 1
    for i in np.flatnonzero(np.bincount(rows[single], minlength=L.shape[0]) >= 2):
        cols = np.flatnonzero(single & (rows == i))
        if cols.size >= 2:
            merged.append((cols[0], float(row_sum_up(np.abs(L[i, cols])[None, :])[0])))
            drop[cols[1:]] = True
    if not drop.any():
        return G, A
    L = L.copy()
    for k, radius in merged:
        L[rows[k], k] = radius
    L = L[:, ~drop]
    return L[: G.shape[0]], L[G.shape[0] :]
