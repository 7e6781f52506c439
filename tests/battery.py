"""Known-answer battery for the analytic updates and the SDP references.

In the style of cvxpy's ``solver_test_helpers``: each function builds a problem object that
knows its sets, its objective and the answer both routes must reach, so one test can run it
through ``optbound.analytic`` *and* ``optbound.optimal`` and compare. The known answers come
from closed-form results (the papers' equations and the anchors below):

- ellipsoid ∩ strip with both planes cutting: the [HS96, eq. (26)] member is the minimum-volume
  outer ellipsoid, and the S-procedure SDP reaches it; the same for the projection [HS96,
  eq. (27)] and for the trace (for two quadratics every S-procedure certificate is a member of
  the [HS96, eq. (24)] family, so the family's best member is the SDP optimum for any size);
- Minkowski sum of two ellipsoids: the best Schweppe member [HS96, eq. (14)] is the SDP optimum
  for volume and for trace (Durieu, Walter & Polyak 2001);
- partial case (one plane misses): with the raw strip the SDP only reaches the raw family's
  optimum; clipped, both reach a much smaller ellipsoid (27 % less volume on the 3-D case).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from optbound import Ellipsoid, Strip, compare

# The routes agree to this relative size difference (SDP tolerance ~1e-8, certified inflation).
AGREEMENT_RTOL = 1e-5
METRICS = {
    "volume": "volume_ratio",
    "trace": "trace_ratio",
    "projection": "projection_volume_ratio",
}


@dataclass(frozen=True)
class KnownAnswer:
    """One instance: sets, objective, and both routes to its optimal outer ellipsoid.

    ``sets`` are intersected (``kind="intersection"``) or summed (``kind="minkowski"``).
    ``analytic`` returns the analytic route's ellipsoid; ``expected`` (if given) is a
    closed-form value of the objective.
    """

    name: str
    kind: str
    sets: tuple
    objective: str
    analytic: Callable[[], Ellipsoid]
    dims: tuple[int, ...] | None = None
    clip: bool = True
    expected: float | None = None
    rtol: float = AGREEMENT_RTOL

    def sdp(self, lower_bound: bool = False):
        """The optimal route: a certified ``OuterResult`` (lower bound: intersections only)."""
        from optbound import optimal

        if self.kind == "minkowski":
            return optimal.minkowski_outer(*self.sets, objective=self.objective)
        return optimal.outer_ellipsoid(
            list(self.sets),
            objective=self.objective,
            dims=self.dims,
            clip=self.clip,
            lower_bound=lower_bound,
        )

    def ratio(self, A, B) -> float:
        """Size of A over size of B in this instance's objective."""
        metric = getattr(compare, METRICS[self.objective])
        return metric(A, B, self.dims) if self.objective == "projection" else metric(A, B)

    def size(self, E: Ellipsoid) -> float:
        """The objective's value on E (volume, trace or projected volume)."""
        from optbound.optimal.result import objective_value

        return objective_value(E, self.objective, self.dims)


def _random_ellipsoid(rng: np.random.Generator, n: int, cond: float | None = None) -> Ellipsoid:
    """Random rotation; squared semi-axes in [0.25, 4], or log-spaced over ``cond``."""
    Q, _ = np.linalg.qr(rng.standard_normal((n, n)))
    axes2 = rng.uniform(0.5, 2.0, n) ** 2 if cond is None else np.logspace(0, np.log10(cond), n)
    return Ellipsoid(rng.standard_normal(n), Q @ np.diag(axes2) @ Q.T)


def _cutting_strip(rng: np.random.Generator, E: Ellipsoid) -> Strip:
    """A strip over 20 % of E's extent along a random normal, off-centre by 5 %: both planes
    cut E and the [HS96, eq. (26)] root is positive up to n = 6."""
    a = rng.standard_normal(E.dim)
    lo, hi = E.extent(a)
    mid, half = 0.5 * (lo + hi), 0.5 * (hi - lo)
    return Strip.from_bounds(a, mid - 0.1 * half, mid + 0.3 * half)


def strip_both_planes(
    n: int, objective: str = "volume", seed: int = 0, cond: float | None = None
) -> KnownAnswer:
    """Ellipsoid ∩ strip, both planes cutting: [HS96, eq. (26)] (or trace) = SDP optimum.

    ``cond``: condition number of the ellipsoid's shape (default: moderate, <= 16)."""
    from optbound import analytic

    rng = np.random.default_rng(1000 * n + seed)
    E = _random_ellipsoid(rng, n, cond)
    S = _cutting_strip(rng, E)
    suffix = "" if cond is None else f"_cond{cond:.0e}"
    return KnownAnswer(
        name=f"strip_both_planes_{objective}_{n}d{suffix}",
        kind="intersection",
        sets=(E, S),
        objective=objective,
        analytic=lambda: analytic.intersect_strip(E, S, criterion=objective).ellipsoid,
    )


def strip_projection_3d(seed: int = 0, cond: float | None = None) -> KnownAnswer:
    """3-D ellipsoid ∩ strip, projection on (0, 1): [HS96, eq. (27)] = projection SDP."""
    from optbound import analytic

    rng = np.random.default_rng(3000 + seed)
    E = _random_ellipsoid(rng, 3, cond)
    S = _cutting_strip(rng, E)
    dims = (0, 1)
    return KnownAnswer(
        name="strip_projection_3d" + ("" if cond is None else f"_cond{cond:.0e}"),
        kind="intersection",
        sets=(E, S),
        objective="projection",
        dims=dims,
        analytic=lambda: (
            analytic.intersect_strip(E, S, criterion="projection", dims=dims).ellipsoid
        ),
    )


def unit_disc_cut() -> KnownAnswer:
    """Unit disc ∩ |x1| <= 0.5: closed form diag(0.5, 1.5) (Known facts), volume pi sqrt(0.75)."""
    from optbound import analytic

    E = Ellipsoid([0.0, 0.0], np.eye(2))
    S = Strip.from_bounds([1.0, 0.0], -0.5, 0.5)
    return KnownAnswer(
        name="unit_disc_cut",
        kind="intersection",
        sets=(E, S),
        objective="volume",
        analytic=lambda: analytic.intersect_strip(E, S).ellipsoid,
        expected=float(np.pi * np.sqrt(0.75)),
    )


def minkowski_pair(objective: str) -> KnownAnswer:
    """C1 = diag(4, 1), C2 = I (Known facts): volume pi sqrt(9.2720018727 * 4.1075011704),
    trace 7 + 2 sqrt(10); analytic best Schweppe member = SDP optimum."""
    from optbound import analytic

    E1 = Ellipsoid([0.0, 0.0], np.diag([4.0, 1.0]))
    E2 = Ellipsoid([1.0, -2.0], np.eye(2))
    expected = {
        "volume": float(np.pi * np.sqrt(9.2720018727 * 4.1075011704)),
        "trace": float(7.0 + 2.0 * np.sqrt(10.0)),
    }[objective]
    return KnownAnswer(
        name=f"minkowski_pair_{objective}",
        kind="minkowski",
        sets=(E1, E2),
        objective=objective,
        analytic=lambda: analytic.minkowski_sum(E1, E2, criterion=objective).ellipsoid,
        expected=expected,
    )


def minkowski_random(
    n: int, objective: str, seed: int = 0, cond: float | None = None
) -> KnownAnswer:
    """Two random summands in R^n: analytic best member = SDP optimum."""
    from optbound import analytic

    rng = np.random.default_rng(5000 + 10 * n + seed)
    E1, E2 = _random_ellipsoid(rng, n, cond), _random_ellipsoid(rng, n, cond)
    return KnownAnswer(
        name=f"minkowski_random_{objective}_{n}d" + ("" if cond is None else f"_cond{cond:.0e}"),
        kind="minkowski",
        sets=(E1, E2),
        objective=objective,
        analytic=lambda: analytic.minkowski_sum(E1, E2, criterion=objective).ellipsoid,
    )


def partial_case(clip: bool) -> KnownAnswer:
    """Unit ball in R^3 ∩ {0.3 <= x1 <= 2.3}: the far plane misses the ball (HS96 "partial").

    ``clip=False``: the S-procedure with the raw strip equals the raw [HS96, eq. (24)] family
    optimum. ``clip=True``: both routes clip the strip to [0.3, 1] first and agree again, on an
    ellipsoid with about 27 % less volume.
    """
    from optbound import analytic

    E = Ellipsoid(np.zeros(3), np.eye(3))
    S = Strip.from_bounds([1.0, 0.0, 0.0], 0.3, 2.3)
    return KnownAnswer(
        name=f"partial_{'clipped' if clip else 'raw'}",
        kind="intersection",
        sets=(E, S),
        objective="volume",
        clip=clip,
        analytic=lambda: analytic.intersect_strip(E, S, clip=clip).ellipsoid,
    )


def agreeing() -> list[KnownAnswer]:
    """Every instance on which the two routes must agree to ``AGREEMENT_RTOL``."""
    return [
        *(strip_both_planes(n, "volume") for n in range(2, 7)),
        *(strip_both_planes(n, "trace") for n in (2, 3, 4)),
        strip_projection_3d(),
        unit_disc_cut(),
        minkowski_pair("volume"),
        minkowski_pair("trace"),
        *(minkowski_random(n, obj) for n in (2, 3, 4) for obj in ("volume", "trace")),
        partial_case(clip=False),
        partial_case(clip=True),
        # Ill-conditioned shapes (condition number 1e6), where a naive formulation fails.
        *(strip_both_planes(3, obj, cond=1e6) for obj in ("volume", "trace")),
        strip_projection_3d(cond=1e6),
        *(minkowski_random(3, obj, cond=1e6) for obj in ("volume", "trace")),
    ]


def agreement_rows(cases: list[KnownAnswer] | None = None) -> list[dict]:
    """Per case: analytic/SDP size ratio - 1, SDP inflation - 1, solve time (first solve of a
    shape includes cvxpy's compilation) and, for intersections, SDP objective / lower bound."""
    rows = []
    for case in agreeing() if cases is None else cases:
        result = case.sdp(lower_bound=case.kind == "intersection")
        gap = None if result.lower_bound is None else result.objective / result.lower_bound
        rows.append(
            {
                "name": case.name,
                "objective": case.objective,
                "analytic_over_sdp_minus_1": case.ratio(case.analytic(), result.ellipsoid) - 1.0,
                "inflation_minus_1": result.inflation - 1.0,
                "solve_ms": 1e3 * result.solve_time,
                "sdp_over_lower_bound": gap,
            }
        )
    return rows


if __name__ == "__main__":
    print(
        f"{'case':38s} {'analytic/SDP - 1':>17s} {'inflation - 1':>14s} {'solve ms':>9s}"
        f" {'SDP/lower bound':>16s}"
    )
    for row in agreement_rows():
        gap = row["sdp_over_lower_bound"]
        print(
            f"{row['name']:38s} {row['analytic_over_sdp_minus_1']:17.2e} "
            f"{row['inflation_minus_1']:14.2e} {row['solve_ms']:9.2f}"
            f" {'-' if gap is None else f'{gap:.4f}':>16s}"
        )
