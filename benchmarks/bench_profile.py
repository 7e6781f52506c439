"""Where the CPU of a warm ``optbound bench`` goes: per family, and per function within each.

Each family of the suite runs alone in this process (``optbound bench --family NAME --jobs
1``) under ``cProfile``, after one unprofiled run of the whole suite that fills numba's cache
and imports everything (so compiles and first imports are not counted). Printed: one row per
family (its CPU seconds and its share of the suite), then per family the functions with the
most own time (``tottime``, with the cumulative time beside it) and the own time summed per
package (numpy, scipy, cvxpy, clarabel, optbound's subpackages, numba's dispatch, ...).

cProfile slows pure-Python code more than compiled code, so the shares of Python-heavy
functions are upper bounds; the per-family CPU seconds are measured without it.

Run: ``python -m benchmarks.bench_profile [--suite quick] [--top 8]``; the documentation's
table (``docs/performance.md``) is this output, written by ``python -m tests.doc_tables
bench-profile``.
"""

from __future__ import annotations

import argparse
import contextlib
import cProfile
import io
import os
import pstats
import tempfile
import time
from collections import defaultdict


def family_names() -> list[str]:
    """The bench's families, as its command line lists them."""
    from optbound import cli

    bench = next(
        action for action in cli.build_parser()._subparsers._group_actions[0].choices.values()
        if action.prog.endswith("bench")
    )  # fmt: skip
    option = next(a for a in bench._actions if "--family" in a.option_strings)
    return list(option.choices)


def _bench(suite: str, families: list[str], out: str) -> None:
    from optbound import cli

    args = ["bench", "--suite", suite, "--jobs", "1", "--no-progress", "--force", "--out", out]
    for name in families:
        args += ["--family", name]
    with contextlib.redirect_stdout(io.StringIO()):  # the bench's own tables: not wanted here
        cli.main(args)


def _package(filename: str, function: str) -> str:
    """A coarse owner of a profiled function: optbound's subpackage or the library."""
    path = filename.replace(os.sep, "/")
    if filename == "~":  # a builtin: numpy's C functions show up as these
        return "builtins (numpy C calls, ...)" if "numpy" in function else "builtins"
    for marker in ("/optbound/", "/benchmarks/", "/papers_repro/"):
        if marker in path:
            parts = path.split(marker, 1)[1].split("/")
            head = marker.strip("/")
            return f"{head}.{parts[0].removesuffix('.py')}" if len(parts) > 1 else head
    if "site-packages/" in path:
        return path.split("site-packages/", 1)[1].split("/")[0]
    return "python stdlib"


def profile_family(suite: str, name: str) -> tuple[float, pstats.Stats]:
    """CPU seconds of one family (unprofiled run) and its profile (a second run)."""
    with tempfile.TemporaryDirectory() as out:
        start = time.process_time()
        _bench(suite, [name], out)
        cpu = time.process_time() - start
        profiler = cProfile.Profile()
        profiler.runcall(_bench, suite, [name], out)
    return cpu, pstats.Stats(profiler)


def measure(suite: str = "quick", names: list[str] | None = None) -> dict:
    """Per family: its CPU seconds and profile, after one warm-up run of ``names`` (default:
    every family); also the load average at start and end."""
    names = names or family_names()
    load = os.getloadavg()[0]
    with tempfile.TemporaryDirectory() as out:
        _bench(suite, names, out)  # warm: numba's cache filled, modules imported
    families = {name: profile_family(suite, name) for name in names}
    return {"suite": suite, "load": (load, os.getloadavg()[0]), "families": families}


def tables(measured: dict, top: int = 8) -> str:
    """The Markdown tables of :func:`measure`'s result: the families, then per family the
    packages and the ``top`` functions with the most own time."""
    results = measured["families"]
    total = sum(cpu for cpu, _ in results.values())
    load0, load1 = measured["load"]
    lines = [
        f"optbound bench --suite {measured['suite']}, warm, --jobs 1; load {load0:.1f} at "
        f"start, {load1:.1f} at end; {total:.1f} s CPU in all",
        "",
        "| family | CPU s | share |",
        "|---|---|---|",
    ]
    ranked_families = sorted(results.items(), key=lambda kv: -kv[1][0])
    lines += [f"| {name} | {cpu:.1f} | {cpu / total:.0%} |" for name, (cpu, _) in ranked_families]
    for name, (cpu, stats) in ranked_families:
        rows = stats.stats  # {(file, line, function): (cc, nc, tottime, cumtime, callers)}
        own = sum(r[2] for r in rows.values()) or 1.0
        packages: dict = defaultdict(float)
        for (filename, _, function), r in rows.items():
            packages[_package(filename, function)] += r[2]
        lines += ["", f"{name}: {cpu:.1f} s CPU; own time per package (profiled run)", ""]
        lines += ["| package | share |", "|---|---|"]
        for package, spent in sorted(packages.items(), key=lambda kv: -kv[1])[:6]:
            lines.append(f"| {package} | {spent / own:.0%} |")
        lines += ["", "| function | own | cumulative | calls |", "|---|---|---|---|"]
        for (filename, _line, function), (_, calls, tottime, cumtime, _) in sorted(
            rows.items(), key=lambda kv: -kv[1][2]
        )[:top]:
            where = f"{_package(filename, function)}:{function}"
            lines.append(f"| {where} | {tottime / own:.0%} | {cumtime / own:.0%} | {calls} |")
    return "\n".join(lines)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--suite", choices=("tiny", "quick", "full"), default="quick")
    parser.add_argument("--top", type=int, default=8, help="functions shown per family")
    parser.add_argument("--family", action="append", help="only these families")
    args = parser.parse_args(argv)
    print(tables(measure(args.suite, args.family), args.top))


if __name__ == "__main__":
    main()
