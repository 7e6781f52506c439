"""The GLH12 speed benchmark runs, and its references compute the same answers as ours."""

import numpy as np

from optbound.bench import speed_glh12 as bench
from optbound.interval import Tri
from optbound.localization.visibility import visibility_test
from optbound.scenarios import arena


def test_records_and_table():
    records = bench.bench_visibility(40) + bench.bench_luvia(20)  # bench_luvia checks equality
    assert len(records) == 4 and all(r["value"] > 0 for r in records)
    assert all(r["ratio"] > 0 for r in records[1::2])
    assert bench.markdown(records).count("\n") == 5


def test_interval_reference_never_contradicts_visibility_test():
    """A crossing proven by the reference means "not visible" for the compiled test too."""
    rng = np.random.default_rng(0)
    lo1, lo2 = rng.uniform(0, 9, (300, 2)), rng.uniform(0, 9, (300, 2))
    b1 = np.stack([lo1, lo1 + 0.2], -1)
    b2 = np.stack([lo2, lo2 + 0.2], -1)
    env = arena.environment(6)
    crossed = np.any(bench._interval_signs(b1, b2, env.outer) == Tri.TRUE, axis=1)
    assert crossed.any()
    assert np.all(visibility_test(b1, b2, env.outer)[crossed] == Tri.FALSE)
