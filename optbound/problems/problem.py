"""``Problem``: one public set-membership instance, its exact set and its reference bounds.

A problem is described once, by the three-valued interval test of its true set (``test``,
built from the ``tri_test`` of its constituent sets). Both :meth:`Problem.member` (points)
and :meth:`Problem.exact` (a SIVIA paving [LJMW97, Sect. 3.2]) evaluate that one test, so the
membership of a point and the paving can never disagree.

References
----------
[LJMW97] O. Lévêque, L. Jaulin, D. Meizel, E. Walter, "Vehicle localization from
inaccurate telemetric data: a set inversion approach", IFAC SYROCO, 1997.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from optbound._core import validate as v
from optbound.compare.size import paving_volume_bracket
from optbound.compare.tri import point_test
from optbound.interval import Paving, pave
from optbound.sets import Box


@dataclass(frozen=True, eq=False)
class Problem:
    """A set-membership problem: what an estimator sees, and the exact set it must bound.

    Parameters
    ----------
    family, name : str
        Family (e.g. ``"strip"``) and instance name, unique within the family and suite.
    seed : int
        Instance seed: ``np.random.default_rng(seed)`` rebuilds the data.
    dim : int
        Dimension of the state.
    data : mapping
        What an estimator gets (numpy arrays and optbound sets; per family, documented there).
    truth : np.ndarray or None
        The simulated true state where there is one.
    test : callable
        ``test(*coords) -> Tri array`` on ``Interval`` coordinates: the true set's interval
        test, the one description of the true set.
    domain : Box
        A box proven to contain the true set (where it is paved).
    eps : float
        Default paving resolution of :meth:`exact`.
    intersection : tuple
        Optbound sets whose intersection is the true set: the SDP reference's input, and
        the closed-form soundness proofs' (``compare.prove_contains``).
    volume : callable or None
        ``volume() -> (lo, hi)``: a closed-form certified bracket of the true set's volume,
        where the family has one (else the exact paving's bracket is used).
    optimal : callable or None
        ``optimal(problem) -> Ellipsoid``: the family's certified optimal outer ellipsoid,
        where it is not the S-procedure SDP of :attr:`intersection` (e.g. the SDP of a
        Minkowski sum, or the best of an SDP and the MVEE of the exact paving's boxes).

    Examples
    --------
    >>> from optbound import problems
    >>> p = problems.suite("tiny", families=["recursive"])[0]
    >>> (p.family, p.dim, sorted(p.data))
    ('recursive', 2, ['prior', 'strips'])
    >>> from optbound.interval import Tri
    >>> bool(p.member(p.truth)[0] == Tri.TRUE)
    True
    >>> lo, hi = p.volume_bracket()
    >>> bool(0 < lo <= hi)
    True
    """

    family: str
    name: str
    seed: int
    dim: int
    data: Mapping[str, Any]
    truth: np.ndarray | None
    test: Callable[..., np.ndarray] = field(repr=False)
    domain: Box = field(repr=False)
    eps: float = field(repr=False)
    intersection: tuple = field(default=(), repr=False)
    volume: Callable[[], tuple[float, float]] | None = field(default=None, repr=False)
    optimal: Callable[[Problem], Any] | None = field(default=None, repr=False)
    _cache: dict = field(default_factory=dict, repr=False, init=False)

    def member(self, X) -> np.ndarray:
        """Decide the membership of the float points ``X`` in the true set, as Tri values.

        TRUE only if the point is proven in the set, FALSE only if proven outside (outward-
        rounded interval arithmetic on degenerate boxes); a point on the boundary may be
        UNKNOWN.

        Parameters
        ----------
        X : array_like, shape (m, n) or (n,)
            Float points, ``n`` = :attr:`dim`; a single point (n,) gives a length-1 array.

        Returns
        -------
        np.ndarray of Tri, shape (m,)
            The three-valued membership of each point.

        Raises
        ------
        ValueError
            If ``X`` is not real and finite or its shape is neither (m, :attr:`dim`) nor
            (:attr:`dim`,).
        """
        pts, _ = v.points("X", X, self.dim)
        return point_test(self.test, pts)

    def exact(self, eps: float | None = None) -> Paving:
        """Pave the true set in :attr:`domain`: ``inner ⊂ true set ⊂ inner ∪ boundary``.

        The SIVIA paving [LJMW97, Sect. 3.2] of :attr:`test`; cached per ``eps``.

        Parameters
        ----------
        eps : float, optional
            The box width where bisection stops; :attr:`eps` if None.

        Returns
        -------
        Paving
            The inner and boundary boxes of the true set.

        Raises
        ------
        ValueError
            If ``eps`` is not a real, finite, positive number.

        References
        ----------
        [LJMW97] O. Lévêque, L. Jaulin, D. Meizel, E. Walter, "Vehicle localization from
        inaccurate telemetric data: a set inversion approach", IFAC SYROCO, 1997.
        """
        eps = self.eps if eps is None else v.finite_scalar("eps", eps)
        if eps <= 0:
            raise ValueError(f"eps must be positive, got {eps}")
        key = ("exact", eps)
        if key not in self._cache:
            self._cache[key] = pave(self.test, self.domain, eps)
        return self._cache[key]

    def volume_bracket(self) -> tuple[float, float]:
        """Bracket the true set's volume, certified.

        Returns
        -------
        tuple of float
            ``(lo, hi)`` with ``lo <= volume <= hi``: the family's closed form
            (:attr:`volume`), else the exact paving's inner and outer volumes (rounded
            outward).
        """
        if self.volume is not None:
            return self.volume()
        return paving_volume_bracket(self.exact())

    def references(self) -> dict[str, Any]:
        """Compute the reference bounds of the true set, all certified to contain it.

        Cached: the second call costs nothing.

        Returns
        -------
        dict of str to set
            A copy of the cached references.

            - ``"optimal_ellipsoid"``: the family's :attr:`optimal` reference where it has
              one, else the S-procedure SDP optimum of :attr:`intersection`
              (``optimal.outer_ellipsoid``, certified and inflated if needed), else (no
              intersection) the certified MVEE of the exact paving's box corners
              (``optimal.mvee``, which contains every box);
            - ``"best_box"``: the hull of the exact paving's inner and boundary boxes
              (floats, hence exact), the smallest box the paving can prove.
        """
        if "references" not in self._cache:
            self._cache["references"] = {
                "optimal_ellipsoid": self._optimal_ellipsoid(),
                "best_box": self.exact().hull(),
            }
        return dict(self._cache["references"])

    def _optimal_ellipsoid(self):
        if self.optimal is not None:
            return self.optimal(self)
        from optbound import optimal  # cvxpy only when a reference is asked for

        if self.intersection:
            return optimal.outer_ellipsoid(list(self.intersection)).ellipsoid
        return optimal.mvee(paving_corners(self.exact())).ellipsoid


def paving_corners(paving: Paving) -> np.ndarray:
    """Find the convex-hull vertices of the corners of a paving's inner and boundary boxes.

    An ellipsoid containing them contains every box, hence the paved set: the input of the
    MVEE reference (the hull's vertices alone give the same MVEE, far fewer points).

    Parameters
    ----------
    paving : Paving
        A paving with at least ``n + 1`` affinely independent box corners.

    Returns
    -------
    np.ndarray, shape (k, n)
        The hull's vertices.
    """
    from scipy.spatial import ConvexHull

    outer = paving.outer()
    n = outer.shape[1]
    picks = np.array(list(itertools.product((0, 1), repeat=n)))
    corners = np.unique(np.concatenate([outer[:, np.arange(n), pick] for pick in picks]), axis=0)
    return corners[ConvexHull(corners).vertices]
