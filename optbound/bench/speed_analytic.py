"""Speed of the analytic updates against a plain numba kernel of the same formula, and vs SDP.

Every ratio is taken between two timings of the same run on the same machine, measured
alternately (ours, reference, ours, ...) and summarized by their medians, so that the load of
a shared machine hits both alike; each sample is the mean over back-to-back calls filling at
least 20 ms (a sustained rate):

- batch: seconds per update of ``intersect_strip_batch`` / ``minkowski_sum_batch`` (3-D,
  volume criterion, including validation and the certified margin) over seconds per update of
  the plain kernels of ``optbound.bench.analytic_reference`` (same formula, same threads, no
  validation, no margin; both return new arrays), B = 1e3 ... 1e6;
- one call: ``intersect_strip(E, S)`` / ``minkowski_sum(E1, E2)`` end to end (including the
  result's Ellipsoid) over one call of the reference kernel (into existing arrays);
- every criterion (strip: trace, projection, robust with and without dims; Minkowski: trace,
  size_xy_psi) over the volume criterion of the same operation: one call and a batch of 1e4;
- SDP cost: one SDP solve over one analytic call.

``python -m optbound.bench.speed_analytic [--suite quick]`` prints the ratio table, the JIT
warm-up (a fresh compile in a subprocess with an empty cache) and the margin distribution;
``--phases`` the strip rate at B = 1e3 over 20 s (see :func:`phases`).

Sampling in ``optbound bench`` (:data:`SAMPLING`): the full suite takes the median of 7
alternating rounds, each sample >= 20 ms of back-to-back calls (a batch of 1e5 or more is one
call), and each SDP time is the best of 3 batches of >= 50 ms; the quick and tiny suites 5
rounds of >= 10 ms samples and SDP batches of >= 20 ms (one or two solves). Every task notes
the instruction set numba compiled for (:func:`optbound.bench.target.numba_target`).
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from functools import partial

import numpy as np

from optbound.bench.family import Family
from optbound.bench.target import numba_target
from optbound.bench.timing import per_call, speed_record
from optbound.problems.generators import random_ellipsoid, random_strip, task_seeds

NAME = "speed_analytic"
DIM = 3
BATCHES = {
    "tiny": (10**3,),
    "quick": (10**3, 10**4, 10**5),
    "full": (10**3, 10**4, 10**5, 10**6),
}
REPEATS = 7
SAMPLE_SECONDS = 0.02
#: Seconds of discarded one-call calls before the one-call timing (each of ours, reference).
WARM_UP_SECONDS = 0.02
#: Per suite: alternating rounds, seconds per sample, seconds per batch of SDP solves.
SAMPLING = {
    "tiny": {"rounds": 5, "sample": 0.01, "sdp_batch": 0.02},
    "quick": {"rounds": 5, "sample": 0.01, "sdp_batch": 0.02},
    "full": {"rounds": REPEATS, "sample": SAMPLE_SECONDS, "sdp_batch": 0.05},
}


def tasks(suite: str, seed: int) -> list[dict]:
    """Build the tasks of ``suite``: the strip timings and the Minkowski timings.

    Parameters
    ----------
    suite : {"tiny", "quick", "full"}
        Size of the run; it sets the batch sizes (:data:`BATCHES`).
    seed : int
        Suite seed; each task's seed is derived from it.

    Returns
    -------
    list of dict
        Two JSON-able tasks, with their ``"seed"``, ``"what"``, ``"batches"`` and the
        suite's sampling (:data:`SAMPLING`).
    """
    s1, s2 = task_seeds(seed, NAME, 2)
    return [
        {"seed": s1, "what": "strip", "batches": list(BATCHES[suite]), **SAMPLING[suite]},
        {"seed": s2, "what": "minkowski", "batches": list(BATCHES[suite]), **SAMPLING[suite]},
    ]


def batch_instances(rng: np.random.Generator, count: int, dim: int, cond: float | None = None):
    """Draw ``count`` random ellipsoids and one strip per ellipsoid, as batch arrays.

    Shapes are ``A A^T + 0.1 I`` for Gaussian A (or, with ``cond``, random rotations of
    eigenvalues log-spaced over ``cond``); each strip passes near its ellipsoid's centre so
    that most updates are genuine reductions, not the trivial "no reduction" case.

    Parameters
    ----------
    rng : numpy.random.Generator
        The random generator.
    count : int
        Number of instances.
    dim : int
        Their dimension.
    cond : float, optional
        Condition number of the shapes (default: Gaussian ``A A^T + 0.1 I``).

    Returns
    -------
    centers : numpy.ndarray
        ``(count, dim)`` centres.
    shapes : numpy.ndarray
        ``(count, dim, dim)`` shape matrices.
    a : numpy.ndarray
        ``(count, dim)`` strip normals.
    b : numpy.ndarray
        ``(count,)`` strip offsets; strip k is ``|a[k]·x - b[k]| <= 1``.
    """
    if cond is None:
        A = rng.standard_normal((count, dim, dim))
        shapes = A @ A.transpose(0, 2, 1) + 0.1 * np.eye(dim)
    else:
        q, r = np.linalg.qr(rng.standard_normal((count, dim, dim)))
        q = q * np.sign(np.diagonal(r, axis1=1, axis2=2))[:, None, :]
        eig = np.logspace(0.0, -np.log10(cond), dim)
        shapes = (q * eig) @ q.transpose(0, 2, 1)
    shapes = 0.5 * (shapes + shapes.transpose(0, 2, 1))
    centers = rng.standard_normal((count, dim))
    a = rng.standard_normal((count, dim))
    half = np.sqrt(np.einsum("bi,bij,bj->b", a, shapes, a))
    b = np.einsum("bi,bi->b", a, centers) + rng.uniform(-0.5, 0.5, count) * half
    scale = 2.0 / (rng.uniform(0.2, 1.0, count) * half)  # strip width 20-100 % of the extent
    return centers, shapes, a * scale[:, None], b * scale


def interleaved(*fns, repeat: int = REPEATS) -> list[float]:
    """Time functions called in turn, so that a shared machine's load hits them alike.

    Parameters
    ----------
    *fns : callable
        The calls to time, without arguments.
    repeat : int
        Rounds; each calls every function once.

    Returns
    -------
    list of float
        Median seconds of each function, in order.
    """
    times = [[] for _ in fns]
    for _ in range(repeat):
        for fn, out in zip(fns, times, strict=True):
            start = time.perf_counter()
            fn()
            out.append(time.perf_counter() - start)
    return [float(np.median(t)) for t in times]


def alternating(ours, reference, repeat: int = REPEATS) -> tuple[float, float]:
    """Time ``ours()`` and ``reference()``, called alternately (:func:`interleaved`).

    Parameters
    ----------
    ours, reference : callable
        The calls to time, without arguments.
    repeat : int
        Rounds.

    Returns
    -------
    tuple of float
        Median seconds of ``ours`` and of ``reference``.
    """
    t_ours, t_ref = interleaved(ours, reference, repeat=repeat)
    return t_ours, t_ref


def interleaved_calls(*fns, repeat: int = REPEATS, sample: float = SAMPLE_SECONDS) -> list[float]:
    """Time functions in turn, each sample the mean over back-to-back calls filling >= ``sample`` s.

    As :func:`interleaved`, but results are dropped at once and the number of calls is set
    by the first function: a sustained rate, not the latency of one call after idling.

    Parameters
    ----------
    *fns : callable
        The calls to time, without arguments.
    repeat : int
        Rounds.
    sample : float
        Minimum seconds of a sample of the first function.

    Returns
    -------
    list of float
        Median seconds per call of each function, in order.
    """
    number = 1
    while per_call(fns[0], repeat=1, min_time=0.0) * number < sample:
        number *= 2

    def looped(fn):
        def run() -> None:
            for _ in range(number):
                fn()

        return run

    return [t / number for t in interleaved(*map(looped, fns), repeat=repeat)]


def alternating_calls(
    ours, reference, repeat: int = REPEATS, sample: float = SAMPLE_SECONDS
) -> tuple[float, float]:
    """Time ``ours`` and ``reference`` with :func:`interleaved_calls`.

    Parameters
    ----------
    ours, reference : callable
        The calls to time, without arguments.
    repeat : int
        Rounds.
    sample : float
        Minimum seconds per sample.

    Returns
    -------
    tuple of float
        Median seconds per call of ``ours`` and of ``reference``.
    """
    t_ours, t_ref = interleaved_calls(ours, reference, repeat=repeat, sample=sample)
    return t_ours, t_ref


def threading_timings(rng: np.random.Generator, batches, rounds: int = 3 * REPEATS) -> list:
    """Time our strip kernel (3-D, volume) with the batch handed to the cores two ways.

    The thread pool of ``analytic._kernels.threads.run_sliced`` (the library's) and numba's
    ``prange`` (the threading layer is numba's choice or ``NUMBA_THREADING_LAYER``). Each
    round times both interleaved (one :func:`interleaved_calls` sample each), so the load of
    a shared machine hits them alike. Both schemes' outputs are checked bitwise equal first.

    Parameters
    ----------
    rng : numpy.random.Generator
        Draws the instances (:func:`batch_instances`).
    batches : sequence of int
        Batch sizes.
    rounds : int
        Rounds per batch size.

    Returns
    -------
    list of tuple
        Per batch size: (B, pool rate [updates/s], median over rounds of prange / pool time).
    """
    from optbound.bench import analytic_reference as ref

    c, C, a, b = batch_instances(rng, max(batches), DIM)
    rows = []
    for count in batches:
        args = tuple(x[:count] for x in (c, C, a, b))
        pool, par = ref.strip_sliced(*args), ref.strip_prange(*args)
        assert all(np.array_equal(x, y) for x, y in zip(pool, par, strict=True))
        calls = (partial(ref.strip_sliced, *args), partial(ref.strip_prange, *args))
        times = np.array([interleaved_calls(*calls, repeat=1) for _ in range(rounds)])
        rows.append((count, count / np.median(times[:, 0]), np.median(times[:, 1] / times[:, 0])))
    return rows


def _ratio_records(what: str, count: int, ours: float, ref: float) -> list[dict]:
    label = f"{what}, batch of {count:.0e} ({DIM}-D, volume)"
    return [
        speed_record(NAME, f"{label}, reference kernel", ref / count, unit="s/update",
                     throughput=count / ref),
        speed_record(NAME, f"{label}, optbound", ours / count, unit="s/update",
                     throughput=count / ours, ratio=ours / ref,
                     ratio_label="time / plain numba reference"),
    ]  # fmt: skip


def _one_call_records(what: str, ours: float, ref: float) -> list[dict]:
    return [
        speed_record(NAME, f"{what}, one call, reference kernel ({DIM}-D, volume)", ref),
        speed_record(NAME, f"{what}, one call, optbound ({DIM}-D, volume)", ours,
                     ratio=ours / ref, ratio_label="time / plain numba reference"),
    ]  # fmt: skip


def _timings(one, ours, reference, inputs, batches, sampling) -> dict:
    """Medians of ours vs the reference: ``one`` is a pair of one-call functions; for each
    batch size, ``ours(*inputs[:count])`` against ``reference(*inputs[:count])`` (both
    return new arrays); ``sampling`` the keyword arguments of :func:`alternating_calls`."""
    for call in one:  # the first calls in a process run at about half speed: discarded
        warm_until = time.perf_counter() + WARM_UP_SECONDS
        while time.perf_counter() < warm_until:
            call()
    out = {"one": alternating_calls(*one, **sampling)}
    for count in batches:
        args = tuple(x[:count] for x in inputs)
        out[count] = alternating_calls(
            lambda args=args: ours(*args), lambda args=args: reference(*args), **sampling
        )
    return out


def strip_timings(
    rng: np.random.Generator, batches, repeat: int = REPEATS, sample: float = SAMPLE_SECONDS
) -> dict:
    """Time our strip update against the plain numba reference: one call and batches.

    Parameters
    ----------
    rng : numpy.random.Generator
        Draws the instances (:func:`batch_instances`).
    batches : sequence of int
        Batch sizes.
    repeat, sample
        Rounds and seconds per sample (:func:`alternating_calls`).

    Returns
    -------
    dict
        ``"one"`` -> ``(ours, reference)`` median seconds of one call, and each batch size
        -> ``(ours, reference)`` median seconds of the batch.
    """
    from optbound import Ellipsoid, Strip, analytic
    from optbound.bench import analytic_reference as ref

    c, C, a, b = batch_instances(rng, max(batches), DIM)
    E, S = Ellipsoid(c[0], C[0]), Strip(a[0], b[0])
    oc, oC = np.empty((1, DIM)), np.empty((1, DIM, DIM))
    one = (
        lambda: analytic.intersect_strip(E, S),
        lambda: ref.strip_range(c[:1], C[:1], a[:1], b[:1], oc, oC, 0, 1),
    )
    sampling = {"repeat": repeat, "sample": sample}
    return _timings(
        one, analytic.intersect_strip_batch, ref.strip_batch, (c, C, a, b), batches, sampling
    )


def minkowski_timings(
    rng: np.random.Generator, batches, repeat: int = REPEATS, sample: float = SAMPLE_SECONDS
) -> dict:
    """Time the volume-optimal Minkowski sum as :func:`strip_timings` does the strip.

    Parameters
    ----------
    rng : numpy.random.Generator
        Draws the instances (:func:`batch_instances`).
    batches : sequence of int
        Batch sizes.
    repeat, sample
        Rounds and seconds per sample (:func:`alternating_calls`).

    Returns
    -------
    dict
        ``"one"`` -> ``(ours, reference)`` median seconds of one call, and each batch size
        -> ``(ours, reference)`` median seconds of the batch.
    """
    from optbound import Ellipsoid, analytic
    from optbound.bench import analytic_reference as ref

    c1, C1, _, _ = batch_instances(rng, max(batches), DIM)
    c2, C2, _, _ = batch_instances(rng, max(batches), DIM)
    E1, E2 = Ellipsoid(c1[0], C1[0]), Ellipsoid(c2[0], C2[0])
    oc, oC = np.empty((1, DIM)), np.empty((1, DIM, DIM))
    one = (
        lambda: analytic.minkowski_sum(E1, E2),
        lambda: ref.minkowski_range(c1[:1], C1[:1], c2[:1], C2[:1], oc, oC, 0, 1),
    )
    inputs = (c1, C1, c2, C2)
    sampling = {"repeat": repeat, "sample": sample}
    return _timings(
        one, analytic.minkowski_sum_batch, ref.minkowski_batch, inputs, batches, sampling
    )


STRIP_CRITERIA = (
    ("volume", {}),
    ("trace", {}),
    ("projection", {"dims": (0, 1)}),
    ("robust", {}),
    ("robust", {"dims": (0, 1)}),
)
MINKOWSKI_CRITERIA = (("volume", {}), ("trace", {}), ("size_xy_psi", {}))


def criteria_timings(rng: np.random.Generator, count: int = 10**4) -> list[tuple]:
    """Time every criterion against the volume criterion of the same operation.

    The volume criterion is the reference, timed alternately in the same run.

    Parameters
    ----------
    rng : numpy.random.Generator
        Draws the instances (:func:`batch_instances`).
    count : int
        Batch size.

    Returns
    -------
    list of tuple
        (operation, criterion, one call [s], one call of the volume criterion [s], batch of
        ``count`` [s], the same batch with the volume criterion [s]).
    """
    from optbound import Ellipsoid, Strip, analytic

    c, C, a, b = batch_instances(rng, count, DIM)
    c2, C2, _, _ = batch_instances(rng, count, DIM)
    E, S, E2 = Ellipsoid(c[0], C[0]), Strip(a[0], b[0]), Ellipsoid(c2[0], C2[0])
    ops = [
        ("strip", crit, kw, lambda kw: analytic.intersect_strip(E, S, **kw),
         lambda kw: analytic.intersect_strip_batch(c, C, a, b, **kw))
        for crit, kw in STRIP_CRITERIA
    ] + [
        ("minkowski", crit, kw, lambda kw: analytic.minkowski_sum(E, E2, **kw),
         lambda kw: analytic.minkowski_sum_batch(c, C, c2, C2, **kw))
        for crit, kw in MINKOWSKI_CRITERIA
    ]  # fmt: skip
    rows = []
    for op, crit, kw, one, batch in ops:
        kw = {"criterion": crit, **kw}
        vol = {"criterion": "volume"}
        one_ours, one_vol = alternating_calls(partial(one, kw), partial(one, vol))
        batch_ours, batch_vol = alternating(partial(batch, kw), partial(batch, vol))
        name = crit + (f" dims={kw['dims']}" if "dims" in kw else "")
        rows.append((op, name, one_ours, one_vol, batch_ours, batch_vol))
    return rows


def run_strip(task: dict) -> list[dict]:
    """Time the strip update: one call, the SDP solve it replaces, and the batches.

    Parameters
    ----------
    task : dict
        The ``"strip"`` task of :func:`tasks`.

    Returns
    -------
    list of dict
        Speed records, each against the plain numba reference (the SDP against one call).
    """
    from optbound import optimal

    rng = np.random.default_rng(task["seed"])
    E = random_ellipsoid(rng, DIM, 1e2)
    S = random_strip(rng, E, "narrow")
    sampling = {**SAMPLING["full"], **task}
    sdp = per_call(
        lambda: optimal.outer_ellipsoid(intersection=[E, S], objective="volume"),
        repeat=3,
        min_time=sampling["sdp_batch"],
    )
    timings = strip_timings(rng, task["batches"], sampling["rounds"], sampling["sample"])
    out = _one_call_records("strip update", *timings.pop("one"))
    out.append(sdp_record("SDP outer_ellipsoid, one solve", sdp, out[-1]))
    for count, (ours, ref) in timings.items():
        out += _ratio_records("strip updates", count, ours, ref)
    return out


def run_minkowski(task: dict) -> list[dict]:
    """Time the Minkowski sum: one call, the SDP solve it replaces, and the batches.

    Parameters
    ----------
    task : dict
        The ``"minkowski"`` task of :func:`tasks`.

    Returns
    -------
    list of dict
        Speed records, each against the plain numba reference (the SDP against one call).
    """
    from optbound import optimal

    rng = np.random.default_rng(task["seed"])
    E1, E2 = random_ellipsoid(rng, DIM, 1e2), random_ellipsoid(rng, DIM, 1e2, scale=0.1)
    sampling = {**SAMPLING["full"], **task}
    sdp = per_call(
        lambda: optimal.minkowski_outer(E1, E2, objective="volume"),
        repeat=3,
        min_time=sampling["sdp_batch"],
    )
    timings = minkowski_timings(rng, task["batches"], sampling["rounds"], sampling["sample"])
    out = _one_call_records("Minkowski sum", *timings.pop("one"))
    out.append(sdp_record("SDP minkowski_outer, one solve", sdp, out[-1]))
    for count, (ours, ref) in timings.items():
        out += _ratio_records("Minkowski sums", count, ours, ref)
    return out


def sdp_record(solver: str, sdp: float, analytic: dict) -> dict:
    """Build the record of an SDP solve, its ratio taken to the analytic call it replaces.

    The ratio uses the one-call time of the analytic record (one measurement of that call
    in the report, not two).

    Parameters
    ----------
    solver : str
        What was solved, in the record's name.
    sdp : float
        Seconds of one solve.
    analytic : dict
        The speed record of one analytic call.

    Returns
    -------
    dict
        The speed record, with ``ratio`` = ``sdp`` / the analytic call's time.
    """
    return speed_record(
        NAME,
        f"{solver} ({DIM}-D, volume)",
        sdp,
        ratio=sdp / analytic["value"],
        ratio_label=f"slower than one analytic call ({analytic['name']})",
    )


def run(task: dict) -> dict:
    """Run one task: :func:`run_strip` or :func:`run_minkowski`.

    Parameters
    ----------
    task : dict
        A task of :func:`tasks`.

    Returns
    -------
    dict
        ``{"records": [...], "notes": [...]}``: the note names the instruction set.
    """
    runner = run_strip if task["what"] == "strip" else run_minkowski
    return {"records": runner(task), "notes": [f"Compiled by numba for {numba_target()}."]}


def _margin_row(operation: str, cond: float, margin: np.ndarray, shapes: np.ndarray) -> tuple:
    """(operation, input cond, margin median, 99 %, max, median output cond, median of
    margin / (U cond(output)))."""
    eig = np.linalg.eigvalsh(shapes)
    cond_out = eig[:, -1] / eig[:, 0]
    quant = np.quantile(margin, [0.5, 0.99, 1.0])
    return (operation, cond, *quant, np.median(cond_out), np.median(margin / (U * cond_out)))


U = 2.0**-53


def margin_distribution(seed: int = 0, count: int = 10**4) -> list[tuple]:
    """Measure the certified margins over random 3-D instances per input condition number.

    The margin is the relative inflation (see ``optbound.analytic._kernels.midrad``), shown
    next to the output's condition number: storing a shape S in floats already costs about
    ``U cond(S)`` in its thin direction, the floor of any certified margin on a float matrix.

    Parameters
    ----------
    seed : int
        Seed of the instances.
    count : int
        Instances per row.

    Returns
    -------
    list of tuple
        Per operation and input condition number: (operation, input cond, margin median,
        99 %, max, median output cond, median of margin / (U cond(output))).
    """
    from optbound import analytic

    rng = np.random.default_rng(seed)
    rows = []
    for cond in (1.0, 1e2, 1e4, 1e6, 1e8, 1e10):
        c, C, a, b = batch_instances(rng, count, DIM, cond)
        out = analytic.intersect_strip_batch(c, C, a, b)
        k = out.lam > 0
        rows.append(_margin_row("strip", cond, out.margin[k], out.shapes[k]))
        c2, C2, _, _ = batch_instances(rng, count, DIM, cond)
        out = analytic.minkowski_sum_batch(c, C, c2, C2)
        rows.append(_margin_row("minkowski", cond, out.margin, out.shapes))
    return rows


def jit_warmup() -> float:
    """Time the first strip and Minkowski calls in a fresh process with an empty numba cache.

    Returns
    -------
    float
        Seconds of the calls (a full compile), without the same process's import time.

    Raises
    ------
    subprocess.CalledProcessError
        If the child process fails.
    """
    code = (
        "import time, numpy as np; t0 = time.perf_counter(); "
        "from optbound import Ellipsoid, Strip, analytic; t1 = time.perf_counter(); "
        "E = Ellipsoid(np.zeros(3), np.eye(3)); "
        "analytic.intersect_strip(E, Strip([1.0, 0, 0], 0.5), lam=0.5); "
        "analytic.intersect_strip_batch(np.zeros((1, 3)), np.eye(3)[None], [1.0, 0, 0], 0.5); "
        "analytic.minkowski_sum(E, E); "
        "analytic.minkowski_sum_batch(np.zeros((1, 3)), np.eye(3)[None], np.zeros((1, 3)), "
        "np.eye(3)[None]); print(time.perf_counter() - t1)"
    )
    with tempfile.TemporaryDirectory() as cache:
        env = {**os.environ, "NUMBA_CACHE_DIR": cache}
        res = subprocess.run(
            [sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True
        )
    return float(res.stdout.strip().splitlines()[-1])


def phases(rng: np.random.Generator, seconds: float = 20.0, count: int = 10**3) -> list:
    """Record the strip batch rate over time, ours and the reference's.

    One :func:`alternating_calls` pair (two samples of >= 20 ms) after another. On a virtual
    machine the parallel rate of small batches can change in phases of seconds that no median
    within one run removes (the host's placement of the vCPUs); this shows them, for ours and
    the reference alike.

    Parameters
    ----------
    rng : numpy.random.Generator
        Draws the instances (:func:`batch_instances`).
    seconds : float
        How long to record.
    count : int
        Batch size.

    Returns
    -------
    list of tuple
        (seconds since start, our rate, the reference's rate), rates in updates/s.
    """
    from optbound import analytic
    from optbound.bench import analytic_reference as ref

    c, C, a, b = batch_instances(rng, count, DIM)
    ours, reference = (
        lambda: analytic.intersect_strip_batch(c, C, a, b),
        lambda: ref.strip_batch(c, C, a, b),
    )
    rows, start = [], time.perf_counter()
    while time.perf_counter() - start < seconds:
        t_ours, t_ref = alternating_calls(ours, reference, repeat=1)
        rows.append((time.perf_counter() - start, count / t_ours, count / t_ref))
    return rows


def main(argv=None) -> None:
    """Print the timing tables (``--suite``, ``--seed``; ``--phases`` or ``--threads`` alone).

    Parameters
    ----------
    argv : list of str, optional
        Command-line arguments (default ``sys.argv[1:]``).
    """
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--suite", choices=tuple(BATCHES), default="full")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument(
        "--phases", action="store_true", help="only the strip rate at B = 1e3 over 20 s"
    )
    parser.add_argument(
        "--threads",
        action="store_true",
        help="only the thread pool vs numba prange (strip, B = 1e3, 1e4, 1e5)",
    )
    args = parser.parse_args(argv)
    rng = np.random.default_rng(args.seed)
    if args.threads:
        import numba

        layer = os.environ.get("NUMBA_THREADING_LAYER", "default")
        print(f"strip kernel, {DIM}-D, volume; median of per-round time ratios (layer: {layer})")
        print("| B | thread pool (run_sliced) | prange / pool |")
        print("|---|---|---|")
        for count, rate, ratio in threading_timings(rng, BATCHES["quick"]):
            print(f"| {count:.0e} | {rate / 1e6:.2f} M/s | {ratio:.2f} |")
        print(f"(prange ran on numba's {numba.threading_layer()} layer)")
        return
    if args.phases:
        print("t (s) | strip, B = 1e3, ours | reference")
        for t, ours, ref in phases(rng):
            print(f"{t:5.1f} | {ours / 1e6:5.1f} M/s | {ref / 1e6:5.1f} M/s")
        return
    batches = BATCHES[args.suite]
    print(f"numba target: {numba_target()}")
    print(f"JIT warm-up (fresh compile, empty cache): {jit_warmup():.1f} s\n")
    for what, timings in (
        ("strip (intersect_strip)", strip_timings(rng, batches)),
        ("Minkowski (minkowski_sum)", minkowski_timings(rng, batches)),
    ):
        print(f"{what}, {DIM}-D, volume; medians of {REPEATS} alternating runs")
        print("| B | optbound | numba reference | time ratio |")
        print("|---|---|---|---|")
        ours, ref = timings.pop("one")
        print(f"| one call | {ours * 1e6:.1f} µs | {ref * 1e6:.1f} µs | {ours / ref:.2f} |")
        for count, (ours, ref) in timings.items():
            print(
                f"| {count:.0e} | {count / ours / 1e6:.2f} M/s | {count / ref / 1e6:.2f} M/s "
                f"| {ours / ref:.2f} |"
            )
        print()
    count = 10**4
    print(f"every criterion against volume, {DIM}-D; medians of {REPEATS} alternating runs")
    print(f"| operation | criterion | one call | volume | ratio | batch {count:.0e} | volume "
          "| ratio |")  # fmt: skip
    print("|---|---|---|---|---|---|---|---|")
    for op, name, one, one_vol, batch, batch_vol in criteria_timings(rng, count):
        print(
            f"| {op} | {name} | {one * 1e6:.1f} µs | {one_vol * 1e6:.1f} µs | "
            f"{one / one_vol:.2f} | {count / batch / 1e6:.2f} M/s | "
            f"{count / batch_vol / 1e6:.2f} M/s | {batch / batch_vol:.2f} |"
        )
    print()
    print("certified margin (relative inflation), random 3-D instances, 1e4 per row")
    print("| operation | cond | median | 99 % | max | median cond(output) | median margin / "
          "(U cond(output)) |")  # fmt: skip
    print("|---|---|---|---|---|---|---|")
    for op, cond, med, p99, top, cond_out, floor in margin_distribution(args.seed):
        print(
            f"| {op} | {cond:.0e} | {med:.1e} | {p99:.1e} | {top:.1e} | {cond_out:.1e} "
            f"| {floor:.2f} |"
        )


FAMILY = Family(
    name=NAME,
    title="Speed: analytic updates (latency, batch throughput) vs a plain numba kernel and SDP",
    kind="speed",
    requires=(
        "optbound.analytic:intersect_strip",
        "optbound.analytic:intersect_strip_batch",
        "optbound.analytic:minkowski_sum",
        "optbound.analytic:minkowski_sum_batch",
        "optbound.optimal:outer_ellipsoid",
        "optbound.optimal:minkowski_outer",
    ),
    tasks=tasks,
    run=run,
    parallel=False,
)

if __name__ == "__main__":
    main()
