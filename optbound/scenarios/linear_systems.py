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
    """A simulated linear system: what an estimator gets, and the true states.

    Parameters
    ----------
    system : LinearSystem
        ``(A, C, W, V)``.
    X0 : Box
        The set of ``x_0``.
    ys : np.ndarray, shape (N, p)
        The measurements; ``ys[k-1]`` measures ``x_k``.
    states : np.ndarray, shape (N, n)
        The true states, ``states[k-1]`` = ``x_k``.
    """

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
    """Draw a seeded random stable system of dimension ``n`` and simulate it (module docstring).

    Parameters
    ----------
    n : int
        The state dimension (>= 1); there are ``max(1, n // 2)`` outputs.
    seed : int
        Fixes the system, the noise sets and the simulation.
    noise : {"box", "ellipsoid"}, default "box"
        The shape of ``W`` and ``V``.
    steps : int, default 100
        Simulated steps (>= 1): the number of measurements.

    Returns
    -------
    LinearScenario
        The system, ``X0 = [-1, 1]^n``, the measurements and the true states.

    Raises
    ------
    ValueError
        For ``n < 1``, ``steps < 1`` or an unknown ``noise`` (one of :data:`NOISES`).

    Examples
    --------
    >>> from optbound.scenarios.linear_systems import random_system
    >>> run = random_system(3, seed=0, steps=5)
    >>> run.system.A.shape, run.ys.shape, run.states.shape
    ((3, 3), (5, 1), (5, 3))
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
