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

No solver is involved, so the bound holds up to float64 rounding. The bound is only as good as
the points: an enclosing ellipsoid is pinned by the set's extreme points (the corners, for an
intersection of strips), which uniform samples and random rays almost never reach (a 5-D cube
gave a volume bound 2.2 times too low that way). The points are:

1. an interior point ``x0``: the deepest (shortest exit along the outer ellipsoid's axes) of
   the outer ellipsoid's centre and uniform samples of the set drawn inside it;
2. first exits: rays ``x0 + t d`` followed to the first exit ``t*`` from the intersection, the
   smallest positive root of the quadratics ``q_i(x0 + t d)``; the directions are the axes and
   random directions shaped first by the outer ellipsoid, then again by the exits' own rough
   enclosing ellipsoid (the outer one can be far too long: the projection objective leaves
   the other coordinates free);
3. a climb toward the extreme points: ``_SEARCH_ROUNDS`` rounds, each trying for every point
   (a) a walk along its active faces, uphill in the level of a rough enclosing ellipsoid of
   the points (Khachiyan, refitted every ``_REFIT_EVERY`` rounds), to the first constraint
   met (the level is convex, so the far end of the segment is the higher one; on a polytope
   this reaches a vertex), and (b) a ray from ``x0`` past the point shifted uphill or at
   random (for curved boundaries); a trial replaces the point when it lies farther out.
   Only the climbing points go on: of rays that climbed to one vertex one is kept, and a point
   that has not risen (by ``_MIN_RISE``) for ``_PATIENCE`` rounds stops unless it is near the
   top level (``_TOP_BAND``): most of the thousands of rays stall at low vertices after a few
   rounds (in 2-D all but one per vertex after two), and the rounds cost what the points do.
   A round is one compiled pass over the points (``_climb_round``: about a microsecond per
   point in 3-D with ten strips), not a dozen numpy calls;
4. a polish: ``_POLISH_ROUNDS`` rounds of the same moves for the support points of the
   minimum-volume ellipsoid of the points alone (refitted, warm-started, every round, by
   exchange steps), in its own level; where the set touches its optimum along curves (a
   strip's rims on an ellipsoid) the broad climb leaves them short (SDP / bound - 1 on the
   battery's 3-D strip: 1.6e-4 without, 1.5e-5 with).

Every point is pulled back toward its start by a relative ``_SHRINK`` and kept only if every
quadratic is negative there by more than a bound on its float64 rounding, so every point is in
the set. For a non-convex set the rays see only what is visible from ``x0``, which still gives
a valid (if looser) bound. Near-duplicates (rays that climbed to one vertex) are merged, and
Khachiyan's weights are computed on a growing working set of the points farthest out (zero
weight elsewhere), started from the Kumar-Yildirim core set
(``optbound.optimal.khachiyan.core_set``), which also keeps the working set full-dimensional.
The volume bound's own weights start instead from the polish's last ones (its support
points), take exchange steps and stop on ``max w <= (1 + tol) d`` alone, which already bounds
the gap (``khachiyan_weights``): on the points clustered at a curved contact the separate
forward and away steps zigzag, and took the 5 000 allowed steps without converging.

Cost: a small multiple of the ``outer_ellipsoid`` call without the bound, measured per
instance of the recursive family by ``python -m benchmarks.lower_bound_cost``. Most of it is
the climb of point 3 (thousands of rays), which is what the bound's quality rests on: fewer
rays per dimension (``_RAYS_PER_DIM``) give measurably lower (weaker) bounds in 4-D.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from math import lgamma, log, pi

import numpy as np

from optbound._core import validate as v
from optbound._core.compiled_copy import copy_into
from optbound._core.jit import njit
from optbound.optimal.certify import EPS
from optbound.optimal.enclosing import validated_points
from optbound.optimal.khachiyan import _quad, core_set, covariance, khachiyan_weights
from optbound.sets import Ellipsoid, QuadraticSet

_SAMPLES = 2_000  # first batch of samples for x0; four times more while too few are inside
_MAX_SAMPLES = 512_000
_CANDIDATES = 200  # interior samples whose depth is compared when choosing x0
# Random rays per dimension, by dimension (the last entry for all higher ones): in 2-D the
# climbs collapse onto the polygon's few vertices; the vertices a climb can end at grow in
# number with the dimension (module docstring, "Cost").
_RAYS_PER_DIM = {2: 50, 3: 200, 4: 450}
_SEARCH_ROUNDS = 20  # uphill moves along the boundary, alternating with random ones
_FIRST_STEP = 0.3  # move length relative to the ray's length; doubled on success, else halved
_REFIT_EVERY = 5  # rounds between refits of the enclosing ellipsoid that defines 'uphill'
_WORKING_PER_DIM = 50  # initial working set of Khachiyan's weights, and its growth per round
_WORKING_ROUNDS = 8
_SHRINK = 1e-9
_MERGE_RTOL = 1e-7
_ACTIVE_RTOL = 1e-7
_FACE_SWEEPS = 3
_WEIGHT_TOL = 1e-6
_WEIGHT_STEPS = 5_000  # any weights give a valid bound; more steps only tighten it
_TRACE_STEPS = 20_000  # Frank-Wolfe steps (compiled: microseconds each)
_SEARCH_WEIGHT_STEPS = 500  # a rough enclosing ellipsoid is enough to rank points
_ROUGH_TOL = 1e-3
_PATIENCE = 3  # rounds without rising after which a point low in the level stops climbing
_TOP_BAND = 0.9  # "near the top": level above this fraction of the highest
_MIN_RISE = 1e-3  # a relative rise of the level below this does not count
_POLISH_ROUNDS = 10
_POLISH_TOL = 1e-4  # the fit that picks the points to polish (the bound's own: _WEIGHT_TOL)


def _stack(quadratics: Sequence[QuadraticSet]) -> np.ndarray:
    """The forms ``F_i`` stacked, shape (k, n + 1, n + 1): every query below is vectorized
    over points and inequalities at once."""
    return np.stack([q.F for q in quadratics])


def _lifted(X: np.ndarray) -> np.ndarray:
    return np.hstack([X, np.ones((X.shape[0], 1))])


def _inside(F: np.ndarray, X: np.ndarray) -> np.ndarray:
    """Rows of X where every ``q_i`` is negative by more than its float64 rounding bound."""
    lifted = _lifted(X)
    return _inside_loop(_membership(F, 4.0 * lifted.shape[1] * EPS), lifted)


def _membership(F: np.ndarray, rel: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """What ``_inside_one`` needs: the forms, their entrywise absolute values and the sums of
    those, and the relative rounding bound."""
    absF = np.abs(F)
    return np.ascontiguousarray(F), absF, absF.sum(axis=(1, 2)), rel


@njit(cache=True)
def _inside_loop(membership, L: np.ndarray) -> np.ndarray:
    """``_inside_one`` per row ``x~`` of L."""
    out = np.empty(L.shape[0], dtype=np.bool_)
    for p in range(L.shape[0]):
        out[p] = _inside_one(membership, L[p])
    return out


@njit(cache=True)
def _inside_one(membership, x: np.ndarray) -> bool:
    """``q_i(x) < -rel |x~|^T |F_i| |x~|`` for every form, at the lifted point ``x~`` (compiled:
    stopping at the first form that fails).

    ``|x~|^T |F_i| |x~| <= max|x~|^2 sum|F_i|``: where ``q_i`` is below twice that bound (the
    factor 2 covers the rounding of both sides) the test holds without the products by
    ``|F_i|``, which are the costlier half.
    """
    F, absF, abs_sum, rel = membership
    # |x~| and its maximum in a loop: no array expression, no compiled np.max helper.
    x_abs = np.empty(x.shape[0])
    top = 0.0
    for j in range(x.shape[0]):
        x_abs[j] = abs(x[j])
        if x_abs[j] > top:
            top = x_abs[j]
    for i in range(F.shape[0]):
        value = _quad(F[i], x)
        if value < -2.0 * rel * abs_sum[i] * top * top:
            continue
        if not value < -rel * _quad(absF[i], x_abs):
            return False
    return True


def _first_exit(F: np.ndarray, X0: np.ndarray, D: np.ndarray) -> np.ndarray:
    """Smallest ``t > 0`` with ``q_i(x0 + t d) = 0`` crossing upward, per row pair (may be inf).

    ``X0`` is one point (n,) or one per direction (m, n). ``q(x0 + t d) = a t^2 + 2 b t + g``
    with ``g = q(x0) <= 0``.
    """
    lifted = _lifted(np.ascontiguousarray(np.broadcast_to(X0, D.shape)))
    D1 = np.hstack([D, np.zeros((D.shape[0], 1))])
    return _first_exit_loop(np.ascontiguousarray(F), lifted, D1)


@njit(cache=True)
def _first_exit_loop(F: np.ndarray, L: np.ndarray, D1: np.ndarray) -> np.ndarray:
    k, n1 = F.shape[0], L.shape[1]
    out = np.empty(L.shape[0])
    Fx, q = np.empty((k, n1)), np.empty(k)
    for p in range(L.shape[0]):
        _apply(F, L[p], Fx, q)
        out[p] = _exit(F, Fx, q, D1[p, :-1])
    return out


@njit(cache=True)
def _apply(F: np.ndarray, x: np.ndarray, Fx: np.ndarray, q: np.ndarray) -> None:
    """``Fx[i] = F_i x~`` and ``q[i] = x~^T F_i x~`` at the lifted point ``x~`` (in place)."""
    n1 = x.shape[0]
    for i in range(F.shape[0]):
        total = 0.0
        for r in range(n1):
            row = 0.0
            for c in range(n1):
                row += F[i, r, c] * x[c]
            Fx[i, r] = row
            total += x[r] * row
        q[i] = total


@njit(cache=True)
def _exit(F: np.ndarray, Fx: np.ndarray, q: np.ndarray, d: np.ndarray) -> float:
    """First exit ``t*`` along ``d`` from the point of ``_apply``'s ``Fx``, ``q``: the smallest
    positive root of ``q_i(x + t d) = a t^2 + 2 b t + g`` crossing upward (may be inf)."""
    out = np.inf
    n = d.shape[0]
    for i in range(F.shape[0]):
        a, b, g = 0.0, 0.0, q[i]
        for r in range(n):
            row = 0.0
            for c in range(n):
                row += F[i, r, c] * d[c]
            a += d[r] * row
            b += d[r] * Fx[i, r]
        disc = b * b - a * g
        root = np.sqrt(max(disc, 0.0))
        if a == 0.0:
            t = -g / (2.0 * b) if b > 0.0 else np.inf
        elif a > 0.0:
            t = (root - b) / a
        else:  # concave q: it rises from g <= 0 only if b > 0, and crosses 0 if disc >= 0
            t = (b - root) / -a if (b > 0.0 and disc >= 0.0) else np.inf
        if t >= 0.0 and t < out:
            out = t
    return out


def _interior_point(F: np.ndarray, outer: Ellipsoid, gen: np.random.Generator) -> np.ndarray:
    """The deepest candidate for ``x0``.

    Depth is the shortest exit along the outer ellipsoid's axes (in its own metric, so that
    elongated sets are judged fairly); candidates are its centre and uniform samples.
    """
    found = [outer.center[None, :]] if _inside(F, outer.center[None, :])[0] else []
    size = _SAMPLES
    while sum(x.shape[0] for x in found) < _CANDIDATES and size <= _MAX_SAMPLES:
        X = outer.sample(size, gen)
        found.append(X[_inside(F, X)])
        size *= 4
    inside = np.vstack(found) if found else np.empty((0, outer.dim))
    if inside.shape[0] == 0:
        raise ValueError("sampling found no point of the set for a lower bound")
    candidates = inside[:_CANDIDATES]
    axes = np.vstack([outer.chol.T, -outer.chol.T])
    pairs = np.repeat(candidates, axes.shape[0], axis=0)
    exits = _first_exit(F, pairs, np.tile(axes, (candidates.shape[0], 1)))
    depth = exits.reshape(candidates.shape[0], -1).min(axis=1)
    return candidates[int(np.argmax(depth))]


def _cast(
    F: np.ndarray, x0: np.ndarray, Z: np.ndarray, chol: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Exit points of the rays from x0 along ``chol z`` (z per row of Z), and the kept rows."""
    D = Z @ chol.T
    t_star = _first_exit(F, x0, D)
    finite = np.flatnonzero(np.isfinite(t_star))
    points = x0 + (t_star[finite] * (1.0 - _SHRINK))[:, None] * D[finite]
    kept = _inside(F, points)
    return points[kept], finite[kept]


def _rough_fit(
    points: np.ndarray, level: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """Centre and weighted covariance of a rough minimum-volume ellipsoid around the points
    (its shape is n times the covariance); ``level`` as in ``_enclosing_weights``."""
    # Separate forward and away steps here (not exchange steps): their rougher fit, as the
    # climb's "uphill", gave the better trace bounds (battery's 3-D strip at condition 1e6,
    # eight seeds: SDP / bound 1.0026 against 1.0037 on average).
    active, u = _enclosing_weights(points, level, _ROUGH_TOL, _SEARCH_WEIGHT_STEPS)
    return covariance(points[active], u)


def _level(X: np.ndarray, mean: np.ndarray, inv: np.ndarray) -> np.ndarray:
    centered = X - mean
    return np.einsum("ij,jk,ik->i", centered, inv, centered)


def _unit_rows(Z: np.ndarray) -> np.ndarray:
    return Z / np.linalg.norm(Z, axis=1, keepdims=True)


def _distinct(points: np.ndarray) -> np.ndarray:
    """One point of each cluster closer than ``_MERGE_RTOL`` (relative to the spread): rays
    that climbed to one vertex nearly coincide, and make Khachiyan's matrix singular."""
    return points[np.sort(_cluster_firsts(points, _grid(points)))]


def _grid(reference: np.ndarray) -> tuple[np.ndarray, float]:
    """Origin and cell size of the ``_MERGE_RTOL`` grid relative to the spread of the rows."""
    low = reference.min(axis=0)
    return low, _MERGE_RTOL * float(np.max(reference.max(axis=0) - low))


def _cluster_firsts(points: np.ndarray, grid: tuple[np.ndarray, float]) -> np.ndarray:
    """Indices of the first row of each cluster of ``points``: one cell of ``grid``."""
    cells = np.round((points - grid[0]) / grid[1])
    # One key per row (a linear hash of the cells with fixed irrational-like weights; a
    # collision only merges two points, which drops one valid point): np.unique on rows is
    # several times slower.
    keys = cells @ (1.0 + np.modf(np.arange(1.0, points.shape[1] + 1.0) * 0.6180339887498949)[0])
    return np.unique(keys, return_index=True)[1]


def sample_set(
    quadratics: Sequence[QuadraticSet],
    outer: Ellipsoid,
    rng,
    dims: tuple[int, ...] | None = None,
) -> np.ndarray:
    """Points of the intersection: first exits and the points of the climb (module docstring).

    ``outer`` is any ellipsoid containing the set; ``dims`` judges "farther out" by the
    projection onto these coordinates (projection objective).

    Parameters
    ----------
    quadratics : sequence of QuadraticSet
        The inequalities whose intersection is the set.
    outer : Ellipsoid
        Any ellipsoid containing the set (the rays are shaped by it).
    rng : numpy.random.Generator or int
        Random generator or integer seed.
    dims : tuple of int, optional
        Coordinates of the projection objective (judges "farther out").

    Returns
    -------
    np.ndarray, shape (m, n)
        Distinct points of the set.
    """
    return _sample(quadratics, outer, rng, dims)[0]


def _sample(
    quadratics: Sequence[QuadraticSet],
    outer: Ellipsoid,
    rng,
    dims: tuple[int, ...] | None,
) -> tuple[np.ndarray, tuple[np.ndarray, np.ndarray]]:
    """``sample_set``'s points, and the polish's last rough weights (indices of the points,
    weights): a warm start for the bound's own (on ``dims``)."""
    gen = v.rng_of(rng)
    n = outer.dim
    F = _stack(quadratics)
    x0 = _interior_point(F, outer, gen)
    rays = _RAYS_PER_DIM[min(max(n, 2), max(_RAYS_PER_DIM))] * n
    Z = np.vstack([np.eye(n), -np.eye(n), _unit_rows(gen.standard_normal((rays, n)))])
    first, _ = _cast(F, x0, Z, outer.chol)
    # The outer ellipsoid can be far longer than the set (the projection objective leaves the
    # other coordinates free): shape the rays again by the exits' own enclosing ellipsoid.
    mean, cov = _rough_fit(validated_points(_distinct(first)))
    chol = np.linalg.cholesky(cov)
    start = np.vstack([first, _cast(F, x0, Z, chol)[0]])
    points = start.copy()
    cols = list(dims) if dims else list(range(n))
    climb = _Climb(F, x0, chol, cols, gen)
    mean, inv = mean[cols], np.linalg.inv(cov[np.ix_(cols, cols)])  # ranks the first refit
    step = np.full(points.shape[0], _FIRST_STEP)
    stalled = np.zeros(points.shape[0], dtype=int)
    alive = np.arange(points.shape[0])
    grid = _grid(start)  # the first exits' spread: the climb changes it little
    for round_ in range(_SEARCH_ROUNDS):
        if round_ % _REFIT_EVERY == 0:
            # With the first exits, so that it never collapses onto the few vertices reached.
            fit = _distinct(np.vstack([start, points])[:, cols])
            mean, cov = _rough_fit(fit, _level(fit, mean, inv))  # ranked by the last fit
            inv = np.linalg.inv(cov)
            level = _level(points[:, cols], mean, inv)
        alive = _still_climbing(points, level, alive, stalled, grid)
        if alive.size == 0:
            break
        sub, sub_level, sub_step = points[alive], level[alive], step[alive]
        climb(sub, sub_level, sub_step, mean, inv, uphill=round_ % 2 == 0)
        risen = sub_level > (1.0 + _MIN_RISE) * level[alive]
        points[alive], level[alive], step[alive] = sub, sub_level, sub_step
        stalled[alive] = np.where(risen, 0, stalled[alive] + 1)
    return _polish(climb, _distinct(np.vstack([start, points])))


def _polish(climb: Callable, pool: np.ndarray) -> tuple[np.ndarray, tuple[np.ndarray, np.ndarray]]:
    """The pool and the points of ``_POLISH_ROUNDS`` more rounds of climbing by the support
    points of the minimum-volume ellipsoid of a working set (refitted every round), in that
    ellipsoid's level: they pin the bound, and on curved boundaries the broad climb leaves
    them short of the contact. Also the last weights of that working set (as in ``_sample``)."""
    cols = climb.cols
    active, u = _enclosing_weights(
        pool[:, cols], tol=_POLISH_TOL, steps=_SEARCH_WEIGHT_STEPS, exchange=True
    )
    work = pool[active]  # the rest lies inside its ellipsoid (to the tolerance)
    step = np.full(work.shape[0], _FIRST_STEP)
    for round_ in range(_POLISH_ROUNDS):
        mean, cov = covariance(work[:, cols], u)
        inv = np.linalg.inv(cov)
        support = np.flatnonzero(u > 0.0)
        tips, tip_step = work[support], step[support]
        level = _level(tips[:, cols], mean, inv)
        before = level.copy()
        climb(tips, level, tip_step, mean, inv, uphill=round_ % 2 == 0)
        step[support] = tip_step
        rose = level > before
        work = np.vstack([work, tips[rose]])
        step = np.concatenate([step, tip_step[rose]])
        # Warm-started from the last weights (zero on the new points).
        start = np.concatenate([u, np.zeros(int(rose.sum()))])
        u, _ = khachiyan_weights(
            work[:, cols], _POLISH_TOL, _SEARCH_WEIGHT_STEPS, start, exchange=True
        )
    added = work.shape[0] - active.size
    indices = np.concatenate([active, pool.shape[0] + np.arange(added)])
    support = u > 0.0  # the rest lies inside (to the tolerance): the bound's check re-adds
    return np.vstack([pool, work[active.size :]]), (indices[support], u[support])


def _still_climbing(
    points: np.ndarray,
    level: np.ndarray,
    alive: np.ndarray,
    stalled: np.ndarray,
    grid: tuple[np.ndarray, float],
) -> np.ndarray:
    """The climbing points worth another round: one of each cluster (rays that climbed to one
    vertex; one cell of ``grid``), and of the points that did not rise for ``_PATIENCE``
    rounds only those near the top level (they pin the enclosing ellipsoid; a low one that
    stalled is at a low vertex)."""
    top = np.max(level)
    keep = (stalled[alive] < _PATIENCE) | (level[alive] >= _TOP_BAND * top)
    alive = alive[keep]
    if alive.size == 0:
        return alive
    return alive[np.sort(_cluster_firsts(points[alive], grid))]


class _Climb:
    """One round of moves uphill in an ellipsoid's level, for points of the set (in place):
    (a) a walk along the active faces, (b) a ray from x0 past the point shifted uphill (or at
    random) by its relative step, which doubles on success, else halves (``_climb_round``)."""

    def __init__(self, F, x0, chol, cols, gen) -> None:
        self.F, self.x0, self.chol, self.cols, self.gen = F, x0, chol, cols, gen
        self.membership = _membership(F, 4.0 * (x0.shape[0] + 1) * EPS)
        self.chol_inv = np.linalg.inv(chol)
        self.chol_t = np.ascontiguousarray(chol.T)  # C-ordered: one _matvec specialization
        self.in_cols = np.zeros(x0.shape[0], dtype=np.bool_)
        self.in_cols[cols] = True

    def __call__(self, points, level, step, mean, inv, uphill: bool) -> None:
        m, n = points.shape
        shift = np.empty((0, n)) if uphill else self.gen.standard_normal((m, n))
        # Scattered back to full coordinates: rows and columns outside ``cols`` are zero.
        full_mean, full_inv = np.zeros(n), np.zeros((n, n))
        full_mean[self.cols] = mean
        full_inv[np.ix_(self.cols, self.cols)] = inv
        _climb_round(
            self.membership,
            self.x0,
            self.chol,
            self.chol_t,
            self.chol_inv,
            self.in_cols,
            points,
            level,
            step,
            full_mean,
            full_inv,
            shift,
        )


@njit(cache=True)
def _climb_round(
    membership, x0, chol, chol_t, chol_inv, in_cols, points, level, step, mean, inv, shift
):
    """One ``_Climb`` round for every row of ``points`` (in place, with ``level`` and ``step``),
    compiled as one pass: per point, numpy would cost a dozen calls per round.

    (a) The level's gradient, with its outward part along the normal of each active
    constraint removed (active: first-order distance ``-q / |grad q|`` below ``_ACTIVE_RTOL``
    times the point's norm scale; ``_FACE_SWEEPS`` sweeps of projections approximate the
    projection onto the faces' intersection, edges then vertices), walked to the first
    constraint met. (b) The ray from x0 through the point shifted, in the whitened coordinates
    ``y = chol^{-1} (x - x0)``, by ``step |y|`` along the unit row of ``shift`` (empty: along
    the gradient of (a), whitened). A trial replaces the point if it passes the membership
    margin and lies higher in the level ``(x - mean)^T inv (x - mean)`` over ``in_cols``.
    ``chol_t`` is ``chol^T``, C-ordered (``_matvec`` compiles for one layout).
    """
    F = membership[0]  # membership: ``_membership``'s, for ``_inside_one``
    m, n = points.shape
    k = F.shape[0]
    lifted, trial = np.empty(n + 1), np.empty(n + 1)
    lifted[n] = trial[n] = 1.0  # the lifting coordinate (the rest is written before use)
    gradient, G, move = np.empty(n), np.empty(n), np.empty(n)
    Fx, q, inv_norm2 = np.empty((k, n + 1)), np.empty(k), np.empty(k)
    Fx0, q0, zero = np.empty((k, n + 1)), np.empty(k), np.zeros(n)
    metric = (in_cols, mean, inv)
    copy_into(lifted[:n], x0)
    _apply(F, lifted, Fx0, q0)  # every ray of (b) starts at x0
    for p in range(m):
        _matvec(inv, points[p], mean, gradient)  # zero outside in_cols (scattered zeros)
        copy_into(G, gradient)
        copy_into(lifted[:n], points[p])
        _apply(F, lifted, Fx, q)  # the normals are 2 Fx[i, :n]
        scale = 1.0 + np.sqrt(_dot(points[p], points[p]))
        for i in range(k):
            norm2 = 4.0 * _dot(Fx[i, :n], Fx[i, :n])
            active = norm2 > 0.0 and -q[i] < _ACTIVE_RTOL * scale * np.sqrt(norm2)
            inv_norm2[i] = 4.0 / norm2 if active else 0.0  # 1 / |Fx[i, :n]|^2
        for _ in range(_FACE_SWEEPS):
            for i in range(k):
                if inv_norm2[i] > 0.0:
                    outward = _dot(G, Fx[i, :n])
                    if outward > 0.0:
                        for j in range(n):
                            G[j] -= outward * inv_norm2[i] * Fx[i, j]
        t = _exit(F, Fx, q, G)
        if np.isfinite(t) and t > 0.0:
            _try(membership, metric, points[p], t * (1.0 - _SHRINK), G, points, level, p, trial)
        # (b), from the point as (a) left it: move (whitened) is the shift, y the point.
        if shift.shape[0] == 0:
            _matvec(chol_t, gradient, zero, move)  # chol_t: chol^T, C-ordered
        else:
            copy_into(move, shift[p])
        _matvec(chol_inv, points[p], x0, G)  # G is now y
        size = np.sqrt(_dot(move, move))
        if size > 0.0:
            factor = step[p] * np.sqrt(_dot(G, G)) / size
            for j in range(n):
                G[j] += factor * move[j]
        size = np.sqrt(_dot(G, G))
        success = False
        if size > 0.0:
            for j in range(n):
                G[j] /= size
            _matvec(chol, G, zero, move)  # move is now the ray's direction
            t = _exit(F, Fx0, q0, move)
            if np.isfinite(t):
                shrunk = t * (1.0 - _SHRINK)
                success = _try(membership, metric, x0, shrunk, move, points, level, p, trial)
        step[p] = min(2.0 * step[p], 1.0) if success else 0.5 * step[p]


@njit(cache=True)
def _try(membership, metric, base, t, direction, points, level, p, lifted) -> bool:
    """``points[p] = base + t direction`` (and its level) if that is higher and in the set
    (the cheaper test first); ``lifted`` is a buffer of n + 1 ones. ``membership`` is
    ``_membership``'s, ``metric`` ``(in_cols, mean, inv)`` of the level."""
    in_cols, mean, inv = metric
    n = base.shape[0]
    for j in range(n):
        lifted[j] = base[j] + t * direction[j]
    value = 0.0
    for a in range(n):
        if in_cols[a]:
            row = 0.0
            for b in range(n):
                if in_cols[b]:
                    row += inv[a, b] * (lifted[b] - mean[b])
            value += (lifted[a] - mean[a]) * row
    if not value > level[p] or not _inside_one(membership, lifted):
        return False
    copy_into(points[p], lifted[:n])
    level[p] = value
    return True


@njit(cache=True)
def _dot(a: np.ndarray, b: np.ndarray) -> float:
    total = 0.0
    for j in range(a.shape[0]):
        total += a[j] * b[j]
    return total


@njit(cache=True)
def _matvec(A: np.ndarray, x: np.ndarray, origin: np.ndarray, out: np.ndarray) -> None:
    """``out = A (x - origin)`` by plain loops (no BLAS call or temporary per point)."""
    for a in range(A.shape[0]):
        row = 0.0
        for b in range(A.shape[1]):
            row += A[a, b] * (x[b] - origin[b])
        out[a] = row


def _enclosing_weights(
    points: np.ndarray,
    level: np.ndarray | None = None,
    tol: float = _WEIGHT_TOL,
    steps: int = _WEIGHT_STEPS,
    start: tuple[np.ndarray, np.ndarray] | None = None,
    away_tol: float | None = None,
    exchange: bool = False,
) -> tuple[np.ndarray, np.ndarray]:
    """Khachiyan's weights, computed on a working set of the points farthest out.

    Khachiyan's algorithm crawls on thousands of points near one boundary; the weights of a
    working set (zero elsewhere) are weights of all points, and the set grows by the points
    its ellipsoid leaves out until none is left out by more than the tolerance. ``level``
    ranks the points for the first working set (default: by their covariance); ``start``
    (indices, weights, full-dimensional) is the first working set and its weights instead.
    Each growth of the set warm-starts from the last weights (zero on the new points).
    ``away_tol`` and ``exchange`` as in ``khachiyan_weights``.
    Returns the working set's indices and its weights.
    """
    n = points.shape[1]
    if start is not None:
        active, u = start
    else:
        if level is None:  # the points' own spread (uniform weights) ranks them well enough
            mean, cov = covariance(points, np.full(points.shape[0], 1.0 / points.shape[0]))
            level = _level(points, mean, np.linalg.pinv(cov))
        # The core set keeps the working set full-dimensional: the points farthest out can
        # all lie near one edge.
        active = np.union1d(core_set(points), np.argsort(level)[::-1][: _WORKING_PER_DIM * n])
        u = None
    for round_ in range(_WORKING_ROUNDS):
        u, _ = khachiyan_weights(points[active], tol, steps, u, away_tol, exchange)
        mean, cov = covariance(points[active], u)
        level = _level(points, mean, np.linalg.inv(n * cov))
        outside = np.setdiff1d(np.flatnonzero(level > 1.0 + tol), active)
        if outside.size == 0 or round_ == _WORKING_ROUNDS - 1:
            break
        worst = outside[np.argsort(level[outside])[::-1][: _WORKING_PER_DIM * n]]
        active = np.concatenate([active, worst])
        u = np.concatenate([u, np.zeros(worst.size)])
    return active, u


def volume_lower_bound(
    points: np.ndarray, start: tuple[np.ndarray, np.ndarray] | None = None
) -> float:
    """``V_n det(n Sigma_u)^{1/2}`` (Khachiyan's weights): <= any enclosing ellipsoid's volume.

    Any weights u on the points give this bound (Khachiyan's duality); the better the
    weights, the tighter it is.

    Parameters
    ----------
    points : np.ndarray, shape (m, n)
        Points of the set (affinely spanning R^n).
    start : tuple of np.ndarray, optional
        A first working set (indices) and its weights, as in ``_enclosing_weights``.

    Returns
    -------
    float
        A lower bound of the volume of every ellipsoid containing the points (0.0 if the weights'
        covariance is singular).
    """
    n = points.shape[1]
    # Only the bound matters here, not which points support it (``khachiyan_weights``).
    active, u = _enclosing_weights(points, start=start, away_tol=np.inf, exchange=True)
    _, cov = covariance(points[active], u)
    sign, logdet = np.linalg.slogdet(n * cov)
    log_unit_ball = 0.5 * n * log(pi) - lgamma(0.5 * n + 1.0)
    return float(np.exp(log_unit_ball + 0.5 * logdet)) if sign > 0 else 0.0


def trace_lower_bound(points: np.ndarray) -> float:
    """``(tr Sigma_u^{1/2})^2`` with Frank-Wolfe weights: <= trace of any enclosing ellipsoid.

    The gradient of ``tr Sigma_u^{1/2}`` in ``u_i`` is ``(p_i - mu)^T Sigma^{-1/2} (p_i - mu) / 2``.

    Parameters
    ----------
    points : np.ndarray, shape (m, n)
        Points of the set (affinely spanning R^n).

    Returns
    -------
    float
        A lower bound of the trace of the shape of every ellipsoid containing the points.
    """
    P = np.ascontiguousarray(points, dtype=float)
    return _frank_wolfe_trace(P, _TRACE_STEPS, _WEIGHT_TOL) ** 2


@njit(cache=True)
def _frank_wolfe_trace(P: np.ndarray, steps: int, tol: float) -> float:
    """The best ``tr Sigma_u^{1/2}`` over Frank-Wolfe iterates from uniform weights (any u
    gives a bound; the loop is compiled as each step is an n x n eigendecomposition)."""
    m, n = P.shape
    u = np.full(m, 1.0 / m)
    grad = np.empty(m)
    best = 0.0
    for k in range(steps):
        mean = np.zeros(n)
        cov = np.zeros((n, n))
        for i in range(m):
            for a in range(n):
                mean[a] += u[i] * P[i, a]
                for b in range(n):
                    cov[a, b] += u[i] * P[i, a] * P[i, b]
        cov -= np.outer(mean, mean)
        lam, V = np.linalg.eigh(cov)
        lam = np.maximum(lam, 0.0)  # a PSD matrix's rounding can leave tiny negatives
        value = np.sum(np.sqrt(lam))
        best = max(best, value)
        inv_root = (V / np.sqrt(np.maximum(lam, 1e-300))) @ V.T
        j, average = 0, 0.0
        for i in range(m):
            total = 0.0
            for a in range(n):
                row = 0.0
                for b in range(n):
                    row += inv_root[a, b] * (P[i, b] - mean[b])
                total += (P[i, a] - mean[a]) * row
            grad[i] = 0.5 * total
            average += u[i] * grad[i]
            if grad[i] > grad[j]:
                j = i
        if grad[j] - average <= tol * value:  # Frank-Wolfe duality gap
            break
        step = 2.0 / (k + 3.0)
        u *= 1.0 - step
        u[j] += step
    return best


def sampled_lower_bound(
    quadratics: Sequence[QuadraticSet],
    outer: Ellipsoid,
    objective: str,
    dims: tuple[int, ...] | None,
    rng,
) -> float:
    """Lower bound on the minimum ``objective`` over all ellipsoids containing the set.

    Parameters
    ----------
    quadratics : sequence of QuadraticSet
        The inequalities whose intersection is the set.
    outer : Ellipsoid
        Any ellipsoid containing the set (the rays are shaped by it).
    objective : {"volume", "trace", "projection"}
        The objective bounded.
    dims : tuple of int or None
        Coordinates of the projection objective.
    rng : numpy.random.Generator or int
        Random generator or integer seed.

    Returns
    -------
    float
        The lower bound, from points sampled in the set (every ellipsoid containing the set contains
        them).

    Raises
    ------
    ValueError
        If the sampled points do not span R^n (see
        :func:`~optbound.optimal.enclosing.validated_points`).
    """
    points, start = _sample(quadratics, outer, rng, dims)
    if objective == "projection":
        points = _distinct(points[:, list(dims)])  # corners above one another coincide
        start = None  # the polish's weights are on the points before the merge
    points = validated_points(points)
    if objective == "trace":
        # Frank-Wolfe on a working set: the points that matter to the minimum-volume ellipsoid
        # and those nearest the boundary of the (near-optimal) outer one.
        near = np.argsort(outer.level(points))[::-1][: _WORKING_PER_DIM * points.shape[1]]
        return trace_lower_bound(points[np.union1d(_enclosing_weights(points)[0], near)])
    return volume_lower_bound(points, start)
