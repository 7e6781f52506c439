"""``optbound.optimal._small``: the compiled kernels compute numpy's formulas (to rounding:
numba may call another LAPACK build and sums may run in another order)."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from optbound.optimal import _small

EPS = np.finfo(float).eps


def _symmetric(rng, k, m):
    A = rng.standard_normal((k, m, m))
    return A + A.transpose(0, 2, 1)


@given(st.integers(0, 10_000), st.integers(1, 7))
def test_largest_eigenvalue_is_numpys(seed, m):
    A = _symmetric(np.random.default_rng(seed), 1, m + 1)[0]
    close = {"rtol": 0, "atol": 1e-13 * np.max(np.abs(A))}
    np.testing.assert_allclose(_small.max_eig(A), np.linalg.eigvalsh(A)[-1], **close)


def test_only_the_lower_triangle_is_read_as_by_numpy():
    assert _small.max_eig(np.array([[1.0, 5.0], [0.0, 2.0]])) == 2.0


@given(st.integers(0, 10_000), st.integers(1, 5), st.integers(1, 6))
def test_in_frame_is_the_normalised_congruence_with_its_error_bound(seed, n, k):
    rng = np.random.default_rng(seed)
    forms = _symmetric(rng, k, n + 1)
    frame = np.eye(n + 1)
    frame[:n, :] = rng.standard_normal((n, n + 1))
    normalized, norms, errors = _small.in_frame(forms, frame)
    scaled = frame.T @ forms @ frame
    expected_norms = np.sqrt(np.einsum("kij,kij->k", scaled, scaled))
    np.testing.assert_allclose(norms, expected_norms, rtol=1e-13)
    np.testing.assert_allclose(normalized, scaled / expected_norms[:, None, None], atol=1e-13)
    assert np.array_equal(normalized, normalized.transpose(0, 2, 1))
    magnitudes = np.abs(frame).T @ np.abs(forms) @ np.abs(frame)
    bound = 16 * (n + 1) * EPS * np.sqrt(np.einsum("kij,kij->k", magnitudes, magnitudes))
    np.testing.assert_allclose(errors, bound / expected_norms, rtol=1e-13)


@given(st.integers(0, 10_000), st.integers(1, 5), st.integers(1, 6))
def test_certificate_eigs_are_those_of_the_parts_and_of_their_sum(seed, n, k):
    forms = _symmetric(np.random.default_rng(seed), k, n + 1)
    lowest, joint = _small.certificate_eigs(forms)
    parts = forms[:, :n, :n]
    close = {"rtol": 0, "atol": 1e-13 * np.max(np.abs(forms)) * k}
    np.testing.assert_allclose(lowest, np.linalg.eigvalsh(parts)[:, 0].min(), **close)
    np.testing.assert_allclose(joint, np.linalg.eigvalsh(parts.sum(axis=0))[0], **close)


@given(st.integers(0, 10_000), st.integers(1, 5), st.integers(1, 6))
def test_weighted_sum_eig_and_its_margin(seed, m, k):
    rng = np.random.default_rng(seed)
    forms = _symmetric(rng, k, m)
    tau, errors = rng.uniform(0.0, 2.0, k), rng.uniform(0.0, 1e-12, k)
    lowest, margin = _small.weighted_sum_eig(tau, forms, errors)
    S = np.einsum("k,kij->ij", tau, forms)
    np.testing.assert_allclose(lowest, np.linalg.eigvalsh(S)[0], rtol=0, atol=1e-12)
    frob = np.sqrt(np.einsum("kij,kij->k", forms, forms))
    expected = 16 * m * EPS * (tau @ frob) + tau @ errors
    assert margin == pytest.approx(expected, rel=1e-13)


@given(st.integers(0, 10_000), st.integers(1, 5))
def test_ellipsoid_in_x_maps_the_frame_answer_back(seed, n):
    rng = np.random.default_rng(seed)
    B = rng.standard_normal((n, n))
    M, bt = B @ B.T + np.eye(n), rng.standard_normal(n)
    center, W = rng.standard_normal(n), np.tril(rng.standard_normal((n, n))) + 3 * np.eye(n)
    x0, C, L, status = _small.ellipsoid_in_x(M, bt, center, W)
    assert status == 0 and np.allclose(L @ L.T, C, rtol=1e-12, atol=1e-12)
    shape_y = np.linalg.inv(M)
    np.testing.assert_allclose(x0, center - W @ shape_y @ bt, rtol=1e-10, atol=1e-10)
    np.testing.assert_allclose(C, W @ shape_y @ W.T, rtol=1e-10, atol=1e-12)
    assert np.array_equal(C, C.T)


@given(st.integers(0, 10_000), st.integers(1, 5), st.integers(1, 6))
def test_weighted_sum_and_its_magnitude(seed, m, k):
    rng = np.random.default_rng(seed)
    matrices, weights = _symmetric(rng, k, m), rng.uniform(-2.0, 2.0, k)
    S, magnitude = _small.weighted_sum(weights, matrices)
    np.testing.assert_allclose(S, np.einsum("k,kij->ij", weights, matrices), atol=1e-13)
    frob = np.sqrt(np.einsum("kij,kij->k", matrices, matrices))
    assert magnitude == pytest.approx(np.abs(weights) @ frob, rel=1e-13)


@given(st.integers(0, 10_000), st.integers(1, 5))
def test_lifted_form_is_the_ellipsoid_form_in_the_frame(seed, n):
    rng = np.random.default_rng(seed)
    chol = np.tril(rng.standard_normal((n, n)), -1) + np.diag(rng.uniform(0.5, 2.0, n))
    center, frame = rng.standard_normal(n), np.eye(n + 1)
    frame[:n, :] = rng.standard_normal((n, n + 1))
    P = _small.lifted_form(chol, center, frame)
    X = np.linalg.solve(chol, np.hstack([frame[:n, :n], (frame[:n, n] - center)[:, None]]))
    np.testing.assert_allclose(P, X.T @ X, rtol=1e-10, atol=1e-10 * np.max(np.abs(P)))
    assert np.array_equal(P, P.T)


@given(st.integers(0, 10_000), st.integers(2, 5))
def test_smallest_inflation_is_the_generalized_eigenvalue_over_the_betas(seed, m):
    rng = np.random.default_rng(seed)
    P, fixed, S = (A @ A.T / m for A in rng.standard_normal((3, m, m)))
    betas, delta = np.array([1.0, 0.9, 0.5, -5.0]), 1e-3
    alpha, beta = _small.smallest_inflation(P, fixed, S, delta, betas)
    expected = []
    for b in betas:
        R = fixed + b * S - delta * np.eye(m)
        d, V = np.linalg.eigh(R)
        if d[0] > 0:
            scaled = V / np.sqrt(d)
            expected.append(np.sqrt(max(1.0, np.linalg.eigvalsh(scaled.T @ P @ scaled)[-1])))
        else:
            expected.append(np.inf)
    best = int(np.argmin(expected))
    if np.isfinite(expected[best]):
        assert alpha == pytest.approx(expected[best], rel=1e-9) and beta == betas[best]
    else:
        assert alpha == np.inf and np.isnan(beta)


@given(st.integers(0, 10_000), st.integers(1, 6))
def test_lmi_check_is_the_largest_eigenvalue_and_its_margin(seed, m):
    rng = np.random.default_rng(seed)
    P, G = _symmetric(rng, 2, m)
    worst, margin = _small.lmi_check(P, G, 2.5, 1e-9)
    np.testing.assert_allclose(worst, np.linalg.eigvalsh(P - G)[-1], rtol=0, atol=1e-12)
    assert margin == pytest.approx(16 * m * EPS * (np.linalg.norm(P) + 2.5) + 1e-9, rel=1e-13)
