"""Seeded random stable linear systems with bounded noise, simulated (issue 21's benchmarks).

``random_system(n, seed, noise)`` draws ``A`` with i.i.d. normal entries scaled to spectral
radius ``RHO``, ``p = max(1, n // 2)`` output rows ``C`` (normal entries), process noise
``W`` and measurement noise ``V`` (boxes with half-widths drawn in ``[0.02, 0.1]``, or
ellipsoids with those semi-axes in a random orientation), ``X0 = [-1, 1]^n``, and simulates
``steps`` steps from ``x_0`` uniform in ``X0`` with noise drawn uniformly in ``W`` and ``V``:
so the true states lie in every guaranteed estimate. These are our designs (no paper's data);
the seed fixes everything.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from optbound.estimation import LinearSystem
from optbound.sets import Box, Ellipsoid

__all__ = ["NOISES", "RHO", "LinearScenario", "random_system"]

RHO = 0.9
NOISES = ("box", "ellipsoid")


@dataclass(frozen=True)
class LinearScenario:
    """A system, the set of ``x_0``, the measurements ``ys`` (N, p) and the true states
    ``states`` (N, n), ``states[k-1]`` = x_k measured by ``ys[k-1]``."""

    system: LinearSystem
    X0: Box
    ys: np.ndarray
    states: np.ndarray


def _noise(rng: np.random.Generator, dim: int, kind: str) -> Box | Ellipsoid:
    half = rng.uniform(0.02, 0.1, dim)
    if kind == "box":
        return Box(-half, half)
    Q, _ = np.linalg.qr(rng.normal(size=(dim, dim)))
    return Ellipsoid(np.zeros(dim), Q @ np.diag(half**2) @ Q.T)


def _draw(S: Box | Ellipsoid, rng: np.random.Generator) -> np.ndarray:
    return rng.uniform(S.lo, S.hi) if isinstance(S, Box) else S.sample(1, rng)[0]


def random_system(n: int, seed: int, noise: str = "box", steps: int = 100) -> LinearScenario:
    """A seeded random stable system of dimension ``n`` and its simulation (module docstring).

    Raises
    ------
    ValueError
        For ``n < 1``, ``steps < 1`` or an unknown ``noise`` (one of :data:`NOISES`).
    """
    if int(n) != n or n < 1:
        raise ValueError(f"n must be a positive integer, got {n}")
    if int(steps) != steps or steps < 1:
        raise ValueError(f"steps must be a positive integer, got {steps}")
    if noise not in NOISES:
        raise ValueError(f"noise must be one of {NOISES}, got {noise!r}")
    rng = np.random.default_rng([int(seed), int(n), NOISES.index(noise)])
    A = rng.normal(size=(n, n))
    A *= RHO / max(abs(np.linalg.eigvals(A)))
    p = max(1, n // 2)
    C = rng.normal(size=(p, n))
    W, V = _noise(rng, n, noise), _noise(rng, p, noise)
    X0 = Box(-np.ones(n), np.ones(n))
    x = rng.uniform(-1.0, 1.0, n)
    states, ys = [], []
    for _ in range(steps):
        x = A @ x + _draw(W, rng)
        states.append(x)
        ys.append(C @ x + _draw(V, rng))
    return LinearScenario(LinearSystem(A, C, W, V), X0, np.array(ys), np.array(states))
