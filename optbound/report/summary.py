"""Statistics of ratio records: min / median / max per group, with the worst instance's seed."""

from __future__ import annotations

from collections import defaultdict

import numpy as np

# A ratio this far below 1 means the analytic bound beat the reference: either the reference
# is only an upper bound on the optimum, or something is wrong. Solver noise stays below it.
BELOW_ONE_TOL = 1e-6


# SDP objective / sampled lower bound above this means the lower bound collapsed (e.g. its
# points span a lower-dimensional set, so their enclosing volume is ~0), not that the SDP is
# that loose: the relaxation gaps seen on the benchmark's instances stay below 10.
DEGENERATE_GAP = 1e3


def is_degenerate_lower(rec: dict) -> bool:
    """Decide whether ``rec``'s lower bound on the optimum is degenerate.

    Parameters
    ----------
    rec : dict
        A ratio record, with optional ``"ratio"`` and ``"lower_ratio"``.

    Returns
    -------
    bool
        True if ``lower_ratio / ratio`` (= SDP / lower bound) exceeds
        :data:`DEGENERATE_GAP`; False if either is missing.
    """
    low, ratio = rec.get("lower_ratio"), rec.get("ratio")
    return low is not None and ratio is not None and low > DEGENERATE_GAP * ratio


def without_degenerate_lower(records: list[dict]) -> tuple[list[dict], list[dict]]:
    """Drop the degenerate lower bounds of ``records`` (:func:`is_degenerate_lower`).

    The statistics then count them as missing instead of letting them dominate the max.

    Parameters
    ----------
    records : list of dict
        Ratio records.

    Returns
    -------
    cleaned : list of dict
        ``records`` with each degenerate record's ``lower_ratio`` set to None (copies; the
        input is not modified).
    flagged : list of dict
        The degenerate records, as given.
    """
    flagged = [rec for rec in records if is_degenerate_lower(rec)]
    cleaned = [{**rec, "lower_ratio": None} if is_degenerate_lower(rec) else rec for rec in records]
    return cleaned, flagged


def group(records: list[dict], keys: tuple[str, ...]) -> dict[tuple, list[dict]]:
    """Group records by the values of ``keys``.

    Parameters
    ----------
    records : list of dict
        The records; a missing key reads as None.
    keys : tuple of str
        The record keys to group by.

    Returns
    -------
    dict of tuple to list of dict
        The values of ``keys`` -> the records holding them, groups in first-seen order.

    Examples
    --------
    >>> from optbound.report.summary import group
    >>> recs = [{"c": "trace", "r": 1.2}, {"c": "volume", "r": 1.1}, {"c": "trace", "r": 1.4}]
    >>> {k: len(v) for k, v in group(recs, ("c",)).items()}
    {('trace',): 2, ('volume',): 1}
    """
    groups: dict[tuple, list[dict]] = defaultdict(list)
    for rec in records:
        groups[tuple(rec.get(k) for k in keys)].append(rec)
    return dict(groups)


def ratio_stats(records: list[dict], field: str = "ratio") -> dict:
    """Summarise ``field`` over ``records``: min, median, max and the extreme records.

    Records whose ``field`` is missing or None (e.g. a refused SDP reference) are not part of
    the statistics; ``missing`` counts them.

    Parameters
    ----------
    records : list of dict
        Ratio records.
    field : str, default "ratio"
        The record key summarised.

    Returns
    -------
    dict
        ``n`` (records counted) and ``missing``; with ``n > 0`` also ``min``, ``median``,
        ``max``, ``below_one`` (values below ``1 - BELOW_ONE_TOL``: the bound beat its
        reference), and the records holding the max (``worst``) and the min (``lowest``).

    Examples
    --------
    >>> from optbound.report.summary import ratio_stats
    >>> s = ratio_stats([{"ratio": 1.5}, {"ratio": 1.1}, {"ratio": None}])
    >>> s["n"], s["missing"], s["median"], s["worst"]
    (2, 1, 1.3, {'ratio': 1.5})
    """
    kept = [rec for rec in records if rec.get(field) is not None]
    missing = len(records) - len(kept)
    if not kept:
        return {"n": 0, "missing": missing}
    values = np.array([rec[field] for rec in kept])
    return {
        "n": len(kept),
        "missing": missing,
        "min": float(values.min()),
        "median": float(np.median(values)),
        "max": float(values.max()),
        "below_one": int(np.sum(values < 1.0 - BELOW_ONE_TOL)),
        "worst": kept[int(np.argmax(values))],
        "lowest": kept[int(np.argmin(values))],
    }


def worst_label(rec: dict) -> str:
    """Label an instance by its seed and the parameters that rebuild it.

    Parameters
    ----------
    rec : dict
        A ratio record with ``"seed"`` and ``"dim"``, and optionally ``"variant"``,
        ``"cond"`` and ``"k"``.

    Returns
    -------
    str
        E.g. ``"seed 7, n=3, cond 1e+04"``.
    """
    parts = [f"seed {rec['seed']}"]
    if rec.get("variant"):
        parts.append(str(rec["variant"]))
    parts.append(f"n={rec['dim']}")
    if rec.get("cond") is not None:
        parts.append(f"cond {rec['cond']:.0e}")
    if rec.get("k") is not None:
        parts.append(f"k={rec['k']}")
    return ", ".join(parts)
