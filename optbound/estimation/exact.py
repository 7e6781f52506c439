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
    """``y - V`` as a zonotope (its centre's rounding as extra generators).

    Parameters
    ----------
    system : LinearSystem
        The model; its ``V_zonotope`` is used.
    y : numpy.ndarray, shape (p,)
        One measurement.

    Returns
    -------
    Zonotope
        ``<y - c_V, [G_V, E]>``, E the error generators of the rounded centre, so it contains
        ``y - V`` exactly.
    """
    V = system.V_zonotope
    c, extra = sum_centers(y, -V.center)
    return Zonotope(c, np.hstack([V.generators, extra]))


def as_initial(X0, n: int) -> ConstrainedZonotope:
    """``X0`` (a Box, Zonotope, ConstrainedZonotope or Ellipsoid of dimension n) as a
    constrained zonotope (an ellipsoid by its certified enclosing parallelotope).

    Parameters
    ----------
    X0 : Box, Zonotope, ConstrainedZonotope or Ellipsoid
        The set of ``x_0``.
    n : int
        The state dimension it must have.

    Returns
    -------
    ConstrainedZonotope
        A set containing ``X0`` (equal to it unless ``X0`` is an ellipsoid).

    Raises
    ------
    TypeError
        If ``X0`` is of another type.
    ValueError
        If ``X0`` does not have dimension ``n``.
    """
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
    """``(A X + W) ∩_C (y - V)``, one exact step.

    Parameters
    ----------
    system : LinearSystem
        The model (polytopic noise).
    X : ConstrainedZonotope
        The set ``X_{k-1}``.
    y : numpy.ndarray, shape (p,)
        The measurement of ``x_k``.

    Returns
    -------
    ConstrainedZonotope
        ``X_k``, exact up to rounding generators (module docstring).

    Notes
    -----
    With ``X = <c, G, A_X, b_X>`` and ``W = <c_W, G_W>``, the prediction is
    ``A X ⊕ W = <A c + c_W, [A G, G_W], [A_X, 0], b_X> = <c', G', A', b'>``, and with
    ``y - V = <c_Y, G_Y>`` the generalized intersection of Scott et al. [1]_ (Prop. 1) is
    ``<c', [G', 0], [[A', 0], [C G', -G_Y]], [b', c_Y - C c']>``.

    References
    ----------
    .. [1] J. K. Scott, D. M. Raimondo, G. R. Marseglia, R. D. Braatz, "Constrained zonotopes:
       A new tool for set-based estimation and fault detection", Automatica 69, 2016.
    """
    pred = X.affine_map(system.A).minkowski_sum(system.W_zonotope)
    return pred.generalized_intersection(measurement_set(system, y), system.C)


def exact_sets(system: LinearSystem, X0, ys) -> list[ConstrainedZonotope]:
    """``[X_1, ..., X_N]``, the exact set after each measurement ``ys[k-1]`` (module doc).

    Parameters
    ----------
    system : LinearSystem
        The model, with Box or Zonotope noise W and V.
    X0 : Box, Zonotope or ConstrainedZonotope
        The set of ``x_0`` (no measurement at k = 0).
    ys : array_like, shape (N, p) or (N,) when p = 1
        ``ys[k-1]`` measures ``x_k``.

    Returns
    -------
    list of ConstrainedZonotope
        One set per measurement, each containing the exact ``X_k`` and exceeding it by
        rounding only (no reduction: the number of constraints grows by p per step).

    Raises
    ------
    ValueError
        If ``W``, ``V`` or ``X0`` is an ellipsoid: the exact set is then not a polytope, and no
        constrained zonotope represents it (the observers still bound it); if ``X0`` has the
        wrong dimension or ``ys`` is not finite with p columns.
    TypeError
        If ``X0`` is not a Box, Zonotope or ConstrainedZonotope.

    Notes
    -----
    The recursion ``X_k = (A X_{k-1} ⊕ W) ∩_C (y_k - V)``, each operation exact in the
    constrained-zonotope representation (Scott et al. [1]_, Prop. 1; :func:`predict_correct`).

    References
    ----------
    .. [1] J. K. Scott, D. M. Raimondo, G. R. Marseglia, R. D. Braatz, "Constrained zonotopes:
       A new tool for set-based estimation and fault detection", Automatica 69, 2016.

    Examples
    --------
    >>> from optbound import Box
    >>> from optbound.estimation import LinearSystem, exact_sets
    >>> A, C = [[1.0, 0.5], [0.0, 1.0]], [[1.0, 0.0]]
    >>> system = LinearSystem(A, C, W=Box([-0.1, -0.1], [0.1, 0.1]), V=Box([-0.2], [0.2]))
    >>> X = exact_sets(system, Box([-1.0, -1.0], [1.0, 1.0]), [0.3, 0.5, 0.9])
    >>> len(X), X[-1].n_constraints
    (3, 3)
    >>> B = X[-1].bounding_box()
    >>> [round(float(x), 6) for x in (*B.lo, *B.hi)]
    [0.7, -0.15, 1.1, 1.3]
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
