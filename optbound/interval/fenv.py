"""The floating-point rounding mode: optbound's interval work runs in round-to-nearest.

The outward steps of :mod:`optbound.interval._rounding` assume round-to-nearest (in
round-upward, ``-MAX * (1 + 2^-52)`` rounds back to ``-MAX`` instead of ``-inf``). Other
libraries in the same process may change the mode process-wide: codac's interval backend,
gaol, sets round-upward when codac is imported and relies on it. :func:`round_to_nearest`
switches to round-to-nearest for the duration of a block and then restores the caller's
mode, so optbound computes correctly after ``import codac`` and codac keeps working after
optbound ran. The mode is per thread; the guard costs two to four C calls (well under a
microsecond each).

The switch uses C99 ``fegetround``/``fesetround`` from the C math library through ctypes.
``FE_TONEAREST`` is 0 on every platform glibc and macOS support; the caller's mode is put
back as ``fegetround`` returned it. Without a usable C library (e.g. Windows) the mode is left
alone, and :func:`optbound.interval.pave` refuses to run in a wrong one.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import functools
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TypeVar

FE_TONEAREST = 0

F = TypeVar("F", bound=Callable)


def _libm():
    name = ctypes.util.find_library("m")
    try:
        lib = ctypes.CDLL(name) if name else None
    except OSError:
        return None
    if lib is None or not all(hasattr(lib, f) for f in ("fegetround", "fesetround")):
        return None
    lib.fegetround.restype = ctypes.c_int
    lib.fesetround.argtypes = [ctypes.c_int]
    lib.fesetround.restype = ctypes.c_int
    return lib


_LIBM = _libm()


def get_rounding() -> int | None:
    """Return the current rounding mode as ``fegetround`` reports it.

    Returns
    -------
    int or None
        The mode; None without a C library.
    """
    return None if _LIBM is None else int(_LIBM.fegetround())


def set_rounding(mode: int) -> None:
    """Set the rounding mode (a ``fegetround`` value); a no-op without a C library.

    Parameters
    ----------
    mode : int
        A value of ``fegetround`` (e.g. ``FE_TONEAREST``).

    Raises
    ------
    ValueError
        If the C library refuses ``mode``.
    """
    if _LIBM is not None and _LIBM.fesetround(int(mode)) != 0:
        raise ValueError(f"mode {mode} is not a rounding mode of this platform")


@contextmanager
def round_to_nearest() -> Iterator[None]:
    """Compute in round-to-nearest inside the block; restore the caller's mode afterwards.

    The mode is restored even if code inside the block changed it (e.g. ``import codac``).
    """
    before = get_rounding()
    if before is None:
        yield
        return
    if before != FE_TONEAREST:
        set_rounding(FE_TONEAREST)
    try:
        yield
    finally:
        if get_rounding() != before:
            set_rounding(before)


def nearest(fn: F) -> F:
    """Decorate ``fn`` to run inside :func:`round_to_nearest`.

    Parameters
    ----------
    fn : callable
        The function.

    Returns
    -------
    callable
        ``fn`` wrapped (same signature and metadata).
    """

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        with round_to_nearest():
            return fn(*args, **kwargs)

    return wrapper  # type: ignore[return-value]
