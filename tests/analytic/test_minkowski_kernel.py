"""Tests of the volume-optimal p solver of ``optbound.analytic._kernels.minkowski_kernel``.

References: the generalized eigenvalues of (C1, C2) from ``scipy.linalg.eigh`` (moderate
instances) or at 50 digits with mpmath (extreme ones), and the root of
``sum_i (p^2 - l_i) / (l_i + p)`` (= h(p), module docstring) found by bisection on them.
"""

import warnings

import mpmath as mp
import numpy as np
import pytest
import scipy.linalg as sl
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from optbound import Ellipsoid, analytic
from optbound.analytic._kernels import minkowski_kernel as K
from optbound.analytic._kernels.lanes import W, cholesky_lanes


def _spd(rng, n: int, cond: float, scale: float) -> np.ndarray:
    """Random rotation of eigenvalues log-spaced over ``cond``, times ``scale``."""
    q, _ = np.linalg.qr(rng.standard_normal((n, n)))
    C = (q * (scale * np.logspace(0.0, -np.log10(cond), n))) @ q.T
    return 0.5 * (C + C.T)


def _lanes(stack: np.ndarray) -> np.ndarray:
    """(m, n, n) -> one block (n, n, W), lanes-last; the unused lanes hold NaN."""
    out = np.full((*stack.shape[1:], W), np.nan)
    out[..., : stack.shape[0]] = np.moveaxis(stack, 0, -1)
    return out


def _p_block(C1s, C2s, active=None) -> np.ndarray:
    """p of ``K.p_volume_lanes`` for one block of m = len(C1s) lanes."""
    m, n = C1s.shape[:2]
    A, B = _lanes(C1s), _lanes(C2s)
    L1, L2, pivot1, pivot2 = np.empty((n, n, W)), np.empty((n, n, W)), np.empty(W), np.empty(W)
    cholesky_lanes(A, L1, m, pivot1, 0)
    cholesky_lanes(B, L2, m, pivot2, 0)
    act = np.ones(W) if active is None else np.asarray(active, float)
    assert np.all((pivot1[:m] > 0) & (pivot2[:m] > 0) | (act[:m] == 0))
    p = np.full(W, np.nan)
    mats, vecs, rows, _, _, entries = K.block_work(n, W)
    newton = entries[K.NEWTON_ENTRY]
    K.p_volume_lanes(A, B, L1, L2, m, act, p, mats[:7], vecs[:3], rows[:14], newton)
    return p[:m]


def _p_volume(C1, C2) -> float:
    return float(_p_block(C1[None], C2[None])[0])


def _p_scipy(C1, C2) -> float:
    lam = sl.eigh(C1, C2, eigvals_only=True)
    lo, hi = np.sqrt(lam.min()), np.sqrt(lam.max())
    if hi <= lo * (1 + 1e-15):
        return lo
    h = lambda p: np.sum((p * p - lam) / (lam + p))  # noqa: E731
    return brentq(h, lo * (1 - 1e-12), hi * (1 + 1e-12), xtol=1e-300, rtol=1e-15)


def _p_exact(C1, C2) -> float:
    """The root for the float inputs read exactly, at 50 digits (eigenvalues of L2^-1 C1 L2^-T)."""
    with mp.workdps(50):
        A, B = mp.matrix(C1.tolist()), mp.matrix(C2.tolist())
        Li = mp.inverse(mp.cholesky(B, tol=mp.mpf("1e-5000")))
        lam = list(mp.eigsy(Li * A * Li.T, eigvals_only=True))
        h = lambda p: mp.fsum((p * p - x) / (x + p) for x in lam)  # noqa: E731
        lo, hi = mp.sqrt(min(lam)), mp.sqrt(max(lam))
        while hi - lo > hi * mp.mpf("1e-30"):
            mid = mp.sqrt(lo * hi)
            lo, hi = (mid, hi) if h(mid) < 0 else (lo, mid)
        return float(lo)


@settings(max_examples=60, deadline=None)
@given(
    n=st.integers(1, 6),
    seed=st.integers(0, 2**32 - 1),
    log_cond=st.floats(0.0, 4.0),
    log_scale=st.floats(-6.0, 6.0),
)
def test_p_matches_the_eigenvalue_solve(n, seed, log_cond, log_scale):
    """Moderate instances (cond <= 1e4): the p of scipy's generalized eigenvalues to 1e-12."""
    rng = np.random.default_rng(seed)
    C1, C2 = _spd(rng, n, 10**log_cond, 1.0), _spd(rng, n, 10**log_cond, 10**log_scale)
    assert _p_volume(C1, C2) == pytest.approx(_p_scipy(C1, C2), rel=1e-12)


# (cond, scale of C2 against C1, tolerance on p): the reference's own float inputs are read
# exactly, so the tolerance is the solver's error; it grows with cond as for any float solver
# (p is the root of a function of eigenvalues that cond * eps perturbs).
EXTREME = [
    (1.0, 1e-100, 1e-14),
    (1.0, 1e100, 1e-14),
    (1e2, 1e-100, 1e-13),
    (1e2, 1e100, 1e-13),
    (1e6, 1e-100, 1e-9),
    (1e6, 1e100, 1e-9),
    (1e6, 1.0, 1e-9),
    (1e12, 1.0, 1e-8),
    (1e12, 1e-100, 1e-4),
    (1e12, 1e100, 1e-4),
]


@pytest.mark.parametrize(("cond", "scale", "rtol"), EXTREME)
@pytest.mark.parametrize("n", [2, 3, 5])
def test_p_matches_the_exact_root_on_extreme_instances(cond, scale, rtol, n):
    rng = np.random.default_rng(int(np.log10(cond)) * 100 + n)
    for _ in range(3):
        C1, C2 = _spd(rng, n, cond, 1.0), _spd(rng, n, cond, scale)
        exact = _p_exact(C1, C2)
        assert _p_volume(C1, C2) == pytest.approx(exact, rel=rtol)
        assert _p_volume(C2, C1) == pytest.approx(1.0 / exact, rel=rtol)  # swapped pencil


@pytest.mark.parametrize("r2", [1e-50, 1e-20, 1e-3, 1.0, 1e3, 1e20, 1e50])
def test_balls_of_any_size_ratio(r2):
    """Balls: kappa = r2 / (1 + r2) (kappa -> 0 was lost to cancellation in h before)."""
    out = analytic.minkowski_sum(
        Ellipsoid(np.zeros(3), np.eye(3)), Ellipsoid(np.zeros(3), r2**2 * np.eye(3))
    )
    assert out.kappa == pytest.approx(r2 / (1.0 + r2), rel=1e-14)


def _corner(rng, a: float, cond: float) -> np.ndarray:
    """Semi-axes from a to a * sqrt(cond) if a <= 1, else from a / sqrt(cond) to a: inside
    the domain (squared semi-axes in [1e-120, 1e120], 0.1 % inside against rounding)."""
    return _spd(rng, 3, cond, a * a * (1.001 * cond if a <= 1.0 else 0.999))


@pytest.mark.parametrize("a1", [1e-60, 1e-30, 1.0, 1e30, 1e60])
@pytest.mark.parametrize("a2", [1e-60, 1.0, 1e60])
@pytest.mark.parametrize("cond", [1.0, 1e6, 1e12])
def test_domain_corners_give_finite_positive_p_without_warnings(a1, a2, cond):
    """Semi-axes 1e-60..1e60 and cond up to 1e12 (the domain's corners): a finite p > 0, no
    warning, and the public call succeeds (kappa may round to 1 when p ~ 1e-120) unless the
    sum itself leaves the domain (two summands of semi-axes 1e60: the documented error)."""
    rng = np.random.default_rng(0)
    C1, C2 = _corner(rng, a1, cond), _corner(rng, a2, cond)
    E1, E2 = Ellipsoid(np.zeros(3), C1), Ellipsoid(np.zeros(3), C2)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        p = _p_volume(C1, C2)
        assert np.isfinite(p) and p > 0
        if a1 == a2 == 1e60:
            with pytest.raises(ValueError, match="the sum leaves the supported domain"):
                analytic.minkowski_sum(E1, E2)
        else:
            assert 0 < analytic.minkowski_sum(E1, E2).kappa <= 1
    assert p == pytest.approx(_p_exact(C1, C2), rel=1e-4)


def _rows(count: int) -> tuple:
    """Work rows, as the kernels get them (separate arrays)."""
    return tuple(np.empty(W) for _ in range(count))


def _tridiagonal(Ms: np.ndarray) -> np.ndarray:
    """``K.tridiagonalize_lanes`` on a block of m = len(Ms) lanes, as full (m, n, n) matrices."""
    m, n = Ms.shape[:2]
    T = _lanes(Ms)
    K.tridiagonalize_lanes(T, m, np.empty((n, W)), np.empty((n, W)), _rows(4))
    T = np.moveaxis(T[..., :m], -1, 0)
    d, e = np.diagonal(T, axis1=1, axis2=2), np.diagonal(T, -1, axis1=1, axis2=2)
    return np.stack(
        [np.diag(di) + np.diag(ei, -1) + np.diag(ei, 1) for di, ei in zip(d, e, strict=True)]
    )


def _h_tridiagonal(T: np.ndarray, q: float) -> tuple[float, float]:
    """``K.h_tridiagonal_lanes`` for one lane (T (1, n, n) tridiagonal)."""
    h, dh = np.empty(W), np.empty(W)
    K.h_tridiagonal_lanes(_lanes(T), np.full(W, q), 1, h, dh, _rows(6))
    return h[0], dh[0]


@settings(max_examples=40, deadline=None)
@given(n=st.integers(1, 7), seed=st.integers(0, 2**32 - 1), log_cond=st.floats(0.0, 8.0))
def test_tridiagonal_form_keeps_the_eigenvalues(n, seed, log_cond):
    rng = np.random.default_rng(seed)
    M = _spd(rng, n, 10**log_cond, 1.0)
    T = _tridiagonal(M[None])[0]
    np.testing.assert_allclose(np.linalg.eigvalsh(T), np.linalg.eigvalsh(M), atol=1e-14)


@settings(max_examples=40, deadline=None)
@given(n=st.integers(1, 6), seed=st.integers(0, 2**32 - 1), log_q=st.floats(-3.0, 3.0))
def test_pivot_recurrence_gives_h_and_its_derivative(n, seed, log_q):
    """h and h' of the LDL^T recurrence against the eigenvalue formulas."""
    rng = np.random.default_rng(seed)
    M = _spd(rng, n, 1e3, 1.0)
    lam, q = np.linalg.eigvalsh(M), 10**log_q
    h, dh = _h_tridiagonal(_tridiagonal(M[None]), q)
    assert h == pytest.approx(np.sum(q * (q + 1) / (lam + q)) - n, rel=1e-10, abs=1e-12)
    exact_dh = np.sum((q * q + 2 * q * lam + lam) / (lam + q) ** 2)
    assert dh == pytest.approx(exact_dh, rel=1e-8)


def test_pivot_recurrence_reports_an_indefinite_shift():
    T = np.diag([1.0, -2.0, 3.0])
    assert np.isnan(_h_tridiagonal(T[None], 1.0)[0])


@pytest.mark.parametrize("s", [1e-8, 1e-30, 1e-60])
def test_tiny_first_summand_gives_the_exact_member(s):
    """C1 = s C2 (p = sqrt(s) << 1, the cancelling orientation; the former solver raised
    ZeroDivisionError here at s = 1e-60): the volume of the result is that of the member with
    the exact p."""
    q, _ = np.linalg.qr(np.random.default_rng(3).standard_normal((3, 3)))
    C = q @ q.T  # the identity up to rounding
    C = 0.5 * (C + C.T)
    out = analytic.minkowski_sum(Ellipsoid(np.zeros(3), s * C), Ellipsoid(np.zeros(3), C))
    p = np.sqrt(s)
    exact = (1 + p) * (s * C / p + C)
    logvol = np.linalg.slogdet(out.ellipsoid.shape)[1]
    assert logvol == pytest.approx(np.linalg.slogdet(exact)[1], abs=1e-13)


def _mixed_pairs(rng, count: int, n: int = 3):
    """Pairs of every kind in one block: balls (p exact at the start), cond up to 1e12,
    summands up to 1e100 apart in size, both orientations: the lanes converge after very
    different numbers of Newton steps."""
    cases = [(1.0, 1.0), (1e2, 1e-6), (1e4, 1e6), (1e6, 1.0), (1e12, 1.0), (1e12, 1e-100)]
    C1s, C2s, rtols = [], [], []
    for i in range(count):
        cond, scale = cases[i % len(cases)]
        if i % 5 == 0:
            C1, C2 = np.eye(n), scale * np.eye(n)
        else:
            C1, C2 = _spd(rng, n, cond, 1.0), _spd(rng, n, cond, scale)
        if i % 2:
            C1, C2 = C2, C1
        C1s.append(C1)
        C2s.append(C2)
        rtols.append(1e-4 if cond > 1e6 else 1e-9)
    return np.array(C1s), np.array(C2s), rtols


def test_lockstep_lanes_are_independent_and_match_the_exact_root():
    """A full block of lanes with mixed convergence: each lane gives the bits of the same
    instance alone (a block of one, the scalar remainder of the vector loops), whatever its
    neighbours and the inactive lanes (NaN data) do, and the 50-digit root."""
    C1s, C2s, rtols = _mixed_pairs(np.random.default_rng(7), W)
    active = np.ones(W)
    active[3::9] = 0.0  # inactive lanes hold garbage: they must not disturb the others
    C1s[3::9, 0, 0] = np.nan
    p = _p_block(C1s, C2s, active)
    for i in range(W):
        if active[i]:
            assert p[i] == _p_volume(C1s[i], C2s[i]), i
    for i in range(0, W, 4):
        if active[i]:
            assert p[i] == pytest.approx(_p_exact(C1s[i], C2s[i]), rel=rtols[i]), i


def _kernel_batch(c1, C1, c2, C2, mode, p_in):
    """``K.sum_range`` on the whole batch, inputs read-only as the public functions pass them."""
    B, n = c1.shape
    out = (np.empty((B, n)), np.empty((B, n, n)), np.zeros(B, np.int8), np.empty(B), np.empty(B))
    inputs = [np.array(x) for x in (c1, C1, c2, C2)]
    for x in inputs:
        x.flags.writeable = False
    first = K.sum_range(*inputs, mode, p_in, np.array([0, 1]), np.array([2]), out, 0, B)
    bad = np.flatnonzero(out[2])
    assert first == (bad[0] if bad.size else -1)
    return out


@pytest.mark.parametrize("mode", [K.P_VOLUME, K.P_TRACE, K.P_GIVEN, K.P_XY_PSI])
def test_mixed_batch_matches_single_calls(mode):
    """Valid and invalid instances (every error code of both summands, a bad p, a sum
    leaving the domain) in full blocks and a remainder: each instance's code, p, margin and
    result equal those of a batch of one, the path of a single call (bitwise)."""
    rng = np.random.default_rng(11)
    B = 2 * W + 5
    C1s, C2s, _ = _mixed_pairs(rng, B)
    c1, c2 = rng.standard_normal((B, 3)), rng.standard_normal((B, 3))
    p_in = rng.uniform(0.1, 10.0, B)
    C1s[1::13, 1, 0] += 1e-3  # asymmetric first summand
    C2s[2::17] *= -1.0  # second summand not positive definite
    c2[4::19, 0] = np.inf  # not finite
    c1[5::23] *= 1e70  # centre too far
    C1s[6::29] *= 1e119
    C2s[6::29] *= 1e119  # the sum leaves the domain
    p_in[7::31] = -1.0  # a bad p (kappa outside (0, 1))
    out = _kernel_batch(c1, C1s, c2, C2s, mode, p_in)
    assert len(set(out[2].tolist())) >= 5 and np.sum(out[2] == 0) > B // 2
    for i in range(B):
        one = _kernel_batch(c1[i : i + 1], C1s[i : i + 1], c2[i : i + 1], C2s[i : i + 1], mode,
                            p_in[i : i + 1])  # fmt: skip
        assert [x[i] for x in out[2:]] == [x[0] for x in one[2:]], i
        if one[2][0] == 0:
            assert np.array_equal(out[0][i], one[0][0]), i
            assert np.array_equal(out[1][i], one[1][0]), i
