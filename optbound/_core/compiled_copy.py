"""``copy_into``: the array copy that compiled kernels use instead of slice assignment.

In a numba kernel, ``dst[...] = src`` with an array ``src`` compiles numba's run-time shape
check, whose error message is an f-string of both shapes: formatting it compiles numba's
string machinery (``str`` of integers, ``join``, concatenation), about 3 s of CPU in every
process that compiles such a kernel with an empty cache (issue 23), for a message no caller
of ours can trigger. A loop over the elements compiles to the same copy without it.
"""

from __future__ import annotations

import numpy as np

from optbound._core.jit import njit


@njit(cache=True)
def copy_into(dst: np.ndarray, src: np.ndarray) -> None:
    """``dst[...] = src`` for C-contiguous arrays of one size (in element order).

    Raises ``ValueError`` if the sizes differ (a constant message: no string formatting);
    numba's ``reshape`` refuses an array that is not C-contiguous at run time.
    """
    flat_dst, flat_src = dst.reshape(dst.size), src.reshape(src.size)
    if flat_dst.size != flat_src.size:
        raise ValueError("copy_into: dst and src differ in size")
    for k in range(flat_src.size):
        flat_dst[k] = flat_src[k]
