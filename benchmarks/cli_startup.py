"""Start-up time of the ``optbound`` command: the median wall time of ``optbound --help``.

Run from the repository root: ``python -m benchmarks.cli_startup [--runs 5]``. Each run is a
fresh process (``python -m optbound --help``, the same code as the console script), timed
from the parent with ``time.perf_counter``, so interpreter start-up is included.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import time


def help_seconds(runs: int = 5) -> list[float]:
    """Wall seconds of ``runs`` runs of ``python -m optbound --help``."""
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run(
            [sys.executable, "-m", "optbound", "--help"], check=True, stdout=subprocess.DEVNULL
        )
        times.append(time.perf_counter() - start)
    return times


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5, help="number of runs (default 5)")
    args = parser.parse_args(argv)
    times = help_seconds(args.runs)
    print(
        f"optbound --help: median {statistics.median(times):.3f} s over {args.runs} runs "
        f"(min {min(times):.3f} s, max {max(times):.3f} s)"
    )


if __name__ == "__main__":
    main()
