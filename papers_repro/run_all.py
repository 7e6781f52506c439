"""Run every reproduction script into one folder and write ``summary.md`` with all tables.

The scripts are found by :func:`optbound.papers_repro._common.scripts` (every module with
``PAPER`` and ``main``), the same discovery as ``optbound repro``.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from optbound.papers_repro._common import DEFAULT_OUT, scripts


def run_all(out_dir: Path | str = DEFAULT_OUT, quick: bool = False) -> Path:
    """Run each script's ``main(out_dir, quick)``; return the path of the written ``summary.md``."""
    out_dir = Path(out_dir)
    sections = ["# optbound reproductions of the papers' results"]
    for script in scripts():
        result = script.run(out_dir, quick=quick)
        sections.append(result["markdown"])
        sections.append("\n".join(f"![{p.stem}]({p.name})" for p in result["figures"]))
    path = out_dir / "summary.md"
    path.write_text("\n\n".join(sections))
    return path


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT, help="output folder")
    parser.add_argument("--quick", action="store_true", help="the scripts' fast variants")
    args = parser.parse_args()
    print(run_all(args.out, quick=args.quick))
