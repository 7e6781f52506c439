"""The cold-cache warm-up: which groups it finds uncompiled, and that it never stops a run."""

import importlib
import json
import os
import subprocess
import sys

from optbound.bench import warmup


def test_every_group_is_cold_in_an_empty_cache(tmp_path):
    # optbound.interval compiles its ufuncs when imported (as in every run): before the probes.
    code = (
        "import json, pathlib, sys; import optbound.interval; from optbound.bench import warmup;"
        "index = lambda: sorted(map(str, pathlib.Path(sys.argv[1]).rglob('*.nbi')));"
        "before = index(); cold = warmup.cold_groups();"
        "print(json.dumps([cold, before, index()]))"
    )
    done = subprocess.run(
        [sys.executable, "-c", code, str(tmp_path)],
        env={**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)},
        capture_output=True,
        text=True,
        check=True,
    )
    cold, before, after = json.loads(done.stdout.strip().splitlines()[-1])
    assert cold == sorted(warmup.GROUPS, key=lambda name: -warmup.GROUPS[name][0])
    assert after == before  # finding them cold compiled nothing


def _fails():
    raise ValueError("no solver")


def test_compile_cold_runs_each_cold_group_once_and_reports_failures(monkeypatch):
    probe = "optbound.analytic._kernels.strip_kernel:fuse_range"
    groups = {"ok": (2.0, lambda: None, probe), "bad": (1.0, _fails, probe)}
    monkeypatch.setattr(warmup, "GROUPS", groups)
    monkeypatch.setattr(warmup, "cold_groups", lambda: ["ok", "bad"])
    done = warmup.compile_cold(2)  # a process pool (forked: it sees the patched groups)
    assert done.keys() == {"ok", "bad"} and isinstance(done["ok"], float)
    assert done["bad"] == "ValueError: no solver"
    assert warmup.compile_cold(1) == {}  # one process: nothing to split


def test_groups_probe_distinct_cached_kernels():
    """Each group names real cached kernels, and no kernel module is probed by two groups (the
    groups are disjoint: one process compiles each kernel). Nothing is compiled here."""
    from numba.core.caching import FunctionCache
    from numba.core.registry import CPUDispatcher

    modules = []
    for cost, calls, probes in warmup.GROUPS.values():
        assert cost > 0 and callable(calls) and probes
        for probe in probes:
            module, _, kernel = probe.partition(":")
            dispatcher = getattr(importlib.import_module(module), kernel)
            assert isinstance(dispatcher, CPUDispatcher)
            assert isinstance(dispatcher._cache, FunctionCache)  # @njit(cache=True)
            modules.append(module)
    assert len(modules) == len(set(modules))
