"""Test-only benchmark families: one kills the process running a task, one blocks in a task.

They are registered by the tests that use them (``registry.FAMILIES``), in this process or,
for a run in a subprocess, by the code the subprocess runs.
"""

import dataclasses
import os
import signal
import time
from pathlib import Path

from optbound.bench.family import Family

#: Code that registers the sleeper in a subprocess started with ``python -c``.
REGISTER_SLEEPER = (
    "from optbound.bench import registry; "
    "registry.FAMILIES['sleeper'] = 'tests.bench.test_only_families:SLEEPER'; "
)
KILLED = 2  # the killer's task index (and seed) whose process is killed
#: Set in a run's environment, the path where the sleeper's first task signals that it runs,
#: before blocking for a minute (a run to be killed while the first tasks are stored).
BLOCK_ENV = "OPTBOUND_TEST_BLOCK_MARK"


def _seeds(suite: str, seed: int) -> list[dict]:
    return [{"seed": k} for k in range(5)]


def _kill(task: dict) -> dict:
    if task["seed"] == KILLED:
        os.kill(os.getpid(), signal.SIGKILL)
    time.sleep(0.2)  # the other worker is busy when the pool breaks
    return {"records": [{"family": "killer", "seed": task["seed"]}]}


def _block(task: dict) -> dict:
    mark = os.environ.get(BLOCK_ENV)
    if mark and task["seed"] == 0:
        Path(mark).touch()
        time.sleep(60)
    record = {"family": "sleeper", "seed": task["seed"], "name": "a task", "value": 1.0}
    return {"records": [{**record, "unit": "s"}]}


KILLER = Family(
    name="killer", title="Killer", kind="tightness", requires=(), tasks=_seeds, run=_kill
)
#: The killer's tasks run one at a time, each in its own child process.
KILLER_ISOLATED = dataclasses.replace(KILLER, parallel=False, isolated=True)
#: Serial: it runs after the pooled families, whose tasks are then all stored.
SLEEPER = Family(
    name="sleeper",
    title="Sleeper",
    kind="speed",
    requires=(),
    tasks=lambda suite, seed: _seeds(suite, seed)[:2],
    run=_block,
    parallel=False,
)
