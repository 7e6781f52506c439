"""The pseudo-ellipsoidal filter: bounding-ellipsoid updates in a lifted space [BH, eqs. (15)-(16)].

A pseudo-linear measurement ``z* = H* T(x) + v*`` with ``v*`` in an ellipsoid
``{v : (v - v_hat)^T V^{-1} (v - v_hat) <= 1}`` [BH, eq. (15)] is linear in the lifted state
``x* = T(x)``; the lifted ellipsoid of a :class:`~optbound.sets.PseudoEllipsoid` is updated
with :func:`~optbound.analytic.bounding_update` ([BH, eq. (7)], applied in R^L as eq. (16))
after subtracting the noise centre from the measurement [BH, Sect. IV, last sentence]. Every
lambda >= 0 gives an outer bound; the criterion only picks one.

Criteria:

- ``"volume"``: the lifted volume (log det), the standard choice, solved in closed form by
  ``bounding_update``;
- ``"area"``: the measure of the set in the *original* space, the paper's own choice
  [BH, Sect. III-B, after eq. (16)]. The objective has no closed form: it is estimated by the
  fraction of a ``resolution x resolution`` grid over each candidate's bounding box that lies
  inside, minimized over ``t = lambda / (1 + lambda)`` on a ``AREA_GRID``-point grid in
  ``[0, AREA_T_MAX]`` followed by a bounded Brent refinement (``AREA_REFINE`` evaluations).
  The grid covers the *prior's* bounding box (which contains the feasible set), not each
  candidate's own box: a candidate degenerating toward the whole ring has a huge box on which
  a fixed grid misses the thin set and reports area 0. Cost: about ``AREA_GRID + AREA_REFINE``
  bounding updates plus as many grid evaluations of ``resolution^2`` lifted points, several
  hundred times the cost of "volume" (the BH reproduction reports the measured time).
  ``AREA_T_MAX`` caps lambda at ~1e3. The grid area is an estimate (its boundary cells make
  up a few per cent of a thin set), and the area is often flat over a wide range of lambda,
  where the raw grid minimum lands anywhere, up to the cap, by noise: there the lifted shape
  is nearly singular (cond ~1e8 at the cap against ~1e5 near lambda = 1; "BH filter
  numerics" in the documentation's *Guarantees and numerics* page), the later updates can
  only return lambda = 0 and the containment of the exact set can no longer be proven (1 of 10 sweep
  geometries of the BH reproduction). So the smallest grid lambda whose area is within
  ``AREA_RTOL`` of the grid minimum is taken (the best-conditioned of the equally small
  candidates); only when that is the grid minimum itself is it refined by Brent. Every lambda
  >= 0 is an outer bound, so the choice costs no guarantee.

References
----------
[BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
bearing measurements", IEEE Transactions on Robotics and Automation, 2004.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize_scalar

from optbound._core import validate as v
from optbound.analytic.bounding_update import bounding_update
from optbound.sets.pseudo_ellipsoid import PseudoEllipsoid
from optbound.sets.result import BoundResult

CRITERIA = ("volume", "area")
AREA_GRID = 17
AREA_REFINE = 8
AREA_T_MAX = 1.0 - 1e-3
AREA_RESOLUTION = 80
AREA_RTOL = 0.02  # grid areas within 2 % of the grid minimum count as equally small


@dataclass(frozen=True)
class LiftedUpdate(BoundResult):
    """Result of :func:`lifted_update`.

    As a ``BoundResult``, ``set`` is ``bound``.

    Parameters
    ----------
    bound : PseudoEllipsoid or None
        The bound (None if certified empty).
    lam : float
        The lambda used.
    margin : float, default 0.0
        The certified relative inflation of the lifted member (``BoundingUpdate.margin``).
    """

    set_attribute = "bound"
    certified = True

    bound: PseudoEllipsoid | None
    lam: float
    margin: float = 0.0


def lifted_update(
    P: PseudoEllipsoid,
    H,
    z,
    V,
    v_center=None,
    criterion: str = "volume",
    lam: float | None = None,
    resolution: int = AREA_RESOLUTION,
) -> LiftedUpdate:
    """Pseudo-ellipsoidal measurement update [BH, eq. (16)].

    Parameters
    ----------
    P : PseudoEllipsoid
        Prior set; its lifted ellipsoid is the prior in R^L.
    H : array_like, shape (m, L)
        Lifted measurement matrix H* of ``z* = H* T(x) + v*`` [BH, eq. (15)].
    z : array_like, shape (m,)
        Lifted measurement z*.
    V : array_like, shape (m, m)
        SPD shape of the noise ellipsoid.
    v_center : array_like, shape (m,), optional
        Centre of the noise ellipsoid (default 0); subtracted from ``z``.
    criterion : {"volume", "area"}
        Lifted volume, or the area in the original plane (n = 2 only; see module docstring).
    lam : float, optional
        Explicit lambda >= 0, overriding the criterion.
    resolution : int
        Grid resolution of the "area" objective.

    Returns
    -------
    LiftedUpdate
        The certified bound (None if the intersection is certified empty), the lambda used and
        the certified inflation.

    Raises
    ------
    TypeError
        If ``P`` is not a PseudoEllipsoid.
    ValueError
        Bad shapes or values (as ``bounding_update``), unknown criterion, "area" with n != 2.
    """
    if not isinstance(P, PseudoEllipsoid):
        raise TypeError(f"P must be a PseudoEllipsoid, got {type(P).__name__}")
    if criterion not in CRITERIA:
        raise ValueError(f"criterion must be one of {CRITERIA}, got {criterion!r}")
    z = np.atleast_1d(np.asarray(z, dtype=float))
    if v_center is not None:
        z = z - v.finite_vector("v_center", v_center, z.shape[0])

    def update(lam_value):
        result = bounding_update(P.lifted, H, z, V, lam=lam_value)
        bound = None if result.ellipsoid is None else PseudoEllipsoid(P.lift, *_parts(result))
        return LiftedUpdate(bound, result.lam, result.margin)

    if lam is not None or criterion == "volume":
        return update(lam)
    if P.dim != 2:
        raise ValueError(f'criterion "area" is for n = 2, this set has n = {P.dim}')
    first = update(0.0)
    if first.bound is None:  # emptiness does not depend on the criterion
        return update(None)
    window = P.bounding_box()
    return update(_min_area_lambda(update, window, resolution))


def _parts(result) -> tuple[np.ndarray, np.ndarray]:
    return result.ellipsoid.center, result.ellipsoid.shape


def _min_area_lambda(update, window, resolution: int) -> float:
    """lambda minimizing the grid area over ``t = lambda / (1 + lambda)`` (module docstring)."""

    def area(t: float) -> float:
        try:
            bound = update(t / (1.0 - t)).bound
            return np.inf if bound is None else bound.grid_area(resolution, window)
        except ValueError:  # a nearly singular lifted shape: not a usable candidate
            return np.inf

    ts = np.linspace(0.0, AREA_T_MAX, AREA_GRID)
    values = np.array([area(t) for t in ts])
    k = int(np.argmin(values))
    first = int(np.argmax(values <= (1.0 + AREA_RTOL) * values[k]))
    if first < k:  # a flat minimum: the smallest lambda as small as the minimum (docstring)
        return ts[first] / (1.0 - ts[first])
    lo, hi = ts[max(k - 1, 0)], ts[min(k + 1, AREA_GRID - 1)]
    best_t, best = ts[k], values[k]
    if hi > lo:
        res = minimize_scalar(
            area, bounds=(lo, hi), method="bounded", options={"maxiter": AREA_REFINE}
        )
        if res.fun < best:
            best_t = float(res.x)
    return best_t / (1.0 - best_t)
