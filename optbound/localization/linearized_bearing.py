"""Linearized set-theoretic fusion of relative bearings, HS96 style (*not* a guaranteed bound).

The baseline a BH pseudo-ellipsoid is meant to beat [BH, Sect. III-B]: the ellipsoidal
set-membership filter of [HS96, eqs. (18)-(24)] applied to the relative-bearing data of
[BH, eq. (2)]. Each measurement ``|gamma_ij(x) - gamma_hat| <= eps`` is linearized around the
current centre ``c`` (``geometry.bearing_gradient``),

::

    |g^T x - (g^T c + wrap(gamma_hat - gamma_ij(c)))| <= eps,   g = grad gamma_ij(c),

as [HS96, eqs. (19)-(23)] linearize the bearing equation (18) around the predicted centre, and
the strip is fused with ``analytic.intersect_strip`` (the member of [HS96, eq. (24)] chosen by
``criterion``; "volume" minimizes the area in 2-D). With ``relinearize > 0`` the strip is
linearized again around the fused centre and fused with the set before the update, the
feedback of [HS96, Sect. 4] also used by ``tracker.SetTracker``.

**Not guaranteed.** The strip of the tangent plane is not the crescent: the exact feasible set
can stick out of it (curvature of the bearing circles), so the result can miss part of the
exact set, and the true position. Only the ellipsoid-strip fusion itself is an outer bound.
``optbound/bench/localization_tightness.py`` measures how often the truth and the exact set's
boxes fall outside.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from optbound import analytic
from optbound.localization.geometry import bearing_gradient, bearing_residual
from optbound.localization.relative_bearing import measurements, prior_box
from optbound.sets import Box, Ellipsoid, Strip
from optbound.sets.result import BoundResult

CRITERIA = ("volume", "trace")


@dataclass(frozen=True)
class LinearizedResult(BoundResult):
    """Result of :func:`linearized_localize`.

    As a ``BoundResult``: ``set`` is ``ellipse``, never certified (the strips are linearized,
    module docstring), no margin.

    Parameters
    ----------
    ellipse : Ellipsoid
        The final ellipse.
    rejected : int
        Number of measurements whose linearized strip missed the set (rejected and skipped,
        as [HS96, Fig. 1 d)]).
    """

    set_attribute = "ellipse"
    certified = False
    margin = 0.0

    ellipse: Ellipsoid
    rejected: int


def box_ellipse(box: Box) -> Ellipsoid:
    """Compute the smallest ellipse through the corners of a 2-D box.

    Parameters
    ----------
    box : Box
        A 2-D box with half-widths h.

    Returns
    -------
    Ellipsoid
        The axis-aligned ellipse centred on the box with half-axes ``h sqrt 2``.
    """
    half = 0.5 * (box.hi - box.lo)
    return Ellipsoid(0.5 * (box.lo + box.hi), np.diag(2.0 * half * half))


def linearized_strip(li, lj, gamma_hat: float, eps: float, about) -> Strip:
    """Linearize the strip of one relative bearing around the point ``about`` [HS96, eq. (23)].

    Parameters
    ----------
    li, lj : array_like, shape (2,)
        The two landmarks.
    gamma_hat : float
        Measured relative bearing [rad].
    eps : float
        Noise bound [rad].
    about : array_like, shape (2,)
        Linearization point c.

    Returns
    -------
    Strip
        ``|g^T x - b| <= eps`` scaled to half-width 1, with ``g`` the gradient of the bearing
        at c and ``b = g^T c + wrap(gamma_hat - gamma_ij(c))``.

    Raises
    ------
    ValueError
        If ``about`` is a landmark (the bearing has no gradient there).
    """
    ax, ay = float(about[0]), float(about[1])
    if any(ax == p[0] and ay == p[1] for p in (li, lj)):
        raise ValueError(f"cannot linearize the bearing at {about!r}: a landmark is there")
    g = np.array(bearing_gradient(ax, ay, li, lj), dtype=float)
    # wrap(gamma_hat - gamma_ij(c)) = -bearing_residual(c, gamma_hat)
    b = g @ np.array([ax, ay]) - float(bearing_residual(ax, ay, li, lj, gamma_hat))
    return Strip(g / eps, b / eps)


def linearized_localize(
    landmarks,
    pairs,
    gammas,
    eps,
    prior: Box | None = None,
    relinearize: int = 1,
    criterion: str = "volume",
) -> LinearizedResult:
    """Linearized ellipsoidal localization from relative bearings (module docstring).

    Parameters
    ----------
    landmarks, pairs, gammas, eps
        As in :func:`optbound.localization.relative_bearing.localize`.
    prior : Box, optional
        Prior box of the position (default ``relative_bearing.prior_box``); the filter starts
        from the ellipse through its corners (:func:`box_ellipse`).
    relinearize : int
        Extra linearizations per measurement around the fused centre.
    criterion : {"volume", "trace"}
        Choice of lambda in [HS96, eq. (24)] (``analytic.intersect_strip``).

    Returns
    -------
    LinearizedResult
        Not guaranteed to contain the feasible set (module docstring).

    Examples
    --------
    The setting of [BH, Sect. V] (vehicle at the origin, eps = 4 degrees):

    >>> from optbound.localization.relative_bearing import bearings
    >>> L = np.array([[0.0, 1.0], [1.0, 1.0], [-1.0, 0.0]])
    >>> pairs = [(2, 0), (0, 1), (1, 2)]
    >>> result = linearized_localize(L, pairs, bearings([0.0, 0.0], L, pairs), np.radians(4))
    >>> result.certified, result.rejected, bool(result.ellipse.contains([0.0, 0.0]))
    (False, 0, True)
    """
    data = measurements(landmarks, pairs, gammas, eps)
    if int(relinearize) != relinearize or relinearize < 0:
        raise ValueError(f"relinearize must be a non-negative integer, got {relinearize!r}")
    if criterion not in CRITERIA:
        raise ValueError(f"criterion must be one of {CRITERIA}, got {criterion!r}")
    box = prior_box(data) if prior is None else prior
    if not isinstance(box, Box) or box.dim != 2 or not box.is_bounded:
        raise ValueError(f"prior must be a bounded 2-D Box, got {prior!r}")
    E, rejected = box_ellipse(box), 0
    for k in range(len(data)):
        li, lj, g, e = data.pair(k)
        about, fused = E.center, None
        for _ in range(int(relinearize) + 1):
            step = analytic.intersect_strip(E, linearized_strip(li, lj, g, e, about), criterion)
            if step.ellipsoid is None:
                break
            fused, about = step.ellipsoid, step.ellipsoid.center
        if fused is None:
            rejected += 1
        else:
            E = fused
    return LinearizedResult(E, rejected)


#: The model contract's verb (:mod:`optbound.localization`); *not* a guaranteed bound.
localize = linearized_localize

__all__ = [
    "CRITERIA",
    "LinearizedResult",
    "box_ellipse",
    "linearized_localize",
    "linearized_strip",
    "localize",
]
