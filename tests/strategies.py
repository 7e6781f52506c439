"""Hypothesis strategies shared by the tests: random valid sets of moderate conditioning."""

import numpy as np
from hypothesis import strategies as st

from optbound import Ellipsoid


@st.composite
def ellipsoids(draw, min_dim: int = 2, max_dim: int = 6, max_log10_cond: float = 3.0):
    """A random ellipsoid: random rotation, log-uniform semi-axes, random centre."""
    n = draw(st.integers(min_dim, max_dim))
    seed = draw(st.integers(0, 2**32 - 1))
    rng = np.random.default_rng(seed)
    q, _ = np.linalg.qr(rng.standard_normal((n, n)))
    axes = 10.0 ** rng.uniform(-0.5 * max_log10_cond, 0.5 * max_log10_cond, n)
    shape = (q * axes**2) @ q.T
    return Ellipsoid(rng.uniform(-5.0, 5.0, n), shape)
