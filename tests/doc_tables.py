"""Every table of measured numbers in the documentation is generated here, never typed by hand.

A generated table sits between ``<!-- BEGIN generated:NAME -->`` and
``<!-- END generated:NAME -->``; ``GENERATORS[NAME]`` returns its Markdown. The bench headline
(``<!-- BEGIN bench-headline -->``) is written by ``optbound bench --update-readme`` instead.

``python -m tests.doc_tables [NAME ...]`` recomputes the named blocks (default: all) and
rewrites them in place, in whichever page (README.md or ``docs/**/*.md``) holds them.
``tests/test_docs.py`` checks that no table of measured numbers lies outside such a block.
"""

from __future__ import annotations

import argparse
import contextlib
import functools
import io
import os
import re
import subprocess
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def pages() -> list[Path]:
    """README.md and every Markdown page of the documentation (not the build output)."""
    docs = ROOT / "docs"
    found = [p for p in sorted(docs.rglob("*.md")) if "_build" not in p.relative_to(docs).parts]
    return [ROOT / "README.md", *found]


# The markers may be indented (a table inside a list item); the body gets their indentation.
BLOCK = re.compile(
    r"^(?P<indent>[ \t]*)<!-- BEGIN generated:(?P<name>[\w-]+) -->\n(?P<body>.*?)"
    r"^[ \t]*<!-- END generated:(?P=name) -->",
    re.S | re.M,
)


def _battery() -> str:
    from optbound.report.tables import markdown_table
    from tests.battery import agreement_rows

    rows = [
        (
            row["name"],
            f"{row['analytic_over_sdp_minus_1']:.2g}",
            f"{row['inflation_minus_1']:.2g}",
            "–" if row["sdp_over_lower_bound"] is None else f"{row['sdp_over_lower_bound']:.4f}",
        )
        for row in agreement_rows()
    ]
    headers = ("case", "analytic/SDP − 1", "inflation − 1", "SDP / lower bound")
    return "Output of `python -m tests.doc_tables battery`:\n\n" + markdown_table(headers, rows)


def _clip_effect() -> str:
    from tests.optimal.clip_effect import table

    return table()


def _sivia_codac() -> str:
    from optbound.bench.sivia_codac import run, table

    return table(run())


def _speed_analytic() -> str:
    """Batch throughput of the analytic updates vs the plain numba kernel (full batch sizes)."""
    import numpy as np

    from optbound.bench import speed_analytic as sa
    from optbound.report.tables import markdown_table

    rng = np.random.default_rng(0)
    batches = sa.BATCHES["full"]
    strip, mink = sa.strip_timings(rng, batches), sa.minkowski_timings(rng, batches)

    def cells(timings, key) -> list[str]:
        ours, ref = timings[key]
        if key == "one":
            return [f"{ours * 1e6:.1f} µs", f"{ref * 1e6:.1f} µs", f"{ours / ref:.2f}"]
        return [f"{key / ours / 1e6:.2f} M/s", f"{key / ref / 1e6:.2f} M/s", f"{ours / ref:.2f}"]

    rows = [
        ["one call" if key == "one" else f"{key:.0e}", *cells(strip, key), *cells(mink, key)]
        for key in ("one", *batches)
    ]
    headers = (
        "B",
        "`intersect_strip_batch`",
        "reference",
        "time ratio",
        "`minkowski_sum_batch`",
        "reference",
        "time ratio",
    )
    return (
        f"Output of `python -m tests.doc_tables speed-analytic` (1-min load average "
        f"{os.getloadavg()[0]:.1f}):\n\n" + markdown_table(headers, rows)
    )


def _margin() -> str:
    """The certified margins of the analytic updates against the float-storage floor."""
    from optbound.bench.speed_analytic import margin_distribution
    from optbound.report.tables import markdown_table

    rows = [
        (op, f"{cond:.0e}", f"{med:.1e}", f"{p99:.1e}", f"{top:.1e}", f"{cond_out:.1e}",
         f"{floor:.2f}")
        for op, cond, med, p99, top, cond_out, floor in margin_distribution()
    ]  # fmt: skip
    headers = (
        "operation",
        "input cond",
        "median",
        "99 %",
        "max",
        "median cond(result)",
        "median margin / (U cond(result))",
    )
    return "Output of `python -m tests.doc_tables margin`:\n\n" + markdown_table(headers, rows)


def _localization() -> str:
    """The localization family's BH instance (tiny suite, seed 0): every bound's area ratio."""
    from optbound.bench import localization_tightness as lt
    from optbound.report.tables import markdown_table

    (task,) = lt.tasks("tiny", 0)
    records = lt.run(task)["records"]
    rows = [
        (
            f"`{r['criterion']}`",
            "yes" if r["guaranteed"] else "no (linearized)",
            f"[{r['area_lo']:.4f}, {r['area_hi']:.4f}]",
            f"{r['ratio']:.2f}",
            f"[{r['ratio_lo']:.2f}, {r['ratio_hi']:.2f}]",
            f"{r['outside']} / {lt.SAMPLES}",
            "yes" if r["truth_outside"] else "no",
            {True: "yes", False: "no"}.get(r.get("proven"), "–"),
        )
        for r in records
    ]
    headers = (
        "bound",
        "guaranteed",
        "area bracket [m²]",
        "ratio (midpoints)",
        "certified ratio bracket",
        "exact-set points outside",
        "truth outside",
        "containment proven",
    )
    first = records[0]
    return (
        "Output of `python -m tests.doc_tables localization` (BH Sect. V geometry, eps = 4°, "
        f"exact area in [{first['exact_lo']:.4f}, {first['exact_hi']:.4f}] m² by a paving of "
        f"width {first['paving_width']:.4f} m; 1-min load average {os.getloadavg()[0]:.1f}):\n\n"
        + markdown_table(headers, rows)
    )


def _bench_profile() -> str:
    """Where the CPU of a warm quick bench goes, per family and per function (minutes)."""
    from benchmarks.bench_profile import measure, tables

    return (
        "Output of `python -m tests.doc_tables bench-profile` (`benchmarks/bench_profile.py`; "
        "shares of the profiled run, cProfile inflates pure-Python code):\n\n"
        + tables(measure("quick"), top=4)
    )


@functools.cache
def _first_run_output() -> list[str]:
    """The lines ``python -m benchmarks.first_run`` prints (a cold and a warm bench; minutes),
    measured once for both blocks that quote it."""
    from benchmarks import first_run

    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        first_run.main([])
    return [line for line in printed.getvalue().splitlines() if not line.startswith("  stderr")]


def _first_run() -> str:
    """The first and second ``optbound bench``'s wall and CPU times, as first_run prints them."""
    lines = _first_run_output()
    return (
        "Output of `python -m tests.doc_tables first-run`:\n\n```text\n"
        + "\n".join(lines)
        + "\n```"
    )


def _first_run_verdict() -> str:
    """first_run's last line: both runs' wall times against issue 23's targets."""
    host = _first_run_output()[0].split("; ", 1)[1]
    return f"{_first_run_output()[-1]} (on {host}; `python -m benchmarks.first_run`)"


def _strip_breakdown_avx2() -> str:
    """``benchmarks/strip_breakdown.py`` compiled for AVX2 (``NUMBA_CPU_NAME=haswell``, a fresh
    numba cache), in a child process: the hardware most users have, on any x86 host."""
    with tempfile.TemporaryDirectory() as cache:
        env = {**os.environ, "NUMBA_CPU_NAME": "haswell", "NUMBA_CACHE_DIR": cache}
        done = subprocess.run(
            [sys.executable, "-m", "benchmarks.strip_breakdown"],
            env=env, cwd=ROOT, capture_output=True, text=True, check=True,
        )  # fmt: skip
    lines = "\n".join(line for line in done.stdout.splitlines() if "compiling" not in line)
    return (
        "Output of `python -m tests.doc_tables strip-breakdown-avx2` "
        f"(`NUMBA_CPU_NAME=haswell python -m benchmarks.strip_breakdown`):\n\n```text\n{lines}\n```"
    )


def _compile_cost() -> str:
    """Compile CPU of a cold quick bench in every process, per process and per module
    (``benchmarks/compile_cost.py --jobs 2``; a minute and a half), the duplicates' count."""
    from benchmarks import compile_cost

    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        compile_cost.main(["--suite", "quick", "--jobs", "2", "--top", "12"])
    # The per-process and per-module tables and the duplicates' line; the rest (each
    # duplicate, the compiles left to tasks) is for the one who runs the script.
    kept = printed.getvalue().split("\n| dispatcher | types |")[0].rstrip()
    return (
        "Output of `python -m tests.doc_tables compile-cost` "
        f"(`python -m benchmarks.compile_cost --suite quick --jobs 2 --top 12`, cut):\n\n{kept}"
    )


GENERATORS: dict[str, Callable[[], str]] = {
    "battery": _battery,
    "clip-effect": _clip_effect,
    "sivia-codac": _sivia_codac,
    "localization": _localization,
    "speed-analytic": _speed_analytic,
    "margin": _margin,
    "bench-profile": _bench_profile,
    "first-run": _first_run,
    "first-run-verdict": _first_run_verdict,
    "compile-cost": _compile_cost,
    "strip-breakdown-avx2": _strip_breakdown_avx2,
}


def blocks(text: str) -> dict[str, str]:
    """``{name: body}`` of the generated blocks of ``text``."""
    return {m["name"]: m["body"] for m in BLOCK.finditer(text)}


def update(text: str, names: list[str]) -> str:
    """``text`` with the blocks ``names`` recomputed."""
    unknown = sorted(set(names) - set(GENERATORS))
    if unknown:
        raise ValueError(f"names has unknown blocks {unknown}; known: {sorted(GENERATORS)}")
    fresh = {name: GENERATORS[name]() for name in names}

    def replace(m: re.Match) -> str:
        indent, name = m["indent"], m["name"]
        if name in fresh:
            lines = fresh[name].strip("\n").splitlines()
            body = "".join(f"{indent}{line}".rstrip() + "\n" for line in lines)
        else:
            body = m["body"]
        return (
            f"{indent}<!-- BEGIN generated:{name} -->\n{body}{indent}<!-- END generated:{name} -->"
        )

    return BLOCK.sub(replace, text)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "names", nargs="*", help=f"blocks to recompute (default all: {', '.join(GENERATORS)})"
    )
    args = parser.parse_args()
    for page in pages():
        text = page.read_text()
        wanted = [name for name in args.names or list(GENERATORS) if name in blocks(text)]
        if wanted:
            page.write_text(update(text, wanted))
