"""LJMW97 Sect. 4: localization in a triangular room from four sonars, two components Q1, Q2.

[LJMW97, Sect. 4]: vehicle at q* = (−2 m, 3 m, 0°), four sonars, 2 % relative range
accuracy, ±12° cones, X(0) = [−10, 10]² × [−180°, 180°], ε = 0.04 m; the solution set has two
components, Q1 ⊂ [−2.10, −1.87] × [2.92, 3.11] × [−5.73°, 5.73°] (containing q*) and
Q2 ⊂ [−3.09, −2.88] × [3.63, 3.81] × [83.08°, 91.67°], with association hypotheses
h1 = {(T1, S1) (T2, S2) (T3, S2) (T4, S3)} and h2 = {(T1, S2) (T2, S3) (T3, S3) (T4, S1)}.

**The room and the sonar placement are ours**: Fig. 4(a) is lost, so
:data:`optbound.scenarios.rooms.TRIANGLE` is a triangle we designed (the first and only
one tried) with q* inside, and the four sonars sit on a 0.2 m belt pointing forward, left,
backward and right. Segment and sonar numbers therefore do not correspond to the paper's;
only the kind of result (number of components, sizes, hypotheses) is comparable. The readings
are the noise-free ranges f(q*) (the paper gives no noise values), so q* is in the set.

Two runs: the paper's problem as stated, and the same with a prior [KJWM00, Sect. 2.2] that
the robot's centre is at least 0.2 m (its belt radius) inside the room: without it, poses
whose sonar sits on a wall give unresolvable boundary boxes (the range jumps from ~0 to the
far wall across a wall), which appear as extra small components.
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
from matplotlib.patches import Wedge

from optbound.localization.geometry import to_world
from optbound.localization.sonar import SonarPaving, clearance_test, localize, simulate_ranges
from optbound.papers_repro._common import claim_table, finish_axes, pyplot, run_cli, save_figure
from optbound.report.tables import markdown_table
from optbound.scenarios import rooms

PAPER = "LJMW97"
WORLD = rooms.TRIANGLE
SONARS = rooms.triangle_sonars()
TRUTH = np.array(rooms.TRIANGLE_POSE)
X0 = [[-10.0, 10.0], [-10.0, 10.0], [-np.pi, np.pi]]
EPS = 0.04
CLEARANCE = 0.2
#: The paper's boxes [LJMW97, Sect. 4] (m, m, deg).
PAPER_Q1 = [[-2.10, -1.87], [2.92, 3.11], [-5.73, 5.73]]
PAPER_Q2 = [[-3.09, -2.88], [3.63, 3.81], [83.08, 91.67]]
PAPER_H1 = "{(T1, S1) (T2, S2) (T3, S2) (T4, S3)}"
PAPER_H2 = "{(T1, S2) (T2, S3) (T3, S3) (T4, S1)}"


def readings() -> np.ndarray:
    """The four noise-free ranges f(q*)."""
    return simulate_ranges(WORLD, SONARS, TRUTH)


def solve(prior: bool, repeats: int = 1) -> tuple[SonarPaving, float]:
    """The paving at eps = 0.04 and the median wall time of ``repeats`` runs (after a warm-up)."""
    test = clearance_test(WORLD, CLEARANCE) if prior else None
    d = readings()
    paving = localize(WORLD, SONARS, d, X0, EPS, prior=test)
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        localize(WORLD, SONARS, d, X0, EPS, prior=test)
        times.append(time.perf_counter() - start)
    return paving, float(np.median(times))


def _hypothesis_text(h) -> str:
    pairs = []
    for i, segs in enumerate(h, start=1):
        seen = "/".join(f"S{j + 1}" for j in segs) if segs else "none"
        pairs.append(f"(T{i}, {seen})")
    return "{" + " ".join(pairs) + "}"


def _box_text(lo, hi) -> str:
    deg = np.rad2deg([lo[2], hi[2]])
    return (
        f"[{lo[0]:.2f}, {hi[0]:.2f}] × [{lo[1]:.2f}, {hi[1]:.2f}] × [{deg[0]:.2f}°, {deg[1]:.2f}°]"
    )


def _paper_box_text(box) -> str:
    (a, b), (c, d), (e, f) = box
    return f"[{a:.2f}, {b:.2f}] × [{c:.2f}, {d:.2f}] × [{e:.2f}°, {f:.2f}°]"


def _rows(paving: SonarPaving) -> list[dict]:
    rows = []
    for k, comp in enumerate(paving.components(), start=1):
        hull = comp.hull()
        rows.append(
            {
                "component": k,
                "lo": hull.lo,
                "hi": hull.hi,
                "n_inner": len(comp.inner),
                "n_boundary": len(comp.boundary),
                "volume": comp.volume_bounds()[1],
                "hypothesis": comp.hypothesis,
                "contains_truth": comp.contains(TRUTH),
            }
        )
    return rows


def _nearest_to(rows, paper_box) -> dict:
    """Our component whose hull centre is nearest (x, y in m, theta in rad) to a paper box."""
    p = np.array(paper_box, float)
    centre = np.r_[p[:2].mean(axis=1), np.deg2rad(p[2].mean())]
    return min(rows, key=lambda r: np.linalg.norm(0.5 * (r["lo"] + r["hi"]) - centre))


def _draw_room(ax) -> None:
    for j, (a, b) in enumerate(WORLD):
        ax.plot([a[0], b[0]], [a[1], b[1]], "k-", lw=1.5)
        mid = 0.5 * (a + b)
        normal = np.array([-(b - a)[1], (b - a)[0]]) / np.linalg.norm(b - a)
        ax.annotate(f"S{j + 1}", mid - 0.5 * normal, ha="center", fontsize=9)


def _draw_pose(ax, pose, d, color) -> None:
    """The robot at ``pose`` with its four cones drawn to the measured ranges."""
    for i, s in enumerate(SONARS):
        apex = np.array(to_world(tuple(pose), s.position), float)
        heading = np.rad2deg(pose[2] + s.orientation)
        half = np.rad2deg(s.half_aperture)
        ax.add_patch(
            Wedge(apex, d[i], heading - half, heading + half, color=color, alpha=0.25, lw=0)
        )
        ax.annotate(f"T{i + 1}", apex, fontsize=7, color=color)
    ax.plot(*pose[:2], "o", color=color, ms=4)


def _figures(paving: SonarPaving, rows, out_dir: Path) -> list[Path]:
    plt = pyplot()
    colors = ["#d62728", "#1f77b4", "#2ca02c", "#9467bd"]
    figs = []
    # Fig. 4(a)-(c): the room and the set projected on (x, y) and (x, theta).
    fig, axes = plt.subplots(1, 3, figsize=(15, 5))
    _draw_room(axes[0])
    _draw_pose(axes[0], TRUTH, readings(), "k")
    finish_axes(axes[0], "our triangular room (Fig. 4(a) lost), q* and the 4 cones")
    for ax, dims, title in ((axes[1], (0, 1), "(x, y)"), (axes[2], (0, 2), "(x, θ)")):
        for r, comp in zip(rows[:4], paving.components()[:4], strict=False):
            lo, hi = r["lo"][list(dims)], r["hi"][list(dims)]
            comp.plot(ax=ax, dims=dims)
            ax.add_patch(
                plt.Rectangle(lo, *(hi - lo), fill=False, ec=colors[r["component"] - 1], lw=1.0)
            )
            ax.annotate(f"Q{r['component']}", hi, color=colors[r["component"] - 1])
        lo = np.min([r["lo"][list(dims)] for r in rows[:4]], axis=0)
        hi = np.max([r["hi"][list(dims)] for r in rows[:4]], axis=0)
        pad = 0.1 * (hi - lo) + 0.05
        ax.set_xlim(lo[0] - pad[0], hi[0] + pad[0])
        ax.set_ylim(lo[1] - pad[1], hi[1] + pad[1])
        ax.plot(TRUTH[dims[0]], TRUTH[dims[1]], "k+", ms=10)
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]" if dims[1] == 1 else "θ [rad]")
        ax.set_title(f"Figs. 4(b)-(c): components projected on {title}", fontsize=9)
    figs.append(save_figure(fig, out_dir, "ljmw97_fig4_components.png"))
    # Fig. 5: the association hypothesis of the two largest components.
    fig, axes = plt.subplots(1, 2, figsize=(11, 5))
    for ax, r in zip(axes, rows[:2], strict=False):
        _draw_room(ax)
        _draw_pose(ax, 0.5 * (r["lo"] + r["hi"]), readings(), colors[r["component"] - 1])
        finish_axes(ax, f"Q{r['component']}: {_hypothesis_text(r['hypothesis'])}")
    figs.append(save_figure(fig, out_dir, "ljmw97_fig5_hypotheses.png"))
    return figs


def main(out_dir: Path | str, quick: bool = False) -> dict:
    """Solve the triangle problem without and with the clearance prior; tables and figures.

    ``quick`` times one run instead of the median of five (the paving itself is the same).
    """
    out_dir = Path(out_dir)
    repeats = 1 if quick else 5
    plain, seconds = solve(prior=False, repeats=repeats)
    with_prior, seconds_prior = solve(prior=True, repeats=repeats)
    rows, rows_prior = _rows(plain), _rows(with_prior)
    q1 = next(r for r in rows if r["contains_truth"])
    q2 = _nearest_to([r for r in rows if r is not q1], PAPER_Q2)
    claims = [
        (
            "number of components",
            "2",
            f"{len(rows)} as stated; {len(rows_prior)} with the {CLEARANCE} m clearance prior",
        ),
        ("Q1 (contains q*)", _paper_box_text(PAPER_Q1), _box_text(q1["lo"], q1["hi"])),
        ("Q1 hypothesis", PAPER_H1, _hypothesis_text(q1["hypothesis"])),
        (
            "Q2 (our component nearest to it)",
            _paper_box_text(PAPER_Q2),
            _box_text(q2["lo"], q2["hi"]),
        ),
        ("Q2 hypothesis", PAPER_H2, _hypothesis_text(q2["hypothesis"])),
        ("q* inside the solution set", "yes", "yes" if q1["contains_truth"] else "NO"),
        (
            "paving time at ε = 0.04 (median)",
            "—",
            f"{seconds:.3f} s ({seconds_prior:.3f} s with prior)",
        ),
    ]

    def table(rs):
        return markdown_table(
            ("comp.", "hull box", "inner", "boundary", "outer vol.", "hypothesis", "q*"),
            [
                (
                    f"Q{r['component']}",
                    _box_text(r["lo"], r["hi"]),
                    r["n_inner"],
                    r["n_boundary"],
                    f"{r['volume']:.2e}",
                    _hypothesis_text(r["hypothesis"]),
                    "yes" if r["contains_truth"] else "",
                )
                for r in rs
            ],
        )

    markdown = "\n\n".join(
        [
            "## LJMW97 Sect. 4: triangular room, four sonars",
            "Room and sonar placement are **our design** (the paper's Fig. 4(a) is lost); segment "
            "and sonar numbers do not match the paper's. Readings: noise-free f(q*).",
            claim_table(claims),
            f"All components, problem as stated (X0 = [-10, 10]² × [-180°, 180°], ε = {EPS}):",
            table(rows),
            f"With the prior 'centre at least {CLEARANCE} m inside the room':",
            table(rows_prior),
        ]
    )
    return {
        "components": rows,
        "components_prior": rows_prior,
        "seconds": seconds,
        "seconds_prior": seconds_prior,
        "figures": _figures(with_prior, rows_prior, out_dir),
        "markdown": markdown,
    }


if __name__ == "__main__":
    run_cli(main, __doc__.splitlines()[0])
