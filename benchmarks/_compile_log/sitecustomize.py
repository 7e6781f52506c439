"""Log every numba compile of every process of a run (``benchmarks.compile_cost --jobs N``).

Put on ``PYTHONPATH`` for the measured child only: Python imports this ``sitecustomize`` at
start-up, in the child and in every process it spawns (forked workers inherit the listener).
Each finished compile appends one JSON line to the file named by ``OPTBOUND_COMPILE_LOG`` at
once, since pool workers may exit without running ``atexit``: the process id, its role (the
run's parent, a warm-up group, a task worker with the task's family), the dispatcher, the
argument types, and the compiling thread's CPU seconds, inclusive and self (the callees it
compiled on the way left out). Nothing is logged when the variable is unset.
"""

import json
import os
import resource
import sys

LOG = os.environ.get("OPTBOUND_COMPILE_LOG")
ROOT = "OPTBOUND_COMPILE_LOG_ROOT"


def _thread_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_THREAD)
    return usage.ru_utime + usage.ru_stime


def _role() -> str:
    """Who compiles: a warm-up group, a pooled or lone task (with its family), the parent."""
    frame = sys._getframe(2)
    while frame is not None:
        code = frame.f_code
        if code.co_name == "compile_group" and code.co_filename.endswith("warmup.py"):
            return f"warmup:{frame.f_locals.get('name')}"
        if code.co_name == "_run_registered" and code.co_filename.endswith("runner.py"):
            kind = "parent" if str(os.getpid()) == os.environ[ROOT] else "task"
            return f"{kind}:{frame.f_locals.get('name')}"
        frame = frame.f_back
    return "parent" if str(os.getpid()) == os.environ[ROOT] else "other"


def _install(path: str) -> None:
    from numba.core import event

    stack: list[list] = []  # per open compile: [name, types, role, start cpu, nested cpu]

    class Listener(event.Listener):
        def on_start(self, ev):
            py = ev.data["dispatcher"].py_func
            name = f"{py.__module__}.{py.__qualname__}"
            types = ", ".join(map(str, ev.data["args"]))
            stack.append([name, types, _role(), _thread_cpu(), 0.0])

        def on_end(self, ev):
            name, types, role, start, nested = stack.pop()
            spent = _thread_cpu() - start
            if stack:
                stack[-1][4] += spent
            line = {
                "pid": os.getpid(),
                "role": role,
                "name": name,
                "types": types,
                "inclusive": spent,
                "self": spent - nested,
                "top": not stack,
            }
            with open(path, "a") as fh:
                fh.write(json.dumps(line) + "\n")

    event.register("numba:compile", Listener())


if LOG:
    os.environ.setdefault(ROOT, str(os.getpid()))
    _install(LOG)
