"""Keep numba's on-disk cache of optbound's compiled kernels consistent with their sources.

``@njit(cache=True)`` invalidates a cached function only when the file that defines it changes,
not when a jitted function it calls in *another* file changes: the analytic kernels inline
``analytic._kernels.midrad`` and ``_core.domain``, the polygon predicates inline
``interval.compiled``, and they would silently run stale machine code after an edit of those.
Before any kernel is loaded, one hash of every kernel source is compared with a stamp kept next
to the caches; when it differs, every cached kernel of the package is dropped (numba then
recompiles each once). Each subpackage that defines kernels imports :mod:`optbound._fresh`
first thing in its ``__init__``, which runs :func:`refresh` once per process, on the first import
of such a subpackage; ``import optbound`` alone reads and writes nothing.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

ROOT = Path(__file__).resolve().parent
STAMP = "optbound_kernels.stamp"
#: The subpackages that define kernels; each imports :mod:`optbound._fresh` before them.
KERNEL_PACKAGES = ("_core", "analytic", "interval", "localization", "optimal", "sets")


def kernel_sources(root: Path = ROOT) -> list[Path]:
    """The package's modules that define numba kernels (they mention ``njit``)."""
    return sorted(p for p in root.rglob("*.py") if b"njit" in p.read_bytes())


def refresh(cache_dirs=None, sources=None, stamp: str = STAMP) -> bool:
    """Drop all kernel caches if any kernel source changed; True if something was dropped.

    ``cache_dirs`` and ``sources`` default to the package's kernels; code compiled elsewhere
    that calls them (``optbound.bench.analytic_reference``) passes its own folders, its sources
    and the kernels', and its own ``stamp`` name. Never raises on file-system errors (a
    read-only install keeps numba's own behaviour).
    """
    sources = kernel_sources() if sources is None else sources
    digest = hashlib.sha256(b"".join(p.read_bytes() for p in sources)).hexdigest()
    dirs = cache_dirs or sorted({p.parent / "__pycache__" for p in sources})
    dropped = False
    for folder in dirs:
        marker = folder / stamp
        try:
            if marker.exists() and marker.read_text() == digest:
                continue
            for pattern in ("*.nbi", "*.nbc"):
                for f in folder.glob(pattern):
                    f.unlink()
                    dropped = True
            folder.mkdir(exist_ok=True)
            marker.write_text(digest)
        except OSError:
            continue
    return dropped
