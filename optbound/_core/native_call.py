"""Calls of a compiled kernel through its machine-code address, instead of linking it in.

When a compiled function calls another, numba links the callee's LLVM module into the caller's
and LLVM optimizes and emits the callee's code again there (and again in every other caller):
the lane loop nests of a heavy step cost their compile time once per caller. A call through an
address does not link anything: the callee is compiled once, in its own library, and each
caller holds only an indirect call. For a step called once per block of W lanes (the analytic
kernels' steps) or a search called once per robot (the tracker's LUVIA), the call costs
nothing measurable at run time.

The address is a run-time value (never a constant of the caller's code, so that numba's
on-disk cache stays valid across processes): :func:`address` compiles (or loads from the
cache) the callee for the argument types of the call and returns its entry point; the caller
(an ``njit`` kernel) receives it as an argument and calls :func:`caller`'s intrinsic with
it. The intrinsic checks, when the caller is compiled, that the callee has been compiled for
exactly the types it passes.
"""

from __future__ import annotations

from numba import types
from numba.core import cgutils
from numba.core.errors import TypingError
from numba.extending import intrinsic


def address(dispatcher, *args) -> int:
    """Entry point of ``dispatcher`` compiled for the types of ``args`` (compiled, or loaded
    from the cache, here): numba's calling convention, for :func:`caller`'s intrinsic."""
    sig = tuple(dispatcher.typeof_pyval(arg) for arg in args)
    dispatcher.compile(sig)
    cres = dispatcher.overloads[sig]
    return cres.library.get_pointer_to_function(cres.fndesc.llvm_func_name)


def caller(dispatcher):
    """An intrinsic ``call(addr, args)`` running ``dispatcher(*args)`` at ``addr`` (from
    :func:`address` with the same argument types); the callee returns nothing."""

    @intrinsic
    def call(typingctx, addr, args):
        if not isinstance(addr, types.Integer) or not isinstance(args, types.BaseTuple):
            return None
        argtys = tuple(args)
        if argtys not in dispatcher.overloads:
            raise TypingError(
                f"{dispatcher.py_func.__name__} is not compiled for {argtys}: pass the address "
                "native_call.address returned for the arguments of this call"
            )

        def codegen(context, builder, signature, llargs):
            fnty = context.call_conv.get_function_type(types.none, argtys)
            fn = builder.inttoptr(llargs[0], fnty.as_pointer())
            values = cgutils.unpack_tuple(builder, llargs[1], len(argtys))
            status, _ = context.call_conv.call_function(builder, fn, types.none, argtys, values)
            with cgutils.if_unlikely(builder, status.is_error):
                context.call_conv.return_status_propagate(builder, status)
            return context.get_dummy_value()

        return types.none(addr, args), codegen

    return call
