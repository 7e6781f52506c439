"""Waiting for another thread without sleeping: a flag polled in compiled code, GIL released.

A thread that blocks on a lock sleeps, and waking a sleeping core is slow: on the 2-vCPU test
machine a batch of 1e3 strip updates split over two threads took ~30 µs longer whenever a
thread had to be woken (as long as 600 updates). So the threads of a sliced batch
(``threads``) first poll flags for a bounded time, and sleep on a lock only if that is not
enough: a worker polls for its next slice after each one, the caller for the workers' results.
Every poll runs without the GIL, and a flag is set only where its setter holds no GIL either
(in a kernel, or together with the next poll), so that the thread that sees it can take the
GIL without sleeping.

numba has no atomics on the CPU, so the flag's two accesses are LLVM atomic instructions
(acquire / release: everything the worker wrote before setting the flag is visible to the
caller after it sees the flag), and the poll loop pauses the core between reads (x86
``pause``: it tells the core it is a spin loop, which saves power and the other hyperthread).
"""

from __future__ import annotations

import platform

from llvmlite import ir
from numba import njit, types
from numba.core import cgutils
from numba.extending import intrinsic

_X86 = platform.machine().lower() in ("x86_64", "amd64", "i386", "i686")


def _element_pointer(context, builder, signature, args):
    array_type = signature.args[0]
    array = context.make_array(array_type)(context, builder, args[0])
    return cgutils.get_item_pointer(context, builder, array_type, array, [args[1]])


@intrinsic
def _load_acquire(typingctx, array, index):
    """``array[index]`` (int64) as an atomic load with acquire ordering."""

    def codegen(context, builder, signature, args):
        pointer = _element_pointer(context, builder, signature, args)
        return builder.load_atomic(pointer, "acquire", 8)

    return types.int64(array, index), codegen


@intrinsic
def _store_release(typingctx, array, index, value):
    """``array[index] = value`` (int64) as an atomic store with release ordering."""

    def codegen(context, builder, signature, args):
        pointer = _element_pointer(context, builder, signature, args)
        builder.store_atomic(args[2], pointer, "release", 8)
        return context.get_dummy_value()

    return types.void(array, index, value), codegen


@intrinsic
def _pause(typingctx):
    """The x86 spin-loop hint (nothing elsewhere)."""

    def codegen(context, builder, signature, args):
        if _X86:
            hint = cgutils.get_or_insert_function(
                builder.module, ir.FunctionType(ir.VoidType(), []), "llvm.x86.sse2.pause"
            )
            builder.call(hint, [])
        return context.get_dummy_value()

    return types.void(), codegen


@njit(cache=True, nogil=True)
def wait_for(flag, value, polls):
    """Poll ``flag[0]`` until it equals ``value`` (True) or ``polls`` reads have failed
    (False), without the GIL."""
    for _ in range(polls):
        if _load_acquire(flag, 0) == value:
            return True
        _pause()
    return False


@njit(cache=True, nogil=True)
def publish(flag, value):
    """``flag[0] = value`` after every write before it (release), without the GIL."""
    _store_release(flag, 0, value)


@njit(cache=True, nogil=True)
def handoff(flag, value, post, expected, polls):
    """:func:`publish` ``flag[0] = value``, then :func:`wait_for` ``post[0] == expected``: a
    worker's end of one slice and its wait for the next, without taking the GIL between."""
    publish(flag, value)
    return wait_for(post, expected, polls)


@njit(cache=True, nogil=True, inline="always")
def post_slices(posts):
    """``posts[w, 0] = posts[w, 1]`` for every row (release): the calling thread, in its
    kernel, hands the workers their slices (``posts`` may have no rows)."""
    for w in range(posts.shape[0]):
        _store_release(posts[w], 0, posts[w, 1])
