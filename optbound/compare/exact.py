"""Exact (rational) arithmetic on optbound's set types: membership of float points and
closed-form containment proofs, with every float read as the exact number it is.

Used where a claim must hold with no rounding at all: a counterexample to a containment (a
float point provably in one set and provably outside another), and the proof that a set
contains a whole ellipsoid or box. Dimensions are small (n <= ~10), so ``fractions.Fraction``
Gaussian elimination is cheap.
"""

from __future__ import annotations

import itertools
from fractions import Fraction
from math import isqrt

import numpy as np

from optbound.interval import Paving
from optbound.sets import Box, Ellipsoid, Halfspace, PseudoEllipsoid, Strip

_NELDER_MEAD = {"xatol": 1e-15, "fatol": 1e-18, "maxiter": 800}


def fractions(values) -> list:
    """Convert a float array to nested lists of exact ``Fraction`` values.

    Parameters
    ----------
    values : array_like
        Floats (any shape).

    Returns
    -------
    Fraction or list
        The exact value of each float, nested as the array (a scalar for 0-d input).
    """
    arr = np.asarray(values, dtype=float)
    if arr.ndim == 0:
        return Fraction(float(arr))
    return [fractions(row) for row in arr]


def solve(A: list[list[Fraction]], b: list[Fraction]) -> list[Fraction]:
    """Solve ``A x = b`` for a non-singular rational matrix (Gaussian elimination, exact).

    Parameters
    ----------
    A : list of list of Fraction
        A square rational matrix.
    b : list of Fraction
        The right-hand side.

    Returns
    -------
    list of Fraction
        ``A^{-1} b``.
    """
    n = len(b)
    M = [[*row, rhs] for row, rhs in zip(A, b, strict=True)]
    for k in range(n):
        pivot = next(i for i in range(k, n) if M[i][k] != 0)
        M[k], M[pivot] = M[pivot], M[k]
        for i in range(k + 1, n):
            f = M[i][k] / M[k][k]
            if f:
                M[i] = [x - f * y for x, y in zip(M[i], M[k], strict=True)]
    x = [Fraction(0)] * n
    for k in reversed(range(n)):
        x[k] = (M[k][n] - sum(M[k][j] * x[j] for j in range(k + 1, n))) / M[k][k]
    return x


def inverse(A: list[list[Fraction]]) -> list[list[Fraction]]:
    """Invert a non-singular rational matrix exactly.

    Parameters
    ----------
    A : list of list of Fraction
        A square rational matrix.

    Returns
    -------
    list of list of Fraction
        ``A^{-1}``.
    """
    n = len(A)
    cols = [solve(A, [Fraction(int(i == j)) for i in range(n)]) for j in range(n)]
    return [[cols[j][i] for j in range(n)] for i in range(n)]


def determinant(A: list[list[Fraction]]) -> Fraction:
    """Compute the exact determinant of a rational matrix.

    Parameters
    ----------
    A : list of list of Fraction
        A square rational matrix.

    Returns
    -------
    Fraction
        ``det A`` (0 for a singular matrix).
    """
    M = [list(row) for row in A]
    n, det = len(M), Fraction(1)
    for k in range(n):
        pivot = next((i for i in range(k, n) if M[i][k] != 0), None)
        if pivot is None:
            return Fraction(0)
        if pivot != k:
            M[k], M[pivot] = M[pivot], M[k]
            det = -det
        det *= M[k][k]
        for i in range(k + 1, n):
            f = M[i][k] / M[k][k]
            if f:
                M[i] = [x - f * y for x, y in zip(M[i], M[k], strict=True)]
    return det


def is_psd(A: list[list[Fraction]]) -> bool:
    """Whether a symmetric rational matrix is positive semidefinite (exact LDL^T).

    A zero pivot is allowed only with a zero remaining row (else the matrix is indefinite).

    Parameters
    ----------
    A : list of list of Fraction
        A symmetric rational matrix.

    Returns
    -------
    bool
        True iff ``A`` is positive semidefinite.
    """
    M = [list(row) for row in A]
    n = len(M)
    for k in range(n):
        d = M[k][k]
        if d < 0:
            return False
        if d == 0:
            if any(M[k][j] != 0 for j in range(k + 1, n)):
                return False
            continue
        for i in range(k + 1, n):
            f = M[i][k] / d
            if f:
                for j in range(k + 1, n):
                    M[i][j] -= f * M[k][j]
    return True


def _quadratic_level(center, shape, x) -> Fraction:
    """``(x - c)^T C^{-1} (x - c)`` in exact arithmetic (rational inputs)."""
    d = [xi - ci for xi, ci in zip(x, center, strict=True)]
    y = solve(shape, d)
    return sum(di * yi for di, yi in zip(d, y, strict=True))


def member(S, x) -> bool:
    """Decide exactly whether the float point ``x`` (n,) is in an optbound set or a Paving.

    Parameters
    ----------
    S : Box, Ellipsoid, Strip, Halfspace, PseudoEllipsoid or Paving
        The set (a Paving: its ``inner ∪ boundary``).
    x : array_like, shape (n,)
        The point, its floats read as exact numbers.

    Returns
    -------
    bool
        Membership decided in rational arithmetic.

    Raises
    ------
    TypeError
        For other types (their own ``contains`` is all that is known of them).
    """
    xf = fractions(np.asarray(x, dtype=float))
    if isinstance(S, Box):
        return all(lo <= xi <= hi for lo, xi, hi in zip(S.lo, np.asarray(x), S.hi, strict=True))
    if isinstance(S, Ellipsoid):
        return _quadratic_level(fractions(S.center), fractions(S.shape), xf) <= 1
    if isinstance(S, Strip):
        value = sum(a * xi for a, xi in zip(fractions(S.a), xf, strict=True)) - Fraction(S.b)
        return abs(value) <= 1
    if isinstance(S, Halfspace):
        return sum(a * xi for a, xi in zip(fractions(S.a), xf, strict=True)) <= Fraction(S.b)
    if isinstance(S, PseudoEllipsoid):
        lifted = _lift(S, xf)
        return _quadratic_level(fractions(S.center), fractions(S.shape), lifted) <= 1
    if isinstance(S, Paving):
        boxes = S.outer()
        x = np.asarray(x, dtype=float)
        return bool(np.any(np.all((boxes[:, :, 0] <= x) & (x <= boxes[:, :, 1]), axis=1)))
    raise TypeError(f"no exact membership for {type(S).__name__}")


def _lift(P: PseudoEllipsoid, xf: list[Fraction]) -> list[Fraction]:
    """The lifting ``T(x)`` of a pseudo-ellipsoid in exact arithmetic [BH, eq. (9)]."""
    lift = P.lift
    scale = Fraction(lift.scale)
    u = [(xi - Fraction(o)) / scale for xi, o in zip(xf, lift.offset, strict=True)]
    monos = []
    for e in lift.exponents:
        m = Fraction(1)
        for uj, p in zip(u, e, strict=True):
            m *= uj ** int(p)
        monos.append(m)
    return [
        sum((Fraction(c) * m for c, m in zip(row, monos, strict=True) if c), Fraction(0))
        for row in lift.coefficients
    ]


def _homogeneous(E: Ellipsoid) -> list[list[Fraction]]:
    """``[[Q, -Q c], [-c^T Q, c^T Q c - 1]]`` with ``Q = C^{-1}`` (exact): the quadratic
    ``(x - c)^T Q (x - c) - 1`` as a matrix acting on ``(x, 1)``."""
    Q = inverse(fractions(E.shape))
    c = fractions(E.center)
    n = len(c)
    Qc = [sum(Q[i][j] * c[j] for j in range(n)) for i in range(n)]
    corner = sum(ci * qi for ci, qi in zip(c, Qc, strict=True)) - 1
    return [[*Q[i], -Qc[i]] for i in range(n)] + [[*(-q for q in Qc), corner]]


def ellipsoid_in_ellipsoid(outer: Ellipsoid, inner: Ellipsoid) -> bool:
    """Proof of ``inner ⊂ outer`` by the S-lemma, checked exactly.

    ``inner ⊂ outer`` iff some ``tau >= 0`` makes ``tau A_in - A_out`` positive semidefinite,
    with ``A`` the homogeneous matrices of the two quadratics (S-lemma, lossless for one
    constraint). ``tau`` is found in floats (the maximiser of the smallest eigenvalue, a
    concave function of tau); the semidefiniteness is then checked in rational arithmetic,
    so True is a proof. False means no proof was found.

    Parameters
    ----------
    outer, inner : Ellipsoid
        The two ellipsoids.

    Returns
    -------
    bool
        True if ``inner ⊂ outer`` is proven.
    """
    if outer.dim != inner.dim:
        return False
    A_out, A_in = _homogeneous(outer), _homogeneous(inner)
    f_out = np.array(A_out, dtype=float)
    f_in = np.array(A_in, dtype=float)
    for tau in _tau_candidates(f_in, f_out):
        t = Fraction(tau)
        M = [
            [t * a - b for a, b in zip(ra, rb, strict=True)]
            for ra, rb in zip(A_in, A_out, strict=True)
        ]
        if is_psd(M):
            return True
    return False


def _tau_candidates(A_in: np.ndarray, A_out: np.ndarray) -> list[float]:
    """1 (equal ellipsoids) and the float maximiser of ``lambda_min(tau A_in - A_out)``."""
    from scipy.optimize import minimize_scalar

    def neg_min_eig(tau: float) -> float:
        return -float(np.linalg.eigvalsh(tau * A_in - A_out)[0])

    n = A_in.shape[0] - 1
    Q_in, Q_out = A_in[:n, :n], A_out[:n, :n]
    low = float(np.max(np.linalg.eigvals(np.linalg.solve(Q_in, Q_out)).real))
    best = minimize_scalar(neg_min_eig, bounds=(low, 4.0 * low + 4.0), method="bounded")
    return [1.0, float(best.x)]


def box_in(outer, inner: Box) -> bool:
    """Proof of ``inner ⊂ outer`` for a bounded box inside a Box or an Ellipsoid (exact).

    A Box: corner comparisons; an Ellipsoid (convex): every corner of ``inner`` has an exact
    level <= 1.

    Parameters
    ----------
    outer : Box or Ellipsoid
        The containing set.
    inner : Box
        The contained box.

    Returns
    -------
    bool
        True if ``inner ⊂ outer`` is proven; False for an unbounded box, a dimension mismatch
        or another ``outer`` type.
    """
    if not inner.is_bounded or inner.dim != outer.dim:
        return False
    if isinstance(outer, Box):
        return bool(np.all(outer.lo <= inner.lo) and np.all(inner.hi <= outer.hi))
    if isinstance(outer, Ellipsoid):
        c, C = fractions(outer.center), fractions(outer.shape)
        return all(
            _quadratic_level(c, C, fractions(np.array(corner))) <= 1
            for corner in itertools.product(*zip(inner.lo, inner.hi, strict=True))
        )
    return False


def ellipsoid_in_box(outer: Box, inner: Ellipsoid) -> bool:
    """Prove ``inner ⊂ outer`` for an ellipsoid inside a box, in exact arithmetic.

    The test is ``lo_j <= c_j - sqrt(C_jj)`` and ``c_j + sqrt(C_jj) <= hi_j`` for every j,
    squared.

    Parameters
    ----------
    outer : Box
        The containing box (may be unbounded).
    inner : Ellipsoid
        The contained ellipsoid.

    Returns
    -------
    bool
        True iff ``inner ⊂ outer`` (False on a dimension mismatch).
    """
    if outer.dim != inner.dim:
        return False
    for j in range(inner.dim):
        c, var = Fraction(inner.center[j]), Fraction(inner.shape[j, j])
        lo, hi = outer.lo[j], outer.hi[j]
        for gap in (
            c - Fraction(lo) if np.isfinite(lo) else None,
            Fraction(hi) - c if np.isfinite(hi) else None,
        ):
            if gap is not None and (gap < 0 or gap * gap < var):
                return False
    return True


def _rational_sqrt_bounds(q: Fraction, digits: int = 40) -> tuple[Fraction, Fraction]:
    """Rationals ``lo <= sqrt(q) <= hi`` (q >= 0), ``hi - lo`` about ``10^-digits`` relative."""
    scale = 10 ** (2 * digits)
    root = isqrt(q.numerator * scale // q.denominator)
    lo = Fraction(root, 10**digits)
    return lo, lo + Fraction(1, 10**digits) * (1 + lo)


def _slab_matrix(a: list[Fraction], lo: Fraction, hi: Fraction) -> list[list[Fraction]]:
    """``(a^T x - lo)(a^T x - hi) <= 0`` as a matrix on ``(x, 1)``."""
    n = len(a)
    mid = (lo + hi) / 2
    return [[a[i] * a[j] for j in range(n)] + [-mid * a[i]] for i in range(n)] + [
        [*(-mid * aj for aj in a), lo * hi]
    ]


def _clipped_slab(E: Ellipsoid, S) -> list[list[Fraction]]:
    """The strip or half-space ``S`` clipped to rational bounds of ``E``'s extent along its
    normal, as a slab matrix. The clipped slab contains ``E ∩ S``, and the S-procedure is
    tight with it where it is not with a plane beyond the ellipsoid [HS96, Sect. 4]."""
    a, c, C = fractions(S.a), fractions(E.center), fractions(E.shape)
    n = len(a)
    mid = sum(ai * ci for ai, ci in zip(a, c, strict=True))
    _, half = _rational_sqrt_bounds(sum(a[i] * C[i][j] * a[j] for i in range(n) for j in range(n)))
    lo, hi = mid - half, mid + half
    b = Fraction(S.b)
    if isinstance(S, Strip):
        lo, hi = max(lo, b - 1), min(hi, b + 1)
    else:
        hi = min(hi, b)
    return _slab_matrix(a, lo, hi)


def ellipsoid_contains_intersection(outer: Ellipsoid, E: Ellipsoid, cuts) -> bool:
    """Proof of ``E ∩ cuts ⊂ outer`` by the S-procedure, checked exactly.

    ``cuts`` are strips and half-spaces, each clipped to ``E``'s extent (a slab containing
    ``E ∩ cut``). ``E ∩ cuts ⊂ outer`` holds if multipliers ``tau >= 0`` make
    ``tau_0 A_E + sum_k tau_k A_k - A_out`` positive semidefinite [Boyd et al. 1994,
    Sect. 2.6.3]. The multipliers are searched in floats (the maximiser of the smallest
    eigenvalue, Nelder-Mead on their logarithms) and the semidefiniteness is checked in
    rational arithmetic, so True is a proof; False means no proof was found (a bound that
    touches the set with no margin is usually not proven this way).

    Parameters
    ----------
    outer : Ellipsoid
        The containing ellipsoid.
    E : Ellipsoid
        The ellipsoid intersected.
    cuts : sequence of Strip or Halfspace
        The strips and half-spaces intersected.

    Returns
    -------
    bool
        True if ``E ∩ cuts ⊂ outer`` is proven.

    References
    ----------
    .. [BEFB94] S. Boyd, L. El Ghaoui, E. Feron, V. Balakrishnan, "Linear Matrix Inequalities in
       System and Control Theory", SIAM, 1994.
    """
    from scipy.optimize import minimize

    mats = [_homogeneous(E), *(_clipped_slab(E, S) for S in cuts)]
    A_out = _homogeneous(outer)
    floats = [np.array(M, dtype=float) for M in mats]
    f_out = np.array(A_out, dtype=float)
    d = 1.0 / np.sqrt(np.abs(np.diag(f_out)) + np.finfo(float).tiny)
    scale = np.outer(d, d)

    def worst(z: np.ndarray) -> float:
        M = sum(np.exp(zk) * Fk for zk, Fk in zip(z, floats, strict=True)) - f_out
        return -float(np.linalg.eigvalsh(scale * M)[0])

    k = len(mats)
    starts = [np.zeros(k), *(np.where(np.arange(k) == j, 0.0, -3.0) for j in range(k))]
    for z0 in starts:
        found = minimize(worst, z0, method="Nelder-Mead", options=_NELDER_MEAD)
        if found.fun > 0:
            continue  # no positive semidefinite point found from this start
        tau = [Fraction(float(np.exp(zk))) for zk in found.x]
        M = [
            [
                sum(t * Mk[i][j] for t, Mk in zip(tau, mats, strict=True)) - A_out[i][j]
                for j in range(len(A_out))
            ]
            for i in range(len(A_out))
        ]
        if is_psd(M):
            return True
    return False


def contains_intersection(outer, parts) -> bool:
    """Prove exactly that the intersection of the optbound sets ``parts`` lies in ``outer``.

    Some Box / Ellipsoid part inside ``outer`` (:func:`contains_set`), or, for an Ellipsoid
    ``outer`` and parts made of one Ellipsoid and strips / half-spaces, the S-procedure
    (:func:`ellipsoid_contains_intersection`).

    Parameters
    ----------
    outer : Box or Ellipsoid
        The containing set.
    parts : set or sequence of sets
        The sets intersected (one set alone is accepted).

    Returns
    -------
    bool
        True if the containment is proven; False means no proof was found.
    """
    parts = list(parts) if isinstance(parts, (list, tuple)) else [parts]
    if any(contains_set(outer, part) for part in parts):
        return True
    ellipsoids = [part for part in parts if isinstance(part, Ellipsoid)]
    cuts = [part for part in parts if isinstance(part, (Strip, Halfspace))]
    if isinstance(outer, Ellipsoid) and len(ellipsoids) == 1 and len(cuts) == len(parts) - 1:
        return bool(cuts) and ellipsoid_contains_intersection(outer, ellipsoids[0], cuts)
    return False


def contains_set(outer, inner) -> bool:
    """Exact closed-form proof that the optbound set ``inner`` lies in ``outer``.

    Supported pairs: Ellipsoid/Box inside Ellipsoid/Box; False (no proof) for any other pair.

    Parameters
    ----------
    outer : Box or Ellipsoid
        The containing set.
    inner : Box or Ellipsoid
        The contained set.

    Returns
    -------
    bool
        True if ``inner ⊂ outer`` is proven.

    Examples
    --------
    >>> from optbound.sets import Box, Ellipsoid
    >>> disc = Ellipsoid(np.zeros(2), np.eye(2))
    >>> contains_set(Box([-1, -1], [1, 1]), disc), contains_set(disc, Box([-1, -1], [1, 1]))
    (True, False)
    """
    if isinstance(inner, Box):
        return box_in(outer, inner)
    if isinstance(inner, Ellipsoid):
        if isinstance(outer, Ellipsoid):
            return ellipsoid_in_ellipsoid(outer, inner)
        if isinstance(outer, Box):
            return ellipsoid_in_box(outer, inner)
    return False
