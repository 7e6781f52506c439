"""Imported first by every subpackage that defines numba kernels: drops stale kernel caches.

Python runs a module once per process, so the first such subpackage imported runs
:func:`optbound._jit_cache.refresh` before any kernel is loaded from numba's cache, and the
others find it done (see :mod:`optbound._jit_cache` for why).
"""

from optbound import _jit_cache

_jit_cache.refresh()
