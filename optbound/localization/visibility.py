"""Pose tracking of a team of robots from visibility alone: LUVIA [GLH12].

Two robots see each other when no obstacle meets the segment between them [GLH12, Def. 1].
On boxes this becomes three-valued [GLH12, Def. 9]: TRUE when every pair of points of the two
boxes sees each other, FALSE when no pair does, UNKNOWN otherwise (:func:`visibility_test`,
Algorithm 3). A "visible" measurement is confronted with the inner characterization E⁻, a
"not visible" one with the outer E⁺ [GLH12, Props. 15-16], so that a box is discarded only
when it contains no position consistent with the true environment E (:func:`luvia`,
Algorithm 2). :func:`track` (Algorithm 1) alternates interval odometry with a compass and
LUVIA for every robot.
"""

from __future__ import annotations

import numpy as np

from optbound.interval import Interval, Tri, tri_not
from optbound.localization.environment import Environment
from optbound.localization.geometry import as_polygons, segments_meet_polygons

#: Default bound on nested bisections per LUVIA call, whatever ``eps``: a box is cut into at
#: most 2**MAX_DEPTH sub-boxes, which bounds the cost when boxes grow large.
MAX_DEPTH = 10


def as_boxes(boxes, name: str, *, volume: bool = False) -> np.ndarray:
    """Validate an (m, 2, 2) array of boxes ``[[x_lo, x_hi], [y_lo, y_hi]]`` per row.

    ``volume=True`` also requires ``lo < hi`` on both axes (a robot's position box).
    Raises ``ValueError`` naming ``name`` for a wrong shape, non-finite, complex or
    unordered bounds.
    """
    arr = np.asarray(boxes)
    if np.iscomplexobj(arr):
        raise ValueError(f"{name} must be real, got complex bounds")
    try:
        arr = np.ascontiguousarray(arr, dtype=float)
    except (TypeError, ValueError) as err:
        raise ValueError(f"{name} must be an (m, 2, 2) array of numbers: {err}") from None
    if arr.ndim != 3 or arr.shape[1:] != (2, 2):
        raise ValueError(f"{name} must have shape (m, 2, 2) ([[x_lo, x_hi], [y_lo, y_hi]] rows)")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite")
    if np.any(arr[:, :, 0] > arr[:, :, 1]):
        raise ValueError(f"{name}: a lower bound exceeds its upper bound")
    if volume and np.any(arr[:, :, 0] >= arr[:, :, 1]):
        bad = np.flatnonzero(np.any(arr[:, :, 0] >= arr[:, :, 1], axis=1)).tolist()
        raise ValueError(f"{name}: box(es) {bad} have no volume (lo >= hi on an axis)")
    return arr


def visibility_test(boxes1, boxes2, obstacles) -> np.ndarray:
    """Three-valued visibility of box pairs through polygonal obstacles [GLH12, Algorithm 3].

    Parameters
    ----------
    boxes1, boxes2
        (m, 2, 2) arrays of position boxes, ``[[x_lo, x_hi], [y_lo, y_hi]]`` per row
        (degenerate boxes are points).
    obstacles
        List of polygons, each a (k, 2) array of vertices (closed solid sets); pass E⁻ or E⁺.

    Returns
    -------
    (m,) int8 array of :class:`~optbound.interval.Tri`
        TRUE if for every ``x1`` in ``boxes1[i]`` and ``x2`` in ``boxes2[i]`` no obstacle meets
        ``Seg(x1, x2)`` (touching counts as meeting), FALSE if for every such pair one does,
        UNKNOWN otherwise. Proven with [GLH12, eqs. (6)-(7)] in outward-rounded arithmetic,
        plus the cases eq. (19) alone misses: a segment inside an obstacle, touching.
    """
    b1, b2 = as_boxes(boxes1, "boxes1"), as_boxes(boxes2, "boxes2")
    if b1.shape != b2.shape:
        raise ValueError(f"boxes1 and boxes2 must have the same shape, got {b1.shape}, {b2.shape}")
    return tri_not(segments_meet_polygons(b1, b2, as_polygons(obstacles)))


def _meets(b1: np.ndarray, b2: np.ndarray, packed) -> np.ndarray:
    """:func:`visibility_test` on trusted arrays against a pre-packed polygon set (hot path)."""
    return tri_not(segments_meet_polygons(b1, b2, None, packed=packed))


def _check_env(env) -> Environment:
    if not isinstance(env, Environment):
        raise TypeError(f"env must be an Environment (E⁻ and E⁺), got {type(env).__name__}")
    return env


def _check_eps(eps) -> float:
    if not isinstance(eps, int | float) or not np.isfinite(eps) or eps <= 0:
        raise ValueError(f"eps must be a positive finite area, got {eps!r}")
    return float(eps)


def _check_depth(max_depth) -> int:
    if isinstance(max_depth, bool) or not isinstance(max_depth, int | np.integer) or max_depth < 0:
        raise ValueError(f"max_depth must be a non-negative integer, got {max_depth!r}")
    return int(max_depth)


def _check_measurements(y, m: int, name: str = "y") -> np.ndarray:
    arr = np.asarray(y)
    if arr.dtype != np.bool_:
        raise TypeError(f"{name} must be booleans (visible or not), got dtype {arr.dtype}")
    if arr.shape != (m,):
        raise ValueError(f"{name} must have one entry per robot, shape ({m},), got {arr.shape}")
    return arr


def _bisect(boxes: np.ndarray) -> np.ndarray:
    """Halve each box across its wider side [GLH12, Sect. 2.2]; children interleaved."""
    widths = boxes[:, :, 1] - boxes[:, :, 0]
    axis = np.argmax(widths, axis=1)
    rows = np.arange(len(boxes))
    mid = 0.5 * (boxes[rows, axis, 0] + boxes[rows, axis, 1])
    left, right = boxes.copy(), boxes.copy()
    left[rows, axis, 1] = mid
    right[rows, axis, 0] = mid
    return np.stack([left, right], axis=1).reshape(-1, 2, 2)


#: Boxes taken per direction and round by the best-first search of :func:`_luvia`.
BEAM = 4


def _refute(cur, pending, others, y, boxes, env) -> np.ndarray:
    """Test the still-pending measurements on each box of ``cur``; mask of refuted boxes.

    ``pending[k, o]`` (updated in place) is True while the measurement with robot
    ``others[o]`` is undecided on box k: a box proven consistent with a measurement stays so
    for its sub-boxes, which therefore skip that test.
    """
    k, o = np.nonzero(pending)
    j = others[o]
    seen = y[j]
    result = np.empty(len(k), dtype=np.int8)
    result[seen] = _meets(cur[k[seen]], boxes[j[seen]], env.packed_inner)
    result[~seen] = _meets(cur[k[~seen]], boxes[j[~seen]], env.packed_outer)
    # "visible" is contradicted when no pair sees through E⁻ (Prop. 15); "not visible" when
    # every pair sees through E⁺ (Prop. 16).
    refuted = np.where(seen, result == Tri.FALSE, result == Tri.TRUE)
    decided = result != Tri.UNKNOWN
    pending[k[decided], o[decided]] = False
    out = np.zeros(len(cur), dtype=bool)
    out[k[refuted]] = True
    return out


def _luvia(i: int, y: np.ndarray, boxes: np.ndarray, env: Environment, eps: float, max_depth: int):
    """LUVIA on validated input; the hull of the consistent sub-boxes or None if none.

    Algorithm 2 returns only the hull of its kept boxes, so a box inside the hull of boxes
    already kept need not be bisected: its kept sub-boxes could not enlarge the hull. The
    search is therefore best-first: each round bisects the boxes that stick out farthest
    beyond the current hull in each of the four directions, and drops those that no longer
    stick out. The result is the hull of Algorithm 2 (same bisections, same tests), for a
    fraction of the box tests.
    """
    others = np.array([j for j in range(len(boxes)) if j != i], dtype=np.int64)
    pool = boxes[i][None].copy()
    pending = np.ones((1, len(others)), dtype=bool)
    depth = np.zeros(1, dtype=np.int64)
    hull = np.array([[np.inf, -np.inf], [np.inf, -np.inf]])  # of the kept boxes; empty
    while len(pool):
        beyond = np.stack(
            [
                pool[:, a, b] < hull[a, b] if b == 0 else pool[:, a, b] > hull[a, b]
                for a in (0, 1)
                for b in (0, 1)
            ],
            axis=1,
        )
        relevant = beyond.any(axis=1)
        pool, pending, depth, beyond = (
            pool[relevant],
            pending[relevant],
            depth[relevant],
            beyond[relevant],
        )
        pick = np.zeros(len(pool), dtype=bool)
        for d, (a, b) in enumerate(((0, 0), (0, 1), (1, 0), (1, 1))):
            cand = np.flatnonzero(beyond[:, d])
            if len(cand) > BEAM:
                key = pool[cand, a, b] if b == 0 else -pool[cand, a, b]
                cand = cand[np.argpartition(key, BEAM)[:BEAM]]
            pick[cand] = True
        cur, cur_pending, cur_depth = pool[pick], pending[pick], depth[pick]
        alive = ~_refute(cur, cur_pending, others, y, boxes, env)
        size = np.prod(cur[:, :, 1] - cur[:, :, 0], axis=1)
        split = alive & cur_pending.any(axis=1) & (size > eps) & (cur_depth < max_depth)
        leaves = cur[alive & ~split]
        if len(leaves):
            hull[:, 0] = np.minimum(hull[:, 0], leaves[:, :, 0].min(axis=0))
            hull[:, 1] = np.maximum(hull[:, 1], leaves[:, :, 1].max(axis=0))
        rest = ~pick
        pool = np.concatenate([pool[rest], _bisect(cur[split])])
        pending = np.concatenate([pending[rest], np.repeat(cur_pending[split], 2, axis=0)])
        depth = np.concatenate([depth[rest], np.repeat(cur_depth[split] + 1, 2)])
    return None if hull[0, 0] > hull[0, 1] else hull


def luvia(
    robot: int, y, boxes, env: Environment, eps: float, *, max_depth: int = MAX_DEPTH
) -> np.ndarray | None:
    """Contract one robot's position box with its visibility measurements [GLH12, Alg. 2].

    Parameters
    ----------
    robot
        Index ``i`` of the robot in ``boxes``.
    y
        (m,) booleans: ``y[l]`` is True when robots ``i`` and ``l`` see each other
        [GLH12, eq. (18)]; ``y[i]`` is ignored.
    boxes
        (m, 2, 2) position boxes of all robots (each with volume), ``[[x_lo, x_hi], [y_lo,
        y_hi]]``; the other robots' boxes are used as they are.
    env
        The :class:`Environment` (E⁻ for "visible", E⁺ for "not visible").
    eps
        Boxes of area ``Size([x]) <= eps`` are not bisected further [GLH12, Alg. 2, l. 20].
    max_depth
        At most this many nested bisections whatever ``eps`` (not in the paper: it bounds the
        cost of large boxes; the result is still guaranteed, only coarser).

    Returns
    -------
    (2, 2) array or None
        The hull of the sub-boxes not refuted by any measurement, a subset of ``boxes[robot]``
        containing every position of it consistent with the measurements, the other boxes
        and E; None when every sub-box is refuted (the data contradict the boxes).
    """
    b = as_boxes(boxes, "boxes", volume=True)
    m = len(b)
    if m == 0:
        raise ValueError("boxes is empty: LUVIA needs a team of robots")
    if isinstance(robot, bool) or not isinstance(robot, int | np.integer):
        raise TypeError(f"robot must be an integer index, got {type(robot).__name__}")
    if not 0 <= robot < m:
        raise ValueError(f"robot must be in [0, {m}), got {robot}")
    y = _check_measurements(y, m)
    return _luvia(int(robot), y, b, _check_env(env), _check_eps(eps), _check_depth(max_depth))


def odometry(boxes, distance, heading, heading_error: float) -> np.ndarray:
    """Interval odometry with a compass [GLH12, Alg. 1, l. 3]: ``x + d (cos θ, sin θ)``.

    ``boxes`` (m, 2, 2); ``distance`` (m, 2) interval ``[d_lo, d_hi]`` travelled by each robot
    (or one (2,) interval for all); ``heading`` (m,) compass readings (radians) with error at
    most ``heading_error``. Outward-rounded: the result contains every position reachable by
    a travel in ``[d]`` along a heading in ``[θ - δ, θ + δ]``.
    """
    b = as_boxes(boxes, "boxes")
    m = len(b)
    d = np.broadcast_to(np.asarray(distance, dtype=float), (m, 2))
    th = np.asarray(heading, dtype=float)
    if th.shape != (m,) or not np.all(np.isfinite(th)) or not np.all(np.isfinite(d)):
        raise ValueError(f"heading must be ({m},) finite readings and distance finite")
    if np.any(d[:, 0] > d[:, 1]):
        raise ValueError("distance: lower bound exceeds upper bound")
    if not np.isfinite(heading_error) or heading_error < 0:
        raise ValueError(f"heading_error must be finite and >= 0, got {heading_error!r}")
    theta = Interval(th) + Interval(-heading_error, heading_error)
    step = Interval(d[:, 0], d[:, 1])
    x = Interval(b[:, 0, 0], b[:, 0, 1]) + step * np.cos(theta)
    yy = Interval(b[:, 1, 0], b[:, 1, 1]) + step * np.sin(theta)
    return np.stack([np.stack([x.lo, x.hi], -1), np.stack([yy.lo, yy.hi], -1)], axis=1)


def track(
    boxes0,
    distance,
    headings,
    heading_error: float,
    visibility,
    env: Environment,
    eps: float,
    *,
    max_depth: int = MAX_DEPTH,
) -> np.ndarray:
    """Pose tracking of a team [GLH12, Algorithm 1]: odometry, then LUVIA for every robot.

    Parameters
    ----------
    boxes0
        (m, 2, 2) initial position boxes (with volume), containing the initial positions.
    distance
        Interval ``[d_lo, d_hi]`` of one step's travel, shape (2,), (K, 2) or (K, m, 2).
    headings
        (K, m) compass readings of the heading of each step (radians).
    heading_error
        Compass error bound ``δ`` (radians).
    visibility
        (K, m, m) booleans: ``visibility[k, i, l]`` is ``y_il`` after step ``k``.
    env, eps, max_depth
        As for :func:`luvia`.

    Returns
    -------
    (K + 1, m, 2, 2) array
        The boxes after each step (index 0 is ``boxes0``). Robots are contracted in order,
        each with the others' latest boxes (every contraction is guaranteed, so the order
        changes tightness only). Raises ``ValueError`` if LUVIA refutes a whole box (the
        measurements are inconsistent with E⁻, E⁺ and the odometry).
    """
    b = as_boxes(boxes0, "boxes0", volume=True)
    m = len(b)
    if m == 0:
        raise ValueError("boxes0 is empty: tracking needs at least one robot")
    env, eps, max_depth = _check_env(env), _check_eps(eps), _check_depth(max_depth)
    th = np.asarray(headings, dtype=float)
    if th.ndim != 2 or th.shape[1] != m:
        raise ValueError(f"headings must have shape (K, {m}), got {th.shape}")
    steps = len(th)
    vis = np.asarray(visibility)
    if vis.dtype != np.bool_:
        raise TypeError(f"visibility must be booleans, got dtype {vis.dtype}")
    if vis.shape != (steps, m, m):
        raise ValueError(f"visibility must have shape ({steps}, {m}, {m}), got {vis.shape}")
    dist = np.broadcast_to(np.asarray(distance, dtype=float), (steps, m, 2))
    out = np.empty((steps + 1, m, 2, 2))
    out[0] = b
    for k in range(steps):
        cur = odometry(out[k], dist[k], th[k], heading_error)
        for i in range(m):
            if m > 1:
                box = _luvia(i, vis[k, i], cur, env, eps, max_depth)
                if box is None:
                    raise ValueError(f"step {k}: every position of robot {i} is refuted")
                cur[i] = box
        out[k + 1] = cur
    return out
