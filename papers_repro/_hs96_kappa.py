"""The polynomials [HS96, Sect. 4.2] states for the Schweppe kappa, against numerical optima.

For ``C(kappa) = Xi / (1 - kappa) + Gamma / kappa`` [HS96, eq. (14)] the paper says that
minimizing the volume "in three dimensions leads to the problem of determining the unique root
of a fourth-order polynomial in [0, 1]", the trace to "the unique root of a second-order
polynomial", and the size measure ``tr(proj_xy C) proj_psi C`` of eq. (15) to the cubic of
eqs. (16)-(17). The polynomials, derived here (the paper prints only the cubic):

- volume: with ``q(kappa) = prod_i (l_i kappa + 1 - kappa)`` (``l_i`` the generalized
  eigenvalues of ``Xi v = l Gamma v``), ``det C = det(Gamma) q / (kappa (1 - kappa))^3`` and
  ``d log det C / d kappa = 0`` is ``kappa (1 - kappa) q' + (6 kappa - 3) q = 0``: degree 4;
- trace: ``t1 kappa^2 - t2 (1 - kappa)^2 = 0`` (``t1 = tr Xi``, ``t2 = tr Gamma``): degree 2;
- size_xy_psi: ``K3 kappa^3 + K2 kappa^2 + K1 kappa + K0`` with the K of eq. (17).

Each is checked on seeded random pairs shaped like a pose (metres in x, y, ~0.01 rad in psi)
against ``scipy.optimize.minimize_scalar`` of the criterion itself over kappa: the number of
roots in (0, 1) (the paper: exactly one) and the relative gap between the criterion at the
root and at the numerical minimum, and the same gap for ``analytic.minkowski_sum``.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg
from numpy.polynomial import Polynomial
from scipy.optimize import minimize_scalar

from optbound import analytic
from optbound.sets import Ellipsoid

CRITERIA = ("volume", "trace", "size_xy_psi")
SEED = 96
#: Position and heading scales of the random pairs: metres vs radians.
POSITION_SCALE, HEADING_SCALE = (0.02, 0.5), (0.002, 0.02)
#: Bracket of the numerical search (kappa in the open interval (0, 1)).
KAPPA_EPS = 1e-12


def criterion(Xi: np.ndarray, Gamma: np.ndarray, kind: str, kappa: float) -> float:
    """The size of ``Xi / (1 - kappa) + Gamma / kappa`` by one of :data:`CRITERIA`.

    "volume" is ``log det`` (same minimizer as the volume, no overflow), "trace" the trace,
    "size_xy_psi" ``tr(C[:2, :2]) * C[2, 2]`` [HS96, eq. (15)].
    """
    C = Xi / (1.0 - kappa) + Gamma / kappa
    if kind == "volume":
        return float(np.linalg.slogdet(C)[1])
    if kind == "trace":
        return float(np.trace(C))
    if kind == "size_xy_psi":
        return float(np.trace(C[:2, :2]) * C[2, 2])
    raise ValueError(f"kind must be one of {CRITERIA}, got {kind!r}")


def _at(kappa: float, Xi: np.ndarray, Gamma: np.ndarray, kind: str) -> float:
    return criterion(Xi, Gamma, kind, kappa)


def polynomial(Xi: np.ndarray, Gamma: np.ndarray, kind: str) -> Polynomial:
    """The polynomial in kappa whose root in (0, 1) is the criterion's minimizer (module doc)."""
    if kind == "volume":
        eig = scipy.linalg.eigh(Xi, Gamma, eigvals_only=True)
        q = Polynomial([1.0])
        for li in eig:
            q = q * Polynomial([1.0, li - 1.0])
        k = Polynomial([0.0, 1.0])
        return k * (1 - k) * q.deriv() + (6 * k - 3) * q
    if kind == "trace":
        t1, t2 = np.trace(Xi), np.trace(Gamma)
        return Polynomial([-t2, 2 * t2, t1 - t2])
    if kind == "size_xy_psi":

        def m(A, B):  # [HS96, eq. (15)]
            return np.trace(A[:2, :2]) * B[2, 2]

        mxx, mgg = m(Xi, Xi), m(Gamma, Gamma)
        mxg, mgx = m(Xi, Gamma), m(Gamma, Xi)
        return Polynomial(
            [-2 * mgg, 6 * mgg - mxg - mgx, 3 * (mxg + mgx - 2 * mgg), 2 * (mxx + mgg - mxg - mgx)]
        )
    raise ValueError(f"kind must be one of {CRITERIA}, got {kind!r}")


def roots_in_unit(p: Polynomial) -> np.ndarray:
    """Real roots of ``p`` in (0, 1) (imaginary parts below 1e-9 of the modulus dropped)."""
    r = p.roots()
    real = r[np.abs(r.imag) <= 1e-9 * np.maximum(1.0, np.abs(r))].real
    return np.sort(real[(real > 0.0) & (real < 1.0)])


def random_pair(rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """A random (Xi, Gamma) of pose shape: random correlations, log-uniform axis scales."""

    def shape():
        s = np.exp(
            rng.uniform(*np.log([POSITION_SCALE] * 2 + [HEADING_SCALE]).T)
        )  # (x, y, psi) widths
        A = rng.normal(size=(3, 3))
        R = A @ A.T + 0.1 * np.eye(3)
        d = 1.0 / np.sqrt(np.diag(R))
        return (s * d)[:, None] * R * (s * d)[None, :]

    return shape(), shape()


def check(n: int, seed: int = SEED) -> dict:
    """Roots and gaps of the three polynomials on ``n`` seeded pairs (module docstring).

    Returns, per criterion: ``roots`` (the count of roots in (0, 1) per pair), ``gap`` (the
    largest relative excess of the criterion at the root over the numerical minimum; the
    "volume" criterion compared as ``det``), ``kappa_diff`` (largest |root - numerical
    argmin|), ``library_gap`` (the same gap for ``analytic.minkowski_sum``'s kappa).
    """
    if int(n) != n or n < 1:
        raise ValueError(f"n must be a positive integer, got {n!r}")
    rng = np.random.default_rng(seed)
    out = {
        kind: {"roots": [], "gap": 0.0, "kappa_diff": 0.0, "library_gap": 0.0} for kind in CRITERIA
    }

    def excess(Xi, Gamma, kind, kappa, best):
        value = criterion(Xi, Gamma, kind, kappa)
        # log det: the relative gap of det is exp(difference) - 1.
        return float(np.expm1(value - best)) if kind == "volume" else (value - best) / abs(best)

    for _ in range(int(n)):
        Xi, Gamma = random_pair(rng)
        E1, E2 = Ellipsoid(np.zeros(3), Xi), Ellipsoid(np.zeros(3), Gamma)
        for kind in CRITERIA:
            res = minimize_scalar(
                _at,
                args=(Xi, Gamma, kind),
                bounds=(KAPPA_EPS, 1.0 - KAPPA_EPS),
                method="bounded",
                options={"xatol": 1e-12},
            )
            roots = roots_in_unit(polynomial(Xi, Gamma, kind))
            o = out[kind]
            o["roots"].append(int(roots.size))
            lib = analytic.minkowski_sum(E1, E2, criterion=kind).kappa
            o["library_gap"] = max(o["library_gap"], excess(Xi, Gamma, kind, lib, res.fun))
            if roots.size:
                gaps = [excess(Xi, Gamma, kind, r, res.fun) for r in roots]
                o["gap"] = max(o["gap"], min(gaps))
                o["kappa_diff"] = max(o["kappa_diff"], float(np.min(np.abs(roots - res.x))))
    for kind in CRITERIA:
        counts = np.array(out[kind]["roots"])
        out[kind]["unique"] = int(np.sum(counts == 1))
        out[kind]["n"] = int(n)
    return out


__all__ = ["CRITERIA", "check", "criterion", "polynomial", "random_pair", "roots_in_unit"]
