"""The one-line compile notice: printed at the first real compile of a run, once, never for
work that needs no compile (a warm cache), and once per run across processes."""

from __future__ import annotations

import io
import os
import subprocess
import sys

from numba import njit
from numba.core import event

from optbound import _compile_notice


def _fresh_functions():
    """Two new, uncompiled dispatchers defined in this module (no disk cache)."""

    @njit
    def first(x):
        return x + 1.0

    @njit
    def second(x):
        return first(x) * 2.0

    return first, second


def test_one_line_at_the_first_compile_only(tmp_path):
    stream = io.StringIO()
    notice = _compile_notice.Notice(tmp_path / "marker", modules=(__name__,), stream=stream)
    first, second = _fresh_functions()
    with event.install_listener("numba:compile", notice):
        assert second(1.0) == 4.0  # compiles second, and first inside it
        first(2)  # a new type: another compile
    lines = stream.getvalue().splitlines()
    assert lines == [_compile_notice.MESSAGE.format(seconds=_compile_notice.COMPILE_CPU_SECONDS)]
    assert "compiling" in lines[0] and f"about {_compile_notice.COMPILE_CPU_SECONDS} s" in lines[0]


def test_silent_without_a_compile(tmp_path):
    _, second = _fresh_functions()
    second(1.0)  # compiled before the listener: later calls load nothing, compile nothing
    stream = io.StringIO()
    notice = _compile_notice.Notice(tmp_path / "marker", modules=(__name__,), stream=stream)
    with event.install_listener("numba:compile", notice):
        assert second(3.0) == 8.0
    assert stream.getvalue() == ""
    assert not (tmp_path / "marker").exists()


def test_silent_for_other_packages(tmp_path):
    stream = io.StringIO()
    notice = _compile_notice.Notice(
        tmp_path / "marker", modules=("not_this_module",), stream=stream
    )
    first, _ = _fresh_functions()
    with event.install_listener("numba:compile", notice):
        first(1.0)
    assert stream.getvalue() == ""


def test_once_per_run_across_processes(tmp_path):
    """A second process of the same run (same marker) stays silent."""
    streams = io.StringIO(), io.StringIO()
    for stream in streams:
        notice = _compile_notice.Notice(tmp_path / "marker", modules=(__name__,), stream=stream)
        first, _ = _fresh_functions()
        with event.install_listener("numba:compile", notice):
            first(1.0)
    assert len(streams[0].getvalue().splitlines()) == 1
    assert streams[1].getvalue() == ""


def _run(cache, env_extra=None):
    """A fresh interpreter calling one small optbound kernel with numba's cache in ``cache``."""
    code = (
        "import numpy as np; from optbound.sets._triangular import lower_inverse; "
        "lower_inverse(np.eye(2))"
    )
    env = {k: v for k, v in os.environ.items() if k != _compile_notice.ENV}
    env["NUMBA_CACHE_DIR"] = str(cache)
    done = subprocess.run(
        [sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True
    )
    return [line for line in done.stderr.splitlines() if line.startswith("optbound:")]


def test_end_to_end_cold_then_warm_cache(tmp_path):
    """With an empty cache the run says it compiles, in one line; with the cache warm, not."""
    message = _compile_notice.MESSAGE.format(seconds=_compile_notice.COMPILE_CPU_SECONDS)
    assert _run(tmp_path) == [message]
    assert _run(tmp_path) == []


def test_the_pages_quote_the_notices_estimate():
    # README and getting started state the compile CPU the notice prints: one number, so
    # they cannot drift apart when it is re-measured.
    from tests.doc_tables import ROOT

    said = f"about {_compile_notice.COMPILE_CPU_SECONDS} s of CPU"
    for page in ("README.md", "docs/getting_started.md"):
        text = " ".join((ROOT / page).read_text().split())
        assert said in text, f"{page} should say {said!r} (optbound._compile_notice)"
