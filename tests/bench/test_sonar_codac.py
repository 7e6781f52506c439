"""The codac side of the sonar benchmark computes the same simulation function as optbound."""

import importlib.util

import numpy as np
import pytest

from optbound.bench import sonar_codac as bench
from optbound.localization.sonar import simulate_ranges


@pytest.mark.skipif(importlib.util.find_spec("codac") is None, reason="codac not installed")
def test_codac_model_equals_simulate_ranges():
    """codac's expression (evaluated in a child process) matches f at 200 seeded poses."""
    theirs = bench.codac_values(seed=0, n=200)
    ours = simulate_ranges(bench.WORLD, bench.SONARS, bench.sample_poses(0, 200))
    assert theirs.shape == ours.shape
    assert np.allclose(theirs, ours, rtol=1e-12, atol=1e-12)
    assert np.ptp(ours) > 1.0  # the poses see a variety of ranges, not all d_max
