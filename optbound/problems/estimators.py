"""The built-in analytic updates as estimators ``problem -> set``, for :func:`optbound.evaluate`.

They are registered under the entry-point group ``optbound.estimators`` in ``pyproject.toml``,
the way an installed package registers its own (:mod:`optbound.problems.registry`), so that
``optbound bench --estimator all-registered`` runs them by the path a user's estimator takes.
Each applies one fusion criterion of [HS96, eq. (24)] (:func:`optbound.analytic.intersect_strip`)
to the prior ellipsoid and the strip of a ``strip`` problem; on a problem of another family it
raises a TypeError, which :func:`optbound.evaluate` reports as that row's error.

References
----------
[HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
on an angle measurement technique", IFAC, 1996.
"""

from __future__ import annotations

from optbound.problems.problem import Problem
from optbound.sets import Ellipsoid


def analytic_volume(problem: Problem) -> Ellipsoid | None:
    """Bound a ``strip`` problem by the volume-optimal member of the ellipsoid ∩ strip family.

    [HS96, eq. (26)], by :func:`optbound.analytic.intersect_strip` with
    ``criterion="volume"``.

    Parameters
    ----------
    problem : Problem
        A problem whose ``data`` has an ``"ellipsoid"`` and a ``"strip"``.

    Returns
    -------
    Ellipsoid or None
        The fused ellipsoid; None if the strip misses the ellipsoid.

    Raises
    ------
    TypeError
        If ``problem.data`` lacks ``"ellipsoid"`` or ``"strip"``.

    References
    ----------
    [HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
    on an angle measurement technique", IFAC, 1996.
    """
    return _intersect_strip(problem, "volume")


def analytic_trace(problem: Problem) -> Ellipsoid | None:
    """Bound a ``strip`` problem by the trace-minimising member of the ellipsoid ∩ strip family.

    [HS96, eq. (24)], by :func:`optbound.analytic.intersect_strip` with
    ``criterion="trace"``.

    Parameters
    ----------
    problem : Problem
        A problem whose ``data`` has an ``"ellipsoid"`` and a ``"strip"``.

    Returns
    -------
    Ellipsoid or None
        The fused ellipsoid; None if the strip misses the ellipsoid.

    Raises
    ------
    TypeError
        If ``problem.data`` lacks ``"ellipsoid"`` or ``"strip"``.

    References
    ----------
    [HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
    on an angle measurement technique", IFAC, 1996.
    """
    return _intersect_strip(problem, "trace")


def _intersect_strip(problem: Problem, criterion: str) -> Ellipsoid | None:
    from optbound.analytic import intersect_strip  # numba kernels: loaded on first use

    data = problem.data
    if not {"ellipsoid", "strip"} <= set(data):
        raise TypeError(
            f"the analytic strip update needs a problem with data 'ellipsoid' and 'strip'; "
            f"{problem.family}/{problem.name} has {sorted(data)}"
        )
    return intersect_strip(data["ellipsoid"], data["strip"], criterion=criterion).ellipsoid
