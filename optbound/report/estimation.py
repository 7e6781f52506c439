"""The report's section and headline rows for the observers of linear systems
(:mod:`optbound.bench.linear_estimation`): one table per system, a row per method."""

from __future__ import annotations

from statistics import median

from optbound.report.summary import group
from optbound.report.tables import fmt_ratio, markdown_table

INTRO = (
    "Every observer of `optbound.estimation.METHODS` run over each system; its set at step k "
    "measured against the exact set X_k. 2-D with box noise: the upper end of the certified "
    "bracket of area(set) / area(X_k) (X_k the exact rational polygon), area(set) / area(MVEE "
    "of X_k), and the steps at which containment of X_k was proven in rational arithmetic "
    "(at its vertices, for every kind of set). Otherwise the size is the interval hull: the "
    "mean over states of width(set's hull) / width(X_k's hull) (X_k's hull by certified LPs; "
    "box noise), or, without an exact reference (ellipsoidal noise, the tank), / the "
    "smallest width any method reached. ms/step: the whole run's wall time per step. Where "
    "given (the tank), '/ one-step optimal': the ellipsoidal observer's volume or trace over "
    "that of the certified optimal ellipsoid of the same step (S-procedure SDP of its own "
    "prediction ∩ the measurement strips: the strip fusion's loss in that step), at sampled "
    "steps only (named in the header: one SDP takes seconds there); s/SDP: its median time."
)


def _value(rec: dict) -> float | None:
    """The record's size ratio: the bracket's upper end, else its lower end, else the ratio
    to the best method."""
    for key in ("ratio_hi", "ratio_lo", "hull_ratio"):
        if rec.get(key) is not None:
            return rec[key]
    return None


def _measure(rec: dict) -> str:
    if rec.get("measure") == "area":
        return "area / exact area"
    if rec.get("hull_ratio") is not None:
        return "hull width / best method's hull width"
    return "hull width / exact hull width (lower end)"


def _steps(ks: list[int]) -> str:
    """``k = 10, 20, ..., 230`` style list of the sampled steps."""
    return ", ".join(map(str, ks)) if len(ks) <= 3 else f"{ks[0]}, {ks[1]}, …, {ks[-1]}"


def _one_step_cells(by_k: dict, sampled: list[int]) -> list[str]:
    """The ratio to the one-step optimal ellipsoid at the last sampled step and the median
    SDP time of a method, with the number of SDPs that could not be certified (dashes for a
    method without the SDP)."""
    seconds = [by_k[k]["sdp_seconds"] for k in sampled if by_k[k].get("sdp_seconds") is not None]
    if not seconds:
        return ["–", "–"]
    failed = sum(by_k[k].get("sdp_error") is not None for k in sampled)
    note = f" ({failed} of {len(sampled)} not certified)" if failed else ""
    return [fmt_ratio(by_k[sampled[-1]]["one_step_ratio"]), f"{median(seconds):.3g}{note}"]


def estimation_section(records: list[dict]) -> list[str]:
    """Render the report's section on the observers of linear systems.

    Parameters
    ----------
    records : list of dict
        The records of the ``estimation`` family, one per system, method and step.

    Returns
    -------
    list of str
        Markdown parts: :data:`INTRO`, then per system a title and a table: method, the
        ratio at three steps, the MVEE ratio and proven containments (2-D), ms per step.
    """
    parts = [INTRO]
    for (system,), recs in group(records, ("system",)).items():
        done = [r for r in recs if r["error"] is None]
        ks = sorted({r["k"] for r in done})
        shown = sorted({ks[0], ks[len(ks) // 2], ks[-1]}) if ks else []
        area = any(r.get("measure") == "area" for r in done)
        headers = ["method", *[f"k={k}" for k in shown]]
        headers += [f"/ MVEE (k={ks[-1]})", "proven steps"] if area else []
        sampled = sorted({r["k"] for r in done if r.get("sdp_seconds") is not None})
        if sampled:
            headers += [f"/ one-step optimal (k={sampled[-1]}; SDP at {_steps(sampled)})", "s/SDP"]
        headers.append("ms/step")
        rows = []
        for (method,), mrecs in group(recs, ("method",)).items():
            if mrecs[0]["error"] is not None:
                rows.append([f"`{method}`", f"refused: {mrecs[0]['error']}".replace("|", "\\|")])
                continue
            by_k = {r["k"]: r for r in mrecs}
            row = [f"`{method}`", *[fmt_ratio(_value(by_k[k])) for k in shown]]
            if area:
                proven = sum(r["contained"] is True for r in mrecs)
                undecided = sum(r["contained"] is None for r in mrecs)
                verdict = f"{proven}/{len(mrecs)}" + (" (undecided)" if undecided else "")
                row += [fmt_ratio(by_k[ks[-1]]["mvee_ratio_hi"]), verdict]
            if sampled:
                row += _one_step_cells(by_k, sampled)
            rows.append([*row, f"{mrecs[0]['ms_per_step']:.3g}"])
        width = len(headers)
        rows = [r + [""] * (width - len(r)) for r in rows]
        n, steps = recs[0]["dim"], recs[0]["steps"]
        measure = _measure(done[0]) if done else "–"
        parts += [
            f"**{system}** (n = {n}, {steps} steps; {measure}):",
            markdown_table(headers, rows),
        ]
    return parts


def estimation_rows(records: list[dict]) -> list[tuple[str, str]]:
    """Summarise the observers for the headline.

    Parameters
    ----------
    records : list of dict
        The records of the ``estimation`` family.

    Returns
    -------
    list of tuple of (str, str)
        One ``(measure, value)`` row per 2-D system with an exact area: each method's ratio
        at the last step.
    """
    rows = []
    for (system,), recs in group(records, ("system",)).items():
        done = [r for r in recs if r["error"] is None and r.get("measure") == "area"]
        if not done:
            continue
        last = max(r["k"] for r in done)
        cells = [f"{r['method']} {fmt_ratio(_value(r))}" for r in done if r["k"] == last]
        rows.append((f"linear_estimation · area / exact at k={last}, {system}", ", ".join(cells)))
    return rows
