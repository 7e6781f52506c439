"""Gains of the zonotopic strip update of Alamo, Bravo & Camacho (Automatica 2005, Property 3).

For a zonotope ``<c, G>`` (G of shape (n, m)) and the strip ``|a^T x - mid| <= s``, every
gain ``lam`` gives the guaranteed enclosure ``X(lam) = <c + lam (mid - a^T c),
[(I - lam a^T) G, s lam]>`` of their intersection; the gain only decides its size.

- :func:`frobenius_gain`: ``lam = G G^T a / (a^T G G^T a + s^2)``, the minimiser of the
  Frobenius norm of the generator matrix (Alamo et al.'s F-radius; for one output row it is also
  the covariation-trace gain of Combastel 2015).
- :func:`volume_gain`: the minimiser of the *volume* of ``X(lam)``, the size criterion that
  Alamo et al. (2005, Sect. 5) weigh against the F-radius. By the zonotope volume formula
  ``vol = 2^n sum_S |det H_S|`` over n-subsets S of the generators H (Shephard 1974) and column
  operations (subtract multiples of the column ``s lam``; ``det (I - lam a^T) = 1 - a^T lam``)::

      vol(X(lam)) / 2^n = |1 - a^T lam| sum_{|S|=n} |det G_S|
                          + s sum_{|T|=n-1} |det [G_T, lam]|,

  a sum of absolute values of affine functions of ``lam`` (``det [G_T, lam] = d_T^T lam``,
  d_T the cofactor vector). Its minimiser is the solution of a linear program (an L1
  fit), solved with HiGHS. Any lam is guaranteed, so the LP needs no certification: only the
  enclosure of the new data is certified (``observers.alamo_strip``). The number of subsets,
  ``C(m, n) + C(m, n-1)``, limits this gain to small n or low order (``MAX_SUBSETS``).
"""

from __future__ import annotations

from itertools import combinations
from math import comb

import numpy as np

from optbound._core.linear_program import solve_lp

MAX_SUBSETS = 20000
GAINS = ("frobenius", "volume")


def frobenius_gain(G: np.ndarray, a: np.ndarray, s: float) -> np.ndarray:
    """Alamo et al.'s F-radius gain (module docstring); zero when ``G^T a`` and s vanish.

    Parameters
    ----------
    G : numpy.ndarray, shape (n, m)
        The generator matrix of the zonotope.
    a : numpy.ndarray, shape (n,)
        The strip's normal.
    s : float
        The strip's half-width (``|a^T x - mid| <= s``).

    Returns
    -------
    numpy.ndarray, shape (n,)
        ``lam = G G^T a / (a^T G G^T a + s^2)``.

    Notes
    -----
    The Frobenius norm of ``[(I - lam a^T) G, s lam]`` is a convex quadratic in ``lam``; its
    minimiser is the formula above (Alamo et al. [1]_, Sect. 5; for one output row it is also
    the covariation-trace gain of Combastel [2]_).

    References
    ----------
    .. [1] T. Alamo, J. M. Bravo, E. F. Camacho, "Guaranteed state estimation by zonotopes",
       Automatica 41(6), 2005.
    .. [2] C. Combastel, "Zonotopes and Kalman observers: Gain optimality under distinct
       uncertainty paradigms and robust convergence", Automatica 55, 2015.
    """
    Ga = G.T @ a
    denom = float(Ga @ Ga + s * s)
    return (G @ Ga) / denom if denom > 0.0 else np.zeros(G.shape[0])


def _cofactors(M: np.ndarray) -> np.ndarray:
    """d with ``det [M, x] = d^T x`` for M of shape (n, n-1) (expansion along the last column)."""
    n = M.shape[0]
    return np.array(
        [(-1.0) ** (i + n - 1) * np.linalg.det(np.delete(M, i, axis=0)) for i in range(n)]
    )


def volume_terms(G: np.ndarray) -> tuple[float, np.ndarray]:
    """``sum_{|S|=n} |det G_S|`` and the cofactor vectors d_T (rows) of the module docstring.

    Parameters
    ----------
    G : numpy.ndarray, shape (n, m)
        The generator matrix of the zonotope.

    Returns
    -------
    base : float
        ``sum_{|S|=n} |det G_S|`` over the n-subsets S of the generators.
    d : numpy.ndarray, shape (C(m, n-1), n)
        One cofactor vector per (n-1)-subset T, ``det [G_T, x] = d_T^T x``.

    Raises
    ------
    ValueError
        If ``C(m, n) + C(m, n-1)`` exceeds :data:`MAX_SUBSETS`.
    """
    n, m = G.shape
    if comb(m, n) + comb(m, n - 1) > MAX_SUBSETS:
        raise ValueError(
            f"the volume gain needs C(m, n) + C(m, n-1) <= {MAX_SUBSETS} generator subsets, got "
            f"m = {m} generators in dimension n = {n}: lower the order"
        )
    base = sum(abs(np.linalg.det(G[:, list(S)])) for S in combinations(range(m), n))
    if n == 1:
        return float(base), np.ones((1, 1))
    d = np.array([_cofactors(G[:, list(T)]) for T in combinations(range(m), n - 1)])
    return float(base), d


def volume_of_gain(G: np.ndarray, a: np.ndarray, s: float, lam: np.ndarray) -> float:
    """``vol(X(lam)) / 2^n`` by the formula of the module docstring (floats, for comparisons).

    Parameters
    ----------
    G : numpy.ndarray, shape (n, m)
        The generator matrix of the zonotope.
    a : numpy.ndarray, shape (n,)
        The strip's normal.
    s : float
        The strip's half-width (``|a^T x - mid| <= s``).
    lam : numpy.ndarray, shape (n,)
        The gain.

    Returns
    -------
    float
        ``|1 - a^T lam| sum_S |det G_S| + s sum_T |d_T^T lam|`` (not certified).

    Raises
    ------
    ValueError
        If there are too many generator subsets (:func:`volume_terms`).
    """
    base, d = volume_terms(G)
    return abs(1.0 - a @ lam) * base + s * float(np.sum(np.abs(d @ lam)))


def volume_gain(G: np.ndarray, a: np.ndarray, s: float) -> np.ndarray:
    """The gain minimising the volume of ``X(lam)`` (module docstring), by linear programming:
    minimise ``base t_0 + s sum_T t_T`` subject to ``t_0 >= |1 - a^T lam|``, ``t_T >= |d_T^T
    lam|``.

    Parameters
    ----------
    G : numpy.ndarray, shape (n, m)
        The generator matrix of the zonotope.
    a : numpy.ndarray, shape (n,)
        The strip's normal.
    s : float
        The strip's half-width (``|a^T x - mid| <= s``).

    Returns
    -------
    numpy.ndarray, shape (n,)
        The volume-minimising gain (any gain gives a guaranteed enclosure, so the LP's float
        solution needs no certificate).

    Raises
    ------
    ValueError
        If there are too many generator subsets (:func:`volume_terms`) or the LP fails.

    References
    ----------
    .. [1] T. Alamo, J. M. Bravo, E. F. Camacho, "Guaranteed state estimation by zonotopes",
       Automatica 41(6), 2005.
    """
    n = G.shape[0]
    base, d = volume_terms(G)
    k = d.shape[0]
    # variables: lam (n), t_0, t_T (k)
    cost = np.concatenate([np.zeros(n), [base], np.full(k, s)])
    rows = [np.concatenate([-a, [-1.0], np.zeros(k)]), np.concatenate([a, [-1.0], np.zeros(k)])]
    rhs = [-1.0, 1.0]
    eye = np.eye(k)
    for j in range(k):
        rows.append(np.concatenate([d[j], [0.0], -eye[j]]))
        rows.append(np.concatenate([-d[j], [0.0], -eye[j]]))
        rhs += [0.0, 0.0]
    lower = np.r_[np.full(n, -np.inf), np.zeros(k + 1)]
    res = solve_lp(cost, A_ub=np.array(rows), b_ub=np.array(rhs), lower=lower)
    if not res.optimal:
        raise ValueError(f"the volume-gain LP failed: HiGHS reports {res.status!r}")
    return res.x[:n]
