"""Effect of ``clip`` on the S-procedure reference with many strips (docs' optimal page).

``python -m tests.optimal.clip_effect`` rebuilds instances of the benchmark's recursive family
(``optbound/bench/recursive_tightness.py``: a prior ellipsoid of condition number 10 and k strips of
normalised width 0.2 around one true point) for ``SEEDS`` seeds per dimension, and prints the
medians over the seeds of: the SDP volume over the certified lower bound (the largest of the
modes' ``lower_bound=True``) for ``clip="ellipsoids"``, ``clip="intersection"`` and the
latter with ``products=True``, the recursive analytic filter's volume over each SDP's, and
the wall time of a cached ``outer_ellipsoid`` call (without the lower bound).
"""

from __future__ import annotations

import os
import time

import numpy as np

from optbound import analytic
from optbound.bench.recursive_tightness import instance
from optbound.optimal import outer_ellipsoid

DIMS = (2, 3, 4, 5, 6)
KS = (1, 10, 50)
SEEDS = 5
WIDTH = 0.2
MODES = {
    "ellipsoids": {"clip": "ellipsoids"},
    "intersection": {"clip": "intersection"},
    "products": {"clip": "intersection", "products": True},
}


def strip_instance(n: int, k: int, seed: int) -> list:
    """The prior ellipsoid and the first ``k`` strips of a recursive-family instance."""
    E0, _, strips = instance({"seed": seed, "dim": n, "width": WIDTH, "ks": [k]})
    return [E0, *strips]


def _timed(sets: list, options: dict) -> float:
    start = time.perf_counter()
    outer_ellipsoid(sets, **options)
    return time.perf_counter() - start


def measure(n: int, k: int, seed: int) -> dict:
    """Ratios and times of each mode on one instance.

    All lower bounds are valid for the one set (they differ because the sampling starts from
    each mode's ellipsoid), so every ratio uses the largest.
    """
    sets = strip_instance(n, k, seed)
    E = sets[0]
    for S in sets[1:]:
        E = analytic.intersect_strip(E, S, criterion="volume").ellipsoid
    results = {
        mode: outer_ellipsoid(sets, lower_bound=True, rng=seed, **options)
        for mode, options in MODES.items()
    }
    lower = max(r.lower_bound for r in results.values())
    row = {}
    for mode, r in results.items():
        row[f"{mode}/lower"] = r.objective / lower
        row[f"recursive/{mode}"] = E.volume() / r.objective
        _timed(sets, MODES[mode])  # the shape's problems are cached from here on
        row[f"{mode} s"] = _timed(sets, MODES[mode])
    return row


def medians(n: int, k: int) -> dict:
    """Medians over ``SEEDS`` seeds of :func:`measure`'s entries for one (n, k) cell."""
    rows = [measure(n, k, 1000 * n + seed) for seed in range(SEEDS)]
    return {key: float(np.median([row[key] for row in rows])) for key in rows[0]}


def _chain(cell: dict, template: str, digits: str) -> str:
    return " → ".join(f"{cell[template.format(mode)]:{digits}}" for mode in MODES)


def table(dims=DIMS, ks=KS) -> str:
    """The optimal page table: each entry ``ellipsoids → intersection → products`` (k > 1 only)."""
    lines = [
        "| n | k | SDP / lower bound | recursive filter / SDP | time per call (ms) |",
        "|---|---|---|---|---|",
    ]
    for n in dims:
        for k in ks:
            if k == 1:
                continue
            cell = medians(n, k)
            times = {f"{mode} ms": 1e3 * cell[f"{mode} s"] for mode in MODES}
            lines.append(
                f"| {n} | {k} | {_chain(cell, '{}/lower', '.3g')} "
                f"| {_chain(cell, 'recursive/{}', '.3g')} | {_chain(times, '{} ms', '.2g')} |"
            )
    lines.append(f"\n1-min load average at the end of the run: {os.getloadavg()[0]:.1f}.")
    return "\n".join(lines)


if __name__ == "__main__":
    print(table())
