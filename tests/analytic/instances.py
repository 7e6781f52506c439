"""Hypothesis strategies and samplers shared by the analytic tests.

Instances are random ellipsoids (2-D..6-D, condition numbers up to ~1e3) and strips placed
relative to the ellipsoid's extent so that every case of [HS96, Fig. 1] is generated.
"""

from __future__ import annotations

import numpy as np
from hypothesis import strategies as st

from optbound.sets import Ellipsoid, Strip


def random_ellipsoid(rng: np.random.Generator, n: int, log_spread: float = 1.5) -> Ellipsoid:
    """Random centre and rotation; squared semi-axes exp(U(-log_spread, log_spread))."""
    q, _ = np.linalg.qr(rng.standard_normal((n, n)))
    axes = np.exp(rng.uniform(-log_spread, log_spread, n))
    return Ellipsoid(rng.standard_normal(n), (q * axes) @ q.T)


def strip_relative_to(E: Ellipsoid, a: np.ndarray, position: float, width: float) -> Strip:
    """Strip with normal ``a`` whose centre sits at ``position`` (in units of E's half-extent
    along a, 0 = E's centre) and whose width is ``width`` times E's extent along a."""
    lo_e, hi_e = E.extent(a)
    half_e = 0.5 * (hi_e - lo_e)
    mid = 0.5 * (lo_e + hi_e) + position * half_e
    return Strip.from_bounds(a, mid - width * half_e, mid + width * half_e)


@st.composite
def ellipsoid_and_strip(draw, min_dim: int = 2, max_dim: int = 6):
    """(E, S) with S cutting, covering, touching or missing E."""
    n = draw(st.integers(min_dim, max_dim))
    seed = draw(st.integers(0, 2**32 - 1))
    regime = draw(st.sampled_from(["consistent", "partial", "no_reduction", "inconsistent"]))
    width = draw(st.floats(0.02, 0.9))
    # Position of the strip's centre in units of E's half-extent, chosen to produce the regime.
    if regime == "consistent":
        position = draw(st.floats(-0.98, 0.98)) * (1 - width)
    elif regime == "partial":
        position = (
            draw(st.sampled_from([-1.0, 1.0])) * draw(st.floats(1.01, 1.9)) * (1 - 0.5 * width)
        )
    elif regime == "no_reduction":
        width = draw(st.floats(1.5, 3.0))
        position = draw(st.floats(-0.45, 0.45))
    else:
        position = draw(st.sampled_from([-1.0, 1.0])) * (1 + width + draw(st.floats(0.01, 1.0)))
    rng = np.random.default_rng(seed)
    E = random_ellipsoid(rng, n)
    return E, strip_relative_to(E, rng.standard_normal(n), position, width)


@st.composite
def ellipsoid_pair(draw, min_dim: int = 2, max_dim: int = 6):
    """Two random ellipsoids of the same dimension."""
    n = draw(st.integers(min_dim, max_dim))
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    return random_ellipsoid(rng, n), random_ellipsoid(rng, n)


def sample_intersection(E: Ellipsoid, S: Strip, m: int = 4000, rng=0) -> np.ndarray:
    """3 m points of E ∩ S (none if it is empty), covering its interior and whole boundary.

    In whitened coordinates y = L^{-1} (x - c), E is the unit ball and S a slab
    l <= u^T y <= h. We draw u^T y uniform in [l, h] (m interior points, m points on the
    sphere) and u^T y at l or h (m points on the planes), the rest uniform in the ball slice.
    """
    rng = np.random.default_rng(rng)
    n = E.dim
    a_white = E.chol.T @ S.a
    r = np.linalg.norm(a_white)
    u = a_white / r
    ac = S.a @ E.center
    lo, hi = max((S.b - 1 - ac) / r, -1.0), min((S.b + 1 - ac) / r, 1.0)
    if lo > hi:
        return np.empty((0, n))
    Q, _ = np.linalg.qr(np.column_stack([u, rng.standard_normal((n, n - 1))]))
    Q[:, 0] = u  # QR may flip the sign of the first column
    t = np.concatenate([rng.uniform(lo, hi, 2 * m), np.where(rng.random(m) < 0.5, lo, hi)])
    rest = rng.standard_normal((3 * m, n - 1))
    rest /= np.linalg.norm(rest, axis=1, keepdims=True)
    radius = np.sqrt(np.clip(1 - t * t, 0.0, None))
    scale = rng.random(3 * m) ** (1.0 / (n - 1))
    scale[m : 2 * m] = 1.0  # the middle third on E's boundary
    y = np.column_stack([t, rest * (radius * scale)[:, None]]) @ Q.T
    return E.center + y @ E.chol.T


def sample_sum(E1: Ellipsoid, E2: Ellipsoid, m: int, rng) -> np.ndarray:
    """Points of E1 + E2: random sums and boundary points (support points of a common normal)."""
    random_sums = E1.sample(m, rng) + E2.sample(m, rng)
    d = rng.standard_normal((m, E1.dim))

    def support_point(E):
        Cd = d @ E.shape
        return E.center + Cd / np.sqrt(np.einsum("ij,ij->i", Cd, d))[:, None]

    return np.vstack([random_sums, support_point(E1) + support_point(E2)])
