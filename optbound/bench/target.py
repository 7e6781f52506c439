"""The instruction set numba compiles for: the CPU name and the vector extensions in use.

Throughput of the lane kernels (``optbound.analytic._kernels.lanes``) depends on the SIMD
width (8 doubles per AVX-512 register, 4 per AVX2 one), so every speed figure names it.
"""

from __future__ import annotations

import platform
from pathlib import Path

#: The vector extensions reported, narrowest first.
VECTOR_FEATURES = ("sse4.2", "avx", "avx2", "fma", "avx512f", "avx512vl")
_NAMES = {"avx512f": "AVX-512", "avx2": "AVX2", "avx": "AVX", "sse4.2": "SSE4.2"}


def numba_target() -> str:
    """Name the instruction set numba compiles for.

    Returns
    -------
    str
        ``"host CPU <name>, <widest vector set> (<extensions>)"``, or the CPU that
        ``NUMBA_CPU_NAME`` / ``NUMBA_CPU_FEATURES`` make numba compile for instead of the host.
    """
    import llvmlite.binding as ll
    import numba

    host = ll.get_host_cpu_name()
    if numba.config.CPU_NAME or numba.config.CPU_FEATURES:
        name = numba.config.CPU_NAME or host
        extra = f", features {numba.config.CPU_FEATURES}" if numba.config.CPU_FEATURES else ""
        return f"CPU {name} set by NUMBA_CPU_NAME{extra} (host CPU {host})"
    features = ll.get_host_cpu_features()
    present = [f for f in VECTOR_FEATURES if features.get(f)]
    widest = next((_NAMES[f] for f in reversed(present) if f in _NAMES), "no SIMD extension")
    return f"host CPU {host}, {widest} ({', '.join(present)})"


def processor_name() -> str:
    """Name the CPU model the run is on.

    Returns
    -------
    str
        The model name of ``/proc/cpuinfo`` on Linux, else ``platform.processor()``, else
        ``"unknown"``.
    """
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"
