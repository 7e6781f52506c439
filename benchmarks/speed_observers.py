"""Time per step of every observer of ``optbound.estimation.METHODS``, against the analytic
ellipsoid step, in the same run.

Rows: the example of Alamo et al. 2005, Sect. 7.1 (n = 2, 20 steps) and seeded random stable
systems (``optbound.scenarios.linear_systems``, box noise, 50 steps) for n = 2, 4, 6. The
reference is the bare analytic step of the ellipsoidal observers, one
``analytic.minkowski_sum`` plus one ``analytic.intersect_strip`` per output row on
precomputed ellipsoids and strips (what any ellipsoidal observer costs at least); each
method's column is its median time per step over the runs and its ratio to that reference.
``zonotope_volume`` is skipped where its generator subsets exceed its limit (n >= 4 at the
default order).

Run: ``python -m benchmarks.speed_observers [--repeat R]``.
"""

from __future__ import annotations

import argparse
import statistics
import time

from optbound import analytic
from optbound import estimation as est
from optbound.estimation.ellipsoidal import measurement_strips, predict
from optbound.estimation.noise import ellipsoid_of
from optbound.report.tables import markdown_table
from optbound.scenarios import alamo2005
from optbound.scenarios.linear_systems import random_system


def _cases(steps: int = 50):
    yield "Alamo 2005 (n=2)", alamo2005.system(), alamo2005.X0, alamo2005.MEASUREMENTS
    for n in (2, 4, 6):
        s = random_system(n, 0, "box", steps=steps)
        yield f"random n={n}", s.system, s.X0, s.ys


def per_step(fn, steps: int, repeat: int) -> float | None:
    """Median seconds per step over ``repeat`` runs after a warm-up; None if the method
    refuses the case (ValueError, e.g. the volume gain's subset limit)."""
    try:
        fn()
    except ValueError:
        return None
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append((time.perf_counter() - start) / steps)
    return statistics.median(times)


def analytic_step(system, X0, ys, repeat: int) -> float:
    """Median seconds of the bare analytic step (module docstring) over the case's steps."""
    E = est.observe(system, X0, ys[:1], method="ellipsoid_volume")[0]
    W = ellipsoid_of(system.W)
    pred = predict(system, E, "volume", W)
    strips = measurement_strips(system, ys[1], pred)
    prior = E.affine_map(system.A)

    def step():
        P = analytic.minkowski_sum(prior, W, criterion="volume").ellipsoid
        for S in strips:
            P = analytic.intersect_strip(P, S, criterion="volume").ellipsoid or P

    def run():
        for _ in range(len(ys)):
            step()

    return per_step(run, len(ys), repeat)


def main(repeat: int = 3) -> str:
    """The table (markdown)."""
    rows = []
    for name, system, X0, ys in _cases():
        ref = analytic_step(system, X0, ys, repeat)
        row = [name, f"{1e6 * ref:.0f} us"]
        for m in est.METHODS:

            def run(m=m, system=system, X0=X0, ys=ys):
                return est.observe(system, X0, ys, method=m)

            t = per_step(run, len(ys), repeat)
            row.append("refused" if t is None else f"{1e3 * t:.2f} ms ({t / ref:.0f}x)")
        rows.append(row)
    return markdown_table(("case", "analytic step", *est.METHODS), rows)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    print(main(parser.parse_args().repeat))
