"""The cold-cache warm-up: which groups it finds uncompiled, and that it never stops a run."""

import json
import os
import subprocess
import sys

from optbound.bench import warmup
from optbound.bench.executors import executor


def test_every_group_is_cold_in_an_empty_cache(tmp_path):
    code = "import json; from optbound.bench import warmup; print(json.dumps(warmup.cold_groups()))"
    done = subprocess.run(
        [sys.executable, "-c", code],
        env={**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)},
        capture_output=True,
        text=True,
        check=True,
    )
    cold = json.loads(done.stdout.strip().splitlines()[-1])
    assert cold == sorted(warmup.GROUPS, key=lambda name: -warmup.GROUPS[name][0])
    assert not list(tmp_path.rglob("*.nbi"))  # finding them cold compiled nothing


def test_compile_cold_runs_each_named_group_once(monkeypatch):
    calls = []
    groups = {
        "a": (2.0, lambda: calls.append("a"), "optbound.analytic._kernels.strip_kernel:fuse_range"),
        "b": (1.0, lambda: calls.append("b"), "optbound.analytic._kernels.strip_kernel:fuse_range"),
    }
    monkeypatch.setattr(warmup, "GROUPS", groups)
    with executor("process", 1) as pool:
        spent = warmup.compile_cold(pool, ["a", "b"])
    assert sorted(calls) == ["a", "b"]
    assert set(spent) == {"a", "b"} and all(isinstance(s, float) for s in spent.values())


def test_a_failing_group_is_reported_not_raised(monkeypatch):
    def fails():
        raise ValueError("no solver")

    monkeypatch.setattr(warmup, "GROUPS", {"bad": (1.0, fails, "optbound:__name__")})
    assert warmup.compile_group("bad") == ("bad", "ValueError: no solver")
