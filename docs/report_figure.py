"""Redraw the README's picture of the benchmark report: ``python docs/report_figure.py``.

Runs the tiny suite of the ``strip`` family (``optbound bench --suite tiny --family strip``)
into a temporary folder and copies the report's ``instances_2d.png`` (2-D instances: the exact
set, each analytic bound and the certified optimum) to ``docs/_static/report_instances.png``.
"""

from __future__ import annotations

import shutil
import sys
import tempfile
from pathlib import Path

FIGURE = Path(__file__).resolve().parent / "_static" / "report_instances.png"


def main() -> Path:
    """Run the tiny strip benchmark and copy its instance figure to :data:`FIGURE`."""
    sys.path.insert(0, str(FIGURE.parents[2]))  # this checkout's optbound
    from optbound.cli import main as optbound

    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "report"
        code = optbound(["bench", "--suite", "tiny", "--family", "strip", "--out", str(out)])
        if code != 0:
            raise SystemExit(code)
        shutil.copyfile(out / "instances_2d.png", FIGURE)
    return FIGURE


if __name__ == "__main__":
    print(main())
