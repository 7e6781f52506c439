"""Pose tracking of a team of robots from visibility alone: LUVIA [GLH12].

Two robots see each other when no obstacle meets the segment between them [GLH12, Def. 1].
On boxes this becomes three-valued [GLH12, Def. 9]: TRUE when every pair of points of the two
boxes sees each other, FALSE when no pair does, UNKNOWN otherwise (:func:`visibility_test`,
Algorithm 3). A "visible" measurement is confronted with the inner characterization E⁻, a
"not visible" one with the outer E⁺ [GLH12, Props. 15-16], so that a box is discarded only
when it contains no position consistent with the true environment E (:func:`luvia`,
Algorithm 2). :func:`track` (Algorithm 1) alternates interval odometry with a compass and
LUVIA for every robot. :func:`measure` is the noise-free measurement: the true visibility
matrix of robots at given points. :func:`exact_paving` paves the exact set one LUVIA step
contracts towards, the yardstick of how much a step could contract.
"""

from __future__ import annotations

import numpy as np

from optbound._core import box_array, real_array
from optbound._core.compiled_copy import copy_into
from optbound._core.jit import njit
from optbound._core.native_call import address, caller
from optbound.interval import Interval, Paving, Tri, pave, tri_not
from optbound.interval.compiled import iadd
from optbound.localization.environment import Environment
from optbound.localization.geometry import (
    as_polygons,
    segment_pair_meets,
    segments_meet_polygons,
)

#: Default bound on nested bisections per LUVIA call, whatever ``eps``: a box is cut into at
#: most 2**MAX_DEPTH sub-boxes, which bounds the cost when boxes grow large.
MAX_DEPTH = 10


def visibility_test(boxes1, boxes2, obstacles) -> np.ndarray:
    """Three-valued visibility of box pairs through polygonal obstacles [GLH12, Algorithm 3].

    Parameters
    ----------
    boxes1, boxes2
        (m, 2, 2) arrays of position boxes, ``[[x_lo, x_hi], [y_lo, y_hi]]`` per row
        (degenerate boxes are points).
    obstacles
        List of simple polygons of non-zero area, each a (k, 2) array of vertices (closed
        solid sets); pass E⁻ or E⁺.

    Returns
    -------
    (m,) int8 array of :class:`~optbound.interval.Tri`
        TRUE if for every ``x1`` in ``boxes1[i]`` and ``x2`` in ``boxes2[i]`` no obstacle meets
        ``Seg(x1, x2)`` (touching counts as meeting), FALSE if for every such pair one does,
        UNKNOWN otherwise. Proven with [GLH12, eqs. (6)-(7)] in outward-rounded arithmetic,
        plus the cases eq. (19) alone misses: a segment inside an obstacle, touching.
    """
    b1, b2 = box_array("boxes1", boxes1, 2), box_array("boxes2", boxes2, 2)
    if b1.shape != b2.shape:
        raise ValueError(f"boxes1 and boxes2 must have the same shape, got {b1.shape}, {b2.shape}")
    return tri_not(segments_meet_polygons(b1, b2, as_polygons(obstacles)))


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


def _check_passes(passes) -> int:
    if isinstance(passes, bool) or not isinstance(passes, int | np.integer) or passes < 1:
        raise ValueError(f"passes must be a positive integer, got {passes!r}")
    return int(passes)


def _check_measurements(y, m: int, name: str = "y") -> np.ndarray:
    arr = np.asarray(y)
    if arr.dtype != np.bool_:
        raise TypeError(f"{name} must be booleans (visible or not), got dtype {arr.dtype}")
    if arr.shape != (m,):
        raise ValueError(f"{name} must have one entry per robot, shape ({m},), got {arr.shape}")
    return arr


@njit(cache=True)
def _consistent(box, i, y, boxes, inner, outer, pending) -> int:
    """Test the pending measurements on ``box``: 0 refuted, 1 undecided, 2 consistent.

    ``pending[j]`` (updated in place) stays True while the measurement with robot ``j`` is
    undecided: a box proven consistent with a measurement stays so for its sub-boxes, which
    skip that test. "Visible" is refuted when no pair sees through E⁻ (segments certainly
    meet it) [GLH12, Prop. 15]; "not visible" when every pair sees through E⁺ [Prop. 16].
    """
    undecided = False
    for j in range(len(boxes)):
        if not pending[j]:
            continue
        if y[j]:
            r = segment_pair_meets(box, boxes[j], inner[0], inner[1], inner[2])
            refuted = r == 2
        else:
            r = segment_pair_meets(box, boxes[j], outer[0], outer[1], outer[2])
            refuted = r == 0
        if refuted:
            return 0
        if r == 1:
            undecided = True
        else:
            pending[j] = False
    return 1 if undecided else 2


@njit(cache=True)
def _grow(arr, size: int):
    """``arr`` with its first axis enlarged to ``size`` (the first rows copied)."""
    out = np.empty((size, *arr.shape[1:]), dtype=arr.dtype)
    copy_into(out[: len(arr)], arr)
    return out


@njit(cache=True)
def _luvia_kernel(i, y, boxes, inner, outer, eps, max_depth, hull) -> None:
    """Hull of the boxes kept by [GLH12, Algorithm 2], written into ``hull`` (empty: inf).

    Algorithm 2 returns only the hull of its kept boxes, so each side of the hull is found
    by its own depth-first pass that visits the more extreme child first and skips any box
    not sticking out beyond the hull found so far: its kept sub-boxes could not move that
    side. Same bisections, same tests, same hull as Algorithm 2, for a fraction of the tests.
    The passes share one bisection tree: a box tested in an earlier pass keeps its verdict
    and its children (a node's verdict depends on its box and the measurements still
    pending from its ancestors only).
    """
    m = len(boxes)
    cap = 64
    box_of = np.empty((cap, 2, 2))
    pending_of = np.empty((cap, m), dtype=np.bool_)  # per node: undecided measurements
    verdict_of = np.full(cap, -1, dtype=np.int64)  # -1: not tested yet
    child_of = np.full(cap, -1, dtype=np.int64)  # its low child (the high one follows)
    depth_of = np.empty(cap, dtype=np.int64)
    copy_into(box_of[0], boxes[i])
    pending_of[0] = True
    pending_of[0, i] = False
    depth_of[0] = 0
    nodes = 1
    stack = np.empty(2 * (max_depth + 2), dtype=np.int64)  # one sibling per level
    hull[:, 0] = np.inf
    hull[:, 1] = -np.inf
    for d in range(4):
        a, side = d // 2, d % 2
        stack[0] = 0
        n = 1
        while n > 0:
            n -= 1
            node = stack[n]
            box = box_of[node]
            if (box[a, 0] >= hull[a, 0]) if side == 0 else (box[a, 1] <= hull[a, 1]):
                continue  # cannot move this side of the hull
            verdict = verdict_of[node]
            if verdict < 0:
                verdict = _consistent(box, i, y, boxes, inner, outer, pending_of[node])
                verdict_of[node] = verdict
            if verdict == 0:
                continue
            w0, w1 = box[0, 1] - box[0, 0], box[1, 1] - box[1, 0]
            if verdict == 1 and w0 * w1 > eps and depth_of[node] < max_depth:
                low = child_of[node]
                if low < 0:
                    if nodes + 2 > cap:
                        cap *= 2
                        box_of, pending_of = _grow(box_of, cap), _grow(pending_of, cap)
                        verdict_of, child_of = _grow(verdict_of, cap), _grow(child_of, cap)
                        depth_of = _grow(depth_of, cap)
                        verdict_of[nodes:] = -1
                        child_of[nodes:] = -1
                        box = box_of[node]
                    ax = 0 if w0 >= w1 else 1  # the wider side, as np.argmax would pick
                    mid = 0.5 * (box[ax, 0] + box[ax, 1])
                    low = nodes
                    for k in range(low, low + 2):
                        copy_into(box_of[k], box)
                        copy_into(pending_of[k], pending_of[node])
                        depth_of[k] = depth_of[node] + 1
                    box_of[low, ax, 1] = mid
                    box_of[low + 1, ax, 0] = mid
                    child_of[node] = low
                    nodes += 2
                # Push the less extreme child first so that the more extreme one pops first.
                stack[n], stack[n + 1] = (low + 1, low) if side == 0 else (low, low + 1)
                n += 2
            else:
                for k in range(2):
                    hull[k, 0] = min(hull[k, 0], box[k, 0])
                    hull[k, 1] = max(hull[k, 1], box[k, 1])


_call_luvia = caller(_luvia_kernel)


@njit(cache=True)
def _sweep_kernel(y, cur, inner, outer, eps, max_depth, luvia) -> int:
    """One team sweep of :func:`track`: LUVIA for robot 0, 1, ... in turn, each box replaced
    in ``cur`` by its hull as soon as it is found; -1, or the first robot refuted.

    ``luvia`` is the address of :func:`_luvia_kernel` (:func:`_sweep_address`): called by
    address, the search is not linked into the sweep, where LLVM would optimize and emit it
    and its predicates again (``_core.native_call``)."""
    hull = np.empty((2, 2))
    for i in range(len(cur)):
        _call_luvia(luvia, (i, y[i], cur, inner, outer, eps, max_depth, hull))
        if hull[0, 0] > hull[0, 1]:
            return i
        copy_into(cur[i], hull)
    return -1


def _sweep_address(env: Environment) -> int:
    """The address of :func:`_luvia_kernel` compiled for the types of :func:`_sweep_kernel`'s
    call: a row of a C-ordered bool array, C-ordered float boxes, ``env``'s packed obstacles,
    a float eps and an int depth (the values do not matter, only their types)."""
    rows, boxes, hull = np.zeros((1, 1), dtype=np.bool_), np.empty((1, 2, 2)), np.empty((2, 2))
    return address(
        _luvia_kernel, 0, rows[0], boxes, env.packed_inner, env.packed_outer, 0.0, 0, hull
    )


def _luvia(i: int, y: np.ndarray, boxes: np.ndarray, env: Environment, eps: float, max_depth: int):
    """LUVIA on validated input; the hull of the consistent sub-boxes or None if none."""
    hull = np.empty((2, 2))
    _luvia_kernel(i, y, boxes, env.packed_inner, env.packed_outer, eps, max_depth, hull)
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
    b = box_array("boxes", boxes, 2, volume=True)
    m = len(b)
    if m == 0:
        raise ValueError("boxes is empty: LUVIA needs a team of robots")
    if isinstance(robot, bool) or not isinstance(robot, int | np.integer):
        raise TypeError(f"robot must be an integer index, got {type(robot).__name__}")
    if not 0 <= robot < m:
        raise ValueError(f"robot must be in [0, {m}), got {robot}")
    y = _check_measurements(y, m)
    return _luvia(int(robot), y, b, _check_env(env), _check_eps(eps), _check_depth(max_depth))


def _travel(distance, shape: tuple[int, ...], allowed: str) -> np.ndarray:
    """``distance`` as travel intervals ``0 <= d_lo <= d_hi``, broadcast to ``shape + (2,)``.

    Raises ``ValueError`` naming ``distance`` for another shape, non-finite bounds, a lower
    bound above the upper one, or a negative travel (the model moves along the heading).
    """
    d = real_array("distance", distance)
    try:
        d = np.broadcast_to(d, (*shape, 2))
    except ValueError:
        raise ValueError(f"distance must have shape {allowed}, got {d.shape}") from None
    if not np.all(np.isfinite(d)):
        raise ValueError("distance must be finite")
    if np.any(d[..., 0] > d[..., 1]):
        raise ValueError("distance: lower bound exceeds upper bound")
    if np.any(d[..., 0] < 0.0):
        raise ValueError(
            "distance must be non-negative: the robot travels along its heading "
            f"(got a lower bound {d[..., 0].min()})"
        )
    return d


def _check_heading_error(heading_error) -> float:
    if (
        not isinstance(heading_error, int | float)
        or not np.isfinite(heading_error)
        or heading_error < 0
    ):
        raise ValueError(f"heading_error must be finite and >= 0, got {heading_error!r}")
    return heading_error


def _displacements(d: np.ndarray, th: np.ndarray, heading_error: float):
    """Interval ``d (cos θ, sin θ)`` with ``θ ∈ [th - δ, th + δ]``, element by element.

    ``d``: travel intervals of shape ``th.shape + (2,)``. The result does not depend on the
    boxes, so :func:`track` evaluates it for all its steps in one call (the interval
    operations are elementwise: the same bits as step by step).
    """
    theta = Interval(th) + Interval(-heading_error, heading_error)
    step = Interval(d[..., 0], d[..., 1])
    return step * np.cos(theta), step * np.sin(theta)


@njit(cache=True)
def _shift(b, xl, xh, yl, yh):
    """``b`` (m, 2, 2) plus ``[xl, xh]`` on x and ``[yl, yh]`` on y, rounded outward."""
    out = np.empty_like(b)
    for r in range(len(b)):
        out[r, 0, 0], out[r, 0, 1] = iadd(b[r, 0, 0], b[r, 0, 1], xl[r], xh[r])
        out[r, 1, 0], out[r, 1, 1] = iadd(b[r, 1, 0], b[r, 1, 1], yl[r], yh[r])
    return out


def _moved(b: np.ndarray, dx: Interval, dy: Interval) -> np.ndarray:
    """The boxes ``b`` (m, 2, 2, finite, ``lo <= hi``) shifted by the displacement intervals
    ``dx``, ``dy`` (m,, not empty): ``Interval`` addition, bit for bit (compiled ``iadd``)."""
    return _shift(np.ascontiguousarray(b), dx.lo, dx.hi, dy.lo, dy.hi)


def odometry(boxes, distance, heading, heading_error: float) -> np.ndarray:
    """Interval odometry with a compass [GLH12, Alg. 1, l. 3]: ``x + d (cos θ, sin θ)``.

    Outward-rounded: the result contains every position reachable by a travel in ``[d]``
    along a heading in ``[θ - δ, θ + δ]``.

    Parameters
    ----------
    boxes : array_like, shape (m, 2, 2)
        Position boxes of the m robots.
    distance : array_like, shape (m, 2) or (2,)
        Interval ``0 <= d_lo <= d_hi`` travelled by each robot (or one for all).
    heading : array_like, shape (m,)
        Compass readings (radians).
    heading_error : float
        Compass error bound δ (radians), >= 0.

    Returns
    -------
    numpy.ndarray, shape (m, 2, 2)
        The boxes after the step.

    Raises
    ------
    ValueError
        On malformed boxes, a negative or malformed ``distance``, non-finite headings or a
        negative ``heading_error``.
    """
    b = box_array("boxes", boxes, 2)
    m = len(b)
    d = _travel(distance, (m,), "(2,) or (m, 2)")
    th = np.asarray(heading, dtype=float)
    if th.shape != (m,) or not np.all(np.isfinite(th)):
        raise ValueError(f"heading must be ({m},) finite readings")
    return _moved(b, *_displacements(d, th, _check_heading_error(heading_error)))


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
    passes: int = 1,
    region=None,
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
    passes
        Team contraction sweeps per step (not in the paper). A sweep contracts every robot in
        turn; robots contracted early used the others' boxes from before their contraction,
        so a new sweep can shrink them further. Sweeps are repeated until none changes a box
        (a fixpoint of the team's contraction) or ``passes`` sweeps were run. 1 (default) is
        [GLH12, Algorithm 1] as printed. Each contraction keeps every position consistent
        with boxes that contain the truth, so every sweep keeps the guarantee.
    region
        Optional box ``[[x_lo, x_hi], [y_lo, y_hi]]`` known to contain every robot at every
        step (e.g. the room); each odometry box is intersected with it (not in the paper).

    Returns
    -------
    (K + 1, m, 2, 2) array
        The boxes after each step (index 0 is ``boxes0``). Robots are contracted in order,
        each with the others' latest boxes (every contraction is guaranteed, so the order
        changes tightness only).

    Raises
    ------
    ValueError
        If LUVIA refutes a whole box, or if a box misses ``region`` (the measurements are
        inconsistent with E⁻, E⁺, the odometry and the region); on malformed arguments.
    TypeError
        If ``visibility`` is not boolean.

    References
    ----------
    .. [GLH12] R. Guyonneau, S. Lagrange, L. Hardouin, "Mobile robots pose tracking: a
       set-membership approach using a visibility information", ICINCO, 2012.

    Examples
    --------
    Three robots around a square obstacle move one step north; robots 0 and 1 are hidden
    from each other by it:

    >>> env = Environment.from_polygons([[[4, 4], [6, 4], [6, 6], [4, 6]]], 0.05)
    >>> start = np.array([[1.0, 5.0], [9.0, 5.0], [5.0, 1.0]])
    >>> after = start + [0.0, 1.0]
    >>> y = measure(after, env.exact)
    >>> y.astype(int).tolist()
    [[1, 0, 1], [0, 1, 1], [1, 1, 1]]
    >>> boxes0 = np.stack([start - 0.5, start + 0.5], axis=-1)
    >>> boxes = track(boxes0, [0.9, 1.1], [[np.pi / 2] * 3], 0.01, y[None], env, 0.05)
    >>> boxes.shape
    (2, 3, 2, 2)
    >>> bool(np.all((boxes[1, :, :, 0] <= after) & (after <= boxes[1, :, :, 1])))
    True
    """
    b = box_array("boxes0", boxes0, 2, volume=True)
    m = len(b)
    if m == 0:
        raise ValueError("boxes0 is empty: tracking needs at least one robot")
    env, eps, max_depth = _check_env(env), _check_eps(eps), _check_depth(max_depth)
    passes = _check_passes(passes)
    room = None if region is None else box_array("region", [region], 2)[0]
    th = np.asarray(headings, dtype=float)
    if th.ndim != 2 or th.shape[1] != m:
        raise ValueError(f"headings must have shape (K, {m}), got {th.shape}")
    steps = len(th)
    vis = np.ascontiguousarray(visibility)  # C order: the type the sweep's search is compiled for
    if vis.dtype != np.bool_:
        raise TypeError(f"visibility must be booleans, got dtype {vis.dtype}")
    if vis.shape != (steps, m, m):
        raise ValueError(f"visibility must have shape ({steps}, {m}, {m}), got {vis.shape}")
    dist = real_array("distance", distance)
    dist = _travel(
        dist[:, None] if dist.ndim == 2 else dist, (steps, m), "(2,), (K, 2) or (K, m, 2)"
    )
    if not np.all(np.isfinite(th)):
        raise ValueError(f"headings must be ({steps}, {m}) finite readings")
    dx, dy = _displacements(dist, th, _check_heading_error(heading_error))
    inner, outer = env.packed_inner, env.packed_outer
    luvia = _sweep_address(env) if m > 1 else 0
    out = np.empty((steps + 1, m, 2, 2))
    out[0] = b
    for k in range(steps):
        cur = _moved(out[k], dx[k], dy[k])
        if room is not None:
            cur[..., 0] = np.maximum(cur[..., 0], room[:, 0])
            cur[..., 1] = np.minimum(cur[..., 1], room[:, 1])
            if np.any(cur[..., 0] > cur[..., 1]):
                raise ValueError(f"step {k}: a robot's box misses region")
        for _ in range(passes if m > 1 else 0):
            before = cur.copy()
            refuted = _sweep_kernel(vis[k], cur, inner, outer, eps, max_depth, luvia)
            if refuted >= 0:
                raise ValueError(f"step {k}: every position of robot {refuted} is refuted")
            if np.array_equal(before, cur):
                break
        out[k + 1] = cur
    return out


def measure(points, obstacles) -> np.ndarray:
    """(m, m) true visibility of robots at ``points`` through the exact obstacles [GLH12, Def. 1].

    The model's noise-free measurement: ``y_il`` is True when no obstacle meets the segment
    between robots i and l. Certified on the points; a pair within rounding of grazing an
    obstacle counts as not visible, which keeps the guarantee of a simulation whose E⁺
    contains E with a margin and whose E⁻ has one inside E.

    Parameters
    ----------
    points
        (m, 2) robot positions, or (K, m, 2): K teams (e.g. the steps of a run) measured in
        one call.
    obstacles
        As for :func:`visibility_test` (typically ``Environment.exact``).

    Returns
    -------
    (m, m) or (K, m, m) bool array
        Symmetric, True on the diagonal.
    """
    pts = real_array("points", points, "an (m, 2) array")
    if pts.ndim not in (2, 3) or pts.shape[-1] != 2:
        raise ValueError(f"points must have shape (m, 2) or (K, m, 2), got {pts.shape}")
    m = pts.shape[-2]
    i, j = np.triu_indices(m, 1)
    boxes = np.repeat(pts[..., None], 2, axis=-1)
    b1, b2 = boxes[..., i, :, :].reshape(-1, 2, 2), boxes[..., j, :, :].reshape(-1, 2, 2)
    seen = visibility_test(b1, b2, obstacles) == Tri.TRUE
    y = np.zeros((*pts.shape[:-2], m, m), dtype=bool)
    y[..., np.arange(m), np.arange(m)] = True
    y[..., i, j] = y[..., j, i] = seen.reshape(*pts.shape[:-2], len(i))
    return y


def _cells(box: np.ndarray, split: int) -> np.ndarray:
    """``box`` cut into a ``split`` x ``split`` grid of (split², 2, 2) cells covering it."""
    xs = np.linspace(box[0, 0], box[0, 1], split + 1)
    ys = np.linspace(box[1, 0], box[1, 1], split + 1)
    xs[[0, -1]], ys[[0, -1]] = box[0], box[1]  # the grid covers the box exactly
    gx, gy = np.meshgrid(np.arange(split), np.arange(split), indexing="ij")
    gx, gy = gx.ravel(), gy.ravel()
    return np.stack(
        [np.stack([xs[gx], xs[gx + 1]], -1), np.stack([ys[gy], ys[gy + 1]], -1)], axis=1
    )


def exact_paving(robot: int, y, boxes, env: Environment, eps: float, *, split: int = 8) -> Paving:
    """Pave the positions of ``robot`` consistent with one step's measurements and boxes.

    The set LUVIA contracts towards, with one witness per measurement (the robots l are
    distinct) and E⁻ for "visible", E⁺ for "not visible" [GLH12, Props. 15-16]:

        S_i = {x ∈ [x_i] : for every l ≠ i there is an x_l ∈ [x_l] with
               Seg(x, x_l) ∩ E⁻ = ∅ if y_il, Seg(x, x_l) ∩ E⁺ ≠ ∅ if not}.

    Algorithm 2 bisects ``[x_i]`` only and tests each sub-box against the whole ``[x_l]``;
    here each ``[x_l]`` is also cut into ``split`` x ``split`` cells, so a box is refuted when
    every cell is (no witness anywhere) and proven inner when one cell witnesses all its
    points. The hull of the inner boxes and that of the inner and boundary boxes bracket the
    hull of S_i: the best any contraction from this step's data alone can return.

    Parameters
    ----------
    robot, y, boxes, env
        As for :func:`optbound.localization.visibility.luvia` (``y[robot]`` is ignored).
    eps
        Boxes whose widest side is at most ``eps`` (metres) are not bisected further.
    split
        Each other robot's box is cut into ``split`` x ``split`` cells (1: Algorithm 2's test).

    Returns
    -------
    Paving
        ``inner ⊂ S_i ⊂ inner ∪ boundary`` within ``boxes[robot]``.
    """
    b = box_array("boxes", boxes, 2, volume=True)
    m = len(b)
    if isinstance(robot, bool) or not isinstance(robot, int | np.integer) or not 0 <= robot < m:
        raise ValueError(f"robot must be an index in [0, {m}), got {robot!r}")
    y, env = _check_measurements(y, m), _check_env(env)
    if isinstance(split, bool) or not isinstance(split, int) or split < 1:
        raise ValueError(f"split must be a positive integer, got {split!r}")
    inner, outer = as_polygons(env.inner), as_polygons(env.outer)
    others = [(_cells(b[j], split), inner if y[j] else outer, bool(y[j])) for j in range(m)]
    others = [o for j, o in enumerate(others) if j != robot]

    def test(x, yy) -> np.ndarray:
        n = len(x.lo)
        xbox = np.stack([np.stack([x.lo, x.hi], -1), np.stack([yy.lo, yy.hi], -1)], axis=1)
        proven = np.ones(n, dtype=bool)
        refuted = np.zeros(n, dtype=bool)
        for cells, polygons, visible in others:
            c = len(cells)
            meets = segments_meet_polygons(
                np.repeat(xbox, c, axis=0), np.tile(cells, (n, 1, 1)), polygons
            ).reshape(n, c)
            good, bad = (Tri.FALSE, Tri.TRUE) if visible else (Tri.TRUE, Tri.FALSE)
            proven &= np.any(meets == good, axis=1)
            refuted |= np.all(meets == bad, axis=1)
        out = np.full(n, Tri.UNKNOWN, dtype=np.int8)
        out[proven] = Tri.TRUE
        out[refuted] = Tri.FALSE
        return out

    return pave(test, b[robot], eps)


__all__ = [
    "MAX_DEPTH",
    "exact_paving",
    "luvia",
    "measure",
    "odometry",
    "track",
    "visibility_test",
]
