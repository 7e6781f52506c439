"""What ``lower_bound=True`` costs: an ``outer_ellipsoid`` call with and without it.

Instances of the recursive family (``optbound/bench/recursive_tightness.py``: a prior of condition
number 10 and k strips of normalised width 0.2 through one point). For each (n, k), the two
kinds of call alternate on the same instances, so that machine load affects both alike; the
ratio is the median over instances of (call with the bound) / (call without it), both with the
problem template already cached.

Run ``python -m benchmarks.lower_bound_cost`` to print the table.
"""

from __future__ import annotations

import os
import time

import numpy as np

from optbound.bench.recursive_tightness import instance

CELLS = ((2, 10), (3, 10), (4, 50))
SEEDS = 5


def _seconds(sets: list, **options) -> float:
    from optbound.optimal import outer_ellipsoid

    start = time.perf_counter()
    outer_ellipsoid(sets, **options)
    return time.perf_counter() - start


def run(cells=CELLS, seeds: int = SEEDS) -> list[dict]:
    """Per (n, k): median seconds with and without the bound, and the median ratio."""
    rows = []
    for n, k in cells:
        with_lb, without, ratios = [], [], []
        for seed in range(seeds):
            E0, _, strips = instance({"seed": 1000 * n + seed, "dim": n, "width": 0.2, "ks": [k]})
            sets = [E0, *strips[:k]]
            _seconds(sets)  # the template is cached from here on
            a = _seconds(sets, lower_bound=True, rng=seed)
            b = _seconds(sets)
            with_lb.append(a)
            without.append(b)
            ratios.append(a / b)
        rows.append(
            {
                "n": n,
                "k": k,
                "with_s": float(np.median(with_lb)),
                "without_s": float(np.median(without)),
                "ratio": float(np.median(ratios)),
            }
        )
    return rows


if __name__ == "__main__":
    print("| n | k | with lower_bound [s] | without [s] | ratio (median per instance) |")
    print("|---|---|---|---|---|")
    for r in run():
        print(
            f"| {r['n']} | {r['k']} | {r['with_s']:.3f} | {r['without_s']:.4f} | {r['ratio']:.1f} |"
        )
    print(f"\n1-min load average at the end: {os.getloadavg()[0]:.2f}")
