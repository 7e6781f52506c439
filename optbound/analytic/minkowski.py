"""Outer ellipsoids of the Minkowski sum of two ellipsoids: the Schweppe family [HS96, eq. (14)].

For any kappa in (0, 1), the ellipsoid with centre ``c1 + c2`` and shape
``C1 / (1 - kappa) + C2 / kappa`` contains E1 + E2 (Schweppe, 1973). The criteria choose kappa:

- ``"volume"``: the exact minimizer of det. With p = (1 - kappa) / kappa it is the unique root
  of ``h(p) = sum_i p (p + 1) / (l_i + p) - n`` (l_i the generalized eigenvalues of
  ``C1 v = l C2 v``), which is increasing in p and bracketed by ``[sqrt(min l), sqrt(max l)]``;
  solved by safeguarded Newton to full precision. For two summands this member is the
  minimum-volume ellipsoid among all outer ellipsoids (Durieu, Walter & Polyak 2001).
- ``"trace"``: ``kappa = sqrt(tr C2) / (sqrt(tr C1) + sqrt(tr C2))`` (closed form).
- ``"size_xy_psi"``: the root of the cubic [HS96, eqs. (15)-(17)] for the size measure
  ``tr(proj_xy C) * tr(proj_psi C)``; ``dims = (planar, heading)`` selects the coordinates
  (default in 3-D: planar ``(0, 1)``, heading ``(2,)``, the pose ``(x, y, psi)`` of HS96).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from optbound.analytic import _batch
from optbound.analytic._roots import argmin_candidates, real_roots
from optbound.sets import _validate as v
from optbound.sets.ellipsoid import Ellipsoid

CRITERIA = ("volume", "trace", "size_xy_psi")
DEFAULT_XY_PSI = ((0, 1), (2,))
NEWTON_MAX_STEPS = 100


@dataclass(frozen=True)
class MinkowskiResult:
    """Outer ellipsoid of E1 + E2 and the Schweppe parameter kappa that produced it.

    The shape is computed from p = (1 - kappa) / kappa, so it stays accurate even when the
    reported kappa rounds to 0 or 1 (summands differing in size by ~1e16 or more).
    """

    ellipsoid: Ellipsoid
    kappa: float


@dataclass(frozen=True)
class MinkowskiBatch:
    """Batched result: ``centers`` (B, n), ``shapes`` (B, n, n), ``kappa`` (B,)."""

    centers: np.ndarray
    shapes: np.ndarray
    kappa: np.ndarray


def _xy_psi_dims(dims, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Validate ``dims = (planar, heading)``: two disjoint coordinate lists."""
    if dims is None:
        if n != 3:
            raise ValueError(
                f"dims=(planar, heading) is required for criterion='size_xy_psi' when dim={n} "
                "(the default ((0, 1), (2,)) is for 3-D poses)"
            )
        dims = DEFAULT_XY_PSI
    if not isinstance(dims, (tuple, list)) or len(dims) != 2:
        raise ValueError(f"dims must be a pair (planar, heading) of coordinate lists, got {dims}")
    planar = v.dims_index("dims[0] (planar)", dims[0], n)
    heading = v.dims_index("dims[1] (heading)", dims[1], n)
    if set(planar.tolist()) & set(heading.tolist()):
        raise ValueError(f"planar and heading coordinates must be disjoint, got {dims}")
    return planar, heading


def _p_volume(C1: np.ndarray, C2: np.ndarray) -> np.ndarray:
    """Exact min-volume p = (1 - kappa) / kappa: the root of the monotone h(p) (module doc)."""
    n = C1.shape[-1]
    L2 = np.linalg.cholesky(C2)
    X = np.linalg.solve(L2, C1)
    M = np.linalg.solve(L2, X.transpose(0, 2, 1))  # L2^-1 C1 L2^-T: same spectrum as C2^-1 C1
    lam = np.linalg.eigvalsh(0.5 * (M + M.transpose(0, 2, 1)))
    lam = np.maximum(lam, np.finfo(float).tiny)
    lo, hi = np.sqrt(lam[:, 0]), np.sqrt(lam[:, -1])
    p = np.sqrt(lo * hi)
    for _ in range(NEWTON_MAX_STEPS):
        pc = p[:, None]
        h = np.sum(pc * (pc + 1.0) / (lam + pc), axis=1) - n
        dh = np.sum((pc * pc + 2.0 * pc * lam + lam) / (lam + pc) ** 2, axis=1)
        lo = np.where(h < 0, p, lo)
        hi = np.where(h > 0, p, hi)
        step = p - h / dh
        # Fall back to bisection whenever Newton leaves the bracket.
        step = np.where((step > lo) & (step < hi), step, 0.5 * (lo + hi))
        step = np.where(h == 0, p, step)
        done = np.abs(step - p) <= 4.0 * np.finfo(float).eps * p
        p = step
        if done.all():
            break
    return p


def _p_trace(C1: np.ndarray, C2: np.ndarray) -> np.ndarray:
    """p = sqrt(tr C1 / tr C2), i.e. kappa = sqrt(tr C2) / (sqrt(tr C1) + sqrt(tr C2))."""
    return np.sqrt(np.trace(C1, axis1=1, axis2=2) / np.trace(C2, axis1=1, axis2=2))


def _p_xy_psi(C1: np.ndarray, C2: np.ndarray, planar, heading) -> np.ndarray:
    """p of the root of the cubic [HS96, eqs. (16)-(17)] minimizing tr(proj_xy C) tr(proj_psi C)."""

    def block_trace(C, idx):
        return np.trace(C[:, idx][:, :, idx], axis1=1, axis2=2)

    t1, t2 = block_trace(C1, planar), block_trace(C2, planar)
    h1, h2 = block_trace(C1, heading), block_trace(C2, heading)
    m11, m22, m12, m21 = t1 * h1, t2 * h2, t1 * h2, t2 * h1  # M_AB [HS96, eq. (15)]
    coeffs = np.column_stack(
        [
            2.0 * (m11 + m22 - m12 - m21),
            3.0 * (m12 + m21 - 2.0 * m22),
            6.0 * m22 - m12 - m21,
            -2.0 * m22,
        ]
    )
    roots, real = real_roots(coeffs)
    # The trace-optimal kappa is an always-valid extra candidate (a safety net, never worse).
    candidates = np.column_stack([roots, 1.0 / (1.0 + _p_trace(C1, C2))])
    allowed = np.column_stack([real & (roots > 0) & (roots < 1), np.ones(len(t1), dtype=bool)])

    def size(k):
        return (t1[:, None] / (1 - k) + t2[:, None] / k) * (h1[:, None] / (1 - k) + h2[:, None] / k)

    kappa = argmin_candidates(candidates, allowed, size)
    return (1.0 - kappa) / kappa


def _check_kappa(kappa, n_batch: int) -> np.ndarray:
    k = _batch.per_instance("kappa", kappa, n_batch, ())
    if np.any((k <= 0) | (k >= 1)):
        raise ValueError(f"kappa must lie in the open interval (0, 1), got {kappa}")
    return k


def _sum_core(c1, C1, c2, C2, criterion: str, kappa, dims) -> MinkowskiBatch:
    """Shared core of the single and batched sums; inputs are already validated arrays."""
    if criterion not in CRITERIA:
        raise ValueError(f"criterion must be one of {CRITERIA}, got {criterion!r}")
    if kappa is not None:
        k = _check_kappa(kappa, c1.shape[0])
        p = (1.0 - k) / k
    else:
        if criterion == "volume":
            p = _p_volume(C1, C2)
        elif criterion == "trace":
            p = _p_trace(C1, C2)
        else:
            p = _p_xy_psi(C1, C2, *_xy_psi_dims(dims, c1.shape[1]))
        k = 1.0 / (1.0 + p)
    # C1 / (1 - kappa) + C2 / kappa written in p = (1 - kappa) / kappa: no 1 / (1 - kappa)
    # overflow when kappa rounds to 1 for very differently sized summands.
    shapes = (1.0 + p)[:, None, None] * (C1 / p[:, None, None] + C2)
    return MinkowskiBatch(centers=c1 + c2, shapes=shapes, kappa=k)


def minkowski_sum(
    E1: Ellipsoid, E2: Ellipsoid, criterion: str = "volume", kappa=None, dims=None
) -> MinkowskiResult:
    """Outer ellipsoid of the Minkowski sum ``E1 + E2`` [HS96, eq. (14)].

    Parameters
    ----------
    E1, E2 : Ellipsoid
        Summands of the same dimension.
    criterion : {"volume", "trace", "size_xy_psi"}
        Size measure minimized over kappa (see the module docstring).
    kappa : float, optional
        Explicit Schweppe parameter in (0, 1); overrides the criterion.
    dims : pair of coordinate lists, optional
        ``(planar, heading)`` for ``"size_xy_psi"`` [HS96, eq. (15)]; default ``((0, 1), (2,))``
        in 3-D, required otherwise.

    Returns
    -------
    MinkowskiResult
        ``ellipsoid`` contains E1 + E2 for every kappa; ``kappa`` is the value used.

    Raises
    ------
    ValueError
        On dimension mismatch, unknown criterion, kappa outside (0, 1), or invalid dims.
    """
    if E1.dim != E2.dim:
        raise ValueError(f"E1 and E2 must have the same dimension, got {E1.dim} and {E2.dim}")
    out = _sum_core(
        E1.center[None], E1.shape[None], E2.center[None], E2.shape[None], criterion, kappa, dims
    )
    return MinkowskiResult(Ellipsoid(out.centers[0], out.shapes[0]), float(out.kappa[0]))


def minkowski_sum_batch(
    centers1, shapes1, centers2, shapes2, criterion: str = "volume", kappa=None, dims=None
) -> MinkowskiBatch:
    """Vectorized :func:`minkowski_sum` over B pairs.

    Parameters
    ----------
    centers1, centers2 : array_like, shape (B, n)
    shapes1, shapes2 : array_like, shape (B, n, n)
        Symmetric positive-definite shape matrices.
    criterion, dims
        As in :func:`minkowski_sum`.
    kappa : float or array_like of shape (B,), optional
        Explicit Schweppe parameters in (0, 1).
    """
    c1, C1 = _batch.ellipsoid_stack("centers1", centers1, "shapes1", shapes1)
    c2, C2 = _batch.ellipsoid_stack("centers2", centers2, "shapes2", shapes2)
    if c1.shape != c2.shape:
        raise ValueError(
            f"centers1 and centers2 must have the same shape, got {c1.shape}, {c2.shape}"
        )
    return _sum_core(c1, C1, c2, C2, criterion, kappa, dims)
