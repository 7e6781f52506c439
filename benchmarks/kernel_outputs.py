"""Outputs of the compiled analytic kernels on seeded instances, to check a change bitwise.

A change that should not touch the arithmetic (compile time, layout, threading) must leave
every output bit unchanged. ``dump`` writes, to one ``.npz``, the outputs of the strip
(volume, trace, projection, robust, given lambda, half-space, unclipped) and Minkowski
(volume, trace, size_xy_psi, given kappa) batches of 2000 instances in n = 2, 3, 5 at
condition ~1, 1e3 and 1e8, plus 50 single calls of each operation per case; ``compare``
checks two such files for bitwise equality (dtype, shape and every value).

Run ``python -m benchmarks.kernel_outputs dump before.npz`` on the old code, the same with
``after.npz`` on the new one, then ``python -m benchmarks.kernel_outputs compare before.npz
after.npz``.
"""

from __future__ import annotations

import argparse
import sys

import numpy as np

BATCH, SINGLES = 2000, 50
_RESULT_FIELDS = ("centers", "shapes", "lam", "case", "consistency", "empty", "margin", "kappa")


def _put(out: dict, key: str, result) -> None:
    for field in _RESULT_FIELDS:
        value = getattr(result, field, None)
        if value is not None:
            out[f"{key}:{field}"] = np.asarray(value)


def outputs() -> dict:
    """Every output array, keyed by dimension, condition, operation and field."""
    from optbound import Ellipsoid, Halfspace, Strip
    from optbound.analytic import (
        intersect_strip,
        intersect_strip_batch,
        minkowski_sum,
        minkowski_sum_batch,
    )
    from optbound.analytic.strip_fusion import CASES
    from optbound.bench.speed_analytic import batch_instances

    out: dict = {}
    for n in (2, 3, 5):
        for cond in (None, 1e3, 1e8):
            rng = np.random.default_rng(1000 * n + (0 if cond is None else int(np.log10(cond))))
            c, C, a, b = batch_instances(rng, BATCH, n, cond)
            c2, C2, _, _ = batch_instances(rng, BATCH, n, cond)
            key = f"{n}:{cond}"
            for crit in ("volume", "trace", "projection", "robust"):
                kw = {"dims": [0, 1]} if crit == "projection" else {}
                _put(out, f"{key}:strip:{crit}", intersect_strip_batch(c, C, a, b, crit, **kw))
            lam = rng.uniform(0.0, 2.0, BATCH)
            _put(out, f"{key}:strip:lam", intersect_strip_batch(c, C, a, b, lam=lam))
            _put(out, f"{key}:strip:half", intersect_strip_batch(c, C, a, b, halfspace=True))
            _put(out, f"{key}:strip:noclip", intersect_strip_batch(c, C, a, b, clip=False))
            dims = ((0,), (1,)) if n == 2 else ((0, 1), (2,))
            for crit in ("volume", "trace", "size_xy_psi"):
                kw = {"dims": dims} if crit == "size_xy_psi" else {}
                _put(out, f"{key}:mink:{crit}", minkowski_sum_batch(c, C, c2, C2, crit, **kw))
            kappa = rng.uniform(0.05, 0.95, BATCH)
            _put(out, f"{key}:mink:kappa", minkowski_sum_batch(c, C, c2, C2, kappa=kappa))
            for i in range(SINGLES):
                E1 = Ellipsoid(c[i], 0.5 * (C[i] + C[i].T))
                E2 = Ellipsoid(c2[i], 0.5 * (C2[i] + C2[i].T))
                for j, S in enumerate((Strip(a[i], b[i]), Halfspace(a[i], b[i]))):
                    r = intersect_strip(E1, S)
                    E = r.ellipsoid
                    shape = [] if E is None else [E.center, E.shape.ravel()]
                    scalars = [r.lam, r.consistency, r.margin, CASES.index(r.case)]
                    out[f"{key}:single_strip:{i}:{j}"] = np.concatenate([scalars, *shape])
                r = minkowski_sum(E1, E2)
                E = r.ellipsoid
                scalars = [r.kappa, r.margin]
                out[f"{key}:single_sum:{i}"] = np.concatenate([scalars, E.center, E.shape.ravel()])
    return out


def compare(before: str, after: str) -> list[str]:
    """The keys whose arrays differ (in dtype, shape or any value) or exist in one file only."""
    x, y = np.load(before), np.load(after)
    keys = set(x.files) | set(y.files)
    return sorted(
        k
        for k in keys
        if k not in x.files
        or k not in y.files
        or x[k].dtype != y[k].dtype
        or x[k].shape != y[k].shape
        or not np.array_equal(x[k], y[k], equal_nan=True)
    )


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("dump").add_argument("path")
    both = sub.add_parser("compare")
    both.add_argument("before")
    both.add_argument("after")
    args = parser.parse_args(argv)
    if args.command == "dump":
        out = outputs()
        np.savez(args.path, **out)
        print(f"{len(out)} arrays, {sum(v.size for v in out.values())} values -> {args.path}")
        return
    differing = compare(args.before, args.after)
    count = len(np.load(args.before).files)
    print(f"{count} arrays compared; {len(differing)} differ" + (":" if differing else ""))
    for key in differing:
        print(" ", key)
    sys.exit(1 if differing else 0)


if __name__ == "__main__":
    main()
