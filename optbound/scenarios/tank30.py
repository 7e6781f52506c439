"""CORA's 30-state tank system for guaranteed state estimation (Althoff, ARCH 2021).

The linearised cascade of tanks of ``example_linearSysDT_observe_03_tank.m`` in CORA
(M. Althoff, *Guaranteed state estimation in CORA 2021*, ARCH 2021): 30 states, 15 inputs,
21 outputs, time step 0.5 s,

    x_{k+1} = A x_k + B u_k + w_k,   y_k = C x_k + v_k,

``|w_k|_inf <= 0.001``, ``|v_k|_inf <= 0.2``, ``x_0 in [-4, 4]^30``, with CORA's stored
inputs ``u_k`` and 235 *stored* measurements (not simulated here). The data file
``_data/tank30.json`` holds CORA's numbers unchanged; ``benchmarks/convert_cora_tank.py``
regenerates it from the CORA file (the commit and path are in ``DATA["source"]``).

``optbound.estimation`` has no input term, so :func:`scenario` removes the known input
response exactly: with ``s_0 = 0`` and ``s_{k+1} = fl(A s_k + B u_k)`` (floats), the state
``z_k = x_k - s_k`` satisfies ``z_{k+1} = A z_k + (w_k + r_k)``, ``y_k - C s_k = C z_k + v_k``
with the rounding residual ``r_k = A s_k + B u_k - s_{k+1}`` computed in exact rational
arithmetic; the measurements ``fl(y_k - C s_k)`` differ from the exact ones by ``e_k``, also
exact. ``W`` and ``V`` are widened by ``max_k |r_k|`` and ``max_k |e_k|`` (rounded up), so a
set guaranteed for ``z_k`` plus ``s_k`` is guaranteed for ``x_k``; interval-hull widths do not
change under the shift.

Conventions: CORA's first measurement (t = 0) measures ``x_0``; ``optbound.estimation`` has
no measurement at k = 0, so it is dropped: ``ys[k-1]`` = CORA's ``y(:, k+1)`` measures
``x_k``, k = 1 ... 234.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from fractions import Fraction
from functools import cache
from importlib import resources

import numpy as np

from optbound.estimation import LinearSystem
from optbound.sets import Box
from optbound.sets.constrained_zonotope_polygon import round_up

__all__ = ["REFERENCE", "TankScenario", "data", "scenario"]

REFERENCE = (
    "M. Althoff, Guaranteed state estimation in CORA 2021, ARCH 2021; CORA "
    "examples/contDynamics/linearSysDT/example_linearSysDT_observe_03_tank.m"
)


@dataclass(frozen=True)
class TankScenario:
    """CORA's tank as an ``optbound.estimation`` problem, with the input response removed.

    Parameters
    ----------
    system : LinearSystem
        The shifted system (module docstring), ``W`` and ``V`` widened by the rounding.
    X0 : Box
        The set of ``x_0``, ``[-4, 4]^30``.
    ys : np.ndarray, shape (234, 21)
        The shifted measurements; ``ys[k-1]`` measures ``z_k``.
    offsets : np.ndarray, shape (234, 30)
        The input response ``s_k``: ``x_k in Z_k + offsets[k-1]`` for a set ``Z_k``
        guaranteed for ``z_k``.
    """

    system: LinearSystem
    X0: Box
    ys: np.ndarray
    offsets: np.ndarray


@cache
def data() -> dict:
    """Read CORA's numbers as stored in ``_data/tank30.json`` (cached).

    Returns
    -------
    dict
        CORA's matrices ``"A"``, ``"B"``, ``"C"``, ``"c"``, inputs ``"u"``, measurements
        ``"y"``, noise and initial zonotopes ``"W"``, ``"V"``, ``"R0"``, time step ``"dt"``
        (lists and numbers; see the module docstring), ``"reference"`` and ``"source"``.
    """
    text = resources.files("optbound.scenarios").joinpath("_data/tank30.json").read_text()
    return json.loads(text)


def _exact_product(M: np.ndarray, x: np.ndarray) -> list[Fraction]:
    """``M x`` in exact rational arithmetic (floats read as the rationals they are)."""
    return [
        sum((Fraction(row[j]) * Fraction(x[j]) for j in np.flatnonzero(row)), Fraction(0))
        for row in M
    ]


def _max_abs(current: list[Fraction], exact: list[Fraction], approx: np.ndarray) -> list:
    """Elementwise ``max(current, |exact - approx|)``."""
    return [max(c, abs(e - Fraction(a))) for c, e, a in zip(current, exact, approx, strict=True)]


def _box_noise(Z: dict) -> np.ndarray:
    G = np.array(Z["generators"])
    if np.any(Z["center"]) or np.any(G != np.diag(np.diag(G))):
        raise ValueError("the tank data's noise is expected to be a centred axis-aligned box")
    return np.abs(np.diag(G))


@cache
def scenario() -> TankScenario:
    """Build the tank as an ``optbound.estimation`` problem (module docstring; cached).

    Returns
    -------
    TankScenario
        The shifted system, ``X0``, the measurements and the input response.

    Raises
    ------
    ValueError
        If the stored noise sets are not centred axis-aligned boxes.
    """
    d = data()
    A, B, C = (np.array(d[k]) for k in ("A", "B", "C"))
    u, y = np.array(d["u"]).T, np.array(d["y"]).T  # (235, 15), (235, 21)
    w, v = _box_noise(d["W"]), _box_noise(d["V"])
    n, p = A.shape[0], C.shape[0]
    s = np.zeros(n)
    offsets, ys = [], []
    r_max, e_max = [Fraction(0)] * n, [Fraction(0)] * p
    for k in range(y.shape[0] - 1):
        s_next = A @ s + B @ u[k]
        exact = [a + b for a, b in zip(_exact_product(A, s), _exact_product(B, u[k]), strict=True)]
        r_max = _max_abs(r_max, exact, s_next)
        s = s_next
        y_shift = y[k + 1] - C @ s
        exact = [Fraction(yi) - cs for yi, cs in zip(y[k + 1], _exact_product(C, s), strict=True)]
        e_max = _max_abs(e_max, exact, y_shift)
        offsets.append(s)
        ys.append(y_shift)
    half_w = np.array([round_up(Fraction(x) + r) for x, r in zip(w, r_max, strict=True)])
    half_v = np.array([round_up(Fraction(x) + e) for x, e in zip(v, e_max, strict=True)])
    r0 = _box_noise(d["R0"])
    W, V, X0 = Box(-half_w, half_w), Box(-half_v, half_v), Box(-r0, r0)
    return TankScenario(LinearSystem(A, C, W, V), X0, np.array(ys), np.array(offsets))
