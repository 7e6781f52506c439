"""The headline numbers of a run: one line per criterion, recursion depth and speed ratio.

The same rows go to the top of report.md, to the terminal after ``optbound bench`` and into
the benchmark page of the documentation, so every number a reader sees first is computed here.
"""

from __future__ import annotations

from optbound.report.estimation import estimation_rows
from optbound.report.summary import group, ratio_stats, without_degenerate_lower
from optbound.report.tables import fmt_factor, fmt_ratio, fmt_seconds

HEADERS = ("measure", "value")


def headline_rows(results: dict) -> list[tuple[str, str]]:
    """Summarise ``results`` as ``(measure, value)`` rows.

    One or more rows per family: the ratio statistics per criterion and reference of a
    tightness family, three depths of the recursive family, one row per paper, the
    estimation rows (:func:`~optbound.report.estimation.estimation_rows`), the speed ratios;
    a skipped family gives its reason.

    Parameters
    ----------
    results : dict
        The results dict that ``optbound bench`` saves (:func:`~optbound.report.load_results`).

    Returns
    -------
    list of tuple of (str, str)
        The rows, family by family.
    """
    rows = []
    for name, fam in results["families"].items():
        if fam["status"] != "ok":
            rows.append((fam["title"], f"skipped: {fam['reason']}"))
        elif fam["kind"] == "tightness":
            rows.extend(_tightness_rows(name, fam["records"]))
        elif fam["kind"] == "recursive":
            rows.extend(_recursive_rows(fam["records"]))
        elif fam["kind"] == "papers":
            rows.extend(_paper_rows(fam["records"]))
        elif fam["kind"] == "estimation":
            rows.extend(estimation_rows(fam["records"]))
        else:
            rows.extend(_speed_rows(fam))
    return rows


def _tightness_rows(name: str, records: list[dict]) -> list[tuple[str, str]]:
    rows = []
    for (criterion, reference), recs in group(records, ("criterion", "reference")).items():
        kind = recs[0].get("bound", "analytic")  # "optimal" for a reference measured likewise
        rows.append((f"{name} · {kind} {criterion} / {reference}", stats_text(ratio_stats(recs))))
    return rows


def _recursive_rows(records: list[dict]) -> list[tuple[str, str]]:
    if not records:
        return []
    ks = sorted({rec["k"] for rec in records})
    rows = []
    for k in sorted({ks[0], ks[len(ks) // 2], ks[-1]}):
        at_k = [rec for rec in records if rec["k"] == k]
        text = stats_text(ratio_stats(at_k))
        cleaned, flagged = without_degenerate_lower(at_k)
        low = ratio_stats(cleaned, "lower_ratio")
        if low["n"]:
            text += f"; vs lower bound on the optimum: median {fmt_ratio(low['median'])}"
        if flagged:
            text += f" ({len(flagged)} degenerate lower bound(s) left out)"
        rows.append((f"recursive · analytic filter after k={k} strips / batch SDP", text))
    return rows


def _paper_rows(records: list[dict]) -> list[tuple[str, str]]:
    rows = []
    for (paper,), recs in group(records, ("paper",)).items():
        names = ", ".join(f"`{rec['script']}`" for rec in recs)
        variant = "quick variants" if all(rec["quick"] for rec in recs) else "full"
        rows.append((f"papers · {paper}", f"reproduced by {names} ({variant}); tables in report"))
    return rows


def stats_text(s: dict) -> str:
    """Format ratio statistics as ``median …, max … (n=…)``.

    Parameters
    ----------
    s : dict
        Statistics from :func:`~optbound.report.summary.ratio_stats`.

    Returns
    -------
    str
        The median and max, plus the number of refused SDP references, if any.

    Examples
    --------
    >>> from optbound.report.headline import stats_text
    >>> stats_text({"n": 3, "missing": 1, "median": 1.25, "max": 2.0})
    'median 1.25, max 2 (n=3); 1 SDP solves refused'
    """
    if not s["n"]:
        return f"no reference: all {s['missing']} SDP solves refused"
    text = f"median {fmt_ratio(s['median'])}, max {fmt_ratio(s['max'])} (n={s['n']})"
    return text + (f"; {s['missing']} SDP solves refused" if s["missing"] else "")


def _speed_rows(fam: dict) -> list[tuple[str, str]]:
    rows = [(note_title(fam), note) for note in fam["notes"]]
    for rec in fam["records"]:
        if rec.get("ratio") is not None:
            value = f"{fmt_factor(rec['ratio'])} {rec['ratio_label']}"
            rows.append((rec["name"], f"{fmt_seconds(rec['value'])}; {value}"))
    return rows


def note_title(fam: dict) -> str:
    """Title a speed family's notes: its title without the ``"Speed: "`` prefix.

    Parameters
    ----------
    fam : dict
        A family entry of the results dict, with a ``"title"``.

    Returns
    -------
    str
        The shortened title.
    """
    return fam["title"].removeprefix("Speed: ")
