"""SIVIA: set inversion via interval analysis, breadth-first over whole arrays of boxes.

[LJMW97, Sect. 3.2]: to characterise ``X = {x in X0 : f(x) in Y}``, evaluate an inclusion
function ``[f]`` on a box; if ``[f](box)`` lies in ``Y`` the box is **inner** (inside X); if it
misses ``Y`` the box is **outside**; otherwise the box is bisected, or kept as **boundary**
(undetermined) once its width is at most ``eps``. Then ``inner ⊂ X ⊂ inner ∪ boundary``
[LJMW97, eq. (11)]. In codac's vocabulary: ``inner`` = codac ``inner``, ``boundary`` = codac
``bound``, ``inner ∪ boundary`` = codac ``outer`` and ``outside`` = codac ``outer_complem``.

All boxes of one bisection level are tested by one vectorized call of the test, which receives
each coordinate as an :class:`Interval` over all the boxes of the level.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from optbound._core import Box, box_rows
from optbound._core import validate as v
from optbound.interval._rounding import check_round_to_nearest
from optbound.interval.fenv import nearest
from optbound.interval.interval import Interval, as_interval
from optbound.interval.paving import Paving
from optbound.interval.tribool import Tri, as_tri, from_masks

#: codac's default bisection ratio: the split point sits at 49 % of the widest side, which
#: keeps bisection lines off the symmetry axes of the usual test sets.
DEFAULT_RATIO = 0.49
DEFAULT_MAX_BOXES = 20_000_000
#: Levels with fewer boxes than this are bisected without being tested (see :func:`pave`).
DEFER_BELOW = 1024
# Plain ints: comparing int8 arrays with IntEnum members goes through slow enum lookups.
TRUE, UNKNOWN, FALSE = int(Tri.TRUE), int(Tri.UNKNOWN), int(Tri.FALSE)

Test = Callable[..., np.ndarray]
#: ``contract(lo, hi) -> (lo, hi)`` on coordinate-major (n, m) bound arrays: a box of the
#: same or smaller extent per column that keeps every solution of the column's box
#: (``lo > hi`` on some row: no solution in it).
Contractor = Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]


def constraint(f: Callable, Y) -> Test:
    """The three-valued test ``f(x) ∈ Y`` for SIVIA.

    Parameters
    ----------
    f
        ``f(*coords)`` returns its p outputs as a tuple/list (or one output for p = 1); each
        output is a float array on points and an :class:`Interval` on boxes.
    Y
        ``(p, 2)`` rows of ``[lo, hi]`` or a :class:`~optbound.sets.Box`; infinite bounds allowed.

    Returns
    -------
    callable
        ``test(*coords)`` -> Tri array: TRUE if f is defined on the whole box and every output
        lies in ``Y``; FALSE if some output certainly misses it (or is empty: f undefined on
        the whole box); else UNKNOWN. On points it answers TRUE/FALSE.
    """
    ylo, yhi = box_rows("Y", Y, allow_infinite=True)

    def test(*coords) -> np.ndarray:
        out = f(*coords)
        outs = out if isinstance(out, (tuple, list)) else (out,)
        if len(outs) != ylo.size:
            raise ValueError(f"f returned {len(outs)} outputs but Y has {ylo.size} rows")
        tri = None
        for value, lo_j, hi_j in zip(outs, ylo, yhi, strict=True):
            tri_j = _in_range(as_interval(value, "f output"), lo_j, hi_j)
            tri = tri_j if tri is None else np.minimum(tri, tri_j)
        return tri

    return test


def _in_range(value, lo: float, hi: float) -> np.ndarray:
    """Tri of ``value ⊂ [lo, hi]`` vs ``value ∩ [lo, hi] = ∅``; infinite sides cost nothing."""
    inside = outside = None
    if lo > -np.inf:
        inside, outside = value.lo >= lo, value.hi < lo
    if hi < np.inf:
        inside = value.hi <= hi if inside is None else inside & (value.hi <= hi)
        outside = value.lo > hi if outside is None else outside | (value.lo > hi)
    if inside is None:  # Y = R: only emptiness can fail
        inside, outside = ~value.is_empty, value.is_empty
    elif value._maybe_empty:
        empty = value.is_empty
        inside, outside = inside & ~empty, outside | empty
    if value._partial is not None:
        inside = inside & ~value.partial  # f undefined somewhere on the box: not proven inside
    return from_masks(inside, outside)


@nearest
def pave(
    test: Test | Sequence[Test],
    X0,
    eps: float,
    *,
    ratio: float = DEFAULT_RATIO,
    max_boxes: int = DEFAULT_MAX_BOXES,
    contractor: Contractor | None = None,
    defer_below: int = DEFER_BELOW,
) -> Paving:
    """Pave ``X0`` with a three-valued test (or the conjunction of several).

    Parameters
    ----------
    test
        ``test(*coords)`` -> Tri array with one value per box (booleans allowed), or a
        sequence of such tests, all of which must hold (conjunction).
    X0
        Initial box, ``(n, 2)`` rows of ``[lo, hi]`` or a bounded :class:`~optbound.sets.Box`.
    eps
        Boxes whose widest side is at most ``eps`` are not bisected further (codac's rule).
    ratio
        Bisection point along the widest side (first widest on ties), as a fraction of it.
    max_boxes
        Upper limit on the number of boxes tested; exceeding it is a ``ValueError``.
    contractor
        Optional :data:`Contractor` applied to every undetermined box before it is bisected
        (contraction before bisection, as codac's separators do). It must be sound: the parts
        it removes hold no point of the set. They are recorded as ``outside`` boxes, so inner,
        boundary and outside still tile ``X0``.
    defer_below
        Levels with fewer boxes are bisected without being tested (see Notes); default
        ``DEFER_BELOW`` (1024), suited to tests made of numpy calls. A compiled test, whose
        call costs little, prunes earlier with a smaller value.

    Raises
    ------
    RuntimeError
        If round-to-nearest cannot be set. The paving runs in round-to-nearest and the
        caller's rounding mode is restored afterwards (:mod:`optbound.interval.fenv`), so
        it computes correctly after ``import codac``, which sets round-upward.

    Returns
    -------
    Paving
        ``inner ⊂ set ⊂ inner ∪ boundary`` within ``X0`` [LJMW97, eq. (11)].

    Notes
    -----
    A level holding fewer than ``defer_below`` boxes is bisected without being tested:
    a numpy call costs nearly the same for 1 box as for 1000, and the children of a box that
    would have been proven inner (outside) are proven inner (outside) themselves, by inclusion
    monotonicity. The union of the inner and of the boundary boxes is the one of plain SIVIA;
    there are just more, smaller boxes near the top of the tree.
    """
    check_round_to_nearest()
    tests = list(test) if isinstance(test, (list, tuple)) else [test]
    if not tests or not all(callable(t) for t in tests):
        raise ValueError("test must be a callable or a non-empty sequence of callables")
    x_lo, x_hi = box_rows("X0", X0, allow_infinite=False)
    eps = v.finite_scalar("eps", eps)
    if eps <= 0.0:
        raise ValueError(f"eps must be positive, got {eps}")
    if not 0.0 < ratio < 1.0:
        raise ValueError(f"ratio must lie in (0, 1), got {ratio}")
    if isinstance(defer_below, bool) or not isinstance(defer_below, (int, np.integer)):
        raise TypeError(f"defer_below must be an integer, got {type(defer_below).__name__}")
    # Every split point must fall strictly inside its box: keep eps far above the float spacing.
    spacing = np.spacing(max(np.max(np.abs(x_lo)), np.max(np.abs(x_hi))))
    if min(ratio, 1.0 - ratio) * eps < 8.0 * spacing:
        raise ValueError(f"eps={eps} is below the floating-point resolution of X0")

    n = x_lo.size
    # Boxes of the current level, coordinate-major (n, m): each row is contiguous for the test.
    lo, hi = x_lo[:, None].copy(), x_hi[:, None].copy()
    levels = []  # (lo, hi, tri, split) of every tested level; sorted into the paving at the end
    tested = 0
    while lo.shape[1]:
        m = lo.shape[1]
        tested += m
        if tested > max_boxes:
            raise ValueError(
                f"eps={eps} needs more than max_boxes={max_boxes} boxes; raise eps or max_boxes"
            )
        axis, mid, splittable = _split_points(lo, hi, eps, ratio)
        if m < defer_below and splittable.all():
            # Too few boxes to amortise numpy's per-call cost: bisect without testing. The
            # children are tested later and, by inclusion monotonicity, classify the same
            # union of boxes as the parent would have.
            lo, hi = _children(lo, hi, axis, mid)
            continue
        tri = _evaluate(tests, lo, hi, n, m)
        split = (tri == UNKNOWN) & splittable
        levels.append((lo, hi, tri, split))
        idx = np.flatnonzero(split)
        lo, hi, axis, mid = lo.take(idx, axis=1), hi.take(idx, axis=1), axis[idx], mid[idx]
        if contractor is not None and idx.size:
            # Contract the boxes about to be bisected; what is removed is outside, a box
            # contracted to at most eps wide is a boundary box.
            lo, hi, removed = _contract(contractor, lo, hi)
            levels.append(removed)
            axis, mid, splittable = _split_points(lo, hi, eps, ratio)
            k = lo.shape[1]
            levels.append((lo, hi, np.full(k, UNKNOWN, dtype=np.int8), splittable))
            lo, hi, axis, mid = (a[..., splittable] for a in (lo, hi, axis, mid))
        lo, hi = _children(lo, hi, axis, mid)
    return _paving(levels, Box(x_lo, x_hi), eps)


def _evaluate(tests, lo, hi, n, m) -> np.ndarray:
    """Tri of the conjunction of ``tests``; each test sees only the boxes not yet FALSE."""
    tri = np.full(m, TRUE, dtype=np.int8)
    live = np.arange(m)
    for t in tests:
        coords = [Interval._make(lo[i].take(live), hi[i].take(live)) for i in range(n)]
        tri[live] = np.minimum(tri[live], _one_per_box(t(*coords), live.size))
        live = live[tri[live] != FALSE]
        if not live.size:
            break
    return tri


def _one_per_box(tri, m: int) -> np.ndarray:
    tri = as_tri(tri)
    if tri.shape != (m,):
        try:
            tri = np.broadcast_to(tri, (m,))
        except ValueError:
            raise ValueError(f"test must return one value per box, got shape {tri.shape}") from None
    return tri


def _contract(contractor, lo, hi):
    """Contract the level; return the kept boxes and the removed parts as a FALSE level."""
    c_lo, c_hi = contractor(lo, hi)
    c_lo, c_hi = np.maximum(c_lo, lo), np.minimum(c_hi, hi)  # never grow a box
    empty = np.any(c_lo > c_hi, axis=0)
    c_lo[:, empty], c_hi[:, empty] = lo[:, empty], hi[:, empty]  # removed whole
    parts_lo, parts_hi = [lo[:, empty]], [hi[:, empty]]
    keep = ~empty
    # B \ C as slabs: below and above C on axis k, with C's extent on the axes before k.
    cur_lo, cur_hi = lo[:, keep].copy(), hi[:, keep].copy()
    k_lo, k_hi = c_lo[:, keep], c_hi[:, keep]
    for k in range(lo.shape[0]):
        for side in (0, 1):
            s_lo, s_hi = cur_lo.copy(), cur_hi.copy()
            if side == 0:
                s_hi[k] = k_lo[k]
            else:
                s_lo[k] = k_hi[k]
            wide = s_lo[k] < s_hi[k]
            parts_lo.append(s_lo[:, wide])
            parts_hi.append(s_hi[:, wide])
        cur_lo[k], cur_hi[k] = k_lo[k], k_hi[k]
    r_lo, r_hi = np.concatenate(parts_lo, axis=1), np.concatenate(parts_hi, axis=1)
    r = r_lo.shape[1]
    removed = (r_lo, r_hi, np.full(r, FALSE, dtype=np.int8), np.zeros(r, dtype=bool))
    return k_lo, k_hi, removed


def _split_points(lo, hi, eps, ratio):
    """Bisection axis (first widest side, as codac's bisect_largest) and point of each box.

    ``splittable`` is False for boxes at most ``eps`` wide. (A running comparison over the n
    rows and a flat ``take`` are several times faster than ``argmax`` and 2-D fancy indexing
    along axis 0.) The split point lies strictly inside the box: :func:`pave` checks that eps
    is far above the float spacing of ``X0``.
    """
    n, m = lo.shape
    width = hi - lo
    axis = np.zeros(m, dtype=np.intp)
    w = width[0]
    for d in range(1, n):
        wider = width[d] > w
        axis = np.where(wider, d, axis)
        w = np.where(wider, width[d], w)
    mid = lo.take(axis * m + np.arange(m)) + ratio * w
    return axis, mid, w > eps


def _children(lo, hi, axis, mid):
    """Left halves then right halves of boxes cut at ``mid`` along ``axis``."""
    k = mid.size
    child_lo = np.concatenate([lo, lo], axis=1)
    child_hi = np.concatenate([hi, hi], axis=1)
    flat = axis * (2 * k) + np.arange(k)  # entry (axis, j) of the (n, 2k) arrays
    np.put(child_hi, flat, mid)
    np.put(child_lo, flat + k, mid)
    return child_lo, child_hi


def _paving(levels, X0: Box, eps: float) -> Paving:
    """Sort the tested boxes of all levels into inner, boundary and outside (M, n, 2) arrays."""
    n = X0.dim
    if not levels:
        none = np.empty((0, n, 2))
        return Paving(none, none, none, X0, eps)
    lo = np.concatenate([lev[0] for lev in levels], axis=1)
    hi = np.concatenate([lev[1] for lev in levels], axis=1)
    tri = np.concatenate([lev[2] for lev in levels])
    split = np.concatenate([lev[3] for lev in levels])

    def boxes(mask):
        idx = np.flatnonzero(mask)
        return np.stack([lo.take(idx, axis=1).T, hi.take(idx, axis=1).T], axis=-1)

    return Paving(
        inner=boxes(tri == TRUE),
        boundary=boxes((tri == UNKNOWN) & ~split),
        outside=boxes(tri == FALSE),
        X0=X0,
        eps=eps,
    )


def sivia(
    f: Callable,
    Y,
    X0,
    eps: float,
    *,
    ratio: float = DEFAULT_RATIO,
    max_boxes: int = DEFAULT_MAX_BOXES,
) -> Paving:
    """Characterise ``{x in X0 : f(x) in Y}`` [LJMW97, Sect. 3.2].

    Set inversion by bisection: a box whose image is proven inside ``Y`` is inner, one whose
    image is proven disjoint from ``Y`` is outside, the others are bisected until narrower
    than ``eps``. Every bound is rounded outward, so the inner boxes lie in the set and the
    set lies in the inner and boundary boxes, with the floats read as exact numbers.

    Parameters
    ----------
    f : callable
        ``f(*coords)`` returns its p outputs (see :func:`constraint`); evaluated once per
        bisection level on ``Interval`` arrays of all the level's boxes.
    Y : array_like, shape (p, 2), or Box
        Rows ``[lo, hi]`` of the outputs' target set; may be unbounded.
    X0 : array_like, shape (n, 2), or Box
        The bounded initial box.
    eps : float
        A box is not split once its widest side is at most ``eps``.
    ratio : float
        Where the widest side is cut (codac's rule, 0.49).
    max_boxes : int
        Refuse to create more boxes than this.

    Returns
    -------
    Paving
        ``inner``, ``boundary`` and ``outside`` box arrays of the set.

    Raises
    ------
    ValueError
        On NaN, ``lo > hi``, ``eps <= 0``, a wrong number of outputs or too many boxes (see
        :func:`pave`).

    References
    ----------
    .. [LJMW97] O. Lévêque, L. Jaulin, D. Meizel, E. Walter, "Vehicle localization from
       inaccurate telemetric data: a set inversion approach", IFAC SYROCO, 1997.

    Examples
    --------
    >>> p = sivia(lambda x, y: (x**2 + y**2, 2 * x**2 + y**2),
    ...           [[-np.inf, 1], [1, np.inf]], [[-2.5, 2.5], [-2, 2]], 0.05)
    >>> inner, outer = p.volume_bounds()
    >>> bool(inner <= np.pi * (1 - 1 / np.sqrt(2)) <= outer)
    True
    """
    return pave(constraint(f, Y), X0, eps, ratio=ratio, max_boxes=max_boxes)
