"""Compiled inclusion function of the sonar belt and its q-relaxed test [LJMW97], [KJWM00].

:func:`geometry.nearest_in_cone` on :class:`~optbound.interval.Interval` arrays is the
inclusion function of one sonar's range [LJMW97, eq. (2)]; evaluated with numpy it costs about
a hundred array operations per sonar and bisection level, which dominates SIVIA on the few
thousand boxes of a sonar paving. Here the same formulas (:func:`geometry.cone_candidates`),
in the same order with the same outward-rounded operations (:mod:`optbound.interval.compiled`,
bit for bit those of the numpy interval layer), run in one compiled loop over boxes, sonars and
walls. The tests check that the bounds equal those of the numpy evaluation.

Only the sines and cosines of the heading and of the cone's edges are computed outside, by
the interval layer (:func:`geometry.unit`, once per distinct heading); the walls' own
quantities (``b - a``, length, inward normal) once per map. The determinants of the cone's
edges with a wall's direction and normal depend on the heading only, not on the apex: they
are computed once per distinct heading, sonar and wall (on first use) and read back for the
other boxes of that heading (SIVIA's boxes share few headings). The q-relaxed test [KJWM00]
counts, per box, the sonars whose range interval lies inside / outside their reading and
stops at the first sonar that decides the box (the verdicts of
:func:`optbound.interval.relaxed_test`).
"""

from __future__ import annotations

from itertools import repeat

import numpy as np

from optbound._core.jit import njit
from optbound.interval import Interval
from optbound.interval.compiled import iadd, idiv, imul, isqr, isqrt, isub
from optbound.interval.sivia import FALSE, TRUE, UNKNOWN
from optbound.localization import geometry as g

# Columns of the wall table (:func:`wall_table`).
_AX, _AY, _BX, _BY = 0, 1, 2, 3
_EX, _EY, _LEN, _INX, _INY = 4, 6, 8, 10, 12  # lo at the index, hi at index + 1
_WALL_COLUMNS = 14
# Columns of the per-(box, sonar) table (:func:`pose_table`): lo, hi of each quantity.
_PX, _PY, _RX, _RY, _LX, _LY = 0, 2, 4, 6, 8, 10
_POSE_COLUMNS = 12
# Columns of the per-(heading, sonar, wall) cache (:func:`_cone`): lo, hi of each determinant.
_CR, _CL, _TR, _TL = 0, 2, 4, 6
_CONE_COLUMNS = 8
#: Most boxes :func:`relaxed_tri`'s memo keeps (about 150 bytes each).
MEMO_SIZE = 500_000


def wall_table(world: np.ndarray) -> np.ndarray:
    """(s, 14) per wall: ``a``, ``b``, then the intervals ``b - a``, ``|b - a|``, inward normal.

    Computed by the interval layer exactly as :func:`geometry.cone_candidates` computes them.
    """
    a, b = g.exact(g.segment_points(world)[0]), g.exact(g.segment_points(world)[1])
    ex, ey = b[0] - a[0], b[1] - a[1]
    length = g.distance(b, a)
    short = np.flatnonzero(length.lo <= 0.0)
    if short.size:  # the compiled products assume finite operands: 1 / length must be finite
        raise ValueError(f"world: segment(s) {short.tolist()} are too short (length below 1e-150)")
    inward = (ey / length, -ex / length)
    out = np.empty((world.shape[0], _WALL_COLUMNS))
    out[:, _AX], out[:, _AY], out[:, _BX], out[:, _BY] = a[0].lo, a[1].lo, b[0].lo, b[1].lo
    for col, v in ((_EX, ex), (_EY, ey), (_LEN, length), (_INX, inward[0]), (_INY, inward[1])):
        out[:, col], out[:, col + 1] = v.lo, v.hi
    return out


def pose_table(
    params: np.ndarray, x: Interval, y: Interval, theta: Interval
) -> tuple[np.ndarray, np.ndarray, int]:
    """(m, t, 12) per box and sonar: the apex and the cone's right and left unit vectors.

    ``params`` is (t, 4): each sonar's mounting ``x, y``, orientation and half-aperture.
    The same bounds as the interval layer's in :func:`sonar._ranges`: the heading's sines
    and cosines and the cone's unit vectors depend on the heading only, so the interval
    functions (which act element by element) evaluate them once per distinct ``theta``
    (SIVIA's boxes share a few), and :func:`_poses` forms the apexes with the same outward-
    rounded operations as :func:`geometry.to_world`. Also returned: each box's distinct
    heading (m,) and their number (for :func:`_cone`'s cache).
    """
    sx, sy, alpha, gamma = (np.ascontiguousarray(c) for c in params.T)
    bounds = np.stack([theta.lo, theta.hi], axis=1)
    _, first, row = np.unique(
        bounds.view(np.dtype((np.void, bounds.itemsize * 2))).ravel(),
        return_index=True,
        return_inverse=True,
    )
    n, t = first.size, len(sx)
    heading = Interval._make(theta.lo[first, None], theta.hi[first, None])
    # The heading and the cone's right and left edges in one array: one call of cos and sin.
    angles = (heading, *(heading + alpha + turn for turn in (-gamma, gamma)))
    lo, hi = (np.concatenate([getattr(a, b).ravel() for a in angles]) for b in ("lo", "hi"))
    cos, sin = g.unit(Interval._make(lo, hi))
    units = np.empty((n, t, _POSE_COLUMNS - _RX))
    for j, cols in enumerate(((_RX, _RY), (_LX, _LY))):
        part = slice(n + j * n * t, n + (j + 1) * n * t)
        for col, v in zip(cols, (cos, sin), strict=True):
            units[..., col - _RX] = v.lo[part].reshape(n, t)
            units[..., col + 1 - _RX] = v.hi[part].reshape(n, t)
    cos, sin = (np.stack([v.lo[:n], v.hi[:n]], axis=1) for v in (cos, sin))
    out = np.empty((len(row), t, _POSE_COLUMNS))
    xy = np.stack([x.lo, x.hi, y.lo, y.hi], axis=1)
    _poses(xy, row.ravel(), cos, sin, sx, sy, units, out)
    return out, row.ravel(), first.size


@njit(cache=True)
def _poses(xy, row, cos, sin, sx, sy, units, out):
    """Fill ``out`` (m, t, 12): each box's and sonar's apex and the cone's unit vectors.

    The apex is ``(x + c sx - s sy, y + s sx + c sy)``, operation by operation as in
    :func:`geometry.to_world`; the unit vectors are the rows ``units[row]``. ``xy`` (m, 4)
    holds the boxes' ``x`` and ``y`` bounds, ``cos`` and ``sin`` (n, 2) the bounds per
    distinct heading, ``units`` (n, t, 8) the cone's unit vectors.
    """
    for k in range(out.shape[0]):
        h = row[k]
        cl, ch, sl, sh = cos[h, 0], cos[h, 1], sin[h, 0], sin[h, 1]
        for i in range(out.shape[1]):
            u_lo, u_hi = imul(cl, ch, sx[i], sx[i])
            v_lo, v_hi = imul(sl, sh, sy[i], sy[i])
            p_lo, p_hi = iadd(xy[k, 0], xy[k, 1], u_lo, u_hi)
            out[k, i, _PX], out[k, i, _PX + 1] = isub(p_lo, p_hi, v_lo, v_hi)
            u_lo, u_hi = imul(sl, sh, sx[i], sx[i])
            v_lo, v_hi = imul(cl, ch, sy[i], sy[i])
            p_lo, p_hi = iadd(xy[k, 2], xy[k, 3], u_lo, u_hi)
            out[k, i, _PY], out[k, i, _PY + 1] = iadd(p_lo, p_hi, v_lo, v_hi)
            for col in range(_POSE_COLUMNS - _RX):
                out[k, i, _RX + col] = units[h, i, col]


def _cone_cache(headings: int, t: int, walls: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """An empty cache of :func:`_cone` for ``headings`` distinct headings: values, filled."""
    shape = (headings, t, walls.shape[0])
    return np.empty((*shape, _CONE_COLUMNS)), np.zeros(shape, dtype=np.bool_)


# ``_det`` and ``_norm`` (and the interval operations they call) are called, not inlined by
# numba: inlined, their twelve and two uses in ``_range`` made one function that took numba
# and LLVM ~36 s of CPU to compile, against ~2 s as calls, for the same bits and the same
# speed.
@njit(cache=True)
def _det(ul, uh, vl, vh, wl, wh, zl, zh):
    """``det(u, v, w, z) = u z - v w`` on intervals (:func:`geometry.det`)."""
    p_lo, p_hi = imul(ul, uh, zl, zh)
    q_lo, q_hi = imul(vl, vh, wl, wh)
    return isub(p_lo, p_hi, q_lo, q_hi)


@njit(cache=True)
def _norm(xl, xh, yl, yh):
    """``sqrt(x**2 + y**2)`` on intervals (:func:`geometry.distance`)."""
    sx_lo, sx_hi = isqr(xl, xh)
    sy_lo, sy_hi = isqr(yl, yh)
    n_lo, n_hi = iadd(sx_lo, sx_hi, sy_lo, sy_hi)
    return isqrt(n_lo, n_hi)


@njit(cache=True)
def _cone(pose, w, c):
    """Fill ``c`` (8,): the wall's inward normal n and direction e against the cone's edges.

    ``det(right, n)``, ``det(n, left)`` (n in the cone), ``det(right, e)``, ``det(left, e)``
    (an edge ray towards the wall's front). They depend on the heading, not on the apex:
    :func:`_range` computes them once per distinct heading, sonar and wall.
    """
    r0l, r0h, r1l, r1h = pose[_RX], pose[_RX + 1], pose[_RY], pose[_RY + 1]
    l0l, l0h, l1l, l1h = pose[_LX], pose[_LX + 1], pose[_LY], pose[_LY + 1]
    nxl, nxh, nyl, nyh = w[_INX], w[_INX + 1], w[_INY], w[_INY + 1]
    exl, exh, eyl, eyh = w[_EX], w[_EX + 1], w[_EY], w[_EY + 1]
    c[_CR], c[_CR + 1] = _det(r0l, r0h, r1l, r1h, nxl, nxh, nyl, nyh)
    c[_CL], c[_CL + 1] = _det(nxl, nxh, nyl, nyh, l0l, l0h, l1l, l1h)
    c[_TR], c[_TR + 1] = _det(r0l, r0h, r1l, r1h, exl, exh, eyl, eyh)
    c[_TL], c[_TL + 1] = _det(l0l, l0h, l1l, l1h, exl, exh, eyl, eyh)


@njit(cache=True, error_model="numpy")
def _range(pose, walls, far, y_lo, y_hi, cones, filled):
    """Enclosure ``(lo, hi)`` of one sonar's range on one box (:func:`nearest_in_cone`).

    Per wall, the candidates of :func:`geometry.cone_candidates`: a candidate's value lowers
    ``lo`` where it may be valid and ``hi`` where it is surely valid. Every candidate needs
    the apex on the reflecting side (``front > 0``). The cone-edge margins of the rays are
    the end points' in-cone determinants (``det(a - apex, right) = -det(right, a - apex)``,
    negation being exact in outward rounding), so each product is computed once.

    With ``y_lo = -inf, y_hi = +inf`` the result is the enclosure, bit for bit. With a
    reading ``[y_lo, y_hi]`` only its comparisons with the reading are kept (the test's
    Tri), and a wall that cannot change the Tri is skipped: one whose every candidate lies
    above ``y_hi`` (their least lower bound, the minimum of the end points' distances and
    the perpendicular distance, exceeds it); and, once ``lo < y_lo`` (the Tri is then FALSE
    if ``hi < y_lo`` at the end, else UNKNOWN), one that cannot bring ``hi`` below ``y_lo``:
    not surely in front (no value for ``hi``), or every value for ``hi`` at least ``y_lo``
    (the edge hits' exceed ``perp_hi``). The walls stop once ``hi < y_lo`` (FALSE). Each
    skipped wall leaves the Tri unchanged whatever the walls after it do (``lo`` and ``hi``
    only decrease), so the Tri is that of the enclosure.

    ``cones`` (s, 8) and ``filled`` (s,) are this heading's and sonar's cache of
    :func:`_cone`, per wall; a wall's row is filled on its first use.
    """
    lo = far
    hi = far
    pxl, pxh, pyl, pyh = pose[_PX], pose[_PX + 1], pose[_PY], pose[_PY + 1]
    r0l, r0h, r1l, r1h = pose[_RX], pose[_RX + 1], pose[_RY], pose[_RY + 1]
    l0l, l0h, l1l, l1h = pose[_LX], pose[_LX + 1], pose[_LY], pose[_LY + 1]
    for j in range(walls.shape[0]):
        if hi < y_lo:
            break
        w = walls[j]
        a0, a1, b0, b1 = w[_AX], w[_AY], w[_BX], w[_BY]
        exl, exh, eyl, eyh = w[_EX], w[_EX + 1], w[_EY], w[_EY + 1]
        # front = -side(apex, a, b) = -det(apex - a, b - a)
        ux_lo, ux_hi = isub(pxl, pxh, a0, a0)
        uy_lo, uy_hi = isub(pyl, pyh, a1, a1)
        s_lo, s_hi = _det(ux_lo, ux_hi, uy_lo, uy_hi, exl, exh, eyl, eyh)
        f_lo, f_hi = -s_hi, -s_lo
        sure_front = f_lo > 0.0
        if not f_hi > 0.0 or (lo < y_lo and not sure_front):  # no candidate / none for hi
            continue
        perp_lo, perp_hi = idiv(f_lo, f_hi, w[_LEN], w[_LEN + 1])
        ax_lo, ax_hi = isub(a0, a0, pxl, pxh)
        ay_lo, ay_hi = isub(a1, a1, pyl, pyh)
        bx_lo, bx_hi = isub(b0, b0, pxl, pxh)
        by_lo, by_hi = isub(b1, b1, pyl, pyh)
        da_lo, da_hi = _norm(ax_lo, ax_hi, ay_lo, ay_hi)
        db_lo, db_hi = _norm(bx_lo, bx_hi, by_lo, by_hi)
        if min(min(da_lo, db_lo), perp_lo) > y_hi:
            continue
        if lo < y_lo and min(min(da_hi, db_hi), perp_hi) >= y_lo:
            continue
        # In-cone determinants of the end points: det(right, p - apex), det(p - apex, left).
        ra_lo, ra_hi = _det(r0l, r0h, r1l, r1h, ax_lo, ax_hi, ay_lo, ay_hi)
        al_lo, al_hi = _det(ax_lo, ax_hi, ay_lo, ay_hi, l0l, l0h, l1l, l1h)
        rb_lo, rb_hi = _det(r0l, r0h, r1l, r1h, bx_lo, bx_hi, by_lo, by_hi)
        bl_lo, bl_hi = _det(bx_lo, bx_hi, by_lo, by_hi, l0l, l0h, l1l, l1h)
        # The end points a and b.
        if min(ra_hi, al_hi) >= 0.0:
            lo = min(lo, da_lo)
            if sure_front and min(ra_lo, al_lo) >= 0.0:
                hi = min(hi, da_hi)
        if min(rb_hi, bl_hi) >= 0.0:
            lo = min(lo, db_lo)
            if sure_front and min(rb_lo, bl_lo) >= 0.0:
                hi = min(hi, db_hi)
        c = cones[j]
        if not filled[j]:
            _cone(pose, w, c)
            filled[j] = True
        # The foot of the perpendicular: the inward normal in the cone,
        # dot(apex - a, e) >= 0 and dot(b - apex, e) >= 0.
        cr_lo, cr_hi, cl_lo, cl_hi = c[_CR], c[_CR + 1], c[_CL], c[_CL + 1]
        if min(cr_hi, cl_hi) >= 0.0:
            p_lo, p_hi = imul(-ax_hi, -ax_lo, exl, exh)
            q_lo, q_hi = imul(-ay_hi, -ay_lo, eyl, eyh)
            t1_lo, t1_hi = iadd(p_lo, p_hi, q_lo, q_hi)
            p_lo, p_hi = imul(bx_lo, bx_hi, exl, exh)
            q_lo, q_hi = imul(by_lo, by_hi, eyl, eyh)
            t2_lo, t2_hi = iadd(p_lo, p_hi, q_lo, q_hi)
            if t1_hi >= 0.0 and t2_hi >= 0.0:
                lo = min(lo, perp_lo)
                if sure_front and t1_lo >= 0.0 and t2_lo >= 0.0 and min(cr_lo, cl_lo) >= 0.0:
                    hi = min(hi, perp_hi)
        # The hits of the cone's edge rays u: margins det(a - apex, u) and det(u, b - apex).
        for k in range(2):
            if k == 0:  # right: det(a, r) = -det(r, a); det(r, b)
                to_lo, to_hi = c[_TR], c[_TR + 1]
                m1_lo, m1_hi, m2_lo, m2_hi = -ra_hi, -ra_lo, rb_lo, rb_hi
            else:  # left: det(a, l); det(l, b) = -det(b, l)
                to_lo, to_hi = c[_TL], c[_TL + 1]
                m1_lo, m1_hi, m2_lo, m2_hi = al_lo, al_hi, -bl_hi, -bl_lo
            if m1_hi >= 0.0 and m2_hi >= 0.0 and to_hi > 0.0:  # toward = det(u, e)
                q_lo, q_hi = idiv(f_lo, f_hi, to_lo, to_hi)
                if q_lo <= q_hi:  # not empty (toward = [0, 0])
                    lo = min(lo, max(q_lo, perp_lo))
                    if sure_front and to_lo > 0.0 and m1_lo >= 0.0 and m2_lo >= 0.0:
                        hi = min(hi, max(q_hi, perp_hi))
    return lo, hi


@njit(cache=True)
def _ranges(poses, headings, walls, far, cones, filled, out):
    """Fill ``out`` (m, t, 2) with every box's and sonar's range enclosure.

    ``headings`` (m,) is each box's distinct heading, ``cones`` and ``filled`` the cache of
    :func:`_cone` per distinct heading (:func:`_cone_cache`).
    """
    for k in range(poses.shape[0]):
        h = headings[k]
        for i in range(poses.shape[1]):
            out[k, i, 0], out[k, i, 1] = _range(
                poses[k, i], walls, far, -np.inf, np.inf, cones[h, i], filled[h, i]
            )


@njit(cache=True, inline="always")
def _decide(n_true, n_false, left, t, q):
    """Verdict of "at most q of t sonars FALSE" from the counts so far; -1 while undecided.

    TRUE once ``t - q`` sonars are TRUE, FALSE once more than ``q`` are FALSE, UNKNOWN once
    the ``left`` sonars not yet tested can reach neither, as in
    :func:`optbound.interval.relaxed._verdict`. Each sonar's verdict depends on that sonar
    only, so the decision is a function of the final counts: the same whichever prefix of
    the sonars it is read from, and for every ``q`` from the same counts.
    """
    if n_true >= t - q:
        return TRUE
    if n_false > q:
        return FALSE
    if n_true + left < t - q and n_false + left <= q:
        return UNKNOWN
    return -1


@njit(cache=True)
def _pending(state, t, q, out):
    """Fill ``out`` (m,) with each box's verdict from its ``state`` row, -1 where undecided."""
    for k in range(state.shape[0]):
        out[k] = _decide(state[k, 0], state[k, 1], t - state[k, 2], t, q)


@njit(cache=True)
def _relaxed(poses, headings, walls, far, y_lo, y_hi, q, cones, filled, state, out):
    """Fill ``out`` (m,) with the Tri of "at most q sonars inconsistent" per box.

    ``state`` (m, 3) holds per box the numbers of TRUE and FALSE sonars among the first
    ``state[:, 2]`` (all 0 for a new box); the sonars are tested from there on, in order,
    until the box is decided (:func:`_decide`), and ``state`` is updated, so that a later
    call with another ``q`` resumes where this one stopped. ``headings``, ``cones`` and
    ``filled`` as in :func:`_ranges`.
    """
    t = poses.shape[1]
    for k in range(poses.shape[0]):
        h = headings[k]
        n_true, n_false, i = state[k, 0], state[k, 1], state[k, 2]
        verdict = _decide(n_true, n_false, t - i, t, q)
        while verdict < 0:
            lo, hi = _range(poses[k, i], walls, far, y_lo[i], y_hi[i], cones[h, i], filled[h, i])
            if lo >= y_lo[i] and hi <= y_hi[i]:
                n_true += 1
            elif hi < y_lo[i] or lo > y_hi[i]:
                n_false += 1
            i += 1
            verdict = _decide(n_true, n_false, t - i, t, q)
        state[k, 0], state[k, 1], state[k, 2] = n_true, n_false, i
        out[k] = verdict


def range_bounds(world_table, params, far, x, y, theta) -> Interval:
    """(m, t) range enclosures on 1-D coordinate intervals (the compiled ``range_inclusion``)."""
    poses, headings, n = pose_table(params, x, y, theta)
    out = np.empty((*poses.shape[:2], 2))
    _ranges(poses, headings, world_table, far, *_cone_cache(n, len(params), world_table), out)
    return Interval._make(out[..., 0], out[..., 1])


def relaxed_tri(world_table, params, far, Y, q, x, y, theta, memo=None) -> np.ndarray:
    """Tri per box of "at most ``q`` of the t sonars disagree with their reading ``Y``".

    ``memo`` (a dict, optional) keeps each box's sonar counts (:func:`_relaxed`) between
    calls, keyed by the box's bounds: a box tested again, at another ``q`` (``q = "auto"``
    paves the same tree for q = 0, 1, ...), resumes from its counts, and one whose counts
    already decide it is not tested again. The verdicts are those of a fresh evaluation
    (:func:`_decide`). The memo is emptied when it holds :data:`MEMO_SIZE` boxes. A box's
    counts are kept as one integer, their digits in base ``t + 1`` (0 for a new box).
    """
    t, m = params.shape[0], len(x.lo)
    digits = (t + 1) ** np.arange(2, -1, -1)  # n_true, n_false, sonars tested
    if memo is not None:
        boxes = np.stack([x.lo, x.hi, y.lo, y.hi, theta.lo, theta.hi], axis=1)
        keys = boxes.view(np.dtype((np.void, boxes.itemsize * 6))).ravel().tolist()
    if memo:
        packed = np.fromiter(map(memo.get, keys, repeat(0)), dtype=np.int64, count=m)
        state = packed[:, None] // digits % (t + 1)
    else:
        state = np.zeros((m, 3), dtype=np.int64)
    out = np.empty(m, dtype=np.int8)
    _pending(state, t, q, out)
    todo = np.flatnonzero(out < 0)
    if todo.size:
        sub = todo if todo.size < m else slice(None)
        poses, headings, n = pose_table(params, x[sub], y[sub], theta[sub])
        part, verdicts = state[todo], np.empty(todo.size, dtype=np.int8)
        Y_lo, Y_hi = Y[:, 0].copy(), Y[:, 1].copy()
        cache = _cone_cache(n, t, world_table)
        _relaxed(poses, headings, world_table, far, Y_lo, Y_hi, q, *cache, part, verdicts)
        state[todo], out[todo] = part, verdicts
        if memo is not None:
            if len(memo) + todo.size > MEMO_SIZE:
                memo.clear()
            done = map(keys.__getitem__, todo.tolist())
            memo.update(zip(done, (part @ digits).tolist(), strict=True))
    return out


__all__ = ["pose_table", "range_bounds", "relaxed_tri", "wall_table"]
