"""The standard bounding-ellipsoid measurement update [BH, eqs. (4)-(8)].

Prior E = {x : (x - c)^T C^{-1} (x - c) <= 1} [BH, eq. (4)], measurement z = H x + v
[BH, eq. (5)] with v in {v : v^T V^{-1} v <= 1} [BH, eq. (8)]. For every lambda >= 0 [BH, eq. (7)]::

    S = V + lambda H C H^T,   r = z - H c,
    centre = c + lambda C H^T S^{-1} r,
    P = C - lambda C H^T S^{-1} H C,   s = 1 + lambda - lambda r^T S^{-1} r,   shape = s P,

is an outer bound of the feasible set when s > 0, and s(lambda) < 0 for some lambda certifies
that the feasible set is empty. In the eigenbasis of ``V^{-1/2} H C H^T V^{-1/2} = U diag(mu) U^T``
everything is a scalar function of lambda::

    s(lambda) = 1 + lambda - lambda sum_j rho_j^2 / (1 + lambda mu_j),   rho = U^T V^{-1/2} r,
    log det P = log det C - sum_j log(1 + lambda mu_j),
    tr P = tr C - lambda sum_j beta_j / (1 + lambda mu_j),  beta_j = |C H^T V^{-1/2} u_j|^2.

s is convex in lambda, so emptiness is decided by minimizing s. The size (log det or trace of
s P) is minimized over lambda >= 0 by a dense grid in t = lambda / (1 + lambda), refined by
Brent's root finder on the analytic derivative. For one row and V = 1 this is exactly the
strip family [HS96, eq. (24)].
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import numpy as np
from scipy.optimize import brentq

from optbound._core import validate as v
from optbound.analytic._exact import enclose, matmul, rational, solve, transpose
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.result import BoundResult

CRITERIA = ("volume", "trace")
GRID_POINTS = 257
T_MAX = 1.0 - 1e-9  # lambda up to ~1e9
# s below this is treated as zero: the feasible set is (numerically) a single point or empty.
S_TOL = 1e-12


@dataclass(frozen=True)
class BoundingUpdate(BoundResult):
    """Result of :func:`bounding_update`.

    As a ``BoundResult``: ``set`` is ``ellipsoid``, always certified.

    Parameters
    ----------
    ellipsoid : Ellipsoid or None
        The outer bound (None if the feasible set is empty).
    lam : float
        The lambda used, or for an empty result the lambda whose s(lambda) < 0 certifies
        emptiness.
    margin : float, default 0.0
        The certified relative inflation of the float member (0 for E itself).
    """

    set_attribute = "ellipsoid"
    certified = True

    ellipsoid: Ellipsoid | None
    lam: float
    margin: float = 0.0


@dataclass(frozen=True)
class _Scalarized:
    """The update as scalar functions of lambda (see the module docstring)."""

    n: int
    mu: np.ndarray
    rho2: np.ndarray
    beta: np.ndarray
    trace_c: float

    def s(self, lam):
        """The scale s(lambda) of [BH, eq. (7)], elementwise in lambda."""
        lam = np.asarray(lam, dtype=float)
        return 1 + lam - lam * np.sum(self.rho2 / (1 + lam[..., None] * self.mu), axis=-1)

    def size(self, lam, criterion: str):
        """log det(s P) - log det C (volume) or tr(s P) (trace); +inf where s <= S_TOL."""
        lam = np.asarray(lam, dtype=float)
        s = self.s(lam)
        ok = s > S_TOL
        s_safe = np.where(ok, s, 1.0)
        if criterion == "volume":
            val = self.n * np.log(s_safe) - np.sum(np.log1p(lam[..., None] * self.mu), axis=-1)
        else:
            trace_p = self.trace_c - lam * np.sum(
                self.beta / (1 + lam[..., None] * self.mu), axis=-1
            )
            val = s_safe * trace_p
        return np.where(ok, val, np.inf)

    def slope(self, lam: float, criterion: str) -> float:
        """d/dlambda of ``size`` (or of ``s`` itself for criterion "s")."""
        q = 1 + lam * self.mu
        ds = 1 - np.sum(self.rho2 / q**2)
        if criterion == "s":
            return float(ds)
        s = float(self.s(lam))
        if criterion == "volume":
            return float(self.n * ds / s - np.sum(self.mu / q))
        trace_p = self.trace_c - lam * np.sum(self.beta / q)
        return float(ds * trace_p - s * np.sum(self.beta / q**2))


def _lam_of(t):
    return t / (1.0 - t)


def _minimize(fun, slope) -> float:
    """Minimizer of ``fun(lambda)`` over lambda >= 0 (``slope`` its derivative).

    A grid in t = lambda / (1 + lambda) locates the best cell; the root of the derivative in
    the neighbouring cells (Brent) gives lambda to full precision. Without a sign change the
    minimum is at an end of the range (e.g. lambda = 0) and the best grid point is returned.
    """
    lam = _lam_of(np.linspace(0.0, T_MAX, GRID_POINTS))
    values = fun(lam)
    k = int(np.argmin(values))
    lo, hi = lam[max(k - 1, 0)], lam[min(k + 1, GRID_POINTS - 1)]
    if np.isfinite(fun(lo)) and np.isfinite(fun(hi)) and slope(lo) < 0 < slope(hi):
        return float(brentq(slope, lo, hi, xtol=1e-300, rtol=4 * np.finfo(float).eps))
    return float(lam[k])


def bounding_update(
    E: Ellipsoid, H, z, V, criterion: str = "volume", lam: float | None = None
) -> BoundingUpdate:
    """Bounding-ellipsoid measurement update [BH, eq. (7)].

    Parameters
    ----------
    E : Ellipsoid
        Prior set [BH, eq. (4)].
    H : array_like, shape (m, n)
        Measurement matrix of z = H x + v [BH, eq. (5)]; a 1-D array is one row.
    z : array_like, shape (m,)
        Measurement.
    V : array_like, shape (m, m)
        SPD noise shape, v^T V^{-1} v <= 1 [BH, eq. (8)]; a scalar is accepted when m = 1.
    criterion : {"volume", "trace"}
        Size of s P minimized over lambda >= 0.
    lam : float, optional
        Explicit lambda >= 0; overrides the criterion.

    Returns
    -------
    BoundingUpdate
        Guarantee: ``ellipsoid``, its floats read as exact numbers, contains the feasible set
        exactly. The member at the chosen (float) lambda is evaluated in exact rational
        arithmetic, rounded, and inflated by the certified margin of
        ``optbound.analytic._kernels.midrad``. ``ellipsoid`` is None only when the feasible set is
        proven empty (s(lambda) < 0 exactly for some lambda). If s(lambda) = 0 (the set is at
        most one point) or the member leaves the supported domain, lambda = 0 is used: E
        itself, always a valid outer bound.

    Raises
    ------
    ValueError
        Non-finite or mismatched inputs, V not SPD, unknown criterion, negative lambda.

    References
    ----------
    .. [BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
       bearing measurements", IEEE Transactions on Robotics and Automation, 2004.

    Examples
    --------
    >>> import numpy as np
    >>> from optbound import Ellipsoid, analytic
    >>> E = Ellipsoid(np.zeros(3), np.eye(3))
    >>> u = analytic.bounding_update(E, H=[[1.0, 1.0, 0.0]], z=[0.5], V=[[0.04]])
    >>> bool(u.ellipsoid.contains([0.25, 0.25, 0.0]))
    True
    """
    if not isinstance(E, Ellipsoid):
        raise TypeError(f"E must be an Ellipsoid, got {type(E).__name__}")
    if criterion not in CRITERIA:
        raise ValueError(f"criterion must be one of {CRITERIA}, got {criterion!r}")
    n = E.dim
    H = v.finite_matrix("H", np.atleast_2d(np.asarray(H, dtype=float)), (None, n))
    m = H.shape[0]
    z = v.finite_vector("z", z, m)
    V, R = v.spd_matrix("V", np.atleast_2d(np.asarray(V, dtype=float)), m)
    if lam is not None:
        lam = v.finite_scalar("lam", lam)
        if lam < 0:
            raise ValueError(f"lam must be >= 0, got {lam}")

    Hw = np.linalg.solve(R, H)  # V^{-1/2} H (with R the Cholesky factor of V)
    rw = np.linalg.solve(R, z - H @ E.center)
    CHt = E.shape @ Hw.T
    mu, U = np.linalg.eigh(Hw @ CHt)
    mu = np.maximum(mu, 0.0)
    CHtU = CHt @ U
    f = _Scalarized(n, mu, (U.T @ rw) ** 2, np.sum(CHtU**2, axis=0), float(np.trace(E.shape)))

    s_min_lam = _minimize(f.s, lambda x: f.slope(x, "s"))
    if _member(E, H, z, V, s_min_lam)[2] < 0:
        return BoundingUpdate(None, s_min_lam)  # s(lambda) < 0 exactly: proven empty
    if lam is None:
        lam = _minimize(lambda x: f.size(x, criterion), lambda x: f.slope(x, criterion))
    if lam == 0.0:
        return BoundingUpdate(E, 0.0)
    centre, shape, s = _member(E, H, z, V, lam)
    if s < 0:
        return BoundingUpdate(None, lam)
    if s > 0:
        out, margin = enclose(centre, [[s * x for x in row] for row in shape])
        if out is not None:
            return BoundingUpdate(out, float(lam), margin)
    return BoundingUpdate(E, 0.0)  # a single point, or outside the domain: E itself


def _member(E: Ellipsoid, H, z, V, lam: float):
    """The member [BH, eq. (7)] at ``lam`` in exact rational arithmetic: (centre, P, s)."""
    lf = Fraction(float(lam))
    C, c = rational(E.shape), rational(E.center)
    Hq = rational(H)
    r = [[zi[0] - hc[0]] for zi, hc in zip(rational(z), matmul(Hq, c), strict=True)]
    HC = matmul(Hq, C)
    HCHt = matmul(HC, transpose(Hq))
    S = [
        [v + lf * w for v, w in zip(rv, rw, strict=True)]
        for rv, rw in zip(rational(V), HCHt, strict=True)
    ]
    X = solve(S, [row_hc + row_r for row_hc, row_r in zip(HC, r, strict=True)])
    Sinv_HC = [row[:-1] for row in X]
    Sinv_r = [[row[-1]] for row in X]
    s = 1 + lf - lf * matmul(transpose(r), Sinv_r)[0][0]
    gain = transpose(HC)
    centre = [[ci[0] + lf * g[0]] for ci, g in zip(c, matmul(gain, Sinv_r), strict=True)]
    P = [
        [x - lf * y for x, y in zip(rc, rg, strict=True)]
        for rc, rg in zip(C, matmul(gain, Sinv_HC), strict=True)
    ]
    return centre, P, s
