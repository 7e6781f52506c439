"""Statistics of ratio records: min / median / max per group, with the worst instance's seed."""

from __future__ import annotations

from collections import defaultdict

import numpy as np

# A ratio this far below 1 means the analytic bound beat the reference: either the reference
# is only an upper bound on the optimum, or something is wrong. Solver noise stays below it.
BELOW_ONE_TOL = 1e-6


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
