"""Insert the headline numbers of a quick run into the README's bench section.

The numbers sit between two HTML comments inside the bench section, so the README never
holds a hand-typed benchmark figure: each ``optbound bench`` (quick suite) rewrites them.
"""

from __future__ import annotations

from pathlib import Path

from optbound.report.headline import HEADERS, headline_rows
from optbound.report.tables import markdown_table

BEGIN = "<!-- BEGIN bench-headline -->"
END = "<!-- END bench-headline -->"


def headline_markdown(results: dict) -> str:
    """The block placed between the markers: where the numbers come from, then the table."""
    m = results["meta"]
    return (
        f"Last `optbound bench --suite {m['suite']} --seed {m['seed']}` run ({m['started']}, "
        f"{m['jobs']} job(s), {m['wall_time_s']:.0f} s wall time), written by "
        "`optbound.report.readme`:\n\n" + markdown_table(HEADERS, headline_rows(results))
    )


def update_readme(path: str | Path, results: dict) -> bool:
    """Replace the text between the headline markers of ``path``; False if it has no markers."""
    path = Path(path)
    text = path.read_text()
    start, end = text.find(BEGIN), text.find(END)
    if start < 0 or end < start:
        return False
    head, tail = text[: start + len(BEGIN)], text[end:]
    path.write_text(f"{head}\n{headline_markdown(results)}\n{tail}")
    return True


def source_readme() -> Path | None:
    """README.md of the source checkout this package runs from (editable install), if any."""
    import optbound

    candidate = Path(optbound.__file__).resolve().parents[1] / "README.md"
    return candidate if candidate.is_file() and BEGIN in candidate.read_text() else None
