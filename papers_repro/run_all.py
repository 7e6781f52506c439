"""Run every reproduction script into one folder and write ``summary.md`` with all tables."""

from __future__ import annotations

import argparse
from pathlib import Path

from papers_repro import hs96_fusion, hs96_projection, ljmw97_appendix_a
from papers_repro._common import DEFAULT_OUT

SCRIPTS = (hs96_fusion, hs96_projection, ljmw97_appendix_a)


def run_all(out_dir: Path | str = DEFAULT_OUT) -> Path:
    """Run each script's ``main(out_dir)``; return the path of the written ``summary.md``."""
    out_dir = Path(out_dir)
    sections = ["# optbound reproductions of the papers' results"]
    for script in SCRIPTS:
        result = script.main(out_dir)
        sections.append(result["markdown"])
        sections.append("\n".join(f"![{p.stem}]({p.name})" for p in result["figures"]))
    path = out_dir / "summary.md"
    path.write_text("\n\n".join(sections))
    return path


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT, help="output folder")
    print(run_all(parser.parse_args().out))
