"""Lower bounds on the true optimal outer ellipsoid, from points of the set.

Any ellipsoid that contains a set contains every finite subset of it, so a lower bound on the
smallest ellipsoid enclosing points *of the set* is a lower bound on the true optimum over all
outer ellipsoids. The bounds are weak-duality bounds, valid for *any* weights ``u`` in the
simplex, with ``mu = sum u_i p_i`` and ``Sigma = sum u_i (p_i - mu)(p_i - mu)^T``: if
``E = {x : (x - c)^T H (x - c) <= 1}`` contains the points, averaging their levels gives

    tr(H Sigma) + (mu - c)^T H (mu - c) <= 1,   so   tr(H Sigma) <= 1.

- volume (dimension n): by AM-GM, ``det(H Sigma)^{1/n} <= tr(H Sigma) / n <= 1 / n``, so
  ``vol E = V_n det(H)^{-1/2} >= V_n det(n Sigma)^{1/2}``; Khachiyan's weights make this tight
  (``n Sigma`` is then the MVEE's shape);
- trace: by Cauchy-Schwarz, ``tr(H^{-1}) tr(H Sigma) >= (tr Sigma^{1/2})^2``, so
  ``tr C >= (tr Sigma^{1/2})^2``; ``tr Sigma^{1/2}`` is concave in ``u`` and maximised by
  Frank-Wolfe steps;
- projection onto ``dims``: the volume bound for the projected points.

No solver is involved, so the bound holds up to float64 rounding. The points are

- uniform samples of the set, drawn inside a known outer ellipsoid and kept when they satisfy
  every inequality;
- boundary points: from one interior sample ``x0``, rays ``x0 + t d`` in random directions
  (Gaussian, shaped by the outer ellipsoid) are followed to the first exit ``t*`` from the
  intersection, the smallest positive root of the quadratics ``q_i(x0 + t d)`` (shortened by a
  relative 1e-9 so the end stays inside under rounding). For a non-convex set this sees only
  what is visible from ``x0``, which still gives a valid (if looser) bound.

In dimension <= 3 they are reduced to their convex hull's vertices; above, only the boundary
points are kept. Either way they are subsampled if still too many (a subset still gives a
valid bound).
"""

from __future__ import annotations

from collections.abc import Sequence
from math import lgamma, log, pi

import numpy as np
from scipy.spatial import ConvexHull, QhullError

from optbound.optimal.enclosing import validated_points
from optbound.optimal.khachiyan import covariance, khachiyan_weights
from optbound.sets import Ellipsoid, QuadraticSet
from optbound.sets import _validate as v

_SAMPLES = 20_000
_RAYS_PER_DIM = 4_000
_ROUNDS = 3
_MAX_POINTS = 1_500
_HULL_MAX_DIM = 3  # qhull is fast up to 3-D; above, its cost explodes
_WEIGHT_TOL = 1e-6
_WEIGHT_STEPS = 5_000  # any weights give a valid bound; more steps only tighten it


def _inside(quadratics: Sequence[QuadraticSet], X: np.ndarray) -> np.ndarray:
    return np.all([np.asarray(q.value(X)) <= 0.0 for q in quadratics], axis=0)


def _first_exit(quadratics: Sequence[QuadraticSet], x0: np.ndarray, D: np.ndarray) -> np.ndarray:
    """Smallest ``t > 0`` with ``q_i(x0 + t d) = 0`` crossing upward, per direction (may be inf).

    ``q(x0 + t d) = a t^2 + 2 b t + g`` with ``g = q(x0) <= 0``.
    """
    t_star = np.full(D.shape[0], np.inf)
    for q in quadratics:
        a = np.einsum("ij,jk,ik->i", D, q.A, D)
        b = D @ (q.A @ x0 + q.b)
        g = float(q.value(x0))
        disc = b * b - a * g
        root = np.sqrt(np.maximum(disc, 0.0))
        with np.errstate(divide="ignore", invalid="ignore"):
            # a < 0: the concave q rises from g <= 0 only if b > 0, and crosses 0 if disc >= 0.
            concave = np.where((b > 0) & (disc >= 0), (b - root) / -a, np.inf)
            quad = np.where(a > 0, (root - b) / a, concave)
            t = np.where(a == 0, np.where(b > 0, -g / (2 * b), np.inf), quad)
        t_star = np.minimum(t_star, np.where(t >= 0, t, np.inf))
    return t_star


def sample_set(quadratics: Sequence[QuadraticSet], outer: Ellipsoid, rng) -> np.ndarray:
    """Points of the intersection (interior samples and boundary points), shape (m, n)."""
    gen = v.rng_of(rng)
    for attempt in range(_ROUNDS):
        X = outer.sample(_SAMPLES * 4**attempt, gen)
        inside = X[_inside(quadratics, X)]
        if inside.shape[0] > outer.dim:
            break
    else:
        raise ValueError("sampling found too few points of the set for a lower bound")
    x0 = inside[np.argmin(np.linalg.norm(inside - inside.mean(axis=0), axis=1))]
    # Directions shaped by the outer ellipsoid spread the exits evenly over elongated sets.
    D = gen.standard_normal((_RAYS_PER_DIM * outer.dim, outer.dim)) @ outer.chol.T
    t_star = _first_exit(quadratics, x0, D)
    finite = np.isfinite(t_star)
    boundary = x0 + (t_star[finite] * (1.0 - 1e-9))[:, None] * D[finite]
    boundary = boundary[_inside(quadratics, boundary)]
    if outer.dim > _HULL_MAX_DIM:
        return boundary  # no hull reduction: interior samples would only dilute the bound
    return np.vstack([inside, boundary])


def _reduce(points: np.ndarray, gen: np.random.Generator) -> np.ndarray:
    if points.shape[1] <= _HULL_MAX_DIM:
        try:
            points = points[ConvexHull(points).vertices]
        except QhullError:
            pass  # flat or degenerate cloud: keep all points, validated_points will judge
    if points.shape[0] > _MAX_POINTS:
        points = points[gen.choice(points.shape[0], _MAX_POINTS, replace=False)]
    return points


def volume_lower_bound(points: np.ndarray) -> float:
    """``V_n det(n Sigma_u)^{1/2}`` (Khachiyan's weights): <= any enclosing ellipsoid's volume."""
    n = points.shape[1]
    u, _ = khachiyan_weights(points, tol=_WEIGHT_TOL, max_iter=_WEIGHT_STEPS)
    _, cov = covariance(points, u)
    sign, logdet = np.linalg.slogdet(n * cov)
    log_unit_ball = 0.5 * n * log(pi) - lgamma(0.5 * n + 1.0)
    return float(np.exp(log_unit_ball + 0.5 * logdet)) if sign > 0 else 0.0


def _sqrt_psd(S: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Eigenvalues (clipped at 0) and eigenvectors of a symmetric PSD matrix."""
    lam, V = np.linalg.eigh(S)
    return np.maximum(lam, 0.0), V


def trace_lower_bound(points: np.ndarray) -> float:
    """``(tr Sigma_u^{1/2})^2`` with Frank-Wolfe weights: <= trace of any enclosing ellipsoid.

    The gradient of ``tr Sigma_u^{1/2}`` in ``u_i`` is ``(p_i - mu)^T Sigma^{-1/2} (p_i - mu) / 2``.
    """
    m = points.shape[0]
    u = np.full(m, 1.0 / m)
    best = 0.0
    for k in range(_WEIGHT_STEPS):
        mean, cov = covariance(points, u)
        lam, V = _sqrt_psd(cov)
        value = float(np.sum(np.sqrt(lam)))
        best = max(best, value)
        inv_root = (V / np.sqrt(np.maximum(lam, 1e-300))) @ V.T
        centered = points - mean
        grad = 0.5 * np.einsum("ij,jk,ik->i", centered, inv_root, centered)
        j = int(np.argmax(grad))
        if grad[j] - grad @ u <= _WEIGHT_TOL * value:  # Frank-Wolfe duality gap
            break
        step = 2.0 / (k + 3.0)
        u *= 1.0 - step
        u[j] += step
    return best**2


def sampled_lower_bound(
    quadratics: Sequence[QuadraticSet],
    outer: Ellipsoid,
    objective: str,
    dims: tuple[int, ...] | None,
    rng,
) -> float:
    """Lower bound on the minimum ``objective`` over all ellipsoids containing the set."""
    gen = v.rng_of(rng)
    points = sample_set(quadratics, outer, gen)
    if objective == "projection":
        points = points[:, list(dims)]
    points = validated_points(_reduce(points, gen))
    if objective == "trace":
        return trace_lower_bound(points)
    return volume_lower_bound(points)
