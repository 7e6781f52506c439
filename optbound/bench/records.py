"""Helpers that turn analytic-vs-SDP comparisons into flat, JSON-able records and figures."""

from __future__ import annotations

from optbound import Ellipsoid, Strip

# The size measure each analytic criterion minimises, and hence the ratio it is judged by.
METRIC_OF = {
    "volume": "volume_ratio",
    "robust": "volume_ratio",
    "trace": "trace_ratio",
    "projection": "projection_volume_ratio",
    "bh_volume": "volume_ratio",
    "bh_trace": "trace_ratio",
}
# The SDP objective that minimises each size measure.
OBJECTIVE_OF = {
    "volume_ratio": "volume",
    "trace_ratio": "trace",
    "projection_volume_ratio": "projection",
}


def ratio(metric: str, analytic: Ellipsoid, reference: Ellipsoid, dims=None) -> float:
    """Compute ``size(analytic) / size(reference)`` for the named metric.

    Parameters
    ----------
    metric : {"volume_ratio", "trace_ratio", "projection_volume_ratio"}
        The size ratio, a function of :mod:`optbound.compare`.
    analytic : Ellipsoid
        The analytic bound.
    reference : Ellipsoid
        The SDP reference bound.
    dims : sequence of int, optional
        The coordinates projected on, for ``"projection_volume_ratio"`` only.

    Returns
    -------
    float
        The ratio; >= 1 when the reference is optimal for this metric.

    Examples
    --------
    >>> import numpy as np
    >>> from optbound import Ellipsoid
    >>> from optbound.bench.records import ratio
    >>> wide, unit = Ellipsoid(np.zeros(2), np.diag([4.0, 1.0])), Ellipsoid(np.zeros(2), np.eye(2))
    >>> round(ratio("volume_ratio", wide, unit), 12), ratio("trace_ratio", wide, unit)
    (2.0, 2.5)
    """
    from optbound import compare

    if metric == "projection_volume_ratio":
        return float(compare.projection_volume_ratio(analytic, reference, dims))
    return float(getattr(compare, metric)(analytic, reference))


def lower_ratio(analytic_size: float, result) -> float | None:
    """Bound the analytic method's loss: ``analytic_size / result.lower_bound``.

    ``result.lower_bound`` bounds the true minimum of the SDP's objective (over all outer
    ellipsoids) from below, so this ratio bounds the analytic method's true loss from above.
    ``analytic_size`` must be measured in the same objective (e.g. the volume).

    Parameters
    ----------
    analytic_size : float
        The analytic bound's size in the SDP's objective.
    result : OptimalResult
        The SDP reference result, with its ``lower_bound`` attribute.

    Returns
    -------
    float or None
        The ratio, or None when no lower bound was computed.
    """
    if result.lower_bound is None:
        return None
    return float(analytic_size / result.lower_bound)


def reference(solve, *args, **kwargs) -> tuple[object | None, str]:
    """Run an SDP reference solver; a refused solve gives ``(None, message)``.

    An inaccurate or uncertifiable SDP (e.g. at condition number 1e6) is a finding about the
    reference, reported per criterion, not a reason to drop the instance's other criteria.

    Parameters
    ----------
    solve : callable
        The solver (a function of :mod:`optbound.optimal`).
    *args, **kwargs
        Passed to ``solve``.

    Returns
    -------
    result : object or None
        What ``solve`` returned, or None if it raised ``SolverError`` or
        ``CertificationError``.
    message : str
        Empty on success, else ``"ErrorType: message"``.
    """
    from optbound.optimal import CertificationError, SolverError

    try:
        return solve(*args, **kwargs), ""
    except (SolverError, CertificationError) as exc:
        return None, f"{type(exc).__name__}: {exc}"


def comparison(metric: str, analytic: Ellipsoid, result, error: str, dims=None) -> dict:
    """Build the ratio fields of one analytic-vs-SDP record.

    Parameters
    ----------
    metric : str
        The size ratio (see :func:`ratio`).
    analytic : Ellipsoid
        The analytic bound.
    result : OptimalResult or None
        The SDP reference result, None when the SDP failed.
    error : str
        Why the SDP failed (recorded when ``result`` is None).
    dims : sequence of int, optional
        The projected coordinates, for ``"projection_volume_ratio"``.

    Returns
    -------
    dict
        ``metric``, ``ratio`` (None when the SDP failed) and the SDP's status, certification,
        inflation and solve time, or its error.
    """
    if result is None:
        return {"metric": metric, "ratio": None, "sdp_status": "failed", "sdp_error": error}
    return {
        "metric": metric,
        "ratio": ratio(metric, analytic, result.ellipsoid, dims),
        "sdp_status": str(result.status),
        "sdp_certified": bool(result.certified),
        "sdp_inflation": float(result.inflation),
        "sdp_s": float(result.solve_time),
    }


def ellipsoid_json(E: Ellipsoid) -> dict:
    """Turn an ellipsoid into a JSON-able dict.

    Parameters
    ----------
    E : Ellipsoid
        The ellipsoid.

    Returns
    -------
    dict
        ``{"center": [...], "shape": [[...], ...]}``.
    """
    return {"center": E.center.tolist(), "shape": E.shape.tolist()}


def strip_json(S: Strip) -> dict:
    """Turn a strip into a JSON-able dict.

    Parameters
    ----------
    S : Strip
        The strip ``|a·x - b| <= 1``.

    Returns
    -------
    dict
        ``{"a": [...], "b": b}``.
    """
    return {"a": S.a.tolist(), "b": S.b}


def figure(title: str, seed: int, E: Ellipsoid, strips: list[Strip], bounds: dict) -> dict:
    """Build a drawable 2-D instance: the exact set ``E ∩ strips`` and named bounding ellipses.

    Parameters
    ----------
    title : str
        The figure's title.
    seed : int
        The instance seed.
    E : Ellipsoid
        The prior ellipse.
    strips : list of Strip
        The measurement strips intersected with ``E``.
    bounds : dict
        Label -> bounding :class:`~optbound.Ellipsoid`.

    Returns
    -------
    dict
        The JSON-able figure that :mod:`optbound.report` draws.
    """
    return {
        "title": title,
        "seed": seed,
        "ellipsoid": ellipsoid_json(E),
        "strips": [strip_json(S) for S in strips],
        "bounds": [{"label": k, **ellipsoid_json(v)} for k, v in bounds.items()],
    }


def sum_figure(title: str, seed: int, summands: list[Ellipsoid], bounds: dict) -> dict:
    """Build a drawable 2-D instance: the Minkowski sum of ``summands`` and bounding ellipses.

    Parameters
    ----------
    title : str
        The figure's title.
    seed : int
        The instance seed.
    summands : list of Ellipsoid
        The ellipses whose exact Minkowski sum is drawn.
    bounds : dict
        Label -> bounding :class:`~optbound.Ellipsoid`.

    Returns
    -------
    dict
        The JSON-able figure that :mod:`optbound.report` draws.
    """
    return {
        "title": title,
        "seed": seed,
        "summands": [ellipsoid_json(E) for E in summands],
        "bounds": [{"label": k, **ellipsoid_json(v)} for k, v in bounds.items()],
    }
