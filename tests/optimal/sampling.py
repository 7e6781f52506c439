"""Points of an intersection for containment tests, drawn independently of the solvers."""

from __future__ import annotations

import numpy as np

from optbound import Ellipsoid

MIN_POINTS = 10_000


def points_of(sets, rng, m: int = MIN_POINTS, proposal: Ellipsoid | None = None) -> np.ndarray:
    """At least ``m`` points of the intersection of ``sets`` (uniform inside and on the boundary
    of ``proposal``, by default the first Ellipsoid, kept when every set contains them;
    tolerance 0). A small set needs a proposal that contains it closely."""
    gen = np.random.default_rng(rng)
    if proposal is None:
        proposal = next(s for s in sets if isinstance(s, Ellipsoid))
    kept = np.empty((0, proposal.dim))
    while kept.shape[0] < m:
        X = np.vstack([proposal.sample(4 * m, gen), proposal.sample_boundary(m, gen)])
        inside = np.all([np.asarray(s.contains(X, tol=0.0)) for s in sets], axis=0)
        kept = np.vstack([kept, X[inside]])
    return kept
