"""Certified floating-point evaluation: midpoint-radius arithmetic and the outward margin.

Every analytic bound is a member of a family whose members all contain the true set *in exact
arithmetic* ([HS96, eqs. (14), (24)], [BH, eq. (7)]). What can go wrong is only the rounding
of its evaluation. The kernels therefore carry, next to each computed value x, a radius r with
``|x_exact - x| <= r``, where x_exact is the value of the same formula evaluated exactly on the
float inputs (IEEE round-to-nearest, no fastmath: ``|fl(y) - y| <= U |fl(y)|``).

From the radii D of the shape S and d of the centre, :func:`inflate` returns the shape

    T = (1 + rho) S + mu I,   mu >= (1 + rho) ||D||_F + (1 + 1/rho) ||d||^2 + (rounding of T),

which contains the exact member: ``C* <= S + ||D||_F I`` (Weyl), and the centre offset
``delta = c* - c`` (``|delta| <= ||d||``) is absorbed by Schweppe's bound for the sum of an
ellipsoid and a segment, ``E(0, C*) + [-delta, delta] ⊆ E(0, (1+rho) C* + (1 + 1/rho) delta
delta^T)``, for any rho > 0. No eigenvalue needs to be certified for this; rho only balances
the two terms (rho = |d| / sqrt(lambda_min(S)), estimated).

The strip member (``strip_kernel._member_shape``) applies the same rule with the scale folded into
its scalar factor, so that each entry of its shape is rounded only once (``output_floor``,
``segment_scale`` and ``segment_term`` are shared).

The radii themselves are computed in floating point from non-negative terms; a chain of k such
operations underestimates by at most a factor (1 - U)^k, covered by ``RADIUS_SAFETY`` (k <= 1e4).
"""

from __future__ import annotations

import numpy as np
from numba import types
from numba.extending import intrinsic

from optbound._core import COND_OUT, MAG, MAX_DIAG, RATIO_OUT, cholesky
from optbound._core.jit import njit

U = 2.0**-53  # unit roundoff of binary64
TINY = 1e-300  # absolute slack for the (harmless) underflow of radii terms
RADIUS_SAFETY = 1.0 + 1e-12


def gamma(k: int) -> float:
    """Higham's gamma_k = k U / (1 - k U)."""
    return k * U / (1.0 - k * U)


@njit(cache=True, error_model="numpy", inline="always")
def mr_add(x, rx, y, ry):
    """x + y with radius (both operands carry radii)."""
    z = x + y
    return z, rx + ry + U * abs(z)


@njit(cache=True, error_model="numpy", inline="always")
def mr_mul(x, rx, y, ry):
    """x * y with radius."""
    z = x * y
    return z, abs(x) * ry + abs(y) * rx + rx * ry + U * abs(z)


@njit(cache=True, error_model="numpy", inline="always")
def mr_div(x, rx, y, ry):
    """x / y with radius; requires |y| > ry (the caller guarantees it)."""
    z = x / y
    return z, (rx + abs(z) * ry) / (abs(y) - ry) + U * abs(z)


@intrinsic
def _fma(typingctx, x, y, z):
    """``x * y + z`` with one rounding (the hardware instruction, LLVM's ``llvm.fma.f64``)."""
    sig = types.float64(types.float64, types.float64, types.float64)

    def codegen(context, builder, signature, args):
        return builder.fma(*args)

    return sig, codegen


@njit(cache=True, error_model="numpy", inline="always")
def _two_prod(a, b):
    """a * b = p + e exactly (no overflow/underflow): e is the fused multiply-add's residual."""
    p = a * b
    return p, _fma(a, b, -p)


@njit(cache=True, error_model="numpy", inline="always")
def _two_sum(a, b):
    """a + b = s + e exactly (Knuth)."""
    s = a + b
    bb = s - a
    e = (a - (s - bb)) + (b - bb)
    return s, e


@njit(cache=True, error_model="numpy", inline="always")
def down(x):
    """A float <= x for a value x computed with one or two roundings (relative 4U)."""
    return x - 4.0 * U * abs(x) - TINY


@njit(cache=True, error_model="numpy", inline="always")
def up(x):
    """A float >= x for a value x computed with one or two roundings (relative 4U)."""
    return x + 4.0 * U * abs(x) + TINY


@njit(cache=True, error_model="numpy", inline="always")
def output_floor(trace, cmax):
    """The eigenvalue floor of a result with shape trace ``trace`` and centre ``|c|_inf =
    cmax``: keeping lambda_min above twice it keeps the result inside the domain (``inflate``)."""
    return max(trace / COND_OUT, (cmax / RATIO_OUT) ** 2, 4.0 / (MAG * MAG))


@njit(cache=True, error_model="numpy", inline="always")
def segment_scale(dd, lref):
    """``scale = 1 + rho`` of Schweppe's bound for a centre error of squared norm ``dd`` on a
    shape with lambda_min ~ ``lref`` (rho = |d| / sqrt(lref) balances the two terms). The
    guarantee uses rho = scale - 1 exactly (Sterbenz): at least one ulp above 1."""
    if dd > 0.0:
        return max(1.0 + np.sqrt(dd / lref), 1.0 + 2.0 * U)
    return 1.0


@njit(cache=True, error_model="numpy", inline="always")
def segment_term(dd, rho):
    """``(1 + 1/rho) |d|^2`` of Schweppe's bound (0 without centre error); rounded down by at
    most a factor (1 - U)^3, covered by ``RADIUS_SAFETY``."""
    return (1.0 + 1.0 / rho) * dd if dd > 0.0 else 0.0


@njit(cache=True, error_model="numpy")
def lambda_min_estimate(L) -> float:
    """``1 / ||L^{-1}||_F^2 = 1 / tr(A^{-1})`` for A = L L^T: within a factor n of lambda_min(A).

    Only an estimate (it chooses rho and the widening); no guarantee rests on it. The strict
    lower part of L^{-1} is stored transposed in L's (unused) strict upper triangle.
    """
    n = L.shape[0]
    total = 0.0
    for j in range(n):  # column j of L^{-1} by forward substitution
        xjj = 1.0 / L[j, j]
        total += xjj * xjj
        for i in range(j + 1, n):
            s = L[i, j] * xjj
            for k in range(j + 1, i):
                s += L[i, k] * L[j, k]
            L[j, i] = -s / L[i, i]
            total += L[j, i] * L[j, i]
    return 1.0 / total


@njit(cache=True, error_model="numpy")
def inflate(S, D, c, d, T, L) -> float:
    """Outward shape T (written, symmetric) containing the exact member; see the module doc.

    Parameters: S, D (n, n) the computed shape (lower triangle) and its radii; c, d (n,) the
    computed centre and its radii; L is work space. T may be S itself.

    A near-degenerate result is widened (never refused): lambda_min(T) is kept above twice
    ``floor = max(tr(S) / COND_OUT, (|c|_inf / RATIO_OUT)^2, (2 / MAG)^2)``, so T lies in the
    supported domain with a factor >= 50 to spare (``optbound._core.domain``) and needs no
    second validation; only its magnitude is checked here.

    Returns the margin ``rho + mu / lambda_min(S)`` (estimated: how much a point at level 1 of
    S may be moved outward, relative), or -1.0 if T is too large for the domain (the caller
    falls back to a safe result or reports it).
    """
    n = S.shape[0]
    trace = 0.0
    cmax = 0.0
    for i in range(n):
        trace += S[i, i]
        cmax = max(cmax, abs(c[i]))
    floor = output_floor(trace, cmax)
    lmin = 0.0  # lambda_min(S) estimated; 0 if S is (numerically) singular: full widening
    if cholesky(S, L) > 0.0:
        lmin = lambda_min_estimate(L)
        if not trace <= 1e14 * lmin:  # beyond the estimate's accuracy (~ cond U)
            lmin = 0.0
    lref = max(lmin, floor)
    dd = 0.0
    for i in range(n):
        dd += d[i] * d[i]
    scale = segment_scale(dd, lref)
    rho = scale - 1.0
    DF = 0.0
    SF = 0.0
    for i in range(n):
        for j in range(i + 1):
            w = 2.0 if i > j else 1.0
            DF += w * D[i, j] * D[i, j]
            SF += w * S[i, j] * S[i, j]
    DF = np.sqrt(DF) * (1.0 + 4.0 * U)
    SF = np.sqrt(SF) * (1.0 + 4.0 * U)
    centre = segment_term(dd, rho)
    # Rounding of forming T: |F_ij| <= 2 U |T_ij|, and ||T||_F <= scale ||S||_F + sqrt(n) mu.
    need = scale * DF + centre + 2.0 * U * scale * SF
    mu = need * RADIUS_SAFETY / (1.0 - 2.0 * U * np.sqrt(n) * RADIUS_SAFETY) + TINY
    mu = max(mu, 2.0 * floor - scale * lmin)  # widening (only ever adds to mu)
    for i in range(n):
        for j in range(i + 1):
            t = scale * S[i, j]
            if i == j:
                t += mu
                if not t <= MAX_DIAG:
                    return -1.0
            T[i, j] = t
            T[j, i] = t
    if not cmax <= MAG:
        return -1.0
    return rho + mu / lref
