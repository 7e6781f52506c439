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
    """The block placed between the markers: where, when and on what the numbers were
    measured, then the table."""
    m = results["meta"]
    return (
        f"Last `optbound bench --suite {m['suite']} --seed {m['seed']}` run, written by "
        f"`optbound.report.readme`: {m['started']}, {machine_text(m)}; {m['jobs']} job(s), "
        f"**{m['wall_time_s']:.0f} s wall time**.\n\n"
        + markdown_table(HEADERS, headline_rows(results))
    )


def machine_text(meta: dict) -> str:
    """``Linux x86_64, <CPU model>, 2 CPUs, load average 1.2 / 0.9 / 0.5 at the end``."""
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
    """Why a run with this ``meta`` may not write the bench headline, or None if it may."""
    differs = [f"--{k} {meta.get(k)}" for k, v in DEFAULT_SUITE.items() if meta.get(k) != v]
    if differs:
        return f"the bench headline comes from the default suite only, not {' '.join(differs)}"
    if not meta.get("complete", False):
        return "the bench headline needs a complete run (no --family selection)"
    return None


def update_readme(path: str | Path, results: dict) -> bool:
    """Replace the text between the headline markers of ``path``; False if it has no markers.

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
    """The page holding the headline markers, ``docs/benchmarks.md`` of the source checkout
    this package runs from (editable install), if any."""
    import optbound

    candidate = Path(optbound.__file__).resolve().parents[1] / "docs" / "benchmarks.md"
    return candidate if candidate.is_file() and BEGIN in candidate.read_text() else None
