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
    """True if ``rec``'s lower bound is degenerate: ``lower_ratio / ratio`` (= SDP / lower
    bound) above ``DEGENERATE_GAP``."""
    low, ratio = rec.get("lower_ratio"), rec.get("ratio")
    return low is not None and ratio is not None and low > DEGENERATE_GAP * ratio


def without_degenerate_lower(records: list[dict]) -> tuple[list[dict], list[dict]]:
    """``(records with a degenerate lower bound's lower_ratio set to None, those records)``:
    the statistics then count them as missing instead of letting them dominate the max."""
    flagged = [rec for rec in records if is_degenerate_lower(rec)]
    cleaned = [{**rec, "lower_ratio": None} if is_degenerate_lower(rec) else rec for rec in records]
    return cleaned, flagged


def group(records: list[dict], keys: tuple[str, ...]) -> dict[tuple, list[dict]]:
    """Records grouped by the values of ``keys``, groups in first-seen order."""
    groups: dict[tuple, list[dict]] = defaultdict(list)
    for rec in records:
        groups[tuple(rec.get(k) for k in keys)].append(rec)
    return dict(groups)


def ratio_stats(records: list[dict], field: str = "ratio") -> dict:
    """min, median, max of ``field`` over ``records``, the records holding the max (``worst``)
    and the min (``lowest``).

    Records whose ``field`` is missing or None (e.g. a refused SDP reference) are not part of
    the statistics; ``missing`` counts them. With none left, ``n`` is 0.
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
    """Where to find the worst instance: its seed and the parameters that rebuild it."""
    parts = [f"seed {rec['seed']}"]
    if rec.get("variant"):
        parts.append(str(rec["variant"]))
    parts.append(f"n={rec['dim']}")
    if rec.get("cond") is not None:
        parts.append(f"cond {rec['cond']:.0e}")
    if rec.get("k") is not None:
        parts.append(f"k={rec['k']}")
    return ", ".join(parts)
