"""The compiled kernels against the plain formulas of ``optbound.analytic.reference``.

Two oracles: the reference in floats (the kernel's centre, lambda and p agree with it up to
the reference's own rounding, its shape differs from it by no more than the certified margin
plus that rounding), and the reference evaluated in exact rationals (``fractions``: the
certified kernel output contains the exact member, checked on boundary points at 60 digits,
no tolerance, as ``tests.analytic.exact``). The benchmark's compiled reference is the same
code, bitwise.
"""

from __future__ import annotations

from fractions import Fraction

import mpmath as mp
import numpy as np
import pytest

from optbound import Ellipsoid, Strip, analytic
from optbound.analytic import reference
from optbound.bench import analytic_reference as bench_ref
from optbound.bench.speed_analytic import batch_instances
from tests.analytic import exact as X

U = 2.0**-53


def _strip_reference(c, C, a, b):
    """``reference.intersect_strip_volume`` per instance: (centres, shapes, lambdas)."""
    n_batch, n = c.shape
    out_c, out_C, lam = np.empty((n_batch, n)), np.empty((n_batch, n, n)), np.empty(n_batch)
    w = np.empty(n)
    for i in range(n_batch):
        lam[i] = reference.intersect_strip_volume(c[i], C[i], a[i], b[i], out_c[i], out_C[i], w)
    return out_c, out_C, lam


@pytest.mark.parametrize("cond", [None, 1e3])
def test_strip_kernel_is_the_reference_up_to_rounding_and_its_margin(cond):
    """The deviations are the plain reference's own rounding (its dot products and quadratic
    formula lose about cond U; the kernel's are in twice the working precision): measured
    up to 80 U in lambda, 11 U in the centre, 28 U beyond the margin in the shape."""
    c, C, a, b = batch_instances(np.random.default_rng(7), 2000, 3, cond)
    ref_c, ref_C, ref_lam = _strip_reference(c, C, a, b)
    out = analytic.intersect_strip_batch(c, C, a, b)
    fused = (ref_lam > 0) & (out.lam > 0)
    assert fused.mean() > 0.9  # the instances are genuine reductions
    assert np.all(np.abs(out.lam - ref_lam)[fused] <= 256 * U * ref_lam[fused])
    scale = np.abs(c).max(axis=1) + np.sqrt(np.einsum("bii->b", C))
    dev_c = np.abs(out.centers - ref_c).max(axis=1)
    assert np.all(dev_c[fused] <= 32 * U * scale[fused])
    size = np.linalg.norm(ref_C, 2, axis=(1, 2))
    dev_C = np.linalg.norm(out.shapes - ref_C, 2, axis=(1, 2))
    assert np.all(dev_C[fused] <= (out.margin + 64 * U)[fused] * size[fused])


def _fractions(x) -> np.ndarray:
    """A float array as an object array of exact rationals."""
    x = np.asarray(x, dtype=float)
    return np.array([Fraction(float(t)) for t in x.ravel()], dtype=object).reshape(x.shape)


def _exact_quadric(centre, shape) -> X.Quadric:
    """The ellipsoid of an exact (Fraction) centre and shape, at 60 digits."""
    with mp.workdps(X.DPS):
        c = mp.matrix([mp.mpf(t.numerator) / t.denominator for t in centre])
        M = mp.matrix([[mp.mpf(t.numerator) / t.denominator for t in row] for row in shape])
        return X.Quadric(c, mp.inverse(M))


def _assert_contains_exact_member(result: Ellipsoid, centre, shape, rng) -> None:
    """Boundary points of the exact member (60 digits, 1e-40 inside) lie in ``result``, its
    floats read exactly."""
    member = _exact_quadric(centre, shape)
    directions = list(rng.standard_normal((24, len(centre))))
    directions += list(np.vstack([np.eye(len(centre)), -np.eye(len(centre))]))
    points = X.boundary_points([member], member.c, directions)
    bound = X.Quadric.ellipsoid(result.center, result.shape)
    with mp.workdps(X.DPS):
        assert all(bound.value(x) <= 1 for x in points)


@pytest.mark.parametrize("lam", [0.05, 1.0, 7.0, 300.0])
def test_strip_reference_member_is_exact_and_the_kernel_contains_its_set(lam):
    """For a given lambda: the reference member [HS96, eq. (24)], evaluated exactly, contains
    the exact points of E ∩ S [HS96, eq. (25)] (the oracle is right), and so does the kernel's
    certified output; the kernel's floats are the reference's up to rounding and its margin.

    (The kernel evaluates the member for its own rounded parameter, a neighbouring member of
    the family, so it need not contain the exact member for lambda itself, only E ∩ S.)"""
    rng = np.random.default_rng(int(lam * 100))
    c, C, a, b = batch_instances(rng, 4, 3, 1e2)
    for i in range(4):
        E, S = Ellipsoid(c[i], C[i]), Strip(a[i], b[i])
        fused = analytic.intersect_strip(E, S, lam=lam, clip=False)
        assert fused.lam == lam
        eps = Fraction(float(b[i])) - sum(_fractions(a[i]) * _fractions(c[i]))
        centre, shape = np.empty(3, dtype=object), np.empty((3, 3), dtype=object)
        reference.strip_member(
            _fractions(c[i]), _fractions(C[i]), _fractions(a[i]), eps, Fraction(1),
            Fraction(lam), centre, shape, np.empty(3, dtype=object),
        )  # fmt: skip
        constraints, x0 = X.strip_set(c[i], C[i], a[i], b[i])
        points = X.boundary_points(constraints, x0, list(rng.standard_normal((32, 3))))
        member = _exact_quadric(centre, shape)
        bound = X.Quadric.ellipsoid(fused.ellipsoid.center, fused.ellipsoid.shape)
        with mp.workdps(X.DPS):
            assert all(member.value(x) <= 1 for x in points)
            assert all(bound.value(x) <= 1 for x in points)
        ref_c, ref_C = np.empty(3), np.empty((3, 3))
        reference.strip_member(c[i], C[i], a[i], b[i] - a[i] @ c[i], 1.0, lam, ref_c, ref_C,
                               np.empty(3))  # fmt: skip
        # Rounding scales: the magnitudes of the terms that are summed (C - (lambda / u) w w^T
        # cancels in E's thin direction; the kernel's strip is the true one widened by ~4 U).
        w = C[i] @ a[i]
        scale = np.abs(c[i]).max() + lam * np.abs(w).max()
        terms = (1 + lam) * (np.linalg.norm(C[i], 2) + lam * (w @ w))
        assert np.abs(fused.ellipsoid.center - ref_c).max() <= 8 * U * scale
        dev = np.linalg.norm(fused.ellipsoid.shape - ref_C, 2)
        assert dev <= fused.margin * np.linalg.norm(ref_C, 2) + 64 * U * terms


@pytest.mark.parametrize("kappa", [0.5, 0.25, 0.125])
def test_minkowski_kernel_contains_the_exact_reference_member(kappa):
    """p = (1 - kappa) / kappa is exact for these kappa: the certified member contains the
    Schweppe member [HS96, eq. (14)] evaluated exactly, and is the float member up to its
    margin."""
    rng = np.random.default_rng(int(1 / kappa))
    c1, C1, _, _ = batch_instances(rng, 4, 3)
    c2, C2, _, _ = batch_instances(rng, 4, 3, 1e3)
    p = (1 - kappa) / kappa
    for i in range(4):
        out = analytic.minkowski_sum(Ellipsoid(c1[i], C1[i]), Ellipsoid(c2[i], C2[i]), kappa=kappa)
        centre, shape = np.empty(3, dtype=object), np.empty((3, 3), dtype=object)
        exact_in = (_fractions(x) for x in (c1[i], C1[i], c2[i], C2[i]))
        reference.minkowski_member(*exact_in, Fraction(p), centre, shape)
        _assert_contains_exact_member(out.ellipsoid, centre, shape, rng)
        ref_c, ref_C = np.empty(3), np.empty((3, 3))
        reference.minkowski_member(c1[i], C1[i], c2[i], C2[i], p, ref_c, ref_C)
        assert np.array_equal(out.ellipsoid.center, ref_c)
        size = np.linalg.norm(ref_C, 2)
        assert np.linalg.norm(out.ellipsoid.shape - ref_C, 2) <= (out.margin + 8 * U) * size


def test_minkowski_volume_p_is_the_reference_root():
    rng = np.random.default_rng(3)
    c1, C1, _, _ = batch_instances(rng, 200, 3)
    c2, C2, _, _ = batch_instances(rng, 200, 3, 1e4)
    out = analytic.minkowski_sum_batch(c1, C1, c2, C2)
    p = (1 - out.kappa) / out.kappa
    ref_p = np.array([reference.minkowski_p_volume(C1[i], C2[i]) for i in range(200)])
    assert np.all(np.abs(p - ref_p) <= 1e-12 * ref_p)


def test_the_benchmark_compiles_the_reference_unchanged():
    """``optbound/bench/analytic_reference.py`` times the same code: its compiled strip update
    gives the plain Python reference's floats bitwise; its Minkowski sum (our lane p solver,
    the reference's member) is the reference's member for the reference's root p."""
    c, C, a, b = batch_instances(np.random.default_rng(5), 300, 3)
    ref_c, ref_C, _ = _strip_reference(c, C, a, b)
    bench_c, bench_C = bench_ref.strip_batch(c, C, a, b)
    assert np.array_equal(bench_c, ref_c) and np.array_equal(bench_C, ref_C)
    c2, C2 = c[::-1].copy(), C[::-1].copy()
    m_c, m_C = bench_ref.minkowski_batch(c, C, c2, C2)
    for i in range(0, 300, 37):
        one_c, one_C = np.empty(3), np.empty((3, 3))
        p = reference.minkowski_p_volume(C[i], C2[i])
        reference.minkowski_member(c[i], C[i], c2[i], C2[i], p, one_c, one_C)
        assert np.array_equal(m_c[i], one_c)
        assert np.all(np.abs(m_C[i] - one_C) <= 1e-12 * np.abs(one_C).max())
