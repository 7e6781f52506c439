"""The 3-D hand-unrolled strip kernel of ``benchmarks.strip_breakdown`` computes the update
of the plain reference formula (``analytic.reference.intersect_strip_volume``), up to the
rounding of an uncertified evaluation."""

import numpy as np

from benchmarks.strip_breakdown import plain3_range
from optbound.analytic import reference
from optbound.bench.speed_analytic import batch_instances

U = 2.0**-53


def test_plain3_is_the_reference_strip_update():
    c, C, a, b = batch_instances(np.random.default_rng(3), 40, 3, cond=1e3)
    out_c, out_C = np.empty(c.shape), np.empty(C.shape)
    plain3_range(c, C, a, b, out_c, out_C, np.empty((3, 3)), False)
    for k in range(len(c)):
        ref_c, ref_C = np.empty(3), np.empty((3, 3))
        lam = reference.intersect_strip_volume(c[k], C[k], a[k], b[k], ref_c, ref_C, np.empty(3))
        assert lam > 0.0  # a genuine update, not E itself
        # Rounding only: a few ulps of the inputs' magnitudes times cond(C) (= 1e3 here).
        tol = 1e3 * 64 * U
        scale = np.abs(ref_C).max()
        np.testing.assert_allclose(out_C[k], ref_C, rtol=0, atol=tol * scale)
        width = np.sqrt(np.abs(np.diag(C[k])).max())
        np.testing.assert_allclose(out_c[k], ref_c, rtol=0, atol=tol * (np.abs(c[k]).max() + width))
        assert not np.array_equal(out_C[k], C[k])
