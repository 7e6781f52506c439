"""CPU seconds that numba spends compiling optbound's kernels for a bench run, per dispatcher.

A child process with an empty numba cache (``NUMBA_CACHE_DIR`` pointing at a new folder) runs
the bench suite in-process (``--jobs 1``, so that every compile happens where it is observed)
and records each compile through numba's ``numba:compile`` event, which fires only for a real
compile, never for a load from the cache. The time is the CPU time (user + system) of the
compiling thread (``RUSAGE_THREAD``), not wall time: it does not depend on the machine's load.

Rows: a dispatcher's *inclusive* time counts the callees it compiled on the way (they are
typed and compiled inside its compile), *self* leaves them out; the total is the sum of the
top-level compiles. The compiled types are listed too: one dispatcher compiled for several
argument types is compiled several times.

The suite's kernels are the same at every size, so the ``tiny`` suite (seconds of work)
compiles what ``quick`` compiles; ``--suite quick`` checks that on a quiet machine.

Run: ``python -m benchmarks.compile_cost [--suite tiny|quick]``.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from collections import defaultdict

from optbound.bench.target import numba_target


def _thread_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_THREAD)
    return usage.ru_utime + usage.ru_stime


def _record(suite: str) -> dict:
    """Run ``optbound bench --suite suite --jobs 1`` here, recording every numba compile."""
    from numba.core import event

    from optbound import cli

    stack: list[list] = []  # per open compile: [name, start cpu, cpu of nested compiles]
    rows: dict = defaultdict(lambda: {"inclusive": 0.0, "self": 0.0, "top": 0.0, "types": []})
    modules: dict = {}

    class Listener(event.Listener):
        def on_start(self, ev):
            py = ev.data["dispatcher"].py_func
            stack.append([f"{py.__module__}.{py.__qualname__}", _thread_cpu(), 0.0])
            modules[stack[-1][0]] = py.__module__
            rows[stack[-1][0]]["types"].append(", ".join(map(str, ev.data["args"])))

        def on_end(self, ev):
            name, start, nested = stack.pop()
            spent = _thread_cpu() - start
            row = rows[name]
            row["inclusive"] += spent
            row["self"] += spent - nested
            if stack:
                stack[-1][2] += spent
            else:
                row["top"] += spent

    cpu0, wall0 = time.process_time(), time.perf_counter()
    with tempfile.TemporaryDirectory() as out:
        event.register("numba:compile", Listener())
        cli.main(["bench", "--suite", suite, "--jobs", "1", "--no-progress", "--force",
                  "--out", out])  # fmt: skip
    return {
        "rows": {name: {**row, "module": modules[name]} for name, row in rows.items()},
        "run_cpu": time.process_time() - cpu0,
        "run_wall": time.perf_counter() - wall0,
    }


def measure(suite: str) -> dict:
    """Compile costs of ``suite`` in a child process with an empty numba cache."""
    with tempfile.TemporaryDirectory() as cache:
        env = {**os.environ, "NUMBA_CACHE_DIR": cache}
        code = f"import json, benchmarks.compile_cost as m; print(json.dumps(m._record({suite!r})))"
        done = subprocess.run(
            [sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True
        )
    return json.loads(done.stdout.strip().splitlines()[-1])


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--suite", choices=("tiny", "quick"), default="tiny")
    parser.add_argument("--top", type=int, default=40, help="rows shown (largest self time)")
    parser.add_argument("--json", help="also write the raw measurement to this file")
    args = parser.parse_args(argv)
    load = os.getloadavg()[0]
    result = measure(args.suite)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(result, f, indent=1)
    rows = result["rows"]
    total = sum(r["top"] for r in rows.values())
    print(f"numba target: {numba_target()}; load average {load:.1f} at start, "
          f"{os.getloadavg()[0]:.1f} at end, on {os.cpu_count()} cores")  # fmt: skip
    print(f"bench --suite {args.suite} --jobs 1 with an empty numba cache: {total:.1f} s CPU "
          f"compiling ({len(rows)} dispatchers, "
          f"{sum(len(r['types']) for r in rows.values())} compiles), "
          f"{result['run_cpu']:.1f} s CPU for the whole run")  # fmt: skip
    print("\n| dispatcher | compiles | self CPU s | inclusive CPU s | types |")
    print("|---|---|---|---|---|")
    ranked = sorted(rows.items(), key=lambda kv: -kv[1]["self"])
    for name, r in ranked[: args.top]:
        kinds = "; ".join(sorted(set(r["types"])))
        if len(kinds) > 80:
            kinds = kinds[:77] + "..."
        print(f"| {name} | {len(r['types'])} | {r['self']:.2f} | {r['inclusive']:.2f} | {kinds} |")
    by_module: dict = defaultdict(float)
    for r in rows.values():
        by_module[r["module"]] += r["self"]
    print("\n| module | self CPU s |")
    print("|---|---|")
    for module, spent in sorted(by_module.items(), key=lambda kv: -kv[1]):
        print(f"| {module} | {spent:.2f} |")


if __name__ == "__main__":
    main()
