"""Imported first by every subpackage that defines numba kernels: drops stale kernel caches.

Python runs a module once per process, so the first such subpackage imported runs
:func:`optbound._jit_cache.refresh` before any kernel is loaded from numba's cache, and the
others find it done (see :mod:`optbound._jit_cache` for why). It also installs the one-line
notice of :mod:`optbound._compile_notice`, printed if this run has to compile kernels.
"""

from optbound import _compile_notice, _jit_cache

_jit_cache.refresh()
_compile_notice.install()
