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

With ``--jobs N`` (N > 1) the child runs the real ``optbound bench --jobs N`` instead, with its
cold-cache warm-up (``optbound.bench.warmup``) and its pool of task workers, and every process
of the run logs its compiles (``benchmarks/_compile_log/sitecustomize.py``, on the child's
``PYTHONPATH`` only). The report then gives the compile CPU per process, the dispatchers
compiled in more than one process (the same work done twice), and the compiles left to the task
workers and the parent (kernels no warm-up group covers). It also measures, in another fresh
process, numba's fixed cost of a compile whatever the code (set-up per process, a one-loop
function with and without numba's wrappers) and prints the part of the run's compile CPU that
fixed cost accounts for.

Run: ``python -m benchmarks.compile_cost [--suite tiny|quick] [--jobs N]``.
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

import numpy as np

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


_HOOK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "_compile_log")


def measure_jobs(suite: str, jobs: int) -> dict:
    """Every compile of ``optbound bench --jobs jobs`` in a child with an empty numba cache."""
    with tempfile.TemporaryDirectory() as tmp:
        log = os.path.join(tmp, "compiles.jsonl")
        path = os.pathsep.join(filter(None, [_HOOK, os.environ.get("PYTHONPATH")]))
        env = {**os.environ, "NUMBA_CACHE_DIR": os.path.join(tmp, "cache"),
               "OPTBOUND_COMPILE_LOG": log, "PYTHONPATH": path}  # fmt: skip
        env.pop("OPTBOUND_COMPILE_LOG_ROOT", None)
        command = [sys.executable, "-m", "optbound.cli", "bench", "--suite", suite]
        command += ["--jobs", str(jobs), "--no-progress", "--force", "--out", f"{tmp}/out"]
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        done = subprocess.run(command, env=env, capture_output=True, text=True)
        wall = time.perf_counter() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        if done.returncode != 0:
            raise RuntimeError(f"optbound bench failed:\n{done.stderr[-3000:]}")
        with open(log) as fh:
            events = [json.loads(line) for line in fh]
    run_cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    return {"events": events, "run_cpu": run_cpu, "run_wall": wall}


def _loop():
    """A new function object each call (numba compiles per function object): a loop over an
    array, about the smallest thing a kernel is."""

    def kernel(a, b):
        s = 0.0
        for k in range(a.shape[0]):
            s += a[k] * b
        return s

    return kernel


def _fixed(repeats: int) -> dict:
    """numba's cost of compiling anything, here (run in a fresh process): the first compile's
    extra CPU (numba's typing and LLVM set-up, paid once per process) and the median CPU of a
    compile of :func:`_loop`'s function, with numba's Python and C wrappers (a kernel called
    from Python) and without them (a callee compiled for another compiled function: numba's
    own overloads, or ours with ``no_cpython_wrapper``), the latter as the median of a caller
    and such a callee less the median of one function."""
    from numba import njit

    a = np.ones(3)

    def compile_one() -> float:
        start = _thread_cpu()
        njit(_loop())(a, 2.0)
        return _thread_cpu() - start

    def compile_pair() -> float:
        callee = njit(no_cpython_wrapper=True, no_cfunc_wrapper=True)(_loop())

        def caller(a, b):
            return callee(a, b) + 1.0

        start = _thread_cpu()
        njit(caller)(a, 2.0)
        return _thread_cpu() - start

    first = compile_one()
    one = float(np.median([compile_one() for _ in range(repeats)]))
    pair = float(np.median([compile_pair() for _ in range(repeats)]))
    return {"setup": first - one, "with_wrappers": one, "without_wrappers": pair - one}


def measure_fixed(repeats: int = 15) -> dict:
    """:func:`_fixed` in a child process (a fresh numba)."""
    code = f"import json, benchmarks.compile_cost as m; print(json.dumps(m._fixed({repeats})))"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return json.loads(done.stdout.strip().splitlines()[-1])


def report_fixed(fixed: dict, processes: int, compiles: int, total: float) -> None:
    """The part of a run's compile CPU that is numba's fixed cost, whatever the code."""
    floor = processes * fixed["setup"] + compiles * fixed["without_wrappers"]
    print(f"\nnumba's fixed cost, measured in a fresh process: {fixed['setup']:.2f} s to set up "
          f"(once per process), {1e3 * fixed['with_wrappers']:.0f} ms per compile of a one-loop "
          f"function called from Python, {1e3 * fixed['without_wrappers']:.0f} ms without "
          f"numba's Python and C wrappers. For {processes} processes and {compiles} compiles "
          f"that is at least {floor:.1f} s of the {total:.1f} s, whatever the kernels "
          "hold.")  # fmt: skip


def report_jobs(result: dict, suite: str, jobs: int, top: int) -> None:
    """Print the compile CPU per process, numba's fixed part of it (``result["fixed"]``, from
    :func:`measure_fixed`), per module (the ``top`` largest), the duplicates and the compiles
    left to tasks."""
    events = result["events"]
    procs: dict = defaultdict(lambda: {"roles": set(), "cpu": 0.0, "n": 0})
    for e in events:
        proc = procs[e["pid"]]
        proc["roles"].add(e["role"].split(":")[0] if e["role"].startswith("task") else e["role"])
        proc["n"] += 1
        proc["cpu"] += e["inclusive"] if e["top"] else 0.0
    total = sum(p["cpu"] for p in procs.values())
    print(f"bench --suite {suite} --jobs {jobs} with an empty numba cache: {total:.1f} s CPU "
          f"compiling in {len(procs)} processes ({len(events)} compiles); the whole run "
          f"{result['run_cpu']:.1f} s CPU, {result['run_wall']:.1f} s wall")  # fmt: skip
    report_fixed(result["fixed"], len(procs), len(events), total)
    print("\n| process | role | compiles | compile CPU s |")
    print("|---|---|---|---|")
    for pid, p in sorted(procs.items(), key=lambda kv: -kv[1]["cpu"]):
        print(f"| {pid} | {', '.join(sorted(p['roles']))} | {p['n']} | {p['cpu']:.2f} |")
    by_module: dict = defaultdict(float)  # numba's own overloads (string formatting, ...)
    for e in events:  # are under their numba module: what our kernels pulled in
        by_module[e["name"].split(".<locals>")[0].rsplit(".", 1)[0]] += e["self"]
    print("\n| module (all processes) | self CPU s |")
    print("|---|---|")
    for module, spent in sorted(by_module.items(), key=lambda kv: -kv[1])[:top]:
        print(f"| {module} | {spent:.2f} |")
    where: dict = defaultdict(lambda: defaultdict(float))  # (name, types) -> pid -> self CPU
    for e in events:
        where[e["name"], e["types"]][e["pid"]] += e["self"]
    dup = {key: pids for key, pids in where.items() if len(pids) > 1}
    extra = sum(sum(p.values()) - max(p.values()) for p in dup.values())
    print(f"\nCompiled in more than one process: {len(dup)} specialisations, {extra:.2f} s CPU "
          "beyond one compile each")  # fmt: skip
    print("\n| dispatcher | types | processes | self CPU s (sum) |")
    print("|---|---|---|---|")
    for (name, types), pids in sorted(dup.items(), key=lambda kv: -sum(kv[1].values())):
        kinds = types if len(types) <= 60 else types[:57] + "..."
        print(f"| {name} | {kinds} | {len(pids)} | {sum(pids.values()):.2f} |")
    per_name: dict = defaultdict(set)
    for e in events:
        per_name[e["name"]].add(e["types"])
    multi = {name: t for name, t in per_name.items() if len(t) > 1}
    print(f"\nDispatchers compiled for more than one type signature: {len(multi)}")
    for name, kinds in sorted(multi.items(), key=lambda kv: -len(kv[1])):
        print(f"- {name}: {len(kinds)}")
    late = [e for e in events if not e["role"].startswith("warmup")]
    print(f"\nCompiled outside the warm-up (task workers, the parent): {len(late)} compiles, "
          f"{sum(e['self'] for e in late):.2f} s self CPU")  # fmt: skip
    print("\n| role:family | dispatcher | types | self CPU s |")
    print("|---|---|---|---|")
    for e in sorted(late, key=lambda e: -e["self"]):
        kinds = e["types"] if len(e["types"]) <= 50 else e["types"][:47] + "..."
        print(f"| {e['role']} | {e['name']} | {kinds} | {e['self']:.2f} |")


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--suite", choices=("tiny", "quick"), default="tiny")
    parser.add_argument("--jobs", type=int, default=1, help="> 1: the real run, all processes")
    parser.add_argument("--top", type=int, default=40, help="rows shown (largest self time)")
    parser.add_argument("--json", help="also write the raw measurement to this file")
    args = parser.parse_args(argv)
    load = os.getloadavg()[0]
    if args.jobs > 1:
        result = {**measure_jobs(args.suite, args.jobs), "fixed": measure_fixed()}
        if args.json:
            with open(args.json, "w") as f:
                json.dump(result, f, indent=1)
        print(f"numba target: {numba_target()}; load average {load:.1f} at start, "
              f"{os.getloadavg()[0]:.1f} at end, on {os.cpu_count()} cores")  # fmt: skip
        report_jobs(result, args.suite, args.jobs, args.top)
        return
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
