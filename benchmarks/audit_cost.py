"""What ``optbound.evaluate`` costs per problem, against the cost of the estimator itself.

Run from the repository root: ``python -m benchmarks.audit_cost [--suite tiny]``. For every
family of the suite it prints medians over the family's problems of

- ``setup``: building what the audit compares with, once per problem and cached on it (the
  exact paving, the exact set's volume bracket and the reference bounds, SDPs included);
- ``estimator``: one call of the estimator (the exact paving's hull as a ``Box``, cheap by
  design, so the column shows the floor of the harness);
- ``audit``: measuring and auditing its answer (size bracket, ratio brackets, soundness proof
  or counterexample), with the set-up already paid;

and the ratio audit / estimator, then the wall time of the whole ``evaluate`` call on the suite
in a fresh state (set-up included), which is what a user waits for.
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections import defaultdict


def _hull_box(problem):
    return problem.references()["best_box"]


def measure(suite: str = "tiny", seed: int = 0) -> tuple[list[tuple], float]:
    """Per-family median seconds ``(family, n, setup, estimator, audit)`` and the total wall."""
    from optbound import evaluate, problems

    start = time.perf_counter()
    fresh = problems.suite(suite, seed=seed)
    evaluate(_hull_box, fresh)
    total = time.perf_counter() - start

    setup = defaultdict(list)
    cached = problems.suite(suite, seed=seed)
    for p in cached:
        t0 = time.perf_counter()
        p.exact()
        p.volume_bracket()
        p.references()
        setup[p.family].append(time.perf_counter() - t0)
    rows = evaluate(_hull_box, cached).rows
    per_family = defaultdict(lambda: ([], []))
    for row in rows:
        per_family[row["family"]][0].append(row["seconds"])
        per_family[row["family"]][1].append(row["audit_seconds"])
    table = [
        (
            family,
            len(calls),
            statistics.median(setup[family]),
            statistics.median(calls),
            statistics.median(audits),
        )
        for family, (calls, audits) in per_family.items()
    ]
    return table, total


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--suite", default="tiny", help="problem suite (default tiny)")
    parser.add_argument("--seed", type=int, default=0, help="suite seed (default 0)")
    args = parser.parse_args(argv)
    table, total = measure(args.suite, args.seed)
    call = f"evaluate(hull box, problems.suite({args.suite!r}))"
    print(f"{call}: {total:.1f} s wall, set-up included")
    print("| family | problems | set-up (s) | estimator (s) | audit (s) | audit / estimator |")
    print("|---|---|---|---|---|---|")
    for family, n, setup, call, audit in table:
        print(f"| {family} | {n} | {setup:.3g} | {call:.3g} | {audit:.3g} | {audit / call:.3g} |")


if __name__ == "__main__":
    main()
