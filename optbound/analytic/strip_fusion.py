"""Outer ellipsoid of an ellipsoid intersected with a strip [HS96, eqs. (24)-(30)].

For E = {x : (x - c)^T C^{-1} (x - c) <= 1} and the strip S = {x : |a^T x - b| <= 1}
[HS96, eq. (23)], every lambda >= 0 gives the ellipsoid [HS96, eq. (24)]

    eps = b - a^T c,   G = a^T C a,   u = 1 + lambda G,
    C0  = C - lambda C a a^T C / u,   centre = c + lambda eps C a / u,
    K   = 1 + lambda - lambda eps^2 / u,   shape = K C0,

which contains E ∩ S [HS96, eq. (25)]; so every result here is a guaranteed outer bound and the
criteria only choose *which* member. The four cases of [HS96, Fig. 1] compare the strip's
interval ``[b - 1, b + 1]`` for a^T x with the ellipsoid's ``[a^T c - sqrt(G), a^T c + sqrt(G)]``.

Conventions of this module (numerical decisions, all conservative):

- ``clip=True`` first clips each plane to the ellipsoid's extent (a plane missing the ellipsoid
  moves to the tangent plane). This does not change E ∩ S but shrinks the result a lot in the
  partial case.
- The strip used for fusion is never thinner than ``MIN_REL_WIDTH`` times the ellipsoid's extent
  along a (it is widened, which can only enlarge the bound). This keeps the shape matrix well
  conditioned, and handles a plane that merely *touches* E: the intersection is a single point,
  and the result is a thin ellipsoid containing it (case "partial", consistency 0).
- The strip is declared disjoint ("inconsistent", no ellipsoid) only when the gap exceeds
  ``TOUCH_RTOL`` relative to the problem's scale; a smaller gap is treated as touching.
- If rounding makes a chosen member degenerate (K <= 0), lambda falls back to 0 (E itself).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.special import expit

from optbound.analytic import _batch
from optbound.analytic._roots import argmin_candidates, real_roots
from optbound.sets import _validate as v
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.strip import Strip

CASES = ("no_reduction", "consistent", "partial", "inconsistent")
NO_REDUCTION, CONSISTENT, PARTIAL, INCONSISTENT = range(4)
CRITERIA = ("volume", "trace", "projection", "robust")
MIN_REL_WIDTH = 1e-6
TOUCH_RTOL = 1e-12
K_RTOL = 1e-12


@dataclass(frozen=True)
class StripFusion:
    """Result of :func:`intersect_strip`.

    Attributes
    ----------
    ellipsoid : Ellipsoid or None
        Outer bound of E ∩ S; None when the sets are disjoint.
    lam : float
        The lambda of [HS96, eq. (24)] that was used (0 for "no_reduction"/"inconsistent").
    case : str
        One of ``CASES`` [HS96, Fig. 1].
    consistency : float
        Consistency measure [HS96, eq. (29)] in [0, 1]; 0 when inconsistent.
    """

    ellipsoid: Ellipsoid | None
    lam: float
    case: str
    consistency: float


@dataclass(frozen=True)
class StripFusionBatch:
    """Batched result of :func:`intersect_strip_batch`.

    ``centers`` (B, n) and ``shapes`` (B, n, n) are zero where ``empty`` (B,) is True;
    ``lam`` (B,), ``case`` (B,) integer codes into ``CASES``, ``consistency`` (B,).
    """

    centers: np.ndarray
    shapes: np.ndarray
    lam: np.ndarray
    case: np.ndarray
    consistency: np.ndarray
    empty: np.ndarray


# ------------------------------------------------------------------------ choice of lambda
def _lam_volume(G: np.ndarray, eps: np.ndarray, n: int) -> np.ndarray:
    """Most positive root of [HS96, eq. (26)] with N = n; 0 if there is none.

    A positive root exists iff G > n (1 - eps^2) (constant term negative, leading term
    positive); the roots have opposite signs then, and the stable quadratic formula is used.
    """
    qa = (n - 1) * G * G
    qb = (2 * n - 1 + eps * eps - G) * G
    qc = n * (1 - eps * eps) - G
    root = np.zeros_like(G)
    pos = qc < 0
    sq = np.sqrt(qb[pos] ** 2 - 4 * qa[pos] * qc[pos])
    root[pos] = np.where(
        qb[pos] >= 0, 2 * qc[pos] / (-qb[pos] - sq), (-qb[pos] + sq) / (2 * qa[pos])
    )
    return root


def _shape_factor(lam, G, eps):
    """K of [HS96, eq. (24)] for candidate arrays lam (B, k) and per-instance G, eps (B,)."""
    u = 1 + lam * G[:, None]
    return 1 + lam - lam * eps[:, None] ** 2 / u


def _best_root(coeffs, size) -> np.ndarray:
    """The nonnegative real root (or 0) with the smallest ``size``."""
    roots, real = real_roots(coeffs)
    candidates = np.column_stack([np.zeros(len(coeffs)), roots])
    allowed = np.column_stack([np.ones(len(coeffs), dtype=bool), real & (roots > 0)])
    return argmin_candidates(candidates, allowed, size)


def _lam_projection(C, w, G, eps, idx) -> np.ndarray:
    """Root of the cubic [HS96, eq. (27)] minimizing the projection's volume [HS96, eq. (34)]."""
    L = idx.size
    P = C[:, idx][:, :, idx]
    wd = w[:, idx]
    H = np.einsum("bi,bi->b", wd, np.linalg.solve(P, wd[:, :, None])[:, :, 0])  # eq. (28)
    H = np.clip(H, 0.0, G)  # 0 <= H <= G up to rounding
    e2 = eps * eps
    coeffs = np.column_stack(
        [
            (G - H) * G * G * L,
            (L * (3 * G - 2 * H) - H) * G,
            (3 * G - H + e2 * (H - G)) * L - G * H - H + e2 * H,
            L * (1 - e2) - H,
        ]
    )

    def size(lam):
        K = _shape_factor(lam, G, eps)
        logK = np.where(K > 0, np.log(np.where(K > 0, K, 1.0)), np.inf)
        return L * logK + np.log1p(lam * (G - H)[:, None]) - np.log1p(lam * G[:, None])

    return _best_root(coeffs, size)


def _lam_trace(C, w, G, eps) -> np.ndarray:
    """Root of the cubic d/dlambda [K tr C0] = 0 (derived from [HS96, eq. (24)])."""
    T = np.trace(C, axis1=1, axis2=2)
    W = np.einsum("bi,bi->b", w, w)
    e2 = eps * eps
    D = G * T - W  # >= 0 by Cauchy-Schwarz
    coeffs = np.column_stack(
        [
            G * G * D,
            3 * G * D,
            -G * T * e2 + 3 * G * T - G * W + 2 * W * e2 - 2 * W,
            T * (1 - e2) - W,
        ]
    )

    def size(lam):
        u = 1 + lam * G[:, None]
        K = _shape_factor(lam, G, eps)
        return np.where(K > 0, K * (T[:, None] - lam * W[:, None] / u), np.inf)

    return _best_root(coeffs, size)


# ----------------------------------------------------------------------------- the core
def _fuse(c, C, a, b, criterion, dims, lam, clip, steepness, midpoint) -> StripFusionBatch:
    """Shared core of :func:`intersect_strip` and :func:`intersect_strip_batch` (valid arrays)."""
    n_batch, n = c.shape
    if criterion not in CRITERIA:
        raise ValueError(f"criterion must be one of {CRITERIA}, got {criterion!r}")
    if n < 2:
        raise ValueError("strip fusion needs dimension >= 2 (in 1-D E ∩ S is an interval)")
    idx = None if dims is None else v.dims_index("dims", dims, n)
    if criterion == "projection" and idx is None:
        raise ValueError("dims is required for criterion='projection' (the subspace to project on)")
    if lam is not None:
        lam = _batch.per_instance("lam", lam, n_batch, ())
        if np.any(lam < 0):
            raise ValueError(
                f"lam must be >= 0 (every lambda >= 0 gives an outer bound), got {lam}"
            )

    w = np.einsum("bij,bj->bi", C, a)  # C a
    G = np.einsum("bi,bi->b", a, w)
    g = np.sqrt(G)  # half-extent of E along a, in strip units
    ac = np.einsum("bi,bi->b", a, c)
    lo, hi = b - ac - 1, b - ac + 1  # strip interval relative to a^T c

    # Cases [HS96, Fig. 1]; a gap below the tolerance counts as touching, never as empty.
    lower_cuts = (-g < lo) & (lo < g)
    upper_cuts = (-g < hi) & (hi < g)
    covers = (lo <= -g) & (hi >= g)
    gap = np.maximum(lo - g, -g - hi)
    empty = gap > TOUCH_RTOL * (g + np.abs(b) + np.abs(ac))
    case = np.where(lower_cuts & upper_cuts, CONSISTENT, PARTIAL)
    case = np.where(covers, NO_REDUCTION, np.where(empty, INCONSISTENT, case))

    # Consistency [HS96, eq. (29)]: widths along a of E ∩ S (W_E), E (W_P = 2g) and S (W_M = 2).
    overlap = np.clip(np.minimum(hi, g) - np.maximum(lo, -g), 0.0, None)
    consistency = np.clip(overlap / (2.0 * np.sqrt(g)), 0.0, 1.0)

    # The strip actually fused: optionally clipped to E's extent, never thinner than the floor.
    if clip:
        lo, hi = np.maximum(lo, -g), np.minimum(hi, g)
    width = np.maximum(hi - lo, MIN_REL_WIDTH * 2 * g)
    mid = 0.5 * (lo + hi)
    if clip:
        mid = np.clip(mid, -g + 0.5 * width, g - 0.5 * width)
    half = 0.5 * width
    # Normalized strip |a'^T x - b'| <= 1 with a' = a / half: eps' = mid / half, G' = G / half^2.
    eps = mid / half
    Gs = G / half**2
    ws = w / half[:, None]

    if lam is None:
        # "robust" scales the volume- (with dims: projection-) optimal lambda.
        if criterion == "trace":
            lam = _lam_trace(C, ws, Gs, eps)
        elif criterion == "projection" or (criterion == "robust" and idx is not None):
            lam = _lam_projection(C, ws, Gs, eps, idx)
        else:
            lam = _lam_volume(Gs, eps, n)
        if criterion == "robust":
            lam = lam * expit(steepness * (consistency - midpoint))  # [HS96, eq. (30)]
    lam = np.where((case == NO_REDUCTION) | empty, 0.0, lam)

    u = 1 + lam * Gs
    K = 1 + lam - lam * eps**2 / u
    degenerate = K <= K_RTOL * (1 + lam)  # rounding only: fall back to E itself
    lam = np.where(degenerate, 0.0, lam)
    u = np.where(degenerate, 1.0, u)
    K = np.where(degenerate, 1.0, K)

    gamma = lam / u
    shapes = K[:, None, None] * (C - gamma[:, None, None] * ws[:, :, None] * ws[:, None, :])
    centers = c + (gamma * eps)[:, None] * ws
    shapes = 0.5 * (shapes + shapes.transpose(0, 2, 1))
    shapes[empty] = 0.0
    centers[empty] = 0.0
    return StripFusionBatch(centers, shapes, lam, case.astype(np.int8), consistency, empty)


def _robust_params(steepness, midpoint) -> tuple[float, float]:
    return v.finite_scalar("steepness", steepness), v.finite_scalar("midpoint", midpoint)


def intersect_strip(
    E: Ellipsoid,
    S: Strip,
    criterion: str = "volume",
    dims=None,
    lam: float | None = None,
    clip: bool = True,
    steepness: float = 10.0,
    midpoint: float = 0.5,
) -> StripFusion:
    """Outer ellipsoid of ``E ∩ S`` from the family [HS96, eq. (24)].

    Parameters
    ----------
    E : Ellipsoid
        Prior (predicted) set, dimension n >= 2.
    S : Strip
        Measurement strip ``|a^T x - b| <= 1`` [HS96, eq. (23)].
    criterion : {"volume", "trace", "projection", "robust"}
        ``"volume"``: most positive root of [HS96, eq. (26)] with N = n (lambda = 0 if none;
        a positive root exists iff G > n (1 - eps^2)). ``"trace"``: minimizes tr(shape).
        ``"projection"``: minimizes the volume of the projection onto the coordinates ``dims``,
        [HS96, eqs. (27)-(28)]. ``"robust"``: ``lambda_opt / (1 + exp(-S (CM - M)))``
        [HS96, eq. (30)] with CM the consistency measure [HS96, eq. (29)] and lambda_opt the
        volume-optimal lambda (projection-optimal when ``dims`` is given).
    dims : sequence of int, optional
        Coordinate subspace; required for ``"projection"``.
    lam : float, optional
        Explicit lambda >= 0; overrides the criterion. It refers to the strip actually fused
        (the clipped one when ``clip=True``); ignored for "no_reduction" and "inconsistent".
    clip : bool
        Clip the strip to E's extent first (see the module docstring).
    steepness, midpoint : float
        S and M of [HS96, eq. (30)] (paper values 10 and 0.5).

    Returns
    -------
    StripFusion
        ``ellipsoid`` (None if E and S are disjoint), ``lam``, ``case``, ``consistency``.

    Raises
    ------
    ValueError
        Dimension mismatch, unknown criterion, missing or invalid ``dims``, negative ``lam``.
    """
    if E.dim != S.dim:
        raise ValueError(f"E and S must have the same dimension, got {E.dim} and {S.dim}")
    out = _fuse(
        E.center[None],
        E.shape[None],
        S.a[None],
        np.array([S.b]),
        criterion,
        dims,
        lam,
        clip,
        *_robust_params(steepness, midpoint),
    )
    case = int(out.case[0])
    if out.empty[0]:
        ellipsoid = None
    elif case == NO_REDUCTION:
        ellipsoid = E
    else:
        ellipsoid = Ellipsoid(out.centers[0], out.shapes[0])
    return StripFusion(ellipsoid, float(out.lam[0]), CASES[case], float(out.consistency[0]))


def intersect_strip_batch(
    centers,
    shapes,
    a,
    b,
    criterion: str = "volume",
    dims=None,
    lam=None,
    clip: bool = True,
    steepness: float = 10.0,
    midpoint: float = 0.5,
) -> StripFusionBatch:
    """Vectorized :func:`intersect_strip` over B instances (no Python loop over B).

    Parameters
    ----------
    centers : array_like, shape (B, n)
    shapes : array_like, shape (B, n, n)
        Symmetric positive-definite shape matrices.
    a : array_like, shape (n,) or (B, n)
        Strip normals (shared or per instance), non-zero.
    b : float or array_like of shape (B,)
        Strip offsets.
    criterion, dims, clip, steepness, midpoint
        As in :func:`intersect_strip`.
    lam : float or array_like of shape (B,), optional
        Explicit lambdas >= 0.

    Returns
    -------
    StripFusionBatch
    """
    c, C = _batch.ellipsoid_stack("centers", centers, "shapes", shapes)
    n_batch, n = c.shape
    a = _batch.per_instance("a", a, n_batch, (n,))
    if np.any(~a.any(axis=1)):
        raise ValueError("a must be non-zero for every instance")
    b = _batch.per_instance("b", b, n_batch, ())
    return _fuse(c, C, a, b, criterion, dims, lam, clip, *_robust_params(steepness, midpoint))
