"""The lane-parallel building blocks agree with their scalar counterparts, bitwise."""

import numpy as np
import pytest
from numba import njit

from optbound._core import check_ellipsoid
from optbound.analytic._kernels.lanes import (
    CHECK_ROWS,
    W,
    check_ellipsoids,
    inflate_lanes,
    load_matrices,
    load_vectors,
    store_matrices,
    store_vectors,
    trace_inverse_lanes,
)
from optbound.analytic._kernels.midrad import inflate


@njit(error_model="numpy")
def _check_batch(c, C, code, L_out, c_out, C_out):
    """check_ellipsoids block by block; the centres and shapes are also stored back."""
    n_batch, n = c.shape
    cs, Cs, Ls = np.empty((n, W)), np.empty((n, n, W)), np.empty((n, n, W))
    codes, scratch = np.empty(W, np.int64), np.empty(CHECK_ROWS * W)
    for base in range(0, n_batch, W):
        m = min(W, n_batch - base)
        load_vectors(c[base:], m, cs)
        load_matrices(C[base:], m, Cs)
        check_ellipsoids(cs, Cs, Ls, m, codes, scratch)
        store_matrices(Ls, m, L_out[base:])
        store_vectors(cs, m, c_out[base:])
        store_matrices(Cs, m, C_out[base:])
        code[base : base + m] = codes[:m]


def _inputs(n: int, count: int, seed: int):
    """Random shapes with every kind of defect mixed in (each a known error code)."""
    rng = np.random.default_rng(seed)
    A = rng.standard_normal((count, n, n))
    C = A @ A.transpose(0, 2, 1)
    C[::7] *= -1.0  # not positive definite
    C[::11, 0, 0] = np.nan  # not finite
    C[::13, 1, 0] += 1e-3  # asymmetric
    C[::17] *= 1e-130  # semi-axes too small
    C[::29, n - 1, n - 1] = 1e-13  # ill-conditioned or not PD
    c = rng.standard_normal((count, n))
    c[::19] *= 1e70  # centre too far
    c[::23, 1] = np.inf
    return c, C


@pytest.mark.parametrize("n", [2, 3, 5])
@pytest.mark.parametrize("count", [1, W - 1, 3 * W + 5])
def test_check_ellipsoids_matches_the_scalar_check(n, count):
    c, C = _inputs(n, count, seed=n * 1000 + count)
    code = np.empty(count, np.int64)
    L, c_back, C_back = np.empty((count, n, n)), np.empty((count, n)), np.empty((count, n, n))
    _check_batch(c, C, code, L, c_back, C_back)
    assert np.array_equal(c_back, c, equal_nan=True)
    assert np.array_equal(C_back, C, equal_nan=True)
    for i in range(count):
        L_ref = np.empty((n, n))
        assert code[i] == check_ellipsoid(c[i], C[i], L_ref), i
        if code[i] == 0:
            assert np.array_equal(L[i], L_ref), i  # same operations, same bits


def test_every_code_occurs():
    """The mixed inputs above exercise every error code (else the test above proves less)."""
    c, C = _inputs(3, 5000, seed=1)
    code = np.empty(5000, np.int64)
    _check_batch(c, C, code, np.empty((5000, 3, 3)), np.empty((5000, 3)), np.empty((5000, 3, 3)))
    assert set(np.unique(code)) == set(range(7))


def _inflate_cases(n: int, count: int, seed: int):
    """Computed shapes S with radii D, centres c with radii d: benign, ill-conditioned,
    singular (full widening), far centres, and too large for the domain (margin -1)."""
    rng = np.random.default_rng(seed)
    q = np.linalg.qr(rng.standard_normal((count, n, n)))[0]
    axes = 10.0 ** rng.uniform(-8.0, 8.0, (count, n))
    S = (q * axes[:, None, :]) @ q.transpose(0, 2, 1)
    S[::7, :, 0] = S[::7, 0, :] = 0.0  # singular
    S[::11] *= 1e115  # beyond MAX_DIAG once inflated
    c = rng.standard_normal((count, n)) * 10.0 ** rng.uniform(-3.0, 12.0, (count, 1))
    c[::13, 0] = 1e61  # beyond MAG
    D = np.abs(S) * 10.0 ** rng.uniform(-16.0, -10.0, (count, 1, 1))
    d = np.abs(c) * 1e-16
    d[::3] = 0.0  # no centre error
    return S, D, c, d


@njit(error_model="numpy")
def _inflate_batch(S, D, c, d, T_out, margin_out, rows):
    n_batch, n = c.shape
    mats = np.empty((4, n, n, W))
    Ss, Ds, Ts, Ls = mats[0], mats[1], mats[2], mats[3]
    cs, ds, margin = np.empty((n, W)), np.empty((n, W)), np.empty(W)
    for base in range(0, n_batch, W):
        m = min(W, n_batch - base)
        load_matrices(S[base:], m, Ss)
        load_matrices(D[base:], m, Ds)
        load_vectors(c[base:], m, cs)
        load_vectors(d[base:], m, ds)
        inflate_lanes(Ss, Ds, cs, ds, Ts, Ls, m, margin, rows)
        store_matrices(Ts, m, T_out[base:])
        margin_out[base : base + m] = margin[:m]


@pytest.mark.parametrize("n", [1, 3, 4])
@pytest.mark.parametrize("count", [1, 3 * W + 5])
def test_inflate_lanes_matches_the_scalar_inflate(n, count):
    """Same shapes and margins as ``midrad.inflate`` (bitwise; -1.0 where the scalar version
    refuses), in full blocks and in the remainder."""
    S, D, c, d = _inflate_cases(n, count, seed=n * 100 + count)
    T, margin = np.empty((count, n, n)), np.empty(count)
    _inflate_batch(S, D, c, d, T, margin, tuple(np.empty(W) for _ in range(8)))
    assert {-1.0} < set(margin.tolist()) or count == 1
    for i in range(count):
        T_ref = np.empty((n, n))
        m_ref = inflate(S[i].copy(), D[i], c[i], d[i], T_ref, np.empty((n, n)))
        assert margin[i] == m_ref, i
        if m_ref >= 0.0:
            assert np.array_equal(T[i], T_ref), i


@njit(error_model="numpy")
def _trace_inverse_of(L_batch):
    """trace_inverse_lanes on a block of Cholesky factors."""
    m, n = L_batch.shape[0], L_batch.shape[1]
    L = np.zeros((n, n, W))
    for k in range(m):
        L[:, :, k] = L_batch[k]
    total = np.zeros(W)
    trace_inverse_lanes(L, m, total)
    return total[:m].copy()


@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_trace_inverse_is_the_trace_of_the_inverse(n):
    rng = np.random.default_rng(n)
    A = rng.standard_normal((W, n, n))
    A = A @ A.transpose(0, 2, 1) + 0.1 * np.eye(n)
    total = _trace_inverse_of(np.linalg.cholesky(A))
    np.testing.assert_allclose(total, np.trace(np.linalg.inv(A), axis1=1, axis2=2), rtol=1e-12)
