"""Set types defined only here plug into the SDP layer and the comparisons through the protocol.

``Ball`` and ``Diamond`` implement ``ConvexSet`` and ``QuadraticallyDescribed``
(``optbound.sets.base``) in this file; no library file names them. The SDP answers must equal
those for the same sets written with the library's own types, and contain the sets exactly.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

from optbound import Ellipsoid, QuadraticSet, Strip, compare
from optbound.optimal import outer_ellipsoid
from optbound.sets.base import (
    ConvexSet,
    EmptySetError,
    QuadraticallyDescribed,
    QuadraticDescription,
)


def _rows(values: np.ndarray, X):
    """The protocol's convention: one value for one point (n,), an array for rows (m, n)."""
    return values[0].item() if np.ndim(X) == 1 else values


class Ball(ConvexSet):
    """``{x : |x - c| <= r}``: one quadratic form, and itself as an enclosing ellipsoid."""

    def __init__(self, center, radius: float):
        self.center, self.radius = np.asarray(center, dtype=float), float(radius)

    @property
    def dim(self) -> int:
        return self.center.shape[0]

    def contains(self, X, tol: float = 1e-9):
        inside = np.linalg.norm(np.atleast_2d(X) - self.center, axis=1) <= self.radius * (1 + tol)
        return _rows(inside, X)

    def support(self, d):
        D = np.atleast_2d(d)
        return _rows(D @ self.center + self.radius * np.linalg.norm(D, axis=1), d)

    def quadratic_description(self) -> QuadraticDescription:
        # |x|^2 - 2 c^T x + |c|^2 - r^2 <= 0
        c = self.center
        form = QuadraticSet.from_parts(np.eye(self.dim), -c, c @ c - self.radius**2)
        return QuadraticDescription(forms=(form,))

    def enclosing_ellipsoid(self) -> Ellipsoid:
        return Ellipsoid(self.center, self.radius**2 * np.eye(self.dim))


class Diamond(ConvexSet):
    """``{x in R^2 : |x_1| + |x_2| <= h}``: two linear ranges, no enclosing ellipsoid."""

    def __init__(self, h: float):
        self.h = float(h)

    @property
    def dim(self) -> int:
        return 2

    def contains(self, X, tol: float = 1e-9):
        return _rows(np.abs(np.atleast_2d(X)).sum(axis=1) <= self.h * (1 + tol), X)

    def support(self, d):
        return _rows(self.h * np.abs(np.atleast_2d(d)).max(axis=1), d)

    def quadratic_description(self) -> QuadraticDescription:
        rows = np.array([[1.0, 1.0], [1.0, -1.0]])
        return QuadraticDescription(ranges=tuple((a, -self.h, self.h) for a in rows))

    def enclosing_ellipsoid(self) -> None:
        return None

    def vertices(self) -> np.ndarray:
        return self.h * np.array([[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]])


class EmptyBall(Ball):
    """A ball that reports itself empty when asked for an enclosing ellipsoid."""

    def enclosing_ellipsoid(self) -> Ellipsoid:
        raise EmptySetError("this ball is empty")


def _exact_level(E: Ellipsoid, x: np.ndarray) -> Fraction:
    """``(x - c)^T C^{-1} (x - c)`` for a 2-D ellipsoid, in exact rational arithmetic."""
    (a, b), (_, d) = [[Fraction(float(v)) for v in row] for row in E.shape]
    u, w = (Fraction(float(xi)) - Fraction(float(ci)) for xi, ci in zip(x, E.center, strict=True))
    return (d * u * u - 2 * b * u * w + a * w * w) / (a * d - b * b)


def test_toy_types_satisfy_the_protocol():
    assert isinstance(Ball([0.0, 0.0], 1.0), QuadraticallyDescribed)
    assert isinstance(Diamond(1.0), QuadraticallyDescribed)
    assert Diamond(2.0).extent([1.0, 0.0]) == (-2.0, 2.0)  # free from support


@pytest.mark.parametrize("objective", ["volume", "trace"])
def test_ball_gives_the_same_bound_as_the_ellipsoid(objective):
    ball = Ball([0.3, -0.2], 1.5)
    strip = Strip.from_bounds([1.0, 0.5], -0.4, 0.9)
    toy = outer_ellipsoid([ball, strip], objective=objective)
    own = outer_ellipsoid([ball.enclosing_ellipsoid(), strip], objective=objective)
    assert toy.objective == pytest.approx(own.objective, rel=1e-9)
    # The objective is flat at its optimum: the shapes agree to about the root of the gap.
    np.testing.assert_allclose(toy.ellipsoid.shape, own.ellipsoid.shape, rtol=1e-5)
    # The comparisons read the bound through the result base.
    assert compare.volume_ratio(toy, own) == pytest.approx(1.0, rel=1e-9)
    assert compare.contains(toy, own, tol=1e-5) and compare.contains(own, toy, tol=1e-5)


def test_diamond_is_bounded_and_contained_exactly():
    diamond = Diamond(1.0)
    r = outer_ellipsoid([Ellipsoid([0.0, 0.0], 4.0 * np.eye(2)), diamond])
    assert r.certified
    # The circumcircle of the square |x1| + |x2| <= 1 is the optimum (area pi).
    assert r.objective == pytest.approx(np.pi, rel=1e-6)
    for x in diamond.vertices():
        assert _exact_level(r.ellipsoid, x) <= 1
    rows = [Strip.from_bounds(a, lo, hi) for a, lo, hi in diamond.quadratic_description().ranges]
    same = outer_ellipsoid([Ellipsoid([0.0, 0.0], 4.0 * np.eye(2)), *rows])
    assert r.objective == pytest.approx(same.objective, rel=1e-9)


def test_a_type_without_a_description_is_refused_by_name():
    class Bare(ConvexSet):
        dim = 2

        def contains(self, X, tol=1e-9):
            return np.ones(len(np.atleast_2d(X)), dtype=bool)

        def support(self, d):
            return np.full(len(np.atleast_2d(d)), np.inf)

    with pytest.raises(ValueError, match=r"quadratic description.*got Bare"):
        outer_ellipsoid([Ellipsoid([0.0, 0.0], np.eye(2)), Bare()])


def test_an_empty_member_makes_the_intersection_empty():
    from optbound.optimal import EmptyIntersectionError

    with pytest.raises(EmptyIntersectionError, match="this ball is empty"):
        outer_ellipsoid([EmptyBall([0.0, 0.0], 1.0), Strip([1.0, 0.0], 0.0)])
