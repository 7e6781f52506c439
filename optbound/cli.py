"""The ``optbound`` console script: ``optbound bench``, ``repro``, ``report`` and ``evaluate``.

Errors the user can fix (a bad ``--out``, an unknown paper key, dask not installed, an
unreachable Dask scheduler, a full disk) end the command with one line on stderr and exit code
2, before any work where they can be detected before it. Ctrl-C ends it with one line and exit
code 130. Either way an ``--out`` folder the command created and left empty is removed.

``bench`` and ``repro`` store each finished task in the report folder as it finishes
(:mod:`optbound.bench.run_folder`); ``--resume DIR`` finishes an interrupted run with the
arguments stored in DIR, running only the tasks not stored yet.

Building the parser imports no family, numba, scipy or cvxpy (the family names are declared in
:data:`optbound.bench.registry.FAMILIES`), so ``--help`` and argument errors answer at once;
the work of a command is imported by its handler.
"""

from __future__ import annotations

import argparse
import atexit
import os
import sys
import time
from pathlib import Path
from typing import TYPE_CHECKING

from optbound.bench.executors import EXECUTORS
from optbound.bench.family import SUITES
from optbound.bench.registry import FAMILIES, PAPERS

if TYPE_CHECKING:
    from optbound.bench.run_folder import RunFolder

DEFAULT_OUT = Path("bench-report")
DEFAULT_REPRO_OUT = Path("repro-report")
EXIT_USAGE = 2
EXIT_INTERRUPTED = 130  # 128 + SIGINT, what a shell reports for a Ctrl-C
_IMPORTED = time.perf_counter()  # before the commands' heavy imports


def _since_process_start() -> float:
    """Seconds since this process started: the wall time a user of the command waits.

    Read from ``/proc/self/stat`` (start time in clock ticks after boot) against
    ``/proc/uptime`` on Linux; elsewhere, the time since this module was imported, which
    misses only the interpreter's start-up and optbound's package import.
    """
    try:
        ticks = int(Path("/proc/self/stat").read_text().rsplit(")", 1)[1].split()[19])
        uptime = float(Path("/proc/uptime").read_text().split()[0])
        return uptime - ticks / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError, AttributeError):
        return time.perf_counter() - _IMPORTED


class CommandError(Exception):
    """A user-fixable failure: printed as one line, exit code 2."""


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


def _add_run_options(parser: argparse.ArgumentParser, out: Path) -> None:
    """Options shared by bench and repro: output folder and where the tasks run."""
    parser.add_argument(
        "--out",
        type=Path,
        help=f"report folder (default {out}); created if missing, checked before any work",
    )
    parser.add_argument(
        "--resume",
        type=Path,
        metavar="DIR",
        help="finish the interrupted run whose report folder is DIR: its stored arguments "
        "are used and its finished tasks are not run again",
    )
    parser.add_argument(
        "--force",
        action="store_true",
        help="overwrite the report in --out if there is one (without it, an existing "
        "report folder is an error)",
    )
    parser.add_argument(
        "--jobs",
        type=_int_at_least(1, "jobs"),
        default=os.cpu_count() or 1,
        help="worker processes for the parallel tasks (default: all cores)",
    )
    parser.add_argument(
        "--executor",
        choices=EXECUTORS,
        default="process",
        help="process: a local pool of --jobs processes (default); dask: a Dask LocalCluster "
        'of --jobs workers (needs pip install "optbound[dask]")',
    )
    parser.add_argument(
        "--scheduler",
        metavar="tcp://HOST:PORT",
        help="submit the parallel tasks to this running Dask scheduler (implies dask)",
    )
    parser.add_argument("--no-progress", action="store_true", help="hide the progress bars")


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
        description="Run the benchmark families of optbound.bench and write report.md, "
        "results.json, CSV and PNG figures into --out.",
    )
    bench.add_argument(
        "--suite",
        choices=SUITES,
        help="quick (default: minutes on 2 cores, the papers' fast variants), full "
        "(every family at full size and the papers' full scripts, spread over --jobs), tiny "
        "(a seconds-long smoke test of the same code path)",
    )
    bench.add_argument("--seed", type=_int_at_least(0, "seed"), help="suite seed (default 0)")
    bench.add_argument(
        "--family",
        action="append",
        choices=list(FAMILIES),
        help="run only this family (repeatable; default: all)",
    )
    bench.add_argument(
        "--update-readme",
        action="store_true",
        help="write the headline numbers into the docs' benchmark page; only for a "
        "complete default run (--suite quick --seed 0, every family)",
    )
    bench.add_argument(
        "--estimator",
        action="append",
        metavar="MODULE:CALLABLE",
        help="also evaluate this estimator (problem -> set; module:callable or a registered "
        "name) on the suite's problems, in a "
        'report section "Your estimators" (repeatable; "all-registered": every estimator '
        "registered under the entry-point group optbound.estimators, optbound's analytic "
        "updates included; default: none)",
    )
    _add_run_options(bench, DEFAULT_OUT)
    repro = sub.add_parser(
        "repro",
        help="reproduce the papers' results (papers_repro/) into a report folder",
        description="Run the papers_repro scripts of the given papers (default: all) and "
        "write one paper-vs-optbound table per script plus its figures into --out.",
    )
    repro.add_argument(
        "papers",
        nargs="*",
        metavar="KEY",
        help=f"paper keys, any of {' '.join(PAPERS)}, case-insensitive (default: all)",
    )
    repro.add_argument(
        "--quick", action="store_true", help="the scripts' fast variants (seconds each)"
    )
    _add_run_options(repro, DEFAULT_REPRO_OUT)
    report = sub.add_parser(
        "report",
        help="rebuild the report of DIR from DIR/results.json",
        description="Rewrite report.md, CSV and PNG figures from DIR/results.json alone.",
    )
    report.add_argument("dir", type=Path, metavar="DIR", help="a directory written by bench")
    _add_evaluate_parser(sub)
    bench.set_defaults(handler=_bench, subparser=bench, default_out=DEFAULT_OUT)
    repro.set_defaults(handler=_repro, subparser=repro, default_out=DEFAULT_REPRO_OUT)
    report.set_defaults(handler=_report, subparser=report)
    return parser


def _add_evaluate_parser(sub) -> None:
    evaluate = sub.add_parser(
        "evaluate",
        help="audit your estimator on the public problems and print the table",
        description="Run ESTIMATOR (a callable problem -> set: module:callable, loaded "
        "from the Python path, or the name of an estimator registered under the entry-point "
        "group optbound.estimators) on the problems of a suite (optbound.problems.suite) "
        "and print optbound.evaluate's table: size and ratio brackets, soundness "
        "(proven / refuted at a counterexample / undecided), seconds and errors.",
    )
    evaluate.add_argument("estimator", metavar="ESTIMATOR", help="e.g. my_package.bounds:my_box")
    evaluate.add_argument(
        "--suite", choices=SUITES, default="tiny", help="problem suite (default tiny)"
    )
    evaluate.add_argument(
        "--seed", type=_int_at_least(0, "seed"), default=0, help="suite seed (default 0)"
    )
    evaluate.add_argument(
        "--family",
        action="append",
        metavar="FAMILY",
        help="only this problem family (repeatable; default: all)",
    )
    evaluate.add_argument(
        "--format",
        choices=("markdown", "json", "csv"),
        default="markdown",
        help="output format (default markdown)",
    )
    evaluate.set_defaults(handler=_evaluate, subparser=evaluate)


def _evaluate(args: argparse.Namespace) -> int:
    from optbound import evaluate, problems
    from optbound.problems import registry

    if args.estimator == registry.ALL_REGISTERED:
        raise CommandError(f"evaluate takes one estimator; {args.estimator!r} is for bench")
    try:
        estimator = registry.resolve([args.estimator])[args.estimator]
        todo = problems.suite(args.suite, families=args.family, seed=args.seed)
    except ValueError as exc:
        raise CommandError(str(exc)) from None
    result = evaluate(estimator, todo, name=args.estimator)
    render = {"markdown": result.to_markdown, "json": result.to_json, "csv": result.to_csv}
    text = render[args.format]()
    sys.stdout.write(text if text.endswith("\n") else text + "\n")
    return 0


def _user_estimators(args: argparse.Namespace) -> dict:
    """The ``--estimator`` callables by name, loaded before any work (a bad one: exit 2)."""
    from optbound.problems import registry

    try:
        estimators = registry.resolve(args.estimator or [])
    except ValueError as exc:
        raise CommandError(f"--estimator: {exc}") from None
    if args.estimator and not estimators:
        raise CommandError(
            f"--estimator {registry.ALL_REGISTERED}: no estimator is registered under the "
            f"entry-point group {registry.GROUP!r} (is optbound installed, not only on the path?)"
        )
    return estimators


def _version() -> str:
    from optbound import __version__

    return f"optbound {__version__}"


#: The arguments of each command that decide its results, with their defaults: stored in the
#: run folder and repeated by --resume.
_RUN_ARGUMENTS = {
    "bench": {"suite": "quick", "seed": 0, "family": None, "estimator": None},
    "repro": {"papers": [], "quick": False},
}


def _resolve_run_arguments(args: argparse.Namespace) -> RunFolder:
    """Fill in the run arguments: from ``--resume DIR``'s stored ones, else the defaults.

    Returns the run folder (:class:`optbound.bench.run_folder.RunFolder`). With
    ``--resume``, an argument given that differs from the stored one is an error.
    """
    from optbound.bench.run_folder import RunFolder, RunFolderError

    defaults = _RUN_ARGUMENTS[args.command]
    if args.resume is None:
        for key, default in defaults.items():
            if getattr(args, key) is None:
                setattr(args, key, default)
        args.out = args.out or args.default_out
        return RunFolder(
            args.out, {"command": args.command, **{k: getattr(args, k) for k in defaults}}
        )
    if args.force:
        raise CommandError("--resume finishes a run; it cannot be combined with --force")
    if args.out is not None and args.out.resolve() != args.resume.resolve():
        raise CommandError(f"--out {str(args.out)!r} differs from --resume {str(args.resume)!r}")
    try:
        folder = RunFolder.open(args.resume)
    except RunFolderError as exc:
        raise CommandError(f"--resume: {exc}") from None
    stored = folder.arguments
    if stored.get("command") != args.command:
        raise CommandError(
            f"--resume: {str(args.resume)!r} holds a run of optbound {stored.get('command')}, "
            f"not of optbound {args.command}"
        )
    for key in defaults:
        given = getattr(args, key)
        # Not given: None (bench), or the parser's empty value (repro's papers and --quick).
        if not (given is None or given is False or given == []) and given != stored[key]:
            raise CommandError(
                f"--resume: the run in {str(args.resume)!r} was started with {key} "
                f"{stored[key]!r}, not {given!r}; leave {key} out to resume it"
            )
        setattr(args, key, stored[key])
    args.out = args.resume
    return folder


def _bench(args: argparse.Namespace) -> int:
    from optbound import report

    args.folder = _resolve_run_arguments(args)
    readme = None
    if args.update_readme:
        meta = {"suite": args.suite, "seed": args.seed, "complete": not args.family}
        refusal = report.headline_refusal(meta)
        if refusal:
            raise CommandError(f"--update-readme: {refusal}")
        readme = report.source_readme()
        if readme is None:
            raise CommandError("--update-readme: no docs/benchmarks.md with headline markers found")
    estimators = _user_estimators(args)
    out = _prepare(args)
    results = _run(args, args.suite, args.seed, names=args.family, folder=args.folder)
    if estimators:
        from optbound.bench.user_estimators import run_estimators

        results["estimators"] = run_estimators(estimators, args.suite, args.seed, args.family)
    path = _write(results, out, jobs=args.jobs)
    _print_summary(results, path)
    if readme is not None and report.update_readme(readme, results):
        print(f"Headline numbers written into {readme}")
    return 0


def _repro(args: argparse.Namespace) -> int:
    from optbound.papers_repro._common import scripts

    args.folder = _resolve_run_arguments(args)
    try:
        selected = {script.name for script in scripts(args.papers or None)}
    except ValueError as exc:
        raise CommandError(str(exc)) from None
    out = _prepare(args)
    suite = "quick" if args.quick else "full"
    command = " ".join(["optbound repro", *args.papers, *(["--quick"] if args.quick else [])])
    results = _run(
        args,
        suite,
        0,
        names=["papers"],
        where=lambda t: t["script"] in selected,
        command=command,
        folder=args.folder,
    )
    path = _write(results, out, jobs=args.jobs)
    _print_summary(results, path)
    return 0


def _prepare(args: argparse.Namespace) -> Path:
    """Check the executor, then create and check ``--out``: all before any work.

    The folders this creates are recorded in ``args.created`` so that a run that stops
    before writing anything into them (an error, Ctrl-C) removes them again. A fresh run
    (no ``--resume``) forgets the tasks an earlier run stored in the folder (``--force``).
    """
    from optbound.bench.executors import check_available
    from optbound.report.outdir import OutDirError, prepare_out_dir

    try:
        check_available(args.executor, args.scheduler)
    except ValueError as exc:
        raise CommandError(str(exc)) from None
    args.created = [p for p in (args.out, *args.out.parents) if not p.exists()]
    if args.resume is not None:
        return args.out
    try:
        out = prepare_out_dir(args.out, args.force)
    except OutDirError as exc:
        raise CommandError(str(exc)) from None
    args.folder.clear()
    return out


def _remove_if_empty(folders: list[Path]) -> None:
    """Remove ``folders`` (innermost first) while they exist and are empty."""
    for folder in folders:
        if not folder.is_dir() or any(folder.iterdir()):
            return
        folder.rmdir()


def _run(args: argparse.Namespace, suite: str, seed: int, **selection) -> dict:
    from optbound.bench.runner import run_suite

    try:
        results = run_suite(
            suite,
            seed,
            args.jobs,
            progress=not args.no_progress,
            executor=args.executor,
            scheduler=args.scheduler,
            **selection,
        )
    except (ValueError, OSError) as exc:  # dask missing, scheduler unreachable
        raise CommandError(f"{type(exc).__name__}: {exc}") from None
    results["meta"]["since_start_s"] = _since_process_start()
    return results


def _write(results: dict, out: Path, save: bool = True, jobs: int = 1) -> Path:
    """Write the report (and, if ``save``, results.json), drawing its figures in ``jobs``
    processes; a filesystem error is a CommandError."""
    from optbound import report

    try:
        if save:
            report.save_results(results, out)
        return report.write_report(results, out, jobs=jobs)
    except OSError as exc:
        raise CommandError(f"cannot write the report into {str(out)!r}: {exc}") from None


def _report(args: argparse.Namespace) -> int:
    from optbound import report

    try:
        results = report.load_results(args.dir)
    except ValueError as exc:
        args.subparser.error(str(exc))
    # The figures are drawn over as many processes as the run had.
    path = _write(results, args.dir, save=False, jobs=results["meta"].get("jobs", 1))
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
    print(f"\nReport: {path} (wall time {_since_process_start():.1f} s since the command started)")


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help()
        return 0
    try:
        return args.handler(args)
    except CommandError as exc:
        _remove_if_empty(getattr(args, "created", []))
        print(f"optbound {args.command}: error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:
        _remove_if_empty(getattr(args, "created", []))
        print(f"optbound {args.command}: interrupted{_resumable(args)}", file=sys.stderr)
        return EXIT_INTERRUPTED


def _resumable(args: argparse.Namespace) -> str:
    """How to finish an interrupted run whose folder holds finished tasks ("" if none)."""
    folder = getattr(args, "folder", None)
    if folder is None or not any(folder.tasks.glob("*.json")):
        return ""
    return f"; finish it with: optbound {args.command} --resume {folder.path}"


def run() -> None:
    """Run the ``optbound`` console command (:func:`main`) and exit with its status.

    Once the command's work is done and the exit handlers have run (worker pools joined,
    temporary markers removed), Python's teardown of its modules (numba's and LLVM's, cvxpy's,
    matplotlib's objects) only frees memory that the operating system frees anyway, and takes
    about half a second the user would wait for; the process exits without it.

    numba's error messages are plain text in the command's processes (set before numba is
    imported, inherited by the workers): typing a kernel, numba tries the overload templates of
    each operation in turn and formats, with terminal highlighting, the error of every template
    that does not match (tens of thousands in the analytic kernels' compile); plain text
    costs less (issue 23; measured in ``benchmarks/compile_cost.md``).
    """
    os.environ.setdefault("NUMBA_DISABLE_ERROR_MESSAGE_HIGHLIGHTING", "1")
    code = main()
    atexit._run_exitfuncs()  # what sys.exit would run, before the skipped teardown
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)


if __name__ == "__main__":
    run()
