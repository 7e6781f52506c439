"""Speed of the analytic updates: one call, a vectorised batch, and the SDP that they replace.

Every ratio is taken between two timings of the same run on the same machine:
batch speed-up = (seconds per single call) / (seconds per update inside a batch), and
SDP cost = (seconds per SDP solve) / (seconds per analytic call).
"""

from __future__ import annotations

import numpy as np

from benchmarks.family import Family, task_seeds
from benchmarks.instances import random_ellipsoid, random_strip
from benchmarks.timing import per_call, speed_record

NAME = "speed_analytic"
DIM = 3
BATCHES = {"tiny": (10**3,), "quick": (10**4, 10**5), "full": (10**4, 10**5, 10**6)}


def tasks(suite: str, seed: int) -> list[dict]:
    s1, s2 = task_seeds(seed, NAME, 2)
    return [
        {"seed": s1, "what": "strip", "batches": list(BATCHES[suite])},
        {"seed": s2, "what": "minkowski"},
    ]


def batch_instances(rng: np.random.Generator, count: int, dim: int):
    """``count`` random ellipsoids (centres, shapes) and one strip normal/offset per ellipsoid.

    Shapes are ``A A^T + 0.1 I`` for Gaussian A; each strip passes near its ellipsoid's centre
    so that most updates are genuine reductions, not the trivial "no reduction" case.
    """
    A = rng.standard_normal((count, dim, dim))
    shapes = A @ A.transpose(0, 2, 1) + 0.1 * np.eye(dim)
    centers = rng.standard_normal((count, dim))
    a = rng.standard_normal((count, dim))
    half = np.sqrt(np.einsum("bi,bij,bj->b", a, shapes, a))
    b = np.einsum("bi,bi->b", a, centers) + rng.uniform(-0.5, 0.5, count) * half
    scale = 2.0 / (rng.uniform(0.2, 1.0, count) * half)  # strip width 20-100 % of the extent
    return centers, shapes, a * scale[:, None], b * scale


def run_strip(task: dict) -> list[dict]:
    from optbound import analytic, optimal

    rng = np.random.default_rng(task["seed"])
    E = random_ellipsoid(rng, DIM, 1e2)
    S = random_strip(rng, E, "narrow")
    one = per_call(lambda: analytic.intersect_strip(E, S, criterion="volume"))
    sdp = per_call(
        lambda: optimal.outer_ellipsoid(intersection=[E, S], objective="volume"), repeat=3
    )
    out = one_vs_sdp("strip update, one call", one, "SDP outer_ellipsoid, one solve", sdp)
    for count in task["batches"]:
        centers, shapes, a, b = batch_instances(rng, count, DIM)
        total = per_call(
            lambda c=centers, q=shapes, a=a, b=b: analytic.intersect_strip_batch(
                c, q, a, b, criterion="volume"
            ),
            repeat=3,
            min_time=0.0,
        )
        out.append(
            speed_record(
                NAME,
                f"strip updates, batch of {count:.0e} ({DIM}-D, volume)",
                total / count,
                unit="s/update",
                throughput=count / total,
                ratio=one / (total / count),
                ratio_label="speed-up vs one call",
            )
        )
    return out


def run_minkowski(task: dict) -> list[dict]:
    from optbound import analytic, optimal

    rng = np.random.default_rng(task["seed"])
    E1, E2 = random_ellipsoid(rng, DIM, 1e2), random_ellipsoid(rng, DIM, 1e2, scale=0.1)
    one = per_call(lambda: analytic.minkowski_sum(E1, E2, criterion="volume"))
    sdp = per_call(lambda: optimal.minkowski_outer(E1, E2, objective="volume"), repeat=3)
    return one_vs_sdp("Minkowski sum, one call", one, "SDP minkowski_outer, one solve", sdp)


def one_vs_sdp(analytic: str, one: float, solver: str, sdp: float) -> list[dict]:
    """Records of one analytic call and of the SDP solve it replaces, with their ratio."""
    return [
        speed_record(NAME, f"{analytic} ({DIM}-D, volume)", one),
        speed_record(
            NAME,
            f"{solver} ({DIM}-D, volume)",
            sdp,
            ratio=sdp / one,
            ratio_label="slower than one analytic call",
        ),
    ]


def run(task: dict) -> dict:
    runner = run_strip if task["what"] == "strip" else run_minkowski
    return {"records": runner(task)}


FAMILY = Family(
    name=NAME,
    title="Speed: analytic updates (latency, batch throughput) vs SDP",
    kind="speed",
    requires=(
        "optbound.analytic:intersect_strip",
        "optbound.analytic:intersect_strip_batch",
        "optbound.analytic:minkowski_sum",
        "optbound.optimal:outer_ellipsoid",
        "optbound.optimal:minkowski_outer",
    ),
    tasks=tasks,
    run=run,
    parallel=False,
)
