"""The analytic core's guarantee, checked exactly: levels of exact points of the true set in the
returned ellipsoid, read as exact numbers, are <= 1 with no tolerance (60-digit mpmath, see
``tests.analytic.exact``). Every category of issue 8: far centres, condition numbers up to the
domain's limit, tangent and cap cuts, half-spaces, huge and tiny lambda and kappa, recursive
filtering with the true point on a plane of every strip, and batched vs single (bitwise).
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from optbound import Ellipsoid, Halfspace, Strip, analytic
from optbound._core import COND_MAX, RATIO_MAX
from tests.analytic import exact as X
from tests.analytic.test_strip_fusion import CRITERIA

LAMBDAS = [1e-300, 1e-12, 1e-3, 0.37, 1e3, 1e8, 1e16, 1e300]
KAPPAS = [1e-15, 1e-9, 0.5, 1 - 1e-9, 1 - 2**-53]


def rotated(rng, n: int, cond: float, scale: float) -> np.ndarray:
    """Symmetric shape, random rotation, eigenvalues log-spaced over ``cond``, largest scale^2."""
    q, _ = np.linalg.qr(rng.standard_normal((n, n)))
    C = (q * (scale**2 * np.logspace(0.0, -np.log10(cond), n))) @ q.T
    return 0.5 * (C + C.T)


def strip_at(rng, E: Ellipsoid, lo: float, hi: float) -> Strip:
    """Strip with a random normal between ``lo`` and ``hi`` in E's extent units (-1..1)."""
    a = rng.standard_normal(E.dim)
    g = math.sqrt(a @ E.shape @ a)
    ac = a @ E.center
    return Strip.from_bounds(a, ac + lo * g, ac + hi * g)


def assert_strip_guarantee(E, S, fused, rng, count: int = 24) -> None:
    """``fused`` contains E ∩ S exactly; it is None only if E ∩ S is exactly empty (an empty
    E ∩ S that cannot be proven so at rounding level may get any ellipsoid)."""
    if X.disjoint(E.center, E.shape, S.a, S.b, isinstance(S, Halfspace)):
        return
    assert fused.ellipsoid is not None, "declared inconsistent, but E ∩ S is not empty"
    pts = X.strip_points(E.center, E.shape, S.a, S.b, rng, count, isinstance(S, Halfspace))
    level = X.max_level(fused.ellipsoid.center, fused.ellipsoid.shape, pts)
    assert level <= 1, f"level {level} > 1"


# ----------------------------------------------------------------------- strip: categories
def _instances(seed: int, count: int):
    """Seeded (E, S) covering the categories: conditioning, far centres, cuts of every kind."""
    rng = np.random.default_rng(seed)
    out = []
    for k in range(count):
        n = (2, 3, 3, 4)[k % 4]
        cond = 10.0 ** rng.uniform(0, np.log10(COND_MAX) - 0.5)
        scale = 10.0 ** rng.uniform(-3, 3)
        ratio = 10.0 ** rng.uniform(0, np.log10(RATIO_MAX) - 1.5)
        C = rotated(rng, n, cond, scale)
        lmin = scale**2 / cond
        c = rng.standard_normal(n)
        c *= ratio * math.sqrt(lmin) / np.max(np.abs(c))
        E = Ellipsoid(c, C)
        kind = k % 6
        if kind == 0:  # a cut through the middle
            lo = rng.uniform(-0.9, 0.5)
            S = strip_at(rng, E, lo, lo + rng.uniform(0.05, 0.5))
        elif kind == 1:  # a thin strip
            lo = rng.uniform(-0.9, 0.9)
            S = strip_at(rng, E, lo, lo + 10.0 ** rng.uniform(-9, -3))
        elif kind == 2:  # a cap of relative depth 1e-12..1e-2 (one plane beyond E)
            depth = 10.0 ** rng.uniform(-12, -2)
            S = strip_at(rng, E, 1 - depth, 3.0)
        elif kind == 3:  # tangent up to rounding (touching or just missing)
            S = strip_at(rng, E, 1 + rng.choice([-1, 0, 1]) * 1e-15, 2.0)
        elif kind == 4:  # covering E
            S = strip_at(rng, E, -1.5, 1.5)
        else:  # disjoint or nearly so
            S = strip_at(rng, E, 1 + 10.0 ** rng.uniform(-14, -1), 3.0)
        out.append((E, S))
    return out


@pytest.mark.parametrize(("criterion", "kw"), CRITERIA)
def test_strip_fusion_is_outer_in_exact_arithmetic(criterion, kw):
    rng = np.random.default_rng(1)
    for E, S in _instances(seed=7, count=24):
        assert_strip_guarantee(E, S, analytic.intersect_strip(E, S, criterion, **kw), rng)


@pytest.mark.parametrize("lam", LAMBDAS)
def test_any_lambda_is_outer_and_valid(lam):
    rng = np.random.default_rng(2)
    for E, S in _instances(seed=11, count=12):
        fused = analytic.intersect_strip(E, S, lam=lam)
        assert 0.0 <= fused.lam <= lam
        assert_strip_guarantee(E, S, fused, rng, count=12)


def test_issue_cases_are_outer():
    """The measured failures of issue 8 (centres moved inside the supported domain)."""
    rng = np.random.default_rng(3)
    r, c = 1e-2, np.array([1.23456789e8, 0.0])
    E = Ellipsoid(c, r * r * np.eye(2))
    cases = [(E, Strip.from_bounds([1.0, 0.0], c[0] + 0.3 * r, c[0] + 0.6 * r), {})]
    q = np.array([[np.cos(0.3), -np.sin(0.3)], [np.sin(0.3), np.cos(0.3)]])
    E8 = Ellipsoid([0.0, 0.0], q @ np.diag([1.0, 1e-8]) @ q.T)
    S8 = Strip.from_bounds([0.2, 1.0], 0.0, 5e-5)
    cases += [(E8, S8, {}), (E8, S8, {"clip": False})]
    disc = Ellipsoid([0.0, 0.0], np.eye(2))
    cases += [(disc, Strip.from_bounds([1.0, 0.0], 1 - 1e-12, 3.0), {"clip": False})]
    cases += [(disc, Strip([1.0, 0.0], 0.5), {"lam": 1e16})]
    E2 = Ellipsoid([0.0, 0.0], np.diag([100.0, 1.0]))
    cases += [(E2, Strip.from_bounds([0.0, 1.0], 0.3, 0.3 + 1e-7), {})]
    for E, S, kw in cases:
        fused = analytic.intersect_strip(E, S, **kw)
        assert fused.ellipsoid is not None
        assert_strip_guarantee(E, S, fused, rng)


def test_no_false_inconsistent_near_tangency_at_high_condition():
    """Touching within rounding at cond 1e11: never declared empty unless exactly empty."""
    rng = np.random.default_rng(4)
    for _ in range(20):
        E = Ellipsoid(rng.standard_normal(3), rotated(rng, 3, 1e11, 1.0))
        a = rng.standard_normal(3)
        hi = E.extent(a)[1]
        for shift in (-1e-13, 0.0, 1e-16):
            S = Strip.from_bounds(a, hi * (1 + shift) if hi else shift, hi + 1.0)
            assert_strip_guarantee(E, S, analytic.intersect_strip(E, S), rng, count=8)


def test_halfspace_is_fused_as_a_halfspace():
    rng = np.random.default_rng(5)
    E = Ellipsoid([0.0, 0.0], np.eye(2))
    for b in (-0.9, -0.2, 0.0, 0.7, 0.999999):
        H = Halfspace([1.0, 0.0], b)
        fused = analytic.intersect_strip(E, H)
        assert fused.case == "partial" and fused.ellipsoid is not None
        assert_strip_guarantee(E, H, fused, rng)
        # It is the half-space, not the strip |x1 - b| <= 1 (the old reading): it removes the
        # part of E above b, and nothing below (a small cap, b > 0, may not reduce the volume).
        if b > 0:
            continue
        assert fused.ellipsoid.volume() < E.volume()
        assert fused.ellipsoid.extent([1.0, 0.0])[0] <= -1.0
        as_strip = analytic.intersect_strip(E, Strip([1.0, 0.0], b)).ellipsoid
        assert not np.array_equal(fused.ellipsoid.shape, as_strip.shape)
    assert analytic.intersect_strip(E, Halfspace([1.0, 0.0], 2.0)).case == "no_reduction"
    assert analytic.intersect_strip(E, Halfspace([1.0, 0.0], -1.5)).ellipsoid is None


@pytest.mark.parametrize(
    ("E", "S", "err"),
    [
        ([0.0, 0.0], Strip([1.0, 0.0], 0.0), TypeError),
        (Ellipsoid([0.0, 0.0], np.eye(2)), ([1.0, 0.0], 0.0), TypeError),
        (Ellipsoid([0.0, 0.0], np.eye(2)), Ellipsoid([0.0, 0.0], np.eye(2)), TypeError),
    ],
)
def test_wrong_types_are_refused_with_the_argument_name(E, S, err):
    with pytest.raises(err, match=r"^E must|^S must"):
        analytic.intersect_strip(E, S)


# ------------------------------------------------------------------------- Minkowski sums
@pytest.mark.parametrize("criterion", ["volume", "trace", "size_xy_psi"])
def test_minkowski_sum_is_outer_in_exact_arithmetic(criterion):
    rng = np.random.default_rng(6)
    for k in range(16):
        n = 3
        s1, s2 = 10.0 ** rng.uniform(-3, 3, 2)
        conds = 10.0 ** rng.uniform(0, 11, 2)
        far = min(1e8, 1e9 * s1 / math.sqrt(conds[0])) if k % 2 else 1.0  # inside the domain
        E1 = Ellipsoid(rng.standard_normal(n) * far, rotated(rng, n, conds[0], s1))
        E2 = Ellipsoid(rng.standard_normal(n), rotated(rng, n, conds[1], s2))
        m = analytic.minkowski_sum(E1, E2, criterion)
        pts = X.sum_points(E1, E2, X.directions(rng, n, 40))
        assert X.max_level(m.ellipsoid.center, m.ellipsoid.shape, pts) <= 1


@pytest.mark.parametrize("kappa", KAPPAS)
def test_any_kappa_is_outer(kappa):
    rng = np.random.default_rng(7)
    E1 = Ellipsoid([1e8, 0.1, -3.0], rotated(rng, 3, 1e4, 1e-1))
    E2 = Ellipsoid([0.1, 0.0, 2.0], rotated(rng, 3, 1e2, 1e-2))
    m = analytic.minkowski_sum(E1, E2, kappa=kappa)
    pts = X.sum_points(E1, E2, X.directions(rng, 3, 40))
    assert X.max_level(m.ellipsoid.center, m.ellipsoid.shape, pts) <= 1


# ------------------------------------------------------------------------ bounding update
class _Measurement:
    """``(z - H x)^T V^{-1} (z - H x) <= 1``, read exactly."""

    def __init__(self, H, z, V):
        self.H, self.z, self.W = X._mat(H), X._vec(z), mp.inverse(X._mat(V))

    def value(self, x):
        r = self.z - self.H * x
        return (r.T * self.W * r)[0]

    def ray(self, x0, d):
        e = self.z - self.H * x0
        hd = self.H * d
        qa = (hd.T * self.W * hd)[0]
        qb = -2 * (hd.T * self.W * e)[0]
        qc = (e.T * self.W * e)[0] - 1
        if qa <= 0:
            return mp.inf
        return (-qb + mp.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)


def assert_update_guarantee(E, H, z, V, upd, x0, rng) -> None:
    H = np.atleast_2d(np.asarray(H, dtype=float))
    with mp.workdps(X.DPS):
        cons = [X.Quadric.ellipsoid(E.center, E.shape), _Measurement(H, z, np.atleast_2d(V))]
        pts = X.boundary_points(cons, x0, X.directions(rng, E.dim, 60))
    assert upd.ellipsoid is not None
    assert X.max_level(upd.ellipsoid.center, upd.ellipsoid.shape, pts) <= 1


def test_bounding_update_issue_cases_are_outer():
    rng = np.random.default_rng(8)
    E1 = Ellipsoid([0.0], [[1.0]])
    upd = analytic.bounding_update(E1, [[1.0]], [0.99], [[1e-4]])
    assert_update_guarantee(E1, [[1.0]], [0.99], [[1e-4]], upd, [0.99], rng)
    lo, hi = upd.ellipsoid.extent([1.0])
    assert lo <= 0.98 and hi >= 1.0 and hi - lo < 0.02 * (1 + 1e-6)
    disc = Ellipsoid([0.0, 0.0], np.eye(2))
    for r in (0.01, 3e-4, 1e-5):
        z = np.array([0.3, 0.2])
        upd = analytic.bounding_update(disc, np.eye(2), z, r * r * np.eye(2))
        assert_update_guarantee(disc, np.eye(2), z, r * r * np.eye(2), upd, z, rng)


@pytest.mark.parametrize("criterion", ["volume", "trace"])
def test_bounding_update_is_outer_on_random_measurements(criterion):
    rng = np.random.default_rng(9)
    for k in range(8):
        n, m = (2, 3)[k % 2], 1 + k % 2
        E = Ellipsoid(
            rng.standard_normal(n) * 10.0 ** (k % 4), rotated(rng, n, 10.0 ** (k % 5), 1.0)
        )
        x = E.center + 0.5 * E.chol @ (rng.standard_normal(n) / np.sqrt(n))
        H = rng.standard_normal((m, n))
        V = rotated(rng, m, 10.0, 10.0 ** rng.uniform(-4, 0))
        z = H @ x + 0.3 * np.linalg.cholesky(V) @ (rng.standard_normal(m) / np.sqrt(m))
        upd = analytic.bounding_update(E, H, z, V, criterion=criterion)
        assert_update_guarantee(E, H, z, V, upd, x, rng)


# ------------------------------------------------------------------ recursive filtering
def _on_plane_strip(rng, E: Ellipsoid, x: np.ndarray, width: float) -> Strip:
    """A strip of ``width`` times E's extent with x exactly inside, on (or next to) a plane."""
    a = rng.standard_normal(E.dim)
    a *= 2.0 / (width * 2.0 * math.sqrt(a @ E.shape @ a))
    side = rng.choice([-1.0, 1.0])
    with mp.workdps(X.DPS):
        t = sum(mp.mpf(float(ai)) * mp.mpf(float(xi)) for ai, xi in zip(a, x, strict=True))
        b = float(t + side)  # x on the plane a^T x = b - side, up to the rounding of b
        while abs(t - mp.mpf(b)) > 1:
            b = math.nextafter(b, float(t))
    return Strip(a, b)


def _recursive_run(seed: int, steps: int, n: int, far: float) -> None:
    rng = np.random.default_rng(seed)
    x = far * rng.standard_normal(n)
    E = Ellipsoid(x + rng.uniform(-0.5, 0.5, n), np.eye(n))
    noise = Ellipsoid(np.zeros(n), 1e-12 * np.eye(n))
    for k in range(steps):
        S = _on_plane_strip(rng, E, x, rng.uniform(0.2, 0.9))
        fused = analytic.intersect_strip(E, S, ("volume", "trace", "robust")[k % 3])
        assert fused.ellipsoid is not None, f"step {k}: false inconsistent"
        E = fused.ellipsoid
        if k % 25 == 24:  # a prediction step: x + 0 is in E + noise
            E = analytic.minkowski_sum(E, noise).ellipsoid
        assert X.max_level(E.center, E.shape, [X._vec(x)]) <= 1, f"step {k}"


def test_recursive_on_plane_points_stay_inside():
    _recursive_run(seed=12, steps=150, n=3, far=1e3)


@pytest.mark.slow
@pytest.mark.parametrize(("n", "far"), [(2, 1.0), (3, 1e6), (4, 1e2)])
def test_recursive_on_plane_points_stay_inside_long(n, far):
    _recursive_run(seed=13 + n, steps=600, n=n, far=far)


@pytest.mark.slow
@pytest.mark.parametrize(("criterion", "kw"), CRITERIA)
def test_strip_fusion_is_outer_long(criterion, kw):
    rng = np.random.default_rng(21)
    for E, S in _instances(seed=23, count=240):
        assert_strip_guarantee(E, S, analytic.intersect_strip(E, S, criterion, **kw), rng, 12)


# --------------------------------------------------------------------- batched vs single
@pytest.mark.parametrize(("criterion", "kw"), CRITERIA)
def test_batch_and_single_agree_bitwise(criterion, kw):
    pairs = [(E, S) for E, S in _instances(seed=31, count=48) if E.dim == 3]
    single = [analytic.intersect_strip(E, S, criterion, **kw) for E, S in pairs]
    out = analytic.intersect_strip_batch(
        np.array([E.center for E, _ in pairs]),
        np.array([E.shape for E, _ in pairs]),
        np.array([S.a for _, S in pairs]),
        np.array([float(S.b) for _, S in pairs]),
        criterion,
        **kw,
    )
    for k, f in enumerate(single):
        assert f.lam == out.lam[k] and f.margin == out.margin[k]
        if f.ellipsoid is None:
            assert out.empty[k]
            continue
        assert np.array_equal(f.ellipsoid.center, out.centers[k])
        assert np.array_equal(f.ellipsoid.shape, out.shapes[k])


@pytest.mark.parametrize("criterion", ["volume", "trace", "size_xy_psi"])
def test_minkowski_batch_and_single_agree_bitwise(criterion):
    rng = np.random.default_rng(32)
    E1 = [Ellipsoid(rng.standard_normal(3), rotated(rng, 3, 1e3, 1.0)) for _ in range(12)]
    E2 = [Ellipsoid(rng.standard_normal(3), rotated(rng, 3, 1e2, 0.1)) for _ in range(12)]
    out = analytic.minkowski_sum_batch(
        np.array([E.center for E in E1]),
        np.array([E.shape for E in E1]),
        np.array([E.center for E in E2]),
        np.array([E.shape for E in E2]),
        criterion,
    )
    for k, (A, B) in enumerate(zip(E1, E2, strict=True)):
        m = analytic.minkowski_sum(A, B, criterion)
        assert m.kappa == out.kappa[k]
        assert np.array_equal(m.ellipsoid.shape, out.shapes[k])
        assert np.array_equal(m.ellipsoid.center, out.centers[k])
