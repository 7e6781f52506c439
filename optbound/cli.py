"""The ``optbound`` console script: ``optbound bench`` and ``optbound report DIR``."""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from benchmarks.family import SUITES
from benchmarks.registry import families

DEFAULT_OUT = Path("bench-report")


def _int_at_least(minimum: int, what: str):
    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{what} must be an integer, got {text!r}") from None
        if value < minimum:
            raise argparse.ArgumentTypeError(f"{what} must be >= {minimum}, got {value}")
        return value

    return parse


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="optbound",
        description="Guaranteed bounding sets: analytic vs optimal vs exact.",
    )
    parser.add_argument("--version", action="version", version=_version())
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    bench = sub.add_parser(
        "bench",
        help="run a benchmark suite and write a report",
        description="Run the benchmark families of benchmarks/ and write report.md, "
        "results.json, CSV and PNG figures into --out.",
    )
    bench.add_argument(
        "--suite",
        choices=SUITES,
        default="quick",
        help="quick (default, a few minutes), full (every family at full size, spread over "
        "--jobs), tiny (a seconds-long smoke test of the same code path)",
    )
    bench.add_argument(
        "--out", type=Path, default=DEFAULT_OUT, help=f"report directory (default {DEFAULT_OUT})"
    )
    bench.add_argument(
        "--seed", type=_int_at_least(0, "seed"), default=0, help="suite seed (default 0)"
    )
    bench.add_argument(
        "--jobs",
        type=_int_at_least(1, "jobs"),
        default=os.cpu_count() or 1,
        help="worker processes for the tightness families (default: all cores)",
    )
    bench.add_argument(
        "--family",
        action="append",
        choices=[fam.name for fam in families()],
        help="run only this family (repeatable; default: all)",
    )
    bench.add_argument("--no-progress", action="store_true", help="hide the progress bar")
    bench.add_argument(
        "--no-readme",
        action="store_true",
        help="do not write the headline numbers into the README (done for quick runs only)",
    )
    report = sub.add_parser(
        "report",
        help="rebuild the report of DIR from DIR/results.json",
        description="Rewrite report.md, CSV and PNG figures from DIR/results.json alone.",
    )
    report.add_argument("dir", type=Path, metavar="DIR", help="a directory written by bench")
    bench.set_defaults(handler=_bench, subparser=bench)
    report.set_defaults(handler=_report, subparser=report)
    return parser


def _version() -> str:
    from optbound import __version__

    return f"optbound {__version__}"


def _bench(args: argparse.Namespace) -> int:
    from benchmarks.runner import run_suite
    from optbound import report

    if args.out.exists() and not args.out.is_dir():
        args.subparser.error(f"--out {str(args.out)!r} exists and is not a directory")
    results = run_suite(
        args.suite, args.seed, args.jobs, progress=not args.no_progress, names=args.family
    )
    report.save_results(results, args.out)
    path = report.write_report(results, args.out)
    _print_summary(results, path)
    readme = None if args.no_readme or args.suite != "quick" else report.source_readme()
    if readme is not None and report.update_readme(readme, results):
        print(f"Headline numbers written into {readme}")
    return 0


def _report(args: argparse.Namespace) -> int:
    from optbound import report

    try:
        results = report.load_results(args.dir)
    except ValueError as exc:
        args.subparser.error(str(exc))
    path = report.write_report(results, args.dir)
    _print_summary(results, path)
    return 0


def _print_summary(results: dict, path: Path) -> None:
    from optbound.report import headline_rows
    from optbound.report.headline import HEADERS
    from optbound.report.tables import text_table

    print(text_table(HEADERS, headline_rows(results)))
    failed = sum(len(fam["errors"]) for fam in results["families"].values())
    if failed:
        print(f"warning: {failed} task(s) failed; they are listed in the report")
    print(f"\nReport: {path} (wall time {results['meta']['wall_time_s']:.1f} s)")


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help()
        return 0
    return args.handler(args)


if __name__ == "__main__":
    sys.exit(main())
