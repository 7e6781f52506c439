"""Certified conversions between ellipsoids and zonotopes.

Both directions rest on support functions: a set contains another with the same centre iff its
support function dominates, and for a zonotope ``<c, G>`` and an ellipsoid ``E(c, Q)``

    h_Z(d) - d^T c = ||G^T d||_1 >= ||G^T d||_2 = sqrt(d^T G G^T d),
    h_E(d) - d^T c = sqrt(d^T Q d).

The float data are verified with outward-rounded interval arithmetic (Frobenius norms bound
spectral norms), so the containments hold for the floats read as exact numbers.
"""

from __future__ import annotations

import numpy as np

from optbound.interval import Interval
from optbound.sets.certified import magnitude, matmul, point, row_sum_up


def _transpose(iv: Interval) -> Interval:
    return Interval(iv.lo.T, iv.hi.T)


def _frobenius_up(iv: Interval) -> float:
    """Upper bound of the Frobenius norm of every matrix in ``iv``."""
    mag = point(magnitude(iv).ravel())
    return float(np.sqrt(point(row_sum_up((mag * mag).hi[None, :]))).hi[0])


def _gram_distance(W: np.ndarray, M: np.ndarray, mu: float) -> float:
    """Upper bound of ``||W M M^T W^T - mu I||_2`` (``M`` of shape (n, k))."""
    K = matmul(W, M)
    return _frobenius_up(matmul(K, _transpose(K)) - mu * np.eye(W.shape[0]))


def ellipsoid_generators(E) -> np.ndarray:
    """Generators ``G = s L`` (L the Cholesky factor of E's shape) with ``E subset <c, G>``.

    With ``W = L^{-1}`` (floats), ``delta >= ||W Q W^T - I||_2`` gives ``W Q W^T <= (1 +
    delta) I``; ``s`` is raised until ``W G G^T W^T >= (mu - delta_G) I >= (1 + delta) I``
    is proven, ``delta_G >= ||W G G^T W^T - mu I||_2``. Then ``G G^T >= Q`` (W is
    invertible), so ``h_Z >= h_E`` (module docstring). ``s`` is 1 up to a few rounding
    units: the parallelotope circumscribing E along its Cholesky axes.

    Parameters
    ----------
    E : Ellipsoid
        The ellipsoid enclosed.

    Returns
    -------
    np.ndarray, shape (n, n)
        Generators of a parallelotope centred at E's centre containing E.

    Raises
    ------
    ValueError
        If E is too ill-conditioned for the containment to be proven.
    """
    L, W = E.chol, E.chol_inv
    K = matmul(W, E.shape)
    delta = _frobenius_up(matmul(K, point(W.T)) - np.eye(E.dim))
    target = float((point(1.0) + delta).hi)
    s = float(np.sqrt(target)) * (1.0 + 4.0 * np.finfo(float).eps)
    for _ in range(60):
        G = s * L
        mu = s * s
        if float((point(mu) - _gram_distance(W, G, mu)).lo) >= target:
            return G
        s *= 1.0 + max(delta, 16.0 * np.finfo(float).eps)
    raise ValueError("E is too ill-conditioned to certify an enclosing parallelotope")


def zonotope_ellipsoid_shape(G: np.ndarray, weights: str = "norms") -> np.ndarray:
    """Shape ``Q >= (sum_i w_i) sum_i g_i g_i^T / w_i``, so ``Z subset E(c, Q)``;
    ``weights="norms"``: ``w_i = ||g_i||_2`` (the trace-minimal member), ``"unit"``:
    ``w_i = 1``, ``Q = m G G^T`` (for a parallelotope, m = n, the minimum-volume ellipsoid).

    Proof: for x - c = sum_i xi_i g_i, ``|d^T (x - c)| <= sum_i |d^T g_i|`` and by
    Cauchy-Schwarz ``(sum_i |d^T g_i|)^2 <= (sum_i w_i)(sum_i (d^T g_i)^2 / w_i) = d^T Q d``
    for any weights ``w_i > 0`` (``w_i = 1`` gives ``Q = m G G^T``; the norms minimise the
    trace). Q is enclosed in interval arithmetic and its diagonal raised by an upper bound of
    the Frobenius norm of the enclosure's radius, which dominates the spectral error.

    Parameters
    ----------
    G : np.ndarray, shape (n, m)
        Generators.
    weights : {"norms", "unit"}, default "norms"
        The weights ``w_i``.

    Returns
    -------
    np.ndarray, shape (n, n)
        The symmetric shape matrix Q.

    Raises
    ------
    ValueError
        If the generators do not span R^n (a flat zonotope has no full-dimensional
        enclosing ellipsoid of this form), or ``weights`` is unknown.
    """
    G = G[:, np.any(G != 0, axis=0)]
    n = G.shape[0]
    if G.shape[1] < n or np.linalg.matrix_rank(G) < n:
        raise ValueError("the zonotope is flat (G has rank < n): it has no outer ellipsoid here")
    if weights not in ("norms", "unit"):
        raise ValueError(f"weights must be 'norms' or 'unit', got {weights!r}")
    w = np.linalg.norm(G, axis=0) if weights == "norms" else np.ones(G.shape[1])
    total = point(row_sum_up(w[None, :]))
    scaled = Interval(G) / w * total
    Q_iv = matmul(scaled, point(G.T))
    Q = Q_iv.midpoint()
    Q = np.triu(Q) + np.triu(Q, 1).T
    rho = _frobenius_up(Q_iv - Q)
    diag = (point(np.diag(Q)) + rho).hi
    return Q - np.diag(np.diag(Q)) + np.diag(diag)
