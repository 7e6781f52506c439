"""The compiled kernels of the analytic updates, fenced: machinery, not formulas.

The formulas live beside the updates in ``optbound.analytic`` (``strip_fusion``,
``minkowski``) and, written plainly, in ``optbound.analytic.reference``. This package holds
what makes them fast and certified in floating point:

- ``batch``: conversion of the batched inputs to the arrays the kernels take;
- ``lanes``: the lane layout (W instances per block, lanes last) and its building blocks;
- ``strip_kernel``, ``strip_lambda``, ``cubic``: ellipsoid ∩ strip [HS96, eqs. (24)-(30)];
- ``minkowski_kernel``: the Schweppe family [HS96, eq. (14)] and its volume-optimal p;
- ``midrad``: midpoint-radius arithmetic and the certified outward margin;
- ``threads``: a batch sliced over the cores.

Heavy steps are called by address (``optbound._core.native_call``), without linking them in.

``analytic._exact`` (the bounding update in exact rationals) is not here: it is the formula
evaluated without rounding, not an acceleration.

Rules a kernel follows
----------------------
What it receives. Arrays already converted by ``batch`` (C-contiguous float64, a batch axis
first, shared parameters broadcast to (B, ...)), output arrays made by the caller
(``threads.ellipsoid_outputs``) and the calling thread's scratch (``threads.workspace``). Its
values are *not* checked before: the kernel validates every instance in the same pass
(``lanes.check_ellipsoids``, the supported domain of ``optbound._core.domain``) and reports an error
code per instance, which the Python wrapper turns into a ValueError naming the argument and
the instance.

numba options. ``cache=True`` everywhere (``optbound._jit_cache`` drops the caches when any
kernel source changes, since numba only tracks the defining file). ``error_model="numpy"``:
the default Python model adds a zero-division branch to every division, which blocks LLVM's
vectorization of the lane loops. Never ``fastmath``: every error bound assumes IEEE
round-to-nearest of each operation, and the vector body and scalar remainder of a lane loop
must give the same bits. ``nogil=True`` on the entry points run by threads; ``_nrt=False`` on
the loops that take views (no atomic reference count per view, a cache line the threads would
share); ``inline="always"`` for the per-lane scalar helpers (``midrad``, ``strip_kernel.
locate``) and the Minkowski sum's steps, so that LLVM sees one loop nest. The strip's steps
(``_validate`` ... ``_finish``), called once per block, are compiled functions of their own
(``_nrt=False``): numba inlines by copying and typing their IR in the caller, which costs
more compile time than a call per block of W instances costs at run time.

One compiled entry point per update (``strip_kernel.fuse_range``, ``minkowski_kernel.
sum_blocks``), with the loop over the blocks written in it, and single calls passing through
it from Python as a batch of one. A compiled function calling another links the callee's
code into its own and LLVM optimizes and emits it again: every compiled wrapper around the
lane loop nests costs seconds of compile time on the first run, for nothing at run time. So
the heavy steps called once per block (the strip's steps, ``lanes.check_ellipsoids``, the
Minkowski p solver and ``lanes.inflate_lanes``) are called by address (``_core.native_call``):
each is compiled once, in its own library, and linked into no caller; their addresses come
with the work space (``entry_points``). A step called by address takes the work space's
arrays only, never the caller's inputs, whose types vary (read-only or not): one compiled
signature, which the address was taken for.

No allocation in loops. Scratch is made once per thread and dimension (``workspace``,
``block_work``); a block gets views from its first instance (``c[base:]``), indexed by the
lane alone (a runtime ``base + k`` carries wraparound code). Per-lane scalars of the strip
kernel live in one flat array at constant row offsets (see ``strip_kernel``'s layout).

Certified margin. A kernel returns a member of the update's family (every member contains the
true set in exact arithmetic) inflated so that it contains the member *evaluated exactly on
the float inputs*: each computed value carries a certified radius (``midrad``), and the shape
is widened by the outward rule ``T = (1 + rho) S + mu I`` of ``midrad.inflate``. What member
is chosen (lambda, p) may be approximate; the containment may not. A member that cannot be
certified falls back to a set that is trivially an outer bound (E itself for the strip).

Threads. ``threads.run_sliced`` calls a kernel entry point ``call(start, stop)`` on
contiguous slices of the batch, one per core (the caller runs the first, a thread pool the
others), so an entry point releases the GIL (``nogil=True``) and writes only its slice of the
outputs. A lane's result never depends on its neighbours, its block or its slice, so single
calls, batches and any split agree bitwise.

Testing. Each kernel is tested against its plain reference (``analytic.reference``): the
kernel's centre equals the reference's to a few units in the last place, its shape exceeds the
reference's by no more than its reported margin, and its certified output contains the
reference's member evaluated in exact rational arithmetic (``tests/analytic/
test_reference.py``); the lane layout is tested for bitwise independence of the lanes
(``tests/analytic/test_strip_kernel.py``, ``test_lanes.py``).
"""
