"""Keep numba's on-disk cache of the analytic kernels consistent with their sources.

``@njit(cache=True)`` invalidates a cached function only when the file that defines it changes,
not when a jitted function it calls (in another file) changes: the kernels in
``_strip_kernel`` and ``_minkowski_kernel`` inline ``_midrad``, ``_cubic``, ``_strip_lambda``
and ``sets._domain``, and would silently run stale machine code after an edit of those. Before
any kernel is loaded, this compares one hash of all the kernel sources with a stamp kept next
to the cache and drops the kernels' cache files when it differs (numba then recompiles once).
"""

from __future__ import annotations

import hashlib
from pathlib import Path

_ROOT = Path(__file__).resolve().parents[1]
SOURCES = (
    _ROOT / "sets" / "_domain.py",
    _ROOT / "analytic" / "_midrad.py",
    _ROOT / "analytic" / "_cubic.py",
    _ROOT / "analytic" / "_strip_lambda.py",
    _ROOT / "analytic" / "_strip_kernel.py",
    _ROOT / "analytic" / "_minkowski_kernel.py",
)
STAMP = "optbound_kernels.stamp"


def refresh(cache_dirs=None) -> bool:
    """Drop stale kernel caches; True if something was dropped. Never raises (a read-only
    install just keeps numba's own behaviour)."""
    digest = hashlib.sha256(b"".join(p.read_bytes() for p in SOURCES)).hexdigest()
    dirs = cache_dirs or sorted({p.parent / "__pycache__" for p in SOURCES})
    dropped = False
    for folder in dirs:
        stamp = folder / STAMP
        try:
            if stamp.exists() and stamp.read_text() == digest:
                continue
            for src in SOURCES:
                for pattern in (f"{src.stem}.*.nbi", f"{src.stem}.*.nbc"):
                    for f in folder.glob(pattern):
                        f.unlink()
                        dropped = True
            folder.mkdir(exist_ok=True)
            stamp.write_text(digest)
        except OSError:
            continue
    return dropped
