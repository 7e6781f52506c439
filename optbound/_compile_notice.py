"""One line on stderr when a run compiles optbound's kernels, instead of minutes of silence.

numba compiles a kernel on its first call unless its on-disk cache holds it (the first run
after an install or after a kernel source changed, see ``optbound._jit_cache``). numba's
``numba:compile`` event fires only for such a real compile, never for a load from the cache,
so a listener on it announces exactly the runs that compile, and nothing when the cache is
warm.

One line per run, not per process: the first process that imports a kernel subpackage
(through ``optbound._fresh``) names a marker file in the environment
(``OPTBOUND_COMPILE_NOTICE``), which its worker processes inherit; the process that creates
the marker first prints the line, and the owner removes the marker at exit.
"""

from __future__ import annotations

import atexit
import os
import sys
import tempfile
from pathlib import Path

from numba.core import event

ENV = "OPTBOUND_COMPILE_NOTICE"
#: CPU seconds of a compile of every kernel ``optbound bench`` uses, rounded up, in all the
#: run's processes, as measured by ``python -m benchmarks.compile_cost --suite quick --jobs 2``
#: (44-47 s on the 2-core Intel Xeon test host at load 0.0-1.5, numba 0.68). With two or more
#: workers the warm-up (``optbound.bench.warmup``) splits it over two processes, so the first
#: run waits about half of it longer than later runs (``python -m benchmarks.first_run``).
COMPILE_CPU_SECONDS = 50
MESSAGE = (
    "optbound: compiling numerical kernels once (first run only: about {seconds} s of CPU, "
    "spread over the worker processes; later runs load them from numba's cache) ..."
)


class Notice(event.Listener):
    """Prints :data:`MESSAGE` once, at the first compile of a function of ``modules``, unless
    another process of the run (sharing ``marker``) printed it already."""

    def __init__(self, marker: Path, modules: tuple[str, ...] = ("optbound",), stream=None):
        self.marker, self.modules, self.stream = Path(marker), modules, stream
        self.done = False

    def on_start(self, ev) -> None:
        if self.done:
            return
        module = getattr(ev.data["dispatcher"].py_func, "__module__", "") or ""
        if not module.startswith(self.modules):
            return
        self.done = True
        try:
            os.close(os.open(self.marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY))
        except FileExistsError:
            return  # another process of this run has said it
        except OSError:
            pass  # no marker possible: say it in this process
        stream = self.stream or sys.stderr
        print(MESSAGE.format(seconds=COMPILE_CPU_SECONDS), file=stream, flush=True)

    def on_end(self, ev) -> None:
        pass


def _remove(marker: Path) -> None:
    marker.unlink(missing_ok=True)


def install() -> Notice:
    """Register the run's :class:`Notice` for this process (called once, at import)."""
    if ENV not in os.environ:
        marker = Path(tempfile.gettempdir()) / f"optbound-compile-notice-{os.getpid()}"
        os.environ[ENV] = str(marker)
        atexit.register(_remove, marker)
    notice = Notice(Path(os.environ[ENV]))
    event.register("numba:compile", notice)
    return notice
