"""The exact sets of a linear system with zonotopic noise, as constrained zonotopes.

``X_k = (A X_{k-1} + W) ∩ {x : y_k - C x in V}`` is a polytope, and each operation is exact
in the constrained-zonotope representation (Scott et al., Automatica 2016, Prop. 1): the
affine map, the Minkowski sum with W and the generalized intersection with
``y_k - V = <y_k - c_V, G_V>`` under ``R = C``. No reduction is applied; the floats only add
rounding generators (``optbound.sets.certified``), so each returned set contains the exact
set and exceeds it by rounding only.
"""

from __future__ import annotations

import numpy as np

from optbound._core import Box
from optbound.estimation.system import LinearSystem
from optbound.sets.certified import sum_centers
from optbound.sets.constrained_zonotope import ConstrainedZonotope
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.zonotope import Zonotope


def measurement_set(system: LinearSystem, y: np.ndarray) -> Zonotope:
    """``y - V`` as a zonotope (its centre's rounding as extra generators)."""
    V = system.V_zonotope
    c, extra = sum_centers(y, -V.center)
    return Zonotope(c, np.hstack([V.generators, extra]))


def as_initial(X0, n: int) -> ConstrainedZonotope:
    """``X0`` (a Box, Zonotope, ConstrainedZonotope or Ellipsoid of dimension n) as a
    constrained zonotope (an ellipsoid by its certified enclosing parallelotope)."""
    if isinstance(X0, Ellipsoid):
        X0 = Zonotope.from_ellipsoid(X0)
    if isinstance(X0, Box | Zonotope):
        X0 = ConstrainedZonotope.from_zonotope(X0)
    if not isinstance(X0, ConstrainedZonotope):
        raise TypeError(
            f"X0 must be a Box, Zonotope, ConstrainedZonotope or Ellipsoid, got {type(X0).__name__}"
        )
    if X0.dim != n:
        raise ValueError(f"X0 must have dimension {n}, got {X0.dim}")
    return X0


def predict_correct(
    system: LinearSystem, X: ConstrainedZonotope, y: np.ndarray
) -> ConstrainedZonotope:
    """``(A X + W) ∩_C (y - V)``, one exact step."""
    pred = X.affine_map(system.A).minkowski_sum(system.W_zonotope)
    return pred.generalized_intersection(measurement_set(system, y), system.C)


def exact_sets(system: LinearSystem, X0, ys) -> list[ConstrainedZonotope]:
    """``[X_1, ..., X_N]``, the exact set after each measurement ``ys[k-1]`` (module doc).

    Raises
    ------
    ValueError
        If ``W``, ``V`` or ``X0`` is an ellipsoid: the exact set is then not a polytope, and no
        constrained zonotope represents it (the observers still bound it).
    """
    if not system.polytopic or isinstance(X0, Ellipsoid):
        raise ValueError(
            "exact_sets needs Box or Zonotope noise and X0: with an ellipsoidal W, V or X0 the "
            "exact set is not a polytope"
        )
    ys = system.measurements(ys)
    X = as_initial(X0, system.dim)
    out = []
    for y in ys:
        X = predict_correct(system, X, y)
        out.append(X)
    return out
