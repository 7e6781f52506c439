"""Where the strip update's factor against a dimension-specialised 3-D kernel goes, measured.

``python -m benchmarks.strip_breakdown`` (about a minute warm; a fresh ``NUMBA_CACHE_DIR``
adds the compilation) prints, for the 3-D strip update with the volume criterion:

1. the batch rates of ``intersect_strip_batch`` / ``minkowski_sum_batch`` against the
   general-n reference of ``optbound.bench.analytic_reference`` on all cores, B = 1e4 and
   1e5 (medians of runs alternating ours and the reference, as ``speed_analytic``), and the
   one-call cost of ``intersect_strip(E, S)`` / ``minkowski_sum(E1, E2)`` end to end (median
   wall time per call, and the CPU time per call, which a loaded machine inflates less);
2. the breakdown on one core (the process is pinned to one CPU), B = 1e5, all variants
   measured alternately in one run:

   - (c) :func:`plain3_range`: the strip formula of ``analytic.reference.intersect_strip_volume``
     (clip, width floor, volume-optimal lambda, member [HS96, eqs. (24), (26)]) hand-unrolled
     for n = 3, one instance per iteration, no validation, no margin: **not certified**, its
     member is off by rounding (a few ulps relative to the entries' magnitudes times the
     input's condition number);
   - (c) + validation: each instance first checked by the library's ``check_ellipsoid``
     (Cholesky: finite, symmetric, positive definite, in the supported domain) and the
     strip's domain checks (|a|^2 in [1e-120, 1e120], |b| <= 1e120);
   - (c) + margin: the same member evaluated in midpoint-radius arithmetic
     (``analytic._kernels.midrad``), the strip located with outward bounds by the kernel's
     ``locate``, and the float member inflated by the library's certified ``midrad.inflate``
     (the margin of the Minkowski sum; ours forms each shape entry in double-double instead,
     which makes its margin ~U cond(result) rather than larger, at more work);
   - (c) + validation + margin;
   - (b) the general-n reference (plain formula, one instance per iteration of n-loops);
   - our kernel alone (``fuse_range`` over the batch: validation, Dot2 / double-double
     certification, general n in lanes of W instances), without the Python wrapper;
   - (a) ``intersect_strip_batch``, the public call (argument conversion, output arrays).

   Each is printed as M instances/s (from the CPU time of the pinned thread, and from wall
   time) and as a fraction of (c); then the differences in ns per instance: validation,
   margin, generality (b vs c), the rest of our kernel, the Python wrapper.

The numba target (instruction set), the host and the load average at start and end are
printed with the numbers. AVX2 on an AVX-512 host: ``NUMBA_CPU_NAME=haswell
NUMBA_CACHE_DIR=<an empty folder> python -m benchmarks.strip_breakdown``.
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import time
from functools import partial

import numpy as np

from optbound._core import MAG, check_ellipsoid
from optbound._core.jit import njit
from optbound.analytic._kernels.lanes import (
    CHECK_ROWS,
    W,
    check_ellipsoids,
    load_matrices,
    load_vectors,
    store_matrices,
    store_vectors,
)
from optbound.analytic._kernels.midrad import TINY, inflate, mr_add, mr_div, mr_mul
from optbound.analytic._kernels.strip_kernel import (
    LAM_IN,
    MIN_REL_WIDTH,
    N_ROWS,
    STRIP_B,
    VOLUME,
    _validate,
    locate,
)
from optbound.analytic._kernels.strip_lambda import lam_volume

_OPTIONS = {"error_model": "numpy", "nogil": True, "cache": True}


@njit(**_OPTIONS)
def _lam_volume3(Gn, e):
    """The volume-optimal lambda of [HS96, eq. (26)] for N = 3: the positive root of
    ``2 Gn^2 lam^2 + (5 + e^2 - Gn) Gn lam + 3 (1 - e^2) - Gn``, or 0 without one."""
    qa = 2.0 * Gn * Gn
    qb = (5.0 + e * e - Gn) * Gn
    qc = 3.0 * (1.0 - e * e) - Gn
    if qc >= 0.0:
        return 0.0
    return (-qb + math.sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa)


@njit(**_OPTIONS)
def _strip_valid(c, C, a, b, L):
    """The instance's domain checks: ``check_ellipsoid`` (the library's) and the strip's."""
    aa = a[0] * a[0] + a[1] * a[1] + a[2] * a[2]
    ok = 1.0 / (MAG * MAG) <= aa <= MAG * MAG and abs(b) <= MAG * MAG
    return check_ellipsoid(c, C, L) == 0 and ok


@njit(**_OPTIONS)
def plain3_range(c, C, a, b, out_c, out_C, L, validate):
    """(c): ``reference.intersect_strip_volume`` for n = 3, hand-unrolled (the lower triangle
    of C is read); with ``validate``, each instance is first checked (:func:`_strip_valid`)
    and a failing one gets zeros. Not certified: rounding only."""
    for k in range(c.shape[0]):
        Ck, ak = C[k], a[k]
        if validate and not _strip_valid(c[k], Ck, ak, b[k], L):
            out_c[k, :] = 0.0
            out_C[k, :, :] = 0.0
            continue
        a0, a1, a2 = ak[0], ak[1], ak[2]
        c00, c10, c11, c20, c21, c22 = Ck[0, 0], Ck[1, 0], Ck[1, 1], Ck[2, 0], Ck[2, 1], Ck[2, 2]
        w0 = c00 * a0 + c10 * a1 + c20 * a2  # w = C a
        w1 = c10 * a0 + c11 * a1 + c21 * a2
        w2 = c20 * a0 + c21 * a1 + c22 * a2
        G = a0 * w0 + a1 * w1 + a2 * w2
        eps = b[k] - (a0 * c[k, 0] + a1 * c[k, 1] + a2 * c[k, 2])
        g = math.sqrt(G)
        lo = max(eps - 1.0, -g)
        hi = min(eps + 1.0, g)
        half = max(0.5 * (hi - lo), MIN_REL_WIDTH * g)
        mid = 0.5 * (lo + hi)
        h2 = half * half
        lam = _lam_volume3(G / h2, mid / half)
        gam = lam / ((1.0 + lam * G / h2) * h2)  # lambda / (u half^2)
        K = 1.0 + lam - gam * mid * mid
        f = gam * mid
        out_c[k, 0] = c[k, 0] + f * w0
        out_c[k, 1] = c[k, 1] + f * w1
        out_c[k, 2] = c[k, 2] + f * w2
        s00 = K * (c00 - gam * w0 * w0)
        s10 = K * (c10 - gam * w1 * w0)
        s11 = K * (c11 - gam * w1 * w1)
        s20 = K * (c20 - gam * w2 * w0)
        s21 = K * (c21 - gam * w2 * w1)
        s22 = K * (c22 - gam * w2 * w2)
        o = out_C[k]
        o[0, 0], o[0, 1], o[0, 2] = s00, s10, s20
        o[1, 0], o[1, 1], o[1, 2] = s10, s11, s21
        o[2, 0], o[2, 1], o[2, 2] = s20, s21, s22


@njit(**_OPTIONS)
def certified3_range(c, C, a, b, out_c, out_C, L, validate):
    """(c) + margin: the member of :func:`plain3_range` in midpoint-radius arithmetic (every
    value with a radius, ``midrad``), the strip located with outward bounds by the kernel's
    ``locate``, the float member inflated by ``midrad.inflate``; an instance whose member
    cannot be certified (``1 - gam G`` or K not provably positive, output too large) gets E
    itself. The member is parametrized by ``gam`` as the kernel's: centre ``c + gam mid w``,
    shape ``K (C - gam w w^T)``, ``K = 1 + gam half^2 / (1 - gam G) - gam mid^2``. Loops have
    the constant trip count 3 (LLVM unrolls them). With ``validate`` as :func:`plain3_range`."""
    w, rw = np.empty(3), np.empty(3)
    S, D, d, T = np.empty((3, 3)), np.empty((3, 3)), np.empty(3), np.empty((3, 3))
    for k in range(c.shape[0]):
        ck, Ck, ak = c[k], C[k], a[k]
        if validate and not _strip_valid(ck, Ck, ak, b[k], L):
            out_c[k, :] = 0.0
            out_C[k, :, :] = 0.0
            continue
        G, rG, eps, reps = 0.0, 0.0, b[k], 0.0
        for i in range(3):
            s, r = 0.0, 0.0
            for j in range(3):
                p, rp = mr_mul(Ck[max(i, j), min(i, j)], 0.0, ak[j], 0.0)
                s, r = mr_add(s, r, p, rp)
            w[i], rw[i] = s, r
            p, rp = mr_mul(ak[i], 0.0, s, r)
            G, rG = mr_add(G, rG, p, rp)
            p, rp = mr_mul(ak[i], 0.0, ck[i], 0.0)
            eps, reps = mr_add(eps, reps, -p, rp)
        _, _, mid, half, G, G_lo, rG = locate(eps, reps, G, 0.0, rG, False, True)
        rG += abs(G_lo)
        h2 = half * half
        lam = _lam_volume3(G / h2, mid / half)
        gam = lam / ((1.0 + lam * G / h2) * h2)  # any gam >= 0 gives an outer bound
        p, rp = mr_mul(gam, 0.0, G, rG)
        om, rom = mr_add(1.0, 0.0, -p, rp + TINY)
        ok = lam > 0.0 and om > rom
        gm, rgm = 0.0, 0.0
        if ok:
            h2m, rh2 = mr_mul(half, 0.0, half, 0.0)
            num, rnum = mr_mul(gam, 0.0, h2m, rh2)
            lp, rlp = mr_div(num, rnum, om, rom)
            gm, rgm = mr_mul(gam, 0.0, mid, 0.0)
            q, rq = mr_mul(gm, rgm, mid, 0.0)
            K, rK = mr_add(1.0, 0.0, lp, rlp)
            K, rK = mr_add(K, rK, -q, rq)
            ok = K > rK
        if not ok:  # E itself
            out_c[k, :] = ck
            for i in range(3):
                for j in range(3):
                    out_C[k, i, j] = Ck[max(i, j), min(i, j)]
            continue
        for i in range(3):
            p, rp = mr_mul(gm, rgm, w[i], rw[i])
            out_c[k, i], d[i] = mr_add(ck[i], 0.0, p, rp)
            for j in range(i + 1):
                p, rp = mr_mul(gam, 0.0, w[i], rw[i])
                p, rp = mr_mul(p, rp, w[j], rw[j])
                x, rx = mr_add(Ck[i, j], 0.0, -p, rp)
                S[i, j], D[i, j] = mr_mul(K, rK, x, rx)
        if inflate(S, D, out_c[k], d, T, L) < 0.0:
            out_c[k, :] = ck
            T[:, :] = Ck
        for i in range(3):
            for j in range(i + 1):
                out_C[k, i, j] = T[i, j]
                out_C[k, j, i] = T[i, j]


@njit(**_OPTIONS, _nrt=False)
def lanes_range(c, C, a, b, out_c, out_C, V, M, t, code, scratch, what):
    """The lane layout of our kernel (``analytic._kernels.lanes``: blocks of W instances, each
    step a loop over the lanes, general n) without its certification. ``what``: 0 loads the
    blocks only; 1 loads and validates them with our kernel's own steps (``check_ellipsoids``,
    then ``strip_kernel._validate``; codes in ``code``); 2 loads them and evaluates the plain
    formula of :func:`plain3_range` (no validation, no margin) into the outputs. V (4, n, W),
    M (2, n, n, W), t (``strip_kernel.N_ROWS`` W,: the kernel's rows), code (W,) int,
    scratch (CHECK_ROWS W,) are work space."""
    n = c.shape[1]
    cs, av, w, oc, Cs, Os = V[0], V[1], V[2], V[3], M[0], M[1]
    G, eps, f, gam, K = 0, W, 2 * W, 3 * W, 4 * W  # rows of t
    for base in range(0, c.shape[0], W):
        m = min(W, c.shape[0] - base)
        load_vectors(c[base:], m, cs)
        load_matrices(C[base:], m, Cs)
        load_vectors(a[base:], m, av)
        bb = b[base:]
        if what == 1:
            check_ellipsoids(cs, Cs, Os, m, code, scratch)
            for k in range(m):  # the rows fuse_range fills before its validation step
                t[STRIP_B + k] = bb[k]
                t[LAM_IN + k] = 0.0
            _validate(av, t, VOLUME, m, code)
        if what != 2:
            continue
        for k in range(m):
            t[G + k] = 0.0
            t[eps + k] = bb[k]
        for i in range(n):
            for k in range(m):
                w[i, k] = 0.0
            for j in range(n):
                r, q = (i, j) if j <= i else (j, i)
                for k in range(m):
                    w[i, k] += Cs[r, q, k] * av[j, k]
            for k in range(m):
                t[G + k] += av[i, k] * w[i, k]
                t[eps + k] -= av[i, k] * cs[i, k]
        for k in range(m):
            g = np.sqrt(t[G + k])
            lo = max(t[eps + k] - 1.0, -g)
            hi = min(t[eps + k] + 1.0, g)
            half = max(0.5 * (hi - lo), MIN_REL_WIDTH * g)
            mid = 0.5 * (lo + hi)
            h2 = half * half
            lam = lam_volume(t[G + k] / h2, mid / half, n)
            gk = lam / ((1.0 + lam * t[G + k] / h2) * h2)
            t[gam + k] = gk
            t[K + k] = 1.0 + lam - gk * mid * mid
            t[f + k] = gk * mid
        for i in range(n):
            for k in range(m):
                oc[i, k] = cs[i, k] + t[f + k] * w[i, k]
            for j in range(n):
                r, q = (i, j) if j <= i else (j, i)
                for k in range(m):
                    Os[i, j, k] = t[K + k] * (Cs[r, q, k] - t[gam + k] * w[i, k] * w[j, k])
        store_vectors(oc, m, out_c[base:])
        store_matrices(Os, m, out_C[base:])
    return 0


def _lanes(what: int, c, C, a, b) -> tuple[np.ndarray, np.ndarray]:
    """Run :func:`lanes_range` on a batch into new output arrays."""
    n = c.shape[1]
    out_c, out_C = np.empty(c.shape), np.empty(C.shape)
    work = (np.empty((4, n, W)), np.empty((2, n, n, W)), np.empty(N_ROWS * W))
    lanes_range(c, C, a, b, out_c, out_C, *work, np.zeros(W, np.int64),
                np.empty(CHECK_ROWS * W), what)  # fmt: skip
    return out_c, out_C


def _three_d(fn, validate: bool, c, C, a, b) -> tuple[np.ndarray, np.ndarray]:
    """Run a 3-D variant on a batch into new output arrays (as the others return)."""
    out_c, out_C = np.empty(c.shape), np.empty(C.shape)
    fn(c, C, a, b, out_c, out_C, np.empty((3, 3)), validate)
    return out_c, out_C


def variants() -> list[tuple[str, object]]:
    """The breakdown's variants, (label, call on (c, C, a, b)), (c) first."""
    from optbound import analytic
    from optbound.bench import analytic_reference as ref

    return [
        ("(c) 3-D unrolled, plain", partial(_three_d, plain3_range, False)),
        ("(c) + validation", partial(_three_d, plain3_range, True)),
        ("(c) + margin", partial(_three_d, certified3_range, False)),
        ("(c) + validation + margin", partial(_three_d, certified3_range, True)),
        ("(b) general-n reference", ref.strip_batch),
        ("lanes, general n: loads only", partial(_lanes, 0)),
        ("lanes, general n: loads + validation", partial(_lanes, 1)),
        ("lanes, general n: plain formula", partial(_lanes, 2)),
        ("our kernel (fuse_range) alone", ref.strip_sliced),
        ("(a) intersect_strip_batch", analytic.intersect_strip_batch),
    ]


def _timed(fns, rounds: int) -> tuple[np.ndarray, np.ndarray]:
    """CPU (thread) and wall seconds of each call, ``rounds`` rounds of all calls in turn:
    arrays (rounds, len(fns))."""
    cpu, wall = np.empty((rounds, len(fns))), np.empty((rounds, len(fns)))
    for r in range(rounds):
        for k, fn in enumerate(fns):
            t0, w0 = time.thread_time(), time.perf_counter()
            fn()
            cpu[r, k], wall[r, k] = time.thread_time() - t0, time.perf_counter() - w0
    return cpu, wall


def breakdown(count: int = 10**5, rounds: int = 15, seed: int = 0) -> list[tuple]:
    """Time the variants alternately on one core (the caller pins the process).

    Parameters
    ----------
    count : int
        Batch size.
    rounds : int
        Rounds; each calls every variant once, in turn.
    seed : int
        Seed of the instances (``speed_analytic.batch_instances``).

    Returns
    -------
    list of tuple
        Per variant: (label, median CPU seconds, median wall seconds) of the batch.
    """
    from optbound.bench.speed_analytic import batch_instances

    args = batch_instances(np.random.default_rng(seed), count, 3)
    chosen = variants()
    fns = [partial(fn, *args) for _, fn in chosen]
    _timed(fns, 1)  # compiles and first touches
    cpu, wall = _timed(fns, rounds)
    return [
        (label, float(np.median(cpu[:, k])), float(np.median(wall[:, k])))
        for k, (label, _) in enumerate(chosen)
    ]


def _cpu_per_call(fn, seconds: float = 0.2) -> float:
    """Median CPU seconds per call over 5 samples of back-to-back calls (>= seconds / 5)."""
    number = 1
    while True:
        t0 = time.thread_time()
        for _ in range(number):
            fn()
        if time.thread_time() - t0 >= seconds / 5:
            break
        number *= 2
    samples = []
    for _ in range(5):
        t0 = time.thread_time()
        for _ in range(number):
            fn()
        samples.append((time.thread_time() - t0) / number)
    return float(np.median(samples))


def host() -> str:
    """The host name and its CPU model."""
    from optbound.bench.target import processor_name

    return f"{platform.node()}, {processor_name()}, {os.cpu_count()} CPUs"


def _print_batches(seed: int) -> None:
    from optbound import Ellipsoid, Strip, analytic
    from optbound.bench import speed_analytic as sa

    rng = np.random.default_rng(seed)
    batches = (10**4, 10**5)
    print(f"## Batch rate on all cores ({sa.DIM}-D, volume), medians of {sa.REPEATS} "
          "alternating runs; issue 23 target: ours >= 50 % of the reference")  # fmt: skip
    print("| operation | B | optbound | general-n reference | ours / reference |")
    print("|---|---|---|---|---|")
    one = {}
    for what, timings in (
        ("strip", sa.strip_timings(rng, batches)),
        ("Minkowski", sa.minkowski_timings(rng, batches)),
    ):
        one[what] = timings.pop("one")
        for count, (ours, ref) in timings.items():
            print(f"| {what} | {count:.0e} | {count / ours / 1e6:.2f} M/s "
                  f"| {count / ref / 1e6:.2f} M/s | {ref / ours:.0%} |")  # fmt: skip
    c, C, a, b = sa.batch_instances(rng, 2, sa.DIM)
    E, E2, S = Ellipsoid(c[0], C[0]), Ellipsoid(c[1], C[1]), Strip(a[0], b[0])
    cpu = {
        "strip": _cpu_per_call(lambda: analytic.intersect_strip(E, S)),
        "Minkowski": _cpu_per_call(lambda: analytic.minkowski_sum(E, E2)),
    }
    print("\n## One call end to end (target <= 20 µs)")
    print("| call | wall (median) | CPU | reference kernel, one call (wall) |")
    print("|---|---|---|---|")
    for what, call in (("strip", "intersect_strip(E, S)"), ("Minkowski", "minkowski_sum(E1, E2)")):
        ours, ref = one[what]
        print(f"| {call} | {ours * 1e6:.1f} µs | {cpu[what] * 1e6:.1f} µs "
              f"| {ref * 1e6:.1f} µs |")  # fmt: skip


def _print_breakdown(count: int, rounds: int, seed: int) -> None:
    rows = breakdown(count, rounds, seed)
    base_cpu, base_wall = rows[0][1], rows[0][2]
    print(f"\n## Breakdown on one core, strip update, 3-D, volume, B = {count:.0e}; "
          f"medians of {rounds} alternating rounds")  # fmt: skip
    print("| variant | M/s (CPU) | of (c) | M/s (wall) | of (c) |")
    print("|---|---|---|---|---|")
    for label, cpu, wall in rows:
        print(f"| {label} | {count / cpu / 1e6:.2f} | {base_cpu / cpu:.0%} "
              f"| {count / wall / 1e6:.2f} | {base_wall / wall:.0%} |")  # fmt: skip
    ns = {label: cpu / count * 1e9 for label, cpu, _ in rows}
    (c, cv, cm, _, ref, load, checked, plain, kernel, ours) = ns.values()
    print("\nper instance, CPU ns (differences of the rows):")
    print(f"- (c) itself: {c:.1f} ns")
    print(f"- scalar validation per instance ((c) + validation - (c)): {cv - c:.1f} ns")
    print(f"- scalar certified margin per instance ((c) + margin - (c)): {cm - c:.1f} ns")
    print(f"- generality, one instance per iteration ((b) - (c)): {ref - c:.1f} ns")
    print(f"\nwhere ours goes, {ours:.1f} ns = {ours / c:.1f} x (c):")
    print(f"- (c): {c:.1f} ns")
    print(f"- generality in lanes (lanes plain formula - (c)): {plain - c:.1f} ns")
    print(f"- validation in lanes (loads + validation - loads only): {checked - load:.1f} ns")
    print(
        f"- certification (margin, Dot2 / double-double; our kernel - lanes plain formula"
        f" - validation in lanes): {kernel - plain - (checked - load):.1f} ns"
    )
    print(f"- Python wrapper ((a) - our kernel): {ours - kernel:.1f} ns")


def main(argv=None) -> None:
    """Print the target, host, load, batch ratios, one-call cost and the breakdown.

    Parameters
    ----------
    argv : list of str, optional
        Command-line arguments (default ``sys.argv[1:]``).
    """
    from optbound.bench.target import numba_target

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=10**5, help="breakdown batch size")
    parser.add_argument("--rounds", type=int, default=15, help="breakdown rounds")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    start = time.perf_counter()
    print(f"numba target: {numba_target()}")
    print(f"host: {host()}")
    print(f"load average at start: {' '.join(f'{x:.1f}' for x in os.getloadavg())}\n")
    _print_batches(args.seed)
    cpus = os.sched_getaffinity(0)
    os.sched_setaffinity(0, {min(cpus)})  # one core: every variant single-threaded
    try:
        _print_breakdown(args.count, args.rounds, args.seed)
    finally:
        os.sched_setaffinity(0, cpus)
    print(f"\nload average at end: {' '.join(f'{x:.1f}' for x in os.getloadavg())}; "
          f"{time.perf_counter() - start:.0f} s in all")  # fmt: skip


if __name__ == "__main__":
    main()
