"""Tests of ellipsoid ∩ strip fusion [HS96, eqs. (24)-(30)]."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy.optimize import minimize_scalar

from optbound import Ellipsoid, Strip, analytic
from optbound.analytic.strip_fusion import MIN_REL_WIDTH
from tests.analytic import exact
from tests.analytic.instances import (
    ellipsoid_and_strip,
    random_ellipsoid,
    sample_intersection,
    strip_relative_to,
)

CONTAIN_TOL = 1e-9

CRITERIA = [
    ("volume", {}),
    ("trace", {}),
    ("projection", {"dims": (0, 1)}),
    ("robust", {}),
    ("robust", {"dims": (1,)}),
    ("volume", {"lam": 0.37}),
    ("volume", {"clip": False}),
]


def _fuse(E, S, criterion, **kw):
    return analytic.intersect_strip(E, S, criterion, **kw)


@pytest.mark.parametrize(("criterion", "kw"), CRITERIA)
@given(inst=ellipsoid_and_strip(), seed=st.integers(0, 1000))
def test_result_contains_the_intersection(criterion, kw, inst, seed):
    E, S = inst
    rng = np.random.default_rng(seed)
    fused = _fuse(E, S, criterion, **kw)
    pts = sample_intersection(E, S, rng=rng)
    if fused.ellipsoid is None:
        assert fused.case == "inconsistent" and fused.consistency == 0.0
        assert pts.shape[0] == 0  # nothing of E lies in S
        return
    assert pts.shape[0] >= 10_000 and np.all(S.contains(pts)) and np.all(E.contains(pts))
    assert np.all(np.isfinite(fused.ellipsoid.shape))
    assert 0.0 <= fused.consistency <= 1.0 and fused.lam >= 0.0
    assert np.all(fused.ellipsoid.contains(pts, tol=CONTAIN_TOL))


# --------------------------------------------------------------- closed form vs brute force
def _family_sizes(E, S, lams, size):
    """Size of the members of the family [HS96, eq. (24)] for an array of lambdas."""
    out = analytic.intersect_strip_batch(
        np.broadcast_to(E.center, (len(lams), E.dim)),
        np.broadcast_to(E.shape, (len(lams), E.dim, E.dim)),
        S.a,
        S.b,
        lam=lams,
    )
    return size(out.shapes)


def _numeric_min(E, S, size):
    """Brute-force minimum over lambda = t / (1 - t): dense grid, then bounded refinement."""
    t = np.linspace(0.0, 0.999, 2000)
    values = _family_sizes(E, S, t / (1 - t), size)
    k = int(np.argmin(values))
    res = minimize_scalar(
        lambda x: _family_sizes(E, S, np.array([x / (1 - x)]), size)[0],
        bounds=(t[max(k - 1, 0)], t[min(k + 1, len(t) - 1)]),
        method="bounded",
        options={"xatol": 1e-12},
    )
    return min(res.fun, values[k])


def _logdet(shapes):
    return np.linalg.slogdet(shapes)[1]


def _logdet_xy(shapes):
    return np.linalg.slogdet(shapes[:, :2, :2])[1]


def _log_width_x(shapes):
    return np.log(shapes[:, 0, 0])


def _log_width_y(shapes):
    return np.log(shapes[:, 1, 1])


def _trace(shapes):
    return np.log(np.trace(shapes, axis1=1, axis2=2))


@pytest.mark.parametrize(
    ("criterion", "kw", "size"),
    [
        ("volume", {}, _logdet),
        ("projection", {"dims": (0, 1)}, _logdet_xy),
        ("projection", {"dims": (0,)}, _log_width_x),
        ("projection", {"dims": (1,)}, _log_width_y),
        ("projection", {"dims": (1, 0)}, _logdet_xy),
        ("trace", {}, _trace),
    ],
)
@given(inst=ellipsoid_and_strip(min_dim=2, max_dim=5))
def test_closed_form_root_matches_numeric_minimum(criterion, kw, size, inst):
    """Eqs. (26), (27) and the trace cubic (solved in the compiled kernel) give the numeric
    minimum of their size measure over the family."""
    E, S = inst
    fused = _fuse(E, S, criterion, **kw)
    if fused.case in ("inconsistent", "no_reduction"):
        return
    closed = size(fused.ellipsoid.shape[None])[0]
    numeric = _numeric_min(E, S, size)
    # log sizes: an absolute difference is a relative difference of the size itself.
    assert closed <= numeric + 1e-10
    assert closed >= numeric - 1e-8


# ----------------------------------------------------------------------- known anchors
@pytest.mark.parametrize("n", [2, 3, 4, 6])
def test_unit_ball_symmetric_strip_anchor(n):
    """unit ball ∩ {|x1| <= t}: lambda* = (1 - n t^2)/(n - 1), axes n t^2, n(1 - t^2)/(n - 1)."""
    t = 0.3
    E = Ellipsoid(np.zeros(n), np.eye(n))
    fused = analytic.intersect_strip(E, Strip(np.eye(n)[0] / t, 0.0))
    assert fused.case == "consistent"
    assert fused.lam == pytest.approx((1 - n * t * t) / (n - 1), rel=1e-13)
    expected = np.diag([n * t * t] + [n * (1 - t * t) / (n - 1)] * (n - 1))
    np.testing.assert_allclose(fused.ellipsoid.shape, expected, rtol=1e-13, atol=1e-15)


def test_anchor_n2_t05_and_n3_t07():
    fused = analytic.intersect_strip(Ellipsoid([0, 0], np.eye(2)), Strip([2.0, 0.0], 0.0))
    np.testing.assert_allclose(fused.ellipsoid.shape, np.diag([0.5, 1.5]), rtol=1e-14)
    assert fused.consistency == pytest.approx(1 / np.sqrt(2), rel=1e-14)  # W_E=1, W_P=2, W_M=1
    E3 = Ellipsoid(np.zeros(3), np.eye(3))
    fused = analytic.intersect_strip(E3, Strip([1 / 0.7, 0, 0], 0.0))
    assert fused.case == "consistent" and fused.lam == 0.0
    np.testing.assert_array_equal(fused.ellipsoid.shape, np.eye(3))


@given(inst=ellipsoid_and_strip())
def test_positive_root_iff_known_condition(inst):
    """Eq. (26) has a positive root iff G > n (1 - eps^2) (on the fused, clipped strip)."""
    E, S = inst
    fused = analytic.intersect_strip(E, S, clip=False)
    if fused.case in ("inconsistent", "no_reduction"):
        return
    G = S.a @ E.shape @ S.a
    eps = S.b - S.a @ E.center
    if abs(G - E.dim * (1 - eps**2)) > 1e-9 * G:
        assert (fused.lam > 0) == (G > E.dim * (1 - eps**2))


# ---------------------------------------------------------------------------- four cases
@pytest.mark.parametrize(
    ("lo", "hi", "case"),
    [
        (-2.0, 2.0, "no_reduction"),
        (-0.5, 0.5, "consistent"),
        (0.3, 2.3, "partial"),
        (1.5, 2.5, "inconsistent"),
    ],
)
def test_each_case_is_reached(lo, hi, case):
    E = Ellipsoid(np.zeros(3), np.eye(3))
    fused = analytic.intersect_strip(E, Strip.from_bounds([1, 0, 0], lo, hi))
    assert fused.case == case
    if case == "no_reduction":
        assert fused.ellipsoid is E and fused.lam == 0.0
    if case == "inconsistent":
        assert fused.ellipsoid is None and fused.consistency == 0.0 and fused.lam == 0.0


def test_clipping_gain_in_the_partial_case():
    """unit ball ∩ {0.3 <= x1 <= 2.3} in 3-D: clipping saves ~27 % of the volume (Known facts)."""
    E = Ellipsoid(np.zeros(3), np.eye(3))
    S = Strip.from_bounds([1, 0, 0], 0.3, 2.3)
    clipped = analytic.intersect_strip(E, S)
    raw = analytic.intersect_strip(E, S, clip=False)
    assert clipped.case == raw.case == "partial"
    gain = 1 - clipped.ellipsoid.volume() / raw.ellipsoid.volume()
    assert gain == pytest.approx(0.27, abs=0.005)


@pytest.mark.parametrize("side", [-1.0, 1.0])
@pytest.mark.parametrize("offset", [0.0, 1e-14, -1e-14])
def test_touching_plane_gives_thin_outer_ellipsoid(side, offset):
    """A plane touching E (up to rounding): a thin ellipsoid containing the touching point;
    a plane 1e-14 outside: disjointness, proven."""
    rng = np.random.default_rng(3)
    E = random_ellipsoid(rng, 3)
    a = rng.standard_normal(3)
    lo_e, hi_e = E.extent(a)
    edge = hi_e if side > 0 else lo_e
    extent = hi_e - lo_e
    lo, hi = (edge + offset, edge + extent) if side > 0 else (edge - extent, edge + offset)
    S = Strip.from_bounds(a, lo, hi)
    fused = analytic.intersect_strip(E, S)
    if side * offset > 0:
        # 1e-14 outside E: disjoint, which is proven (the gap is far above rounding), and it
        # is so in exact arithmetic (E's exact extent along a misses the strip).
        assert fused.case == "inconsistent" and fused.ellipsoid is None
        assert exact.disjoint(E.center, E.shape, S.a, S.b)
        return
    assert fused.case == "partial" and fused.ellipsoid is not None
    touching = E.center + side * E.shape @ a / np.sqrt(a @ E.shape @ a)
    assert fused.ellipsoid.contains(touching, tol=1e-6)
    width = 2 * np.sqrt(a @ fused.ellipsoid.shape @ a)
    assert width <= 2 * MIN_REL_WIDTH * extent


def test_clearly_disjoint_is_inconsistent_without_nan():
    E = Ellipsoid(np.zeros(2), np.eye(2))
    fused = analytic.intersect_strip(E, Strip.from_bounds([1, 0], 1 + 1e-9, 3.0))
    assert fused.case == "inconsistent" and fused.ellipsoid is None


# ------------------------------------------------------------------- robust criterion
@pytest.mark.parametrize(
    ("optimal", "kw"),
    [("volume", {}), ("projection", {"dims": (0,)}), ("projection", {"dims": (1,)})],
)
def test_robust_lambda_is_logistic_in_the_consistency(optimal, kw):
    """[HS96, eq. (30)] on the volume-optimal lambda, or the projection-optimal one with dims."""
    E = Ellipsoid(np.zeros(2), np.diag([1.0, 0.5]))
    S = Strip([2.0, 2.0], 0.0)  # every optimal lambda is positive here
    opt = analytic.intersect_strip(E, S, optimal, **kw).lam
    assert opt > 0.0
    cm = analytic.intersect_strip(E, S).consistency
    robust = analytic.intersect_strip(E, S, "robust", midpoint=cm, **kw)
    assert robust.lam == pytest.approx(opt / 2, rel=1e-14)
    steep = analytic.intersect_strip(E, S, "robust", steepness=1e3, **kw)
    assert steep.lam == pytest.approx(opt, rel=1e-12)
    shy = analytic.intersect_strip(E, S, "robust", steepness=10.0, midpoint=cm + 0.1, **kw)
    assert shy.lam == pytest.approx(opt / (1 + np.exp(1.0)), rel=1e-14)


# -------------------------------------------------------------------------- batching
@pytest.mark.parametrize(("criterion", "kw"), CRITERIA)
@given(inst=ellipsoid_and_strip())
def test_batch_matches_single_calls(criterion, kw, inst):
    """Every criterion: one compiled pass over the batch gives the bits of single calls."""
    E, S = inst
    rng = np.random.default_rng(0)
    others = [random_ellipsoid(rng, E.dim) for _ in range(3)]
    ellipsoids = [E, *others]
    out = analytic.intersect_strip_batch(
        np.stack([e.center for e in ellipsoids]),
        np.stack([e.shape for e in ellipsoids]),
        S.a,
        S.b,
        criterion,
        **kw,
    )
    for i, e in enumerate(ellipsoids):
        single = analytic.intersect_strip(e, S, criterion, **kw)
        assert analytic.CASES[out.case[i]] == single.case
        assert out.empty[i] == (single.ellipsoid is None)
        assert out.lam[i] == single.lam and out.consistency[i] == single.consistency
        if single.ellipsoid is not None:
            np.testing.assert_array_equal(out.shapes[i], single.ellipsoid.shape)
            np.testing.assert_array_equal(out.centers[i], single.ellipsoid.center)
        else:
            assert not out.shapes[i].any() and not out.centers[i].any()


# ------------------------------------------------------------------------- bad inputs
E2 = Ellipsoid([0.0, 0.0], np.eye(2))
S2 = Strip([1.0, 0.0], 0.0)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"S": Strip([1.0, 0.0, 0.0], 0.0)}, "same dimension"),
        ({"criterion": "area"}, "criterion"),
        ({"criterion": "projection"}, "dims is required"),
        ({"criterion": "projection", "dims": (0, 2)}, "dims"),
        ({"lam": -0.1}, "lam must be >= 0"),
        ({"lam": float("nan")}, "lam must be finite"),
        ({"steepness": float("inf"), "criterion": "robust"}, "steepness"),
    ],
)
def test_bad_inputs_raise(kwargs, match):
    args = {"E": E2, "S": S2, **kwargs}
    with pytest.raises(ValueError, match=match):
        analytic.intersect_strip(**args)


@pytest.mark.parametrize(
    ("centers", "shapes", "a", "b", "match"),
    [
        ([[np.nan, 0.0]], [np.eye(2)], [1.0, 0.0], 0.0, "centers must be finite"),
        ([[0.0, 0.0]], [np.diag([1.0, -1.0])], [1.0, 0.0], 0.0, "positive definite"),
        # Singular at rounding level: refused like a single Ellipsoid would refuse it.
        ([[0.0, 0.0]], [[[2.0, 4.0], [4.0, 8.0]]], [1.0, 0.0], 0.0, "ill-conditioned|singular"),
        ([[0.0, 0.0]], [np.eye(3)], [1.0, 0.0], 0.0, "shapes must have shape"),
        ([[0.0, 0.0]], [np.eye(2)], [0.0, 0.0], 0.0, "non-zero"),
        # a and b are checked by the kernel, per instance, with the instance's index.
        (
            [[0.0, 0.0]] * 3,
            [np.eye(2)] * 3,
            [[1.0, 0.0], [1.0, np.nan], [1.0, 0.0]],
            0.0,
            r"a must be finite.*\(instance 1\)",
        ),
        (
            [[0.0, 0.0]] * 2,
            [np.eye(2)] * 2,
            [1.0, 0.0],
            [0.0, np.inf],
            r"b must be finite.*\(instance 1\)",
        ),
        ([[0.0, 0.0]], [np.eye(2)], [1.0, 0.0], [0.0, 1.0], "b must have shape"),
        ([[0.0]], [np.eye(1)], [1.0], 0.0, "dimension >= 2"),
    ],
)
def test_batch_bad_inputs_raise(centers, shapes, a, b, match):
    with pytest.raises(ValueError, match=match):
        analytic.intersect_strip_batch(centers, shapes, a, b)


def test_projection_decouples_for_block_diagonal_shapes():
    """Block-diagonal C and a normal in the xy-plane: H = G in [HS96, eq. (28)], the cubic
    (27) degenerates to eq. (26) in L = 2 dimensions, i.e. the 2-D volume-optimal fusion."""
    rng = np.random.default_rng(11)
    A = rng.standard_normal((2, 2))
    Cxy = A @ A.T + 0.5 * np.eye(2)
    C = np.zeros((3, 3))
    C[:2, :2], C[2, 2] = Cxy, 0.01
    E = Ellipsoid([0.1, -0.2, 0.3], C)
    a = np.array([1.3, -0.4])
    S = Strip(np.append(a, 0.0), 0.2)
    proj = analytic.intersect_strip(E, S, "projection", dims=(0, 1))
    flat = analytic.intersect_strip(E.project([0, 1]), Strip(a, 0.2))
    assert proj.lam == pytest.approx(flat.lam, rel=1e-12)
    np.testing.assert_allclose(
        proj.ellipsoid.project([0, 1]).shape, flat.ellipsoid.shape, rtol=1e-12
    )


@pytest.mark.parametrize("width", [1e-3, 1e-5, 1e-7, 1e-9])
@pytest.mark.parametrize("position", [0.0, 0.999, 1.0, 1.0 + 1e-13])
def test_thin_strips_and_tiny_caps_stay_contained(width, position):
    """Extreme thinness (strip or cap down to 1e-9 of E's extent, condition numbers ~1e3).

    The fused strip is floored at MIN_REL_WIDTH of E's extent, so shapes stay well enough
    conditioned; the level of a point in a thin ellipsoid is still evaluated with an error of
    order eps * sqrt(cond), hence the looser tolerance here.
    """
    rng = np.random.default_rng(int(width**-0.25) + int(position * 1000))
    for n in range(2, 7):
        E = random_ellipsoid(rng, n, log_spread=3.0)
        S = strip_relative_to(E, rng.standard_normal(n), position, width)
        pts = sample_intersection(E, S, 4000, rng)
        for criterion, kw in CRITERIA[:5]:
            fused = analytic.intersect_strip(E, S, criterion, **kw)
            assert fused.ellipsoid is not None
            assert np.all(fused.ellipsoid.contains(pts, tol=1e-8))


def test_margin_sits_at_the_float_storage_floor():
    """The certified margin is ~U cond(result): storing the result's floats alone costs that
    much in its thin direction (closing note of issue 8); at input cond 1e4 the median is
    below 1e-12 (the issue's target)."""
    rng = np.random.default_rng(5)
    count = 400
    q, _ = np.linalg.qr(rng.standard_normal((count, 3, 3)))
    shapes = (q * np.logspace(0.0, -4.0, 3)) @ q.transpose(0, 2, 1)
    shapes = 0.5 * (shapes + shapes.transpose(0, 2, 1))
    centers = rng.standard_normal((count, 3))
    a = rng.standard_normal((count, 3))
    half = np.sqrt(np.einsum("bi,bij,bj->b", a, shapes, a))
    b = np.einsum("bi,bi->b", a, centers) + rng.uniform(-0.5, 0.5, count) * half
    out = analytic.intersect_strip_batch(centers, shapes, 2.0 * a / half[:, None], 2.0 * b / half)
    k = out.lam > 0
    eig = np.linalg.eigvalsh(out.shapes[k])
    floor = 2.0**-53 * eig[:, -1] / eig[:, 0]
    assert np.median(out.margin[k]) <= 1e-12
    assert np.median(out.margin[k] / floor) <= 2.0
