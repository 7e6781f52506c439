"""Writing each member of an intersection as quadratic inequalities in ``[x; 1]``.

Every member describes itself through the set protocol (``optbound.sets.base``):
``quadratic_description()`` gives its quadratic forms, used as they are, and its linear ranges
``lo <= a^T x <= hi`` (a strip, a half-space, a box's coordinates); ``enclosing_ellipsoid()``
gives the ellipsoids the ranges are clipped to. No set type is named here, so a new type plugs
in by implementing those two methods in its own module.

The linear ranges are first *clipped* to the extent of the bounded members along their normal:
a strip ``lo <= a^T x <= hi`` becomes ``max(lo, l) <= a^T x <= min(hi, u)`` where ``[l, u]`` is the
range of ``a^T x`` over each ellipsoid. This does not change the intersection, but the
S-procedure is not tight for a strip with one plane outside the ellipsoid (HS96's "partial
consistency", [HS96, Sect. 4]): the far plane then becomes a tangent plane and the bound shrinks
(27 % less volume on the 3-D known-answer case). A clipped half-space is a strip as well.

With ``clip="intersection"`` (the default) the ranges are then shrunk further, to the exact
range of ``a^T x`` over the whole intersection of the first bounded member with all the ranges
(``optbound.optimal.extents``, certified by weak duality). Still the same set, but with many
strips each one is otherwise far wider than the intersection along its normal.

With ``products=True`` the inequalities also include, for every pair of finite ranges
``l_i <= a_i^T x <= u_i`` and ``l_j <= a_j^T x <= u_j``, the four products of one side of each,
such as ``(a_i^T x - l_i)(a_j^T x - u_j) <= 0`` (the Reformulation-Linearization Technique of
Sherali & Adams; Shor-type constraints): valid on the set, and no combination of the single
ranges gives them, so the S-procedure with them is tighter on polytopes
(``docs/user_guide/optimal.md``), at 2 r (r - 1) extra inequalities for r ranges.

The range is then written in product form ``(a^T x - lo)(a^T x - hi) <= 0``; for a strip
``|a^T x - b| <= 1`` this is the very same polynomial as ``(a^T x - b)^2 <= 1``, so the two
forms are one quadratic. An unclipped half-space stays affine, ``a^T x - b <= 0``.

References
----------
[HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
on an angle measurement technique", IFAC, 1996.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence

import numpy as np

from optbound.optimal.errors import EmptyIntersectionError
from optbound.optimal.extents import clip_to_intersection
from optbound.sets import Ellipsoid, Halfspace, QuadraticSet
from optbound.sets.base import (
    EmptySetError,
    LinearRange,
    QuadraticallyDescribed,
    QuadraticDescription,
)

# Extents are widened by this relative amount so that rounding never clips away a feasible point.
_EXTENT_RTOL = 1e-12

CLIPS = ("intersection", "ellipsoids", False)


def _describe(member: QuadraticallyDescribed) -> QuadraticDescription:
    """The member's quadratic description, or a ``ValueError`` naming its type.

    The protocol is checked by its two methods directly: ``isinstance`` with a runtime
    ``Protocol`` inspects the whole protocol on each call and cost more than the lifting.
    """
    describe = getattr(member, "quadratic_description", None)
    if describe is None or not hasattr(member, "enclosing_ellipsoid"):
        raise ValueError(
            "intersection members must be sets with a quadratic description (Ellipsoid, Strip, "
            "Halfspace, Box, QuadraticSet, or a type implementing quadratic_description() and "
            f"enclosing_ellipsoid(), see optbound.sets.base), got {type(member).__name__}"
        )
    return describe()


def _enclosing(member: QuadraticallyDescribed) -> Ellipsoid | None:
    """The member's enclosing ellipsoid; an empty member makes the intersection empty."""
    try:
        return member.enclosing_ellipsoid()
    except EmptySetError as err:
        raise EmptyIntersectionError(str(err)) from err


def _clip(
    member: QuadraticallyDescribed,
    a: np.ndarray,
    lo: float,
    hi: float,
    bounded: Sequence[Ellipsoid],
) -> tuple[float, float]:
    """``[lo, hi]`` intersected with each bounded member's range of ``a^T x`` (widened).

    An empty result is reported with the user's own numbers: the member, its range along its
    unit normal and the range over the bounded member it misses.
    """
    lo0, hi0 = lo, hi
    for ellipsoid in bounded:
        elo, ehi = ellipsoid._extent(a)  # ``a`` is a validated member's normal
        pad = _EXTENT_RTOL * (abs(elo) + abs(ehi) + (ehi - elo))
        lo, hi = max(lo, elo - pad), min(hi, ehi + pad)
        if lo > hi:
            # Along the unit normal: a Strip stores a scaled normal, the user gave bounds.
            norm = float(np.linalg.norm(a))
            raise EmptyIntersectionError(
                f"the intersection is empty: {member!r} allows u^T x in "
                f"[{lo0 / norm:.6g}, {hi0 / norm:.6g}] along its unit normal "
                f"u = {np.round(a / norm, 6).tolist()}, but over {ellipsoid!r} u^T x lies in "
                f"[{elo / norm:.6g}, {ehi / norm:.6g}]"
            )
    return lo, hi


def _quadratic(a: np.ndarray, lo: float, hi: float) -> QuadraticSet:
    if math.isfinite(lo) and math.isfinite(hi):
        # ``a`` is a validated member's normal: only the order of the (clipped) range is left
        # to check, and ``from_bounds`` refuses a wrong one with its message.
        build = QuadraticSet._from_valid_bounds if lo <= hi else QuadraticSet.from_bounds
        return build(a, lo, hi)
    if math.isfinite(hi):
        return QuadraticSet.from_halfspace(Halfspace(a, hi))
    return QuadraticSet.from_halfspace(Halfspace(-a, -lo))


def _pair_products(rows: Sequence[LinearRange]) -> list[QuadraticSet]:
    """``g^T [x;1] * h^T [x;1] <= 0`` for ``g >= 0`` a side of row i, ``h <= 0`` one of row j."""
    above = [np.append(a, -lo) for a, lo, _ in rows]  # a^T x - lo >= 0
    below = [np.append(-a, hi) for a, _, hi in rows]  # hi - a^T x >= 0
    products = []
    for i, j in itertools.combinations(range(len(rows)), 2):
        for g in (above[i], below[i]):
            for h in (-above[j], -below[j]):
                products.append(QuadraticSet(0.5 * (np.outer(g, h) + np.outer(h, g))))
    return products


def check_clip(clip) -> str | bool:
    """The clipping mode; ``True`` means the default, ``"intersection"``.

    Parameters
    ----------
    clip : str or bool or None
        ``"intersection"``, ``"ellipsoids"``, True (the default mode), or False/None (no clipping).

    Returns
    -------
    str or bool
        The mode, or False.

    Raises
    ------
    ValueError
        If ``clip`` is not a mode.
    """
    if clip is True:
        return "intersection"
    if clip is None or clip is False:
        return False
    if clip not in CLIPS:
        raise ValueError(f"clip must be one of {CLIPS} (or True), got {clip!r}")
    return clip


def lift(
    members: Sequence[QuadraticallyDescribed],
    clip: str | bool = "intersection",
    products: bool = False,
) -> list[QuadraticSet]:
    """Quadratic inequalities whose intersection equals the members' intersection.

    Per member, in order: its description's forms, then one inequality per linear range (a
    ``Box`` gives one per coordinate with a finite bound); then, with ``products``, the pair
    products of the finite ranges. ``clip`` is ``"intersection"`` (or ``True``),
    ``"ellipsoids"`` or ``False`` (module docstring).

    Parameters
    ----------
    members : sequence of QuadraticallyDescribed
        The sets intersected, of one dimension.
    clip : str or bool, default "intersection"
        Clipping of the linear ranges (see :func:`check_clip`).
    products : bool, default False
        Add the pair products of the finite ranges.

    Returns
    -------
    list of QuadraticSet
        The quadratic inequalities.

    Raises
    ------
    ValueError
        If ``members`` is empty, has a type without a quadratic description, mixes
        dimensions, or ``clip`` is not a mode.
    EmptyIntersectionError
        If clipping shows that the intersection is empty.
    """
    clip = check_clip(clip)
    members = list(members)
    if not members:
        raise ValueError("intersection must contain at least one set")
    descriptions = [_describe(member) for member in members]
    dims = {member.dim for member in members}
    if len(dims) != 1:
        raise ValueError(f"intersection members must share one dimension, got {sorted(dims)}")
    bounded = [e for e in map(_enclosing, members) if e is not None] if clip else []
    # Linear ranges per member, clipped to the enclosing ellipsoids.
    ranges = [
        [(a, *_clip(member, a, lo, hi, bounded)) for a, lo, hi in description.ranges]
        for member, description in zip(members, descriptions, strict=True)
    ]
    flat = [row for rows in ranges for row in rows]
    # With a single linear row, its range clipped to the ellipsoid already is its exact range
    # over the intersection with that ellipsoid: the extents solve could not shrink it.
    if clip == "intersection" and bounded and len(flat) >= 2:
        A = np.array([a for a, _, _ in flat])
        lo, hi = clip_to_intersection(
            bounded[0], A, np.array([r[1] for r in flat]), np.array([r[2] for r in flat])
        )
        clipped = iter(zip(A, lo, hi, strict=True))
        ranges = [[next(clipped) for _ in rows] for rows in ranges]
    quadratics: list[QuadraticSet] = []
    for description, rows in zip(descriptions, ranges, strict=True):
        quadratics.extend(description.forms)
        quadratics.extend(_quadratic(a, lo, hi) for a, lo, hi in rows)
    if products:
        finite = [row for rows in ranges for row in rows if np.all(np.isfinite(row[1:]))]
        quadratics.extend(_pair_products(finite))
    return quadratics
