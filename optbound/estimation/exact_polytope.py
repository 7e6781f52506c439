"""The exact sets of a linear system (n <= 4) as rational polytopes: vertices and volume exact.

Every float of the data is read as the exact rational it is, and ``X_k = (A X_{k-1} + W) ∩
{x : y_k - C x in V}`` is propagated in the vertex representation, in ``fractions.Fraction``
(:mod:`optbound.estimation.rational_polytope`): the vertices are mapped by A and shifted by
W's centre, W (a box or zonotope) is added one generator segment at a time (the hull of ``P -
g`` and ``P + g``), and the polytope is cut by the two half-spaces of each output row, ``y_i -
hi_i <= c_i^T x <= y_i - lo_i`` (``[lo_i, hi_i]`` the i-th interval of V, exact for a box V
or a V whose generators are axis-aligned, e.g. any V with one output). Nothing is rounded:
the vertices, the volume (the cone formula over the exact boundary triangulation) and every
membership test on them are exact. This generalizes the 2-D polygons of
:mod:`optbound.estimation.exact_polygon` (the same sets, tested equal) to n = 3 and 4.

Cost: each Minkowski segment doubles the candidate points and each hull costs ``O(N F n^2)``
exact integer operations (N points, F boundary simplices), so a few steps of a 3-D system
take a fraction of a second, a 4-D one seconds.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from optbound._core import Box
from optbound.estimation.rational_polytope import RationalPolytope, convex_hull
from optbound.estimation.system import LinearSystem
from optbound.sets.zonotope import Zonotope

#: Largest state dimension :func:`exact_polytopes` accepts (the hull's cost grows fast).
MAX_DIM = 4


def _q(x) -> Fraction:
    return Fraction(float(x))


def output_bounds(system: LinearSystem) -> tuple[list[Fraction], list[Fraction]]:
    """The exact interval ``[lo_i, hi_i]`` of V's i-th coordinate, per output row.

    Parameters
    ----------
    system : LinearSystem
        The model, with Box or Zonotope V.

    Returns
    -------
    lo : list of Fraction
        The lower bound per output row (``c_i - sum_j |G_ij|`` for a zonotope V).
    hi : list of Fraction
        The upper bound per output row (``c_i + sum_j |G_ij|``).

    Raises
    ------
    ValueError
        If V is a zonotope with a generator that moves several outputs: ``{v in V}`` is then
        not the product of its intervals.
    """
    V = system.V
    if isinstance(V, Box):
        return [_q(x) for x in V.lo], [_q(x) for x in V.hi]
    if system.n_outputs > 1 and np.any(np.count_nonzero(V.generators, axis=0) > 1):
        raise ValueError(
            "the exact sets need a box V (or axis-aligned generators) with several outputs"
        )
    rV = [sum(abs(_q(x)) for x in row) for row in V.generators]
    return (
        [_q(c) - r for c, r in zip(V.center, rV, strict=True)],
        [_q(c) + r for c, r in zip(V.center, rV, strict=True)],
    )


def center_segments(Z: Box | Zonotope) -> tuple[list[Fraction], list[list[Fraction]]]:
    """A box or zonotope as its exact centre and generators (a box's are its midpoint and
    half-widths, exact in rationals).

    Parameters
    ----------
    Z : Box or Zonotope
        The set.

    Returns
    -------
    center : list of Fraction
        The exact centre.
    generators : list of list of Fraction
        The exact generators, one list per generator.
    """
    if isinstance(Z, Box):
        lo, hi = [_q(x) for x in Z.lo], [_q(x) for x in Z.hi]
        n = len(lo)
        half = [(b - a) / 2 for a, b in zip(lo, hi, strict=True)]
        gens = [[half[i] if j == i else Fraction(0) for j in range(n)] for i in range(n)]
        return [(a + b) / 2 for a, b in zip(lo, hi, strict=True)], gens
    return [_q(x) for x in Z.center], [[_q(x) for x in g] for g in Z.generators.T]


def zonotope_polytope(Z: Box | Zonotope) -> RationalPolytope:
    """The exact polytope of a box or zonotope (its centre plus one segment at a time).

    Parameters
    ----------
    Z : Box or Zonotope
        The set, its floats read exactly.

    Returns
    -------
    RationalPolytope
        ``c + sum_j [-g_j, g_j]``, exact.
    """
    c, gens = center_segments(Z)
    P = convex_hull([c], len(c))
    for g in gens:
        P = P.minkowski_segment(g)
    return P


def exact_polytopes(system: LinearSystem, X0: Box | Zonotope, ys) -> list[RationalPolytope]:
    """The exact sets ``[X_1, ..., X_N]`` as rational polytopes (module docstring).

    Parameters
    ----------
    system : LinearSystem
        With Box or Zonotope noise and ``dim <= 4``.
    X0 : Box or Zonotope
        The set of ``x_0``.
    ys : array_like, shape (N, p) or (N,)
        ``ys[k-1]`` measures ``x_k``.

    Returns
    -------
    list of RationalPolytope
        ``vertices`` and ``volume`` exact; an empty polytope means the measurements are
        inconsistent from that step on.

    Raises
    ------
    ValueError
        If the system has more than :data:`MAX_DIM` states, ellipsoidal noise, or a V that is
        not a product of intervals (:func:`output_bounds`).
    TypeError
        If X0 is not a Box or Zonotope of the system's dimension.

    Notes
    -----
    ``X_k = (A X_{k-1} ⊕ W) ∩ {x : y_k - hi <= C x <= y_k - lo}`` in the vertex
    representation, every float read as the rational it is (module docstring).

    Examples
    --------
    >>> from optbound import Box
    >>> from optbound.estimation import LinearSystem, exact_polytopes
    >>> A, C = [[1.0, 0.5], [0.0, 1.0]], [[1.0, 0.0]]
    >>> system = LinearSystem(A, C, W=Box([-0.1, -0.1], [0.1, 0.1]), V=Box([-0.2], [0.2]))
    >>> P = exact_polytopes(system, Box([-1.0, -1.0], [1.0, 1.0]), [0.3, 0.5, 0.9])
    >>> len(P), len(P[-1].vertices)
    (3, 6)
    >>> lo, hi = P[-1].volume_bounds()  # the exact Fraction volume, rounded outward
    >>> lo <= P[-1].volume <= hi, round(hi, 9)
    (True, 0.4075)
    """
    n = system.dim
    if n > MAX_DIM:
        raise ValueError(
            f"system must have at most {MAX_DIM} states for the exact polytopes, got {n}"
        )
    if not system.polytopic:
        raise ValueError("the exact polytopes need Box or Zonotope noise W and V")
    if not isinstance(X0, Box | Zonotope) or X0.dim != n:
        raise TypeError(f"X0 must be a Box or Zonotope of dimension {n}")
    lo, hi = output_bounds(system)
    A = [[_q(x) for x in row] for row in system.A]
    C = [[_q(x) for x in row] for row in system.C]
    cW, gW = center_segments(system.W)
    P = zonotope_polytope(X0)
    out = []
    for y in system.measurements(ys):
        mapped = [
            [sum(a * x for a, x in zip(row, p, strict=True)) for row in A] for p in P.vertices
        ]
        P = convex_hull([[x + w for x, w in zip(p, cW, strict=True)] for p in mapped], n)
        for g in gW:
            P = P.minkowski_segment(g)
        for i, c in enumerate(C):
            P = P.cut(c, _q(y[i]) - lo[i])
            P = P.cut([-x for x in c], hi[i] - _q(y[i]))
        out.append(P)
    return out
