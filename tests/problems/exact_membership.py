"""Exact membership of float points in each family's true set, independent of ``Problem.test``.

Each check is a sufficient condition evaluated in exact rational arithmetic (``Fraction``) or
in 50-digit mpmath, on the family's definition of the true set: a point it accepts is in the
true set. Used to verify the points ``Problem.member`` says are TRUE.
"""

from fractions import Fraction

import mpmath
import numpy as np

from optbound.compare import exact
from optbound.estimation.exact_polygon import exact_polygons
from optbound.localization import sonar as sonar_model
from optbound.problems import minkowski, visibility

mpmath.mp.dps = 50


def _level(E, point: list[Fraction]) -> Fraction:
    """``(x - c)^T C^{-1} (x - c)`` of a rational point, exactly."""
    d = [xi - ci for xi, ci in zip(point, exact.fractions(E.center), strict=True)]
    y = exact.solve(exact.fractions(E.shape), d)
    return sum(di * yi for di, yi in zip(d, y, strict=True))


def in_intersection(sets, x) -> bool:
    return all(exact.member(S, x) for S in sets)


def in_minkowski_sum(E1, E2, x) -> bool:
    """A float split ``x = y + (x - y)`` with ``y ∈ E1`` and ``x - y ∈ E2``, checked exactly.

    The split candidates are those of :func:`optbound.problems.minkowski.sum_test`, one per κ.
    """
    C1, c = E1.shape, E1.center + E2.center
    r = np.asarray(x, dtype=float) - c
    Qinv = np.linalg.inv(
        C1 / (1 - minkowski.KAPPAS)[:, None, None] + E2.shape / minkowski.KAPPAS[:, None, None]
    )
    order = np.argsort(-np.einsum("i,kij,j->k", r, Qinv, r))
    xf = exact.fractions(x)
    for k in order[:8]:
        y = E1.center + C1 @ (Qinv[k] @ r) / (1 - minkowski.KAPPAS[k])
        yf = exact.fractions(y)
        if _level(E1, yf) <= 1 and _level(E2, [a - b for a, b in zip(xf, yf, strict=True)]) <= 1:
            return True
    return False


def _wrap(angle):
    return angle - 2 * mpmath.pi * mpmath.floor((angle + mpmath.pi) / (2 * mpmath.pi))


def in_bearing_set(data, x) -> bool:
    """Every relative bearing within its bound [BH, eq. (2)], in 50-digit arithmetic."""
    px, py = (mpmath.mpf(float(v)) for v in x)
    for (i, j), g, e in zip(data.pairs, data.gammas, data.eps, strict=True):
        Li, Lj = data.landmarks[i], data.landmarks[j]
        ai = mpmath.atan2(py - mpmath.mpf(Li[1]), px - mpmath.mpf(Li[0]))
        aj = mpmath.atan2(py - mpmath.mpf(Lj[1]), px - mpmath.mpf(Lj[0]))
        if abs(_wrap(ai - aj - mpmath.mpf(float(g)))) > mpmath.mpf(float(e)):
            return False
    return True


def in_pose_set(data, pose) -> bool:
    """Every bearing explained by a landmark in its ellipse and an error within delta [HS96].

    Sufficient, per bearing: the nominal landmark's bearing is within delta, or the ray of
    direction ``psi + alpha`` (error 0) meets the landmark's ellipse ahead of the robot.
    """
    px, py, psi = (mpmath.mpf(float(v)) for v in pose)
    delta = mpmath.mpf(float(data["delta_alpha"]))
    for L, C, alpha in zip(data["landmarks"], data["landmark_shapes"], data["alphas"], strict=True):
        dx, dy = mpmath.mpf(L[0]) - px, mpmath.mpf(L[1]) - py
        theta = psi + mpmath.mpf(float(alpha))
        if abs(_wrap(mpmath.atan2(dy, dx) - theta)) <= delta:
            continue
        # Ray p + t u, t > 0, in {q : (q - L)^T C^{-1} (q - L) <= 1}: a quadratic in t.
        Ci = mpmath.inverse(mpmath.matrix([[mpmath.mpf(c) for c in row] for row in C]))
        u = mpmath.matrix([mpmath.cos(theta), mpmath.sin(theta)])
        w = mpmath.matrix([-dx, -dy])  # p - L
        a = (u.T * Ci * u)[0]
        b = 2 * (u.T * Ci * w)[0]
        c = (w.T * Ci * w)[0] - 1
        disc = b * b - 4 * a * c
        if disc < 0 or (-b + mpmath.sqrt(disc)) / (2 * a) <= 0:
            return False
    return True


def _meets_convex(p, q, polygon) -> bool:
    """Does the closed segment [p, q] meet the closed convex polygon? Exact (separating axes)."""
    P = [tuple(Fraction(float(c)) for c in v) for v in polygon]
    seg = [tuple(Fraction(float(c)) for c in p), tuple(Fraction(float(c)) for c in q)]
    edges = [(P[k], P[(k + 1) % len(P)]) for k in range(len(P))] + [(seg[0], seg[1])]
    for a, b in edges:
        normal = (a[1] - b[1], b[0] - a[0])
        if normal == (0, 0):
            continue
        on_poly = [normal[0] * v[0] + normal[1] * v[1] for v in P]
        on_seg = [normal[0] * v[0] + normal[1] * v[1] for v in seg]
        if max(on_poly) < min(on_seg) or max(on_seg) < min(on_poly):
            return False
    return True


def in_visibility_set(data, x) -> bool:
    """In the robot's box, and every measurement explained by a witness point [GLH12]."""
    boxes, robot, env = data["boxes"], data["robot"], data["environment"]
    if not all(boxes[robot, k, 0] <= x[k] <= boxes[robot, k, 1] for k in range(2)):
        return False
    u = (np.arange(visibility.WITNESSES) + 0.5) / visibility.WITNESSES
    for j, seen in enumerate(data["visibility"]):
        if j == robot:
            continue
        b = boxes[j]
        gx, gy = np.meshgrid(b[0, 0] + u * (b[0, 1] - b[0, 0]), b[1, 0] + u * (b[1, 1] - b[1, 0]))
        polygons = env.inner if seen else env.outer
        for w in np.column_stack([gx.ravel(), gy.ravel()]):
            meets = any(_meets_convex(x, w, poly) for poly in polygons)
            if meets != bool(seen):
                break
        else:
            return False
    return True


def in_sonar_set(data, pose) -> bool:
    """Float64 cross-check (not exact): simulated ranges in the measurement box, pose in X0."""
    ranges = sonar_model.simulate_ranges(data["world"], data["sonars"], np.asarray(pose))
    Y = sonar_model.measurement_box(data["sonars"], data["ranges"])
    return bool(
        np.all((Y[:, 0] <= ranges) & (ranges <= Y[:, 1])) and data["prior_box"].contains(pose)
    )


def _side_signs(data, x) -> list[Fraction]:
    """Cross products of each edge of the exact polygon of ``X_k`` with the point, exactly:
    all >= 0 iff the point is in the (ccw, convex) polygon."""
    P = exact_polygons(data["system"], data["X0"], data["ys"])[-1]
    q = [Fraction(float(c)) for c in x]
    return [
        (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])
        for a, b in zip(P, P[1:] + P[:1], strict=True)
    ]


def check(p, x) -> bool:
    """Is the float point ``x`` in the true set of problem ``p``? (See the module docstring.)"""
    if p.family == "strip":
        return in_intersection((p.data["ellipsoid"], p.data["strip"]), x)
    if p.family == "recursive":
        return in_intersection((p.data["prior"], *p.data["strips"]), x)
    if p.family == "minkowski":
        return in_minkowski_sum(*p.data["summands"], x)
    if p.family == "bh_bearings":
        return in_bearing_set(p.data["measurements"], x)
    if p.family == "hs96_pose":
        return in_pose_set(p.data, x)
    if p.family == "visibility":
        return in_visibility_set(p.data, x)
    if p.family == "sonar":
        return in_sonar_set(p.data, x)
    if p.family == "linear_estimation":
        return min(_side_signs(p.data, x)) >= 0
    raise ValueError(f"no exact check for family {p.family!r}")


def _outside_minkowski_sum(E1, E2, x) -> bool:
    """A direction ``d`` (the κ family's normals) with ``d^T (x - c) > h(d)``, in 50 digits."""
    r = np.asarray(x, dtype=float) - (E1.center + E2.center)
    Qinv = np.linalg.inv(
        E1.shape / (1 - minkowski.KAPPAS)[:, None, None]
        + E2.shape / minkowski.KAPPAS[:, None, None]
    )
    for d in np.einsum("kij,j->ki", Qinv, r):
        D = mpmath.matrix([mpmath.mpf(float(v)) for v in d])
        reach = sum(
            D[i] * (mpmath.mpf(float(x[i])) - mpmath.mpf(E1.center[i]) - mpmath.mpf(E2.center[i]))
            for i in range(len(d))
        )
        h = sum(
            mpmath.sqrt(
                (D.T * mpmath.matrix([[mpmath.mpf(c) for c in row] for row in E.shape]) * D)[0]
            )
            for E in (E1, E2)
        )
        if reach > h:
            return True
    return False


def _outside_bearing_set(data, x) -> bool:
    """Some relative bearing beyond its bound, in 50-digit arithmetic."""
    return not in_bearing_set(data, x)


#: Families whose FALSE points :func:`check_outside` can verify.
OUTSIDE_FAMILIES = ("strip", "recursive", "minkowski", "bh_bearings", "linear_estimation")


def check_outside(p, x) -> bool:
    """Is the float point ``x`` outside the true set of ``p``? (Exact or 50-digit, as above.)"""
    if p.family == "strip":
        return not in_intersection((p.data["ellipsoid"], p.data["strip"]), x)
    if p.family == "recursive":
        return not in_intersection((p.data["prior"], *p.data["strips"]), x)
    if p.family == "minkowski":
        return _outside_minkowski_sum(*p.data["summands"], x)
    if p.family == "bh_bearings":
        return _outside_bearing_set(p.data["measurements"], x)
    if p.family == "linear_estimation":
        return min(_side_signs(p.data, x)) < 0
    raise ValueError(f"no exact exclusion check for family {p.family!r}")
