"""CORA's 30-state tank: the data as stored, and the exact removal of the known input."""

from fractions import Fraction

import numpy as np

from optbound.scenarios import tank30


def test_data_is_cora_s_tank():
    d = tank30.data()
    assert "TUMcps/CORA@" in d["source"] and d["dt"] == 0.5
    A, B, C = (np.array(d[k]) for k in ("A", "B", "C"))
    assert A.shape == (30, 30) and B.shape == (30, 15) and C.shape == (21, 30)
    assert np.array(d["u"]).shape == (15, 235) and np.array(d["y"]).shape == (21, 235)
    assert np.all(np.diag(np.array(d["W"]["generators"])) == 0.001)
    assert np.all(np.diag(np.array(d["V"]["generators"])) == 0.2)
    assert max(abs(np.linalg.eigvals(A))) < 1.0  # a stable cascade


def test_shifted_system_keeps_the_measurements_of_x1_on():
    d, sc = tank30.data(), tank30.scenario()
    A, B, C = (np.array(d[k]) for k in ("A", "B", "C"))
    u, y = np.array(d["u"]).T, np.array(d["y"]).T
    assert sc.ys.shape == (234, 21) and sc.offsets.shape == (234, 30)
    assert np.array_equal(sc.X0.hi, np.full(30, 4.0)) and np.array_equal(sc.X0.lo, -sc.X0.hi)
    # s_1 = B u_0 (s_0 = 0), and ys[0] = y(:, 2) - C s_1, CORA's y(:, 1) (x_0) dropped.
    assert np.array_equal(sc.offsets[0], A @ np.zeros(30) + B @ u[0])
    assert np.array_equal(sc.ys[0], y[1] - C @ sc.offsets[0])
    # The widened noise covers CORA's plus the exact rounding of every step.
    W, V = sc.system.W, sc.system.V
    assert np.all(W.hi >= 0.001) and np.all(W.hi < 0.001 + 1e-12)
    assert np.all(V.hi >= 0.2) and np.all(V.hi < 0.2 + 1e-12)
    for k in (5, 100, 233):
        s_prev, s = sc.offsets[k - 1], sc.offsets[k]
        for i in range(30):  # r_k = A s_{k-1} + B u_k - s_k, exactly
            r = sum(Fraction(a) * Fraction(x) for a, x in zip(A[i], s_prev, strict=True))
            r += sum(Fraction(b) * Fraction(x) for b, x in zip(B[i], u[k], strict=True))
            assert abs(r - Fraction(s[i])) + Fraction(0.001) <= Fraction(W.hi[i])
        for i in range(21):  # e_k = fl(y - C s) - (y - C s), exactly
            e = Fraction(y[k + 1][i]) - sum(
                Fraction(c) * Fraction(x) for c, x in zip(C[i], s, strict=True)
            )
            assert abs(e - Fraction(sc.ys[k][i])) + Fraction(0.2) <= Fraction(V.hi[i])
