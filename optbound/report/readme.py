"""Insert the headline numbers of a quick run into the documentation's benchmark page.

The numbers sit between two HTML comments of ``docs/benchmarks.md``, so the documentation
never holds a hand-typed benchmark figure. Only ``optbound bench --update-readme`` rewrites them,
and only from a complete run of the default suite (quick, seed 0, every family): a partial
run must not replace the headline with a part of it.
"""

from __future__ import annotations

from pathlib import Path

from optbound.report.headline import HEADERS, headline_rows
from optbound.report.tables import markdown_table

BEGIN = "<!-- BEGIN bench-headline -->"
END = "<!-- END bench-headline -->"


DEFAULT_SUITE = {"suite": "quick", "seed": 0}


def headline_markdown(results: dict) -> str:
    """Render the block placed between the markers.

    Parameters
    ----------
    results : dict
        The results dict that ``optbound bench`` saves (:func:`~optbound.report.load_results`).

    Returns
    -------
    str
        Where, when and on what the numbers were measured, then the headline table
        (:func:`~optbound.report.headline.headline_rows`).
    """
    m = results["meta"]
    return (
        f"Last `optbound bench --suite {m['suite']} --seed {m['seed']}` run, written by "
        f"`optbound.report.readme`: {m['started']}, {machine_text(m)}; {m['jobs']} job(s), "
        f"**{m['wall_time_s']:.0f} s wall time**.\n\n"
        + markdown_table(HEADERS, headline_rows(results))
    )


def machine_text(meta: dict) -> str:
    """Describe the machine a run was measured on.

    Parameters
    ----------
    meta : dict
        The results' ``"meta"``: ``"machine"``, and optionally ``"processor"``, ``"cpus"``
        and ``"load_average"``.

    Returns
    -------
    str
        E.g. ``Linux x86_64, <CPU model>, 2 CPUs, 1/5/15-min load average 1.20 / 0.90 /
        0.50 at the end of the run``.

    Examples
    --------
    >>> from optbound.report.readme import machine_text
    >>> machine_text({"machine": "Linux x86_64", "cpus": 2, "load_average": [1.2, 0.9, 0.5]})
    'Linux x86_64, 2 CPUs, 1/5/15-min load average 1.20 / 0.90 / 0.50 at the end of the run'
    """
    parts = [meta["machine"]]
    if meta.get("processor"):
        parts.append(meta["processor"])
    if meta.get("cpus"):
        parts.append(f"{meta['cpus']} CPUs")
    if meta.get("load_average"):
        load = " / ".join(f"{x:.2f}" for x in meta["load_average"])
        parts.append(f"1/5/15-min load average {load} at the end of the run")
    return ", ".join(parts)


def headline_refusal(meta: dict) -> str | None:
    """Explain why a run with this ``meta`` may not write the bench headline.

    Only a complete run of the default suite (:data:`DEFAULT_SUITE`) may.

    Parameters
    ----------
    meta : dict
        The results' ``"meta"``: ``"suite"``, ``"seed"`` and ``"complete"``.

    Returns
    -------
    str or None
        The reason, or None if the run may write it.

    Examples
    --------
    >>> from optbound.report import headline_refusal
    >>> headline_refusal({"suite": "quick", "seed": 0, "complete": True}) is None
    True
    >>> headline_refusal({"suite": "tiny", "seed": 0, "complete": True})
    'the bench headline comes from the default suite only, not --suite tiny'
    """
    differs = [f"--{k} {meta.get(k)}" for k, v in DEFAULT_SUITE.items() if meta.get(k) != v]
    if differs:
        return f"the bench headline comes from the default suite only, not {' '.join(differs)}"
    if not meta.get("complete", False):
        return "the bench headline needs a complete run (no --family selection)"
    return None


def update_readme(path: str | Path, results: dict) -> bool:
    """Replace the text between the headline markers of ``path`` by the run's headline.

    Parameters
    ----------
    path : str or Path
        The page holding the markers :data:`BEGIN` and :data:`END`.
    results : dict
        The results dict that ``optbound bench`` saves (:func:`~optbound.report.load_results`).

    Returns
    -------
    bool
        True if the page was rewritten; False if it has no markers.

    Raises
    ------
    ValueError
        If ``results`` is not a complete run of the default suite (:func:`headline_refusal`).
    """
    refusal = headline_refusal(results["meta"])
    if refusal:
        raise ValueError(refusal)
    path = Path(path)
    text = path.read_text()
    start, end = text.find(BEGIN), text.find(END)
    if start < 0 or end < start:
        return False
    head, tail = text[: start + len(BEGIN)], text[end:]
    path.write_text(f"{head}\n{headline_markdown(results)}\n{tail}")
    return True


def source_readme() -> Path | None:
    """Find the page holding the headline markers in the source checkout, if any.

    Returns
    -------
    Path or None
        ``docs/benchmarks.md`` of the source checkout this package runs from (editable
        install) if it holds :data:`BEGIN`; None otherwise.
    """
    import optbound

    candidate = Path(optbound.__file__).resolve().parents[1] / "docs" / "benchmarks.md"
    return candidate if candidate.is_file() and BEGIN in candidate.read_text() else None
