"""The speed benchmarks name the instruction set numba compiled for."""

import llvmlite.binding as ll
import numba

from optbound.bench.target import numba_target


def test_names_the_host_cpu_and_its_widest_vector_set(monkeypatch):
    monkeypatch.setattr(numba.config, "CPU_NAME", None)
    monkeypatch.setattr(numba.config, "CPU_FEATURES", None)
    text = numba_target()
    assert text.startswith(f"host CPU {ll.get_host_cpu_name()}, ")
    features = ll.get_host_cpu_features()
    if features.get("avx512f"):
        assert "AVX-512" in text
    elif features.get("avx2"):
        assert "AVX2" in text and "AVX-512" not in text


def test_names_the_cpu_numba_is_told_to_compile_for(monkeypatch):
    monkeypatch.setattr(numba.config, "CPU_NAME", "haswell")
    monkeypatch.setattr(numba.config, "CPU_FEATURES", None)
    host = ll.get_host_cpu_name()
    assert numba_target() == f"CPU haswell set by NUMBA_CPU_NAME (host CPU {host})"
