"""Tests of the certified floating-point helpers of ``optbound.analytic._kernels.midrad``."""

import numpy as np
import pytest

from optbound.analytic._kernels.midrad import lambda_min_estimate


@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_lambda_min_estimate_is_one_over_the_trace_of_the_inverse(n):
    rng = np.random.default_rng(n)
    A = rng.standard_normal((n, n))
    A = A @ A.T + 0.1 * np.eye(n)
    L = np.linalg.cholesky(A)
    total = 1.0 / lambda_min_estimate(L.copy())
    assert total == pytest.approx(np.trace(np.linalg.inv(A)), rel=1e-12)
    # 1 / tr(A^-1) is within a factor n below lambda_min(A)
    lmin = np.linalg.eigvalsh(A)[0]
    assert lmin / n * (1 - 1e-12) <= 1.0 / total <= lmin * (1 + 1e-12)
