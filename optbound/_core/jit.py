"""``njit``: numba's ``njit`` with the options every optbound kernel shares.

Every compiled kernel of optbound and of the benchmarks' own kernels is declared with this
decorator, so that what numba builds next to each kernel is decided once (only
``benchmarks/compile_cost.py`` uses numba's ``njit`` directly: it measures numba's defaults):

- numba compiles, beside a kernel's machine code, a C-callable wrapper that lets the kernel be
  passed around as a first-class function value (``numba.cfunc``-style). No optbound kernel is
  used that way: compiled callers call each other directly or by address
  (``optbound._core.native_call``), and Python calls go through the Python
  wrapper. Skipping it (``no_cfunc_wrapper=True``) changes no machine code of the kernels and
  shortens the compile of a first ``optbound bench`` (issue 23; the measurement is in
  ``benchmarks/compile_cost.md``, the history in the CHANGELOG).

The keyword arguments are numba's (``cache``, ``error_model``, ``inline``, ``_nrt``, ...).
"""

from __future__ import annotations

from collections.abc import Callable

import numba


def njit(**options) -> Callable:
    """``numba.njit(**options)`` without the C-callable wrapper (module docstring).

    Parameters
    ----------
    **options
        numba's ``njit`` options; ``no_cfunc_wrapper`` is set here and may not be passed.

    Returns
    -------
    callable
        The decorator ``numba.njit`` returns for these options.
    """
    if "no_cfunc_wrapper" in options:
        raise TypeError("njit: no_cfunc_wrapper is set by optbound._core.jit, not by callers")
    return numba.njit(no_cfunc_wrapper=True, **options)
