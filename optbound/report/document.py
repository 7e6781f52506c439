"""report.md: the tables, figures and notes of one run, written from the results dict alone."""

from __future__ import annotations

from pathlib import Path

from optbound.report import figures
from optbound.report.drawing import Drawings
from optbound.report.estimation import estimation_section
from optbound.report.estimators import estimators_section
from optbound.report.headline import HEADERS, headline_rows
from optbound.report.results import write_csv
from optbound.report.summary import (
    BELOW_ONE_TOL,
    DEGENERATE_GAP,
    group,
    ratio_stats,
    without_degenerate_lower,
    worst_label,
)
from optbound.report.tables import fmt_factor, fmt_ratio, fmt_seconds, markdown_table

REPORT_FILE = "report.md"
MAX_ERRORS_SHOWN = 5

REFERENCES_NOTE = """\
Every ratio is size(analytic bound) / size(SDP reference) on the same instance, with the size
measure the analytic criterion minimises (volume for `volume` and `robust`, trace for `trace`,
volume of the projection for `projection`). An analytic bound is an outer bound, so a ratio
>= 1 is expected wherever the reference is the true optimum:

- one ellipsoid ∩ one strip, strip clipped to the ellipsoid: the S-procedure SDP is tight
  (volume and projection), so the ratio is the analytic method's exact loss;
- Minkowski sum of two ellipsoids: the best κ-family member is the true minimum (volume and
  trace), so the ratio measures only how well κ was found;
- **several strips at once** (the recursive family): the S-procedure SDP is only an **upper
  bound** on the smallest outer ellipsoid, so a ratio below 1 is possible there and is not a
  violation. The second table divides by a lower bound on the optimum instead (the
  minimum-volume ellipsoid of points sampled in the set), which bounds the true loss from above;
- the projection optimum is itself the best ellipse of the S-procedure family, which can be
  a few percent above the smallest ellipse containing the projected set.

Where the reference is the true optimum, a ratio below 1 can only come from the reference's
own inaccuracy: an SDP answer is certified in float64 and inflated until it contains the set,
and conic solvers lose accuracy at large condition numbers. "below 1" counts ratios under
1 − 1e-6 and "lowest instance" shows where the worst one is; "SDP refused" counts instances
whose SDP the reference solver refused as inaccurate (no ratio is computed for them). That the
analytic bound itself is an outer bound is checked separately by sampling the exact set
("sampled points outside")."""


BELOW_ONE_NOTE = (
    f'"below 1" counts ratios under 1 − {BELOW_ONE_TOL:g}, which the headline\'s ratios '
    "(rounded to 7 digits) do not show. Where the reference is the true optimum they come from "
    "the reference's own inaccuracy (an SDP answer is accurate to about 1e-6 and is inflated to "
    'be certified), not from a bound smaller than the optimum; see "About the references".'
)


def write_report(results: dict, out_dir: str | Path, jobs: int = 1) -> Path:
    """Write report.md, the PNG figures and the CSV files of ``results`` into ``out_dir``.

    Only the results dict is read, so ``optbound report DIR`` can rebuild everything from
    ``DIR/results.json``.

    Parameters
    ----------
    results : dict
        The results dict that ``optbound bench`` saves (:func:`~optbound.report.load_results`).
    out_dir : str or Path
        The output directory, created if needed.
    jobs : int
        Processes to draw the figures in (:class:`~optbound.report.drawing.Drawings`); the
        files are the same for any value.

    Returns
    -------
    Path
        The path of report.md.

    Examples
    --------
    >>> import tempfile
    >>> from optbound.report import write_report
    >>> meta = {"suite": "tiny", "seed": 0, "jobs": 1, "started": "2026-01-01T00:00",
    ...         "wall_time_s": 1.0, "optbound": "0.1", "python": "3.12", "numpy": "2.1",
    ...         "machine": "Linux x86_64"}
    >>> with tempfile.TemporaryDirectory() as out:
    ...     path = write_report({"schema": 1, "meta": meta, "families": {}}, out)
    ...     path.name, path.read_text().splitlines()[0]
    ('report.md', '# optbound benchmark report')
    """
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    csv_files = write_csv(results, out)
    parts = [
        _header(results, [p.name for p in csv_files]),
        "## Headline",
        markdown_table(HEADERS, headline_rows(results)),
    ]
    pictures = []
    drawings = Drawings()
    for name, fam in results["families"].items():
        parts.append(f"## {fam['title']}")
        parts.extend(_family_section(name, fam, out, drawings))
        pictures.extend(fam["figures"])
    if pictures:
        # A panel per picture, each shading its exact set: the costliest figure of a report.
        cost = 0.2 * len(pictures)
        drawings.add(figures.instance_pictures, out / "instances_2d.png", cost, figures=pictures)
        parts += [
            "## Pictures of 2-D instances",
            "The exact set is shaded grey (prior ellipse ∩ strips, on a fine grid; or the "
            "exact Minkowski sum, from the summands' support points); each bound is drawn over "
            "it, the SDP optimum dashed.",
            "![2-D instances](instances_2d.png)",
        ]
    parts += estimators_section(results)
    parts += ["## About the references", REFERENCES_NOTE]
    drawings.draw(jobs)
    path = out / REPORT_FILE
    path.write_text("\n\n".join(parts) + "\n")
    return path


def _header(results: dict, csv_files: list[str]) -> str:
    """Title, run facts, and how to repeat the run (the command recorded in ``meta``)."""
    m = results["meta"]
    # Reports written before meta recorded the command were all bench runs.
    command = m.get("command", f"optbound bench --suite {m['suite']} --seed {m['seed']}")
    title = "paper reproductions" if command.startswith("optbound repro") else "benchmark report"
    raw = f" Raw records: {', '.join(f'`{name}`' for name in csv_files)}." if csv_files else ""
    return (
        f"# optbound {title}\n\n"
        f"Suite **{m['suite']}**, seed {m['seed']}, {m['jobs']} job(s), started {m['started']}, "
        f"{_wall_time(m)} (optbound {m['optbound']}, Python {m['python']}, "
        f"numpy {m['numpy']}, {m['machine']}).\n\n"
        f"Re-run with `{command}`; rebuild this report from `results.json` with "
        "`optbound report DIR`. Every instance is rebuilt by its family's `instance(task)` from "
        f"the seed shown.{raw}"
    )


def _wall_time(meta: dict) -> str:
    """What the run cost: the tasks alone, and (if run by the command) from its start; for a
    resumed run, of the resuming command only."""
    tasks = f"{meta['wall_time_s']:.1f} s running the tasks"
    resumed = meta.get("resumed_tasks", 0)
    if resumed:
        tasks += f" not taken from the interrupted run it resumed ({resumed} task(s) were)"
    if "since_start_s" not in meta:
        return f"wall time {tasks}"
    return (
        f"wall time {meta['since_start_s']:.1f} s from the command's start to the end of its "
        f"tasks ({tasks}; the rest is start-up: imports, compiling, setting up the workers)"
    )


def _family_section(name: str, fam: dict, out: Path, drawings: Drawings) -> list[str]:
    if fam["status"] != "ok":
        return [f"Skipped: {fam['reason']}."]
    parts = []
    if fam["records"]:
        if fam["kind"] == "tightness":
            parts += _tightness_section(name, fam["records"], out, drawings)
        elif fam["kind"] == "recursive":
            parts += _recursive_section(fam["records"], out, drawings)
        elif fam["kind"] == "papers":
            parts += papers_section(fam["records"])
        elif fam["kind"] == "estimation":
            parts += estimation_section(fam["records"])
        else:
            parts.append(_speed_table(fam["records"]))
    elif not fam["notes"] and not fam["errors"]:
        parts.append("No task in this suite.")
    if fam["kind"] != "papers":  # the papers' records place their own figures
        parts += [f"![{Path(name).stem}]({name})" for name in sorted(fam.get("attachments", []))]
    parts += [f"> {note}" for note in fam["notes"]]
    if fam["errors"]:
        parts.append(_errors(fam["errors"]))
    if fam.get("warnings"):
        parts.append(_warnings(fam["warnings"]))
    return parts


def _tightness_section(name: str, records: list[dict], out: Path, drawings: Drawings) -> list[str]:
    checked = any("outside" in rec for rec in records)
    rows = []
    for (criterion, reference), recs in group(records, ("criterion", "reference")).items():
        s = ratio_stats(recs)
        if not s["n"]:
            continue
        matched = "" if recs[0].get("matched", True) else " (different measure)"
        row = [
            f"`{criterion}`",
            reference + matched,
            recs[0]["metric"],
            s["n"],
            fmt_ratio(s["min"]),
            fmt_ratio(s["median"]),
            fmt_ratio(s["max"]),
            worst_label(s["worst"]),
            s["below_one"],
            worst_label(s["lowest"]) if s["below_one"] else "",
            s["missing"],
        ]
        if checked:
            row.append(sum(rec.get("outside", 0) for rec in recs))
        rows.append(row)
    headers = [
        "criterion",
        "reference",
        "ratio",
        "n",
        "min",
        "median",
        "max",
        "worst (max) instance",
        "below 1",
        "lowest instance",
        "SDP refused",
    ] + (["sampled points outside"] if checked else [])
    png = drawings.add(
        figures.ratio_histograms,
        out / f"hist_{name}.png",
        records=records,
        title=f"{name}: ratio − 1",
    )
    parts = [markdown_table(headers, rows)]
    below = headers.index("below 1")
    if any(row[below] for row in rows):
        parts.append(BELOW_ONE_NOTE)
    if checked:
        parts.append(
            '"sampled points outside": points drawn uniformly in the exact set that the '
            "analytic bound misses, summed over the instances; a guaranteed outer bound gives 0."
        )
    return [
        *parts,
        "Median (max) ratio by variant:",
        _matrix(records, "variant"),
        "Median (max) ratio by dimension:",
        _matrix(records, "dim", prefix="n = "),
        f"![{name} ratio histograms]({png})",
    ]


def _matrix(records: list[dict], column: str, prefix: str = "") -> str:
    """Criteria as rows, the values of ``column`` as columns, cells ``median (max)``."""
    columns = list(group(records, (column,)))
    rows = []
    for (criterion,), recs in group(records, ("criterion",)).items():
        cells = group(recs, (column,))
        rows.append([f"`{criterion}`", *(_median_max(cells.get(key, [])) for key in columns)])
    return markdown_table(["criterion"] + [f"{prefix}{key[0]}" for key in columns], rows)


def _median_max(records: list[dict], field: str = "ratio") -> str:
    """The cell ``median (max)`` of ``field`` over ``records``, or "–" when there is none."""
    s = ratio_stats(records, field)
    return f"{fmt_ratio(s['median'])} ({fmt_ratio(s['max'])})" if s["n"] else "–"


def _recursive_section(records: list[dict], out: Path, drawings: Drawings) -> list[str]:
    png = drawings.add(figures.recursive_plot, out / "recursive.png", records=records)
    parts = [
        "Volume of the recursive analytic filter (one strip at a time, minimum-volume λ "
        "[HS96, eq. (26)]) divided by the volume of the batch SDP over the prior and all k "
        "strips at once. With several strips the S-procedure SDP is only an upper bound on "
        "the smallest outer ellipsoid, so a ratio below 1 means the SDP relaxation is looser "
        "than the recursion, not that the recursion is invalid.",
        _k_table(records, "ratio"),
    ]
    if any(rec.get("lower_ratio") is not None for rec in records):
        cleaned, flagged = without_degenerate_lower(records)
        parts += [
            "The same volumes divided by a lower bound on the smallest outer ellipsoid (the "
            "minimum-volume ellipsoid of points sampled in the exact set): an upper bound on "
            "the recursion's true loss, which lies between the two tables.",
            _k_table(cleaned, "lower_ratio"),
        ]
        if flagged:
            where = "; ".join(worst_label(rec) for rec in flagged[:MAX_ERRORS_SHOWN])
            parts.append(
                f"**{len(flagged)} degenerate lower bound(s)** (SDP / lower bound above "
                f"{DEGENERATE_GAP:g}: the sampled points collapsed, not a real gap) are left out "
                f"of this table and of the figure's dotted lines, counted under \"no lower "
                f'bound": {where}.'
            )
    return [*parts, f"![recursive tightness]({png})"]


def _k_table(records: list[dict], field: str) -> str:
    """Rows (strip width, k), one ``median (max)`` column per dimension, then the extremes."""
    dims = sorted({rec["dim"] for rec in records})
    rows = []
    for (variant, k), recs in sorted(group(records, ("variant", "k")).items()):
        by_dim = group(recs, ("dim",))
        cells = [_median_max(by_dim.get((dim,), []), field) for dim in dims]
        s = ratio_stats(recs, field)
        rows.append(
            [
                variant,
                k,
                *cells,
                s.get("below_one", 0),
                s["missing"],
                worst_label(s["worst"]) if s["n"] else "–",
            ]
        )
    missing = "SDP refused" if field == "ratio" else "no lower bound"
    headers = [
        "strips",
        "k",
        *[f"n = {d}: median (max)" for d in dims],
        "below 1",
        missing,
        "worst (max) instance",
    ]
    return markdown_table(headers, rows)


PAPERS_NOTE = (
    "One `quantity | paper | optbound` table per reproduction script (`papers_repro/`): the "
    '**paper** column holds values and claims typed from the paper (quoted; "—" where the '
    "paper gives none), the **optbound** column is computed by the script in this run."
)


def papers_section(records: list[dict], level: int = 3) -> list[str]:
    """Render the paper reproductions: each script's Markdown, then its figures.

    Parameters
    ----------
    records : list of dict
        The records of the ``papers`` family, one per script: ``"paper"``, ``"script"``,
        ``"quick"``, ``"markdown"`` and ``"figures"`` (paths relative to the report).
    level : int, default 3
        The heading level the top headings of each script's Markdown are moved to.

    Returns
    -------
    list of str
        Markdown parts: :data:`PAPERS_NOTE`, then per script a line naming it, its Markdown
        and its figures.
    """
    parts = [PAPERS_NOTE]
    for rec in records:
        variant = " (quick variant)" if rec["quick"] else ""
        parts.append(f"Paper **{rec['paper']}**, `papers_repro/{rec['script']}.py`{variant}:")
        parts.append(_demote(rec["markdown"], level))
        parts.extend(f"![{Path(fig).stem}]({fig})" for fig in rec["figures"])
    return parts


def _demote(markdown: str, level: int) -> str:
    """Headings of ``markdown`` shifted so that its top level becomes ``level``."""
    lines = markdown.splitlines()
    depths = [len(line) - len(line.lstrip("#")) for line in lines if line.startswith("#")]
    shift = level - min(depths) if depths else 0
    return "\n".join("#" * shift + line if line.startswith("#") else line for line in lines)


def _speed_table(records: list[dict]) -> str:
    rows = []
    for rec in records:
        value = fmt_seconds(rec["value"]) + ("" if rec["unit"] == "s" else f" ({rec['unit']})")
        if rec.get("throughput"):
            value += f", {rec['throughput']:.3g} updates/s"
        ratio = f"{fmt_factor(rec['ratio'])} {rec['ratio_label']}" if rec.get("ratio") else ""
        rows.append([rec["name"], value, ratio])
    return markdown_table(["measurement", "time", "ratio (same run)"], rows)


def _warnings(messages: list[str]) -> str:
    items = "\n".join(f"- `{m}`" for m in messages)
    return (
        f"<details><summary>{len(messages)} distinct warning(s) raised by the code under test"
        f"</summary>\n\n{items}\n\n</details>"
    )


def _errors(errors: list[dict]) -> str:
    lines = [f"**{len(errors)} task(s) failed** (first {MAX_ERRORS_SHOWN} shown):", ""]
    for err in errors[:MAX_ERRORS_SHOWN]:
        lines.append(f"- seed {err['task'].get('seed')}: `{err['error']}`")
    return "\n".join(lines)
