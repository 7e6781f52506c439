"""How strong is one LUVIA step? Its hull against the exact consistent set and a team fixpoint.

At sampled steps of a tracked run (one sweep per step, [GLH12, Algorithm 1]), the odometry
boxes of that step are the input, and for every robot:

- ``odometry``: the area of its box before contraction;
- ``luvia``: the area of the hull [GLH12, Algorithm 2] returns (``eps``, ``max_depth`` of the
  sweeps), every other robot's box as it is;
- ``exact_lo`` / ``exact_hi``: the hull of the exact consistent set S_i
  (:func:`optbound.localization.visibility.exact_paving`), bracketed by the hull of its inner
  boxes and of its inner and boundary boxes; no contraction from this step's data alone can
  beat it;
- ``set_hi``: the area of S_i's outer paving (below the hull when S_i is not a box).

Per step, the whole team is also contracted once (one sweep) and to a fixpoint (sweeps until
no box changes) from the same odometry boxes: ``sweep`` / ``fixpoint`` are the summed areas.
"""

from __future__ import annotations

import numpy as np

from optbound.localization.visibility import exact_paving, luvia, odometry, track
from optbound.scenarios import arena

FIXPOINT_PASSES = 50  # a cap never reached in our runs: sweeps stop when nothing changes


def _area(box) -> float:
    return float(np.prod(box[:, 1] - box[:, 0]))


def _hull_area(boxes: np.ndarray) -> float:
    if len(boxes) == 0:
        return 0.0
    return float(np.prod(boxes[:, :, 1].max(axis=0) - boxes[:, :, 0].min(axis=0)))


def study(params: dict, seed: int, at: list[int], paving_eps: float, split: int) -> list[dict]:
    """Rows for each sampled step in ``at`` (1-based step indices) and robot of one run.

    ``params``: ``robots``, ``obstacles``, ``steps``, ``eps``, ``max_depth``, ``layout``.
    """
    run = arena.simulate(
        params["robots"],
        params["obstacles"],
        params["steps"],
        seed,
        arena.Setting(layout=params["layout"]),
    )
    eps, depth = params["eps"], params["max_depth"]
    boxes = track(
        run.boxes0, run.distance, run.headings, run.heading_error, run.visibility, run.env, eps,
        max_depth=depth,
    )  # fmt: skip
    rows = []
    for step in at:
        k = step - 1
        cur = odometry(boxes[k], run.distance, run.headings[k], run.heading_error)
        one = track(
            boxes[k], run.distance, run.headings[k : k + 1], run.heading_error,
            run.visibility[k : k + 1], run.env, eps, max_depth=depth,
        )[1]  # fmt: skip
        fix = track(
            boxes[k], run.distance, run.headings[k : k + 1], run.heading_error,
            run.visibility[k : k + 1], run.env, eps, max_depth=depth, passes=FIXPOINT_PASSES,
        )[1]  # fmt: skip
        team = {
            "sweep": float(sum(_area(b) for b in one)),
            "fixpoint": float(sum(_area(b) for b in fix)),
        }
        for i in range(params["robots"]):
            y = run.visibility[k, i]
            hull = luvia(i, y, cur, run.env, eps, max_depth=depth)
            paving = exact_paving(i, y, cur, run.env, paving_eps, split=split)
            rows.append(
                {
                    "seed": seed,
                    "step": step,
                    "robot": i,
                    "odometry": _area(cur[i]),
                    "luvia": _area(hull),
                    "exact_lo": _hull_area(paving.inner),
                    "exact_hi": _hull_area(paving.outer()),
                    "set_hi": paving.volume_bounds()[1],
                    "truth_in_set": bool(
                        np.any(
                            np.all(
                                (paving.outer()[:, :, 0] <= run.truth[step, i])
                                & (run.truth[step, i] <= paving.outer()[:, :, 1]),
                                axis=1,
                            )
                        )
                    ),
                    **team,
                }
            )
    return rows


def summary(rows: list[dict]) -> dict:
    """Medians and extremes of the ratios over all (seed, step, robot) rows."""
    luvia = np.array([r["luvia"] for r in rows])
    lo = np.array([r["exact_lo"] for r in rows])
    hi = np.array([r["exact_hi"] for r in rows])
    odo = np.array([r["odometry"] for r in rows])
    steps = {(r["seed"], r["step"]): r for r in rows}
    gain = np.array([r["sweep"] / r["fixpoint"] for r in steps.values()])
    return {
        "n": len(rows),
        "n_steps": len(steps),
        # luvia / exact hull lies in [luvia / exact_hi, luvia / exact_lo]
        "luvia_over_exact_max_lower": float(np.max(luvia / hi)),
        "luvia_over_exact_median_lower": float(np.median(luvia / hi)),
        "luvia_over_exact_median_upper": float(np.median(luvia / np.maximum(lo, 1e-300))),
        "luvia_within_exact_bracket": int(np.count_nonzero(luvia <= hi)),
        "contracted_luvia": int(np.count_nonzero(luvia < odo)),
        "contracted_exact": int(np.count_nonzero(hi < odo)),
        "hull_over_set_median": float(np.median(lo / np.array([r["set_hi"] for r in rows]))),
        "sweep_over_fixpoint_median": float(np.median(gain)),
        "sweep_over_fixpoint_max": float(np.max(gain)),
        "truth_lost": int(sum(not r["truth_in_set"] for r in rows)),
    }


__all__ = ["FIXPOINT_PASSES", "study", "summary"]
