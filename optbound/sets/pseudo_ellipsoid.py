"""Pseudo-ellipsoids: ellipsoids in a lifted space, read back in the original one [BH, eq. (10)].

``P = {x in R^n : (T(x) - c)^T C^{-1} (T(x) - c) <= 1}`` for a polynomial lifting
``T : R^n -> R^L`` (:class:`~optbound.sets.lifting.PolynomialLifting`). ``P.lifted`` is the
ellipsoid ``{x* : (x* - c)^T C^{-1} (x* - c) <= 1}`` in R^L; P is its trace on the "universal
manifold" ``T(R^n)`` [BH, Sect. III-B]. P need not be convex, nor connected.

Membership on boxes is proven, not sampled (:meth:`PseudoEllipsoid.tri_contains`):

- the quadratic form is evaluated as ``|W y|^2`` with ``y = T(x) - c`` and ``W`` a float
  approximation of the inverse Cholesky factor of C; with ``A = W C W^T`` computed in interval
  arithmetic and ``delta >= ||A - I||_2`` (Frobenius bound), the exact form satisfies
  ``|W y|^2 / (1 + delta) <= y^T C^{-1} y <= |W y|^2 / (1 - delta)``, because
  ``y^T C^{-1} y = (W y)^T A^{-1} (W y)``. No float inverse is trusted.
- ``W y`` over a box is enclosed by the mean-value form ``W y(m) + (W J(box)) (box - m)``
  (m the box's midpoint, J the lifting's interval Jacobian), intersected with the natural
  extension ``W y(box)``; the mean-value form keeps the cancellations inside ``W J`` that the
  natural extension loses, so its overestimate shrinks like the box width squared.

References
----------
[BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
bearing measurements", IEEE Transactions on Robotics and Automation, 2004.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from optbound._core import Box, as_box, box_array
from optbound._core import validate as v
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.lifting import PolynomialLifting

# Relative outward margin of the bounding box read off the lifted shape (covers the rounding
# of sqrt, of the product by scale and of the sum with offset, each a few ulps).
_BOX_MARGIN = 1e-12
# Bisection rounds prove_covers spends on boxes not proven at once.
COVER_ROUNDS = 10


class PseudoEllipsoid:
    """The set ``{x : (T(x) - c)^T C^{-1} (T(x) - c) <= 1}`` [BH, eqs. (9)-(10)].

    Parameters
    ----------
    lift : PolynomialLifting
        The lifting T : R^n -> R^L.
    center : array_like, shape (L,)
        Centre c of the lifted ellipsoid.
    shape : array_like, shape (L, L)
        Symmetric positive-definite shape matrix C of the lifted ellipsoid.

    Raises
    ------
    TypeError
        If ``lift`` is not a PolynomialLifting.
    ValueError
        Non-finite values, mismatched dimensions, or ``shape`` not SPD.

    Examples
    --------
    A set with a hole: the points ``(+-1, +-1)`` lie in it, their midpoint ``(0, 0)`` does not.

    >>> import numpy as np
    >>> from optbound.interval.tribool import Tri
    >>> from optbound.sets import PseudoEllipsoid
    >>> from optbound.sets.lifting import PolynomialLifting
    >>> P = PseudoEllipsoid(
    ...     PolynomialLifting.bh4(), [0.0, 0.0, 1.0, 1.0], np.diag([4.0, 4.0, 1.0, 1.0])
    ... )
    >>> P.contains([[1.0, 1.0], [-1.0, 1.0], [0.0, 0.0]]).tolist()
    [True, True, False]
    >>> boxes = [[[0.9, 1.0], [0.9, 1.0]], [[-0.1, 0.1], [-0.1, 0.1]], [[0.0, 2.0], [0.0, 2.0]]]
    >>> [Tri(t).name for t in P.tri_contains(boxes)]  # proven inside, proven outside, undecided
    ['TRUE', 'FALSE', 'UNKNOWN']
    """

    def __init__(self, lift: PolynomialLifting, center, shape):
        if not isinstance(lift, PolynomialLifting):
            raise TypeError(f"lift must be a PolynomialLifting, got {type(lift).__name__}")
        self._lift = lift
        self._lifted = Ellipsoid(v.finite_vector("center", center, lift.size), shape)

    @classmethod
    def from_ellipsoid(cls, lift: PolynomialLifting, E: Ellipsoid) -> PseudoEllipsoid:
        """The pseudo-ellipsoid whose lifted ellipsoid is ``E``.

        Parameters
        ----------
        lift : PolynomialLifting
            The lifting T : R^n -> R^L.
        E : Ellipsoid
            The lifted ellipsoid, of dimension L.

        Returns
        -------
        PseudoEllipsoid
            The set ``{x : T(x) in E}``.

        Raises
        ------
        TypeError
            If ``lift`` is not a PolynomialLifting or ``E`` not an Ellipsoid.
        ValueError
            If ``E`` has not dimension ``lift.size``.
        """
        if not isinstance(E, Ellipsoid):
            raise TypeError(f"E must be an Ellipsoid, got {type(E).__name__}")
        return cls(lift, E.center, E.shape)

    # ------------------------------------------------------------------------ attributes
    @property
    def lift(self) -> PolynomialLifting:
        return self._lift

    @property
    def lifted(self) -> Ellipsoid:
        """The ellipsoid in R^L [BH, eq. (10)]."""
        return self._lifted

    @property
    def center(self) -> np.ndarray:
        return self._lifted.center

    @property
    def shape(self) -> np.ndarray:
        return self._lifted.shape

    @property
    def dim(self) -> int:
        return self._lift.dim

    def __repr__(self) -> str:
        return f"PseudoEllipsoid({self._lift!r}, center={self.center.tolist()})"

    # ------------------------------------------------------------------------ membership
    def level(self, X) -> np.ndarray | float:
        """``(T(x) - c)^T C^{-1} (T(x) - c)`` per row of X (<= 1 means inside), in float64.

        Parameters
        ----------
        X : array_like, shape (m, n) or (n,)
            Points, one per row; a single point gives a scalar.

        Returns
        -------
        ndarray, shape (m,), or float
            The level of each point.

        Raises
        ------
        ValueError
            If ``X`` is non-finite or its dimension is not ``dim``.
        """
        pts, single = v.points("X", X, self.dim)
        q = self._lifted.level(self._lift(pts))
        return float(q[0]) if single else q

    def contains(self, X) -> np.ndarray | bool:
        """``level(X) <= 1`` in float64 (use :meth:`tri_contains` for a proof).

        Parameters
        ----------
        X : array_like, shape (m, n) or (n,)
            Points, one per row; a single point gives a scalar.

        Returns
        -------
        ndarray of bool, shape (m,), or bool
            True where the point is inside.

        Raises
        ------
        ValueError
            If ``X`` is non-finite or its dimension is not ``dim``.
        """
        q = np.asarray(self.level(X))
        return bool(q <= 1.0) if q.ndim == 0 else q <= 1.0

    @cached_property
    def _whitening(self) -> tuple[np.ndarray, float]:
        """``W ~ L^{-1}`` and a rigorous ``delta >= ||W C W^T - I||_2`` (see module docstring)."""
        from optbound.interval import Interval

        W = self._lifted.chol_inv
        C = Interval(self.shape)
        size = W.shape[0]
        A = [[None] * size for _ in range(size)]
        WC = [
            [_dot(W[i], [C[k, j] for k in range(size)]) for j in range(size)] for i in range(size)
        ]
        frob = 0.0 * C[0, 0]
        for i in range(size):
            for j in range(size):
                A[i][j] = _dot(W[j], [WC[i][k] for k in range(size)]) - (1.0 if i == j else 0.0)
                frob = frob + A[i][j] ** 2
        delta = float(np.sqrt(frob).hi)
        return W, delta

    def tri_contains(self, boxes) -> np.ndarray:
        """Three-valued membership of whole boxes: TRUE (box ⊂ P), FALSE (box ∩ P = ∅), UNKNOWN.

        Parameters
        ----------
        boxes : array_like, shape (m, n, 2)
            ``[lo, hi]`` rows per box.

        Returns
        -------
        np.ndarray of int8
            :class:`~optbound.interval.Tri` values, proven in outward-rounded interval
            arithmetic (module docstring).

        Raises
        ------
        ValueError
            If ``boxes`` is mis-shaped, non-finite or has ``lo > hi``.
        """
        from optbound.interval import Interval

        B = box_array("boxes", boxes, self.dim)
        return self.tri_test(*(Interval(B[:, j, 0], B[:, j, 1]) for j in range(self.dim)))

    def tri_test(self, *coords) -> np.ndarray:
        """The test ``x ∈ P`` on ``Interval`` coordinates (for ``interval.pave``).

        Parameters
        ----------
        *coords : Interval
            One interval array per coordinate, all of one shape.

        Returns
        -------
        np.ndarray of int8
            ``Tri`` value per box (UNKNOWN everywhere if C is too ill-conditioned for the whitening
            bound).
        """
        from optbound.interval import Interval, intersection
        from optbound.interval.tribool import from_masks

        W, delta = self._whitening
        n, size = self.dim, self._lift.size
        mid = [np.asarray(x.midpoint()) for x in coords]
        y_box = [t - c for t, c in zip(self._lift.components(*coords), self.center, strict=True)]
        y_mid = [
            t - c
            for t, c in zip(
                self._lift.components(*(Interval(m) for m in mid)), self.center, strict=True
            )
        ]
        jac = self._lift.jacobian(*coords)
        steps = [x - m for x, m in zip(coords, mid, strict=True)]
        q = None
        for i in range(size):
            natural = _dot(W[i], y_box)
            mean_value = _dot(W[i], y_mid)
            for j in range(n):
                slope = _dot(W[i], [jac[row][j] for row in range(size)])
                mean_value = mean_value + slope * steps[j]
            u_i = intersection(natural, mean_value)
            q = u_i**2 if q is None else q + u_i**2
        if not delta < 1.0:  # W is too far from C^{-1/2} to prove anything
            return np.full(q.shape, 1, dtype=np.int8)
        inside = q.hi <= np.nextafter(1.0 - delta, 0.0)
        outside = q.lo > np.nextafter(1.0 + delta, 2.0)
        if q._partial is not None:
            inside &= ~q.partial
        return from_masks(inside, outside & ~inside)

    def prove_covers(self, boxes, set_test=None, rounds: int = COVER_ROUNDS) -> CoverProof:
        """Prove that P contains a set X known to lie in the union of ``boxes``.

        Every box is tested with :meth:`tri_contains`. Boxes not proven inside are bisected
        for up to ``rounds`` rounds; a sub-box is dropped when ``set_test`` (the three-valued
        test of X on ``Interval`` coordinates, e.g. SIVIA's) proves it disjoint from X. With
        ``set_test=None`` nothing is dropped: every box must be proven inside P.

        Parameters
        ----------
        boxes : array_like, shape (m, n, 2)
            Boxes whose union contains X.
        set_test : callable, optional
            Three-valued test of X on ``Interval`` coordinates.
        rounds : int, default COVER_ROUNDS
            Bisection rounds for boxes not proven at once.

        Returns
        -------
        CoverProof
            ``proven`` True only if every remaining part was proven inside P.

        Raises
        ------
        ValueError
            If ``boxes`` is mis-shaped, non-finite or has ``lo > hi``.
        """
        from optbound.interval import Interval
        from optbound.interval.tribool import Tri

        B = box_array("boxes", boxes, self.dim)
        t = self.tri_contains(B)
        pending, refuted = B[t != Tri.TRUE], False
        for _ in range(rounds):
            if pending.shape[0] == 0:
                break
            inside = self.tri_contains(pending)
            if set_test is None:
                member = np.full(inside.shape, Tri.UNKNOWN, dtype=np.int8)
            else:
                coords = [Interval(pending[:, j, 0], pending[:, j, 1]) for j in range(self.dim)]
                member = np.asarray(set_test(*coords))
            refuted |= bool(np.any((member == Tri.TRUE) & (inside == Tri.FALSE)))
            pending = _bisect(pending[(member != Tri.FALSE) & (inside != Tri.TRUE)])
        return CoverProof(
            proven=pending.shape[0] == 0 and not refuted,
            boxes=int(B.shape[0]),
            direct=int(np.sum(t == Tri.TRUE)),
            refuted=refuted,
        )

    # ------------------------------------------------------------------------- geometry
    def bounding_box(self) -> Box:
        """A guaranteed axis-aligned box containing P.

        Every point of P has ``|T_k(x) - c_k| <= sqrt(C_kk)``; for the components ``T_k = u_j``
        (the lifting must have them) this bounds ``x_j = offset_j + scale * u_j``.

        Returns
        -------
        Box
            A box containing P.

        Raises
        ------
        ValueError
            If the lifting has no component equal to a normalized coordinate.
        """
        idx = self._lift.identity_components()
        if np.any(idx < 0):
            raise ValueError(
                "bounding_box needs a lifting with every coordinate as a component; "
                "pass an explicit box to paving() instead"
            )
        half = np.sqrt(np.diag(self.shape)[idx]) * (1.0 + _BOX_MARGIN)
        s, o, c = self._lift.scale, self._lift.offset, self.center[idx]
        lo = o + s * (c - half)
        hi = o + s * (c + half)
        pad = _BOX_MARGIN * (np.abs(lo) + np.abs(hi) + s * half)
        return Box(lo - pad, hi + pad)

    def paving(self, eps: float, X0=None):
        """SIVIA paving of P with boxes at most ``eps`` wide (``X0``: default bounding_box).

        Parameters
        ----------
        eps : float
            Largest width of an undecided box, positive.
        X0 : Box or array_like, optional
            Box searched (default :meth:`bounding_box`).

        Returns
        -------
        Paving
            The paving (boxes inside, boundary boxes, and the volume bracket they give).

        Raises
        ------
        ValueError
            If ``eps`` is not a positive finite number, or ``X0`` is omitted and the lifting has no
            identity components.
        """
        from optbound.interval import pave

        eps = v.finite_scalar("eps", eps)
        if eps <= 0:
            raise ValueError(f"eps must be positive, got {eps}")
        return pave(self.tri_test, self.bounding_box() if X0 is None else X0, eps)

    def volume_bounds(self, eps: float, X0=None) -> tuple[float, float]:
        """Guaranteed ``(lower, upper)`` bracket of P's n-dimensional measure (paving at eps).

        Parameters
        ----------
        eps : float
            Largest width of an undecided box, positive.
        X0 : Box or array_like, optional
            Box searched (default :meth:`bounding_box`).

        Returns
        -------
        tuple of float
            ``(lower, upper)``, the inside boxes' and all boxes' measure.

        Raises
        ------
        ValueError
            As :meth:`paving`.
        """
        return self.paving(eps, X0).volume_bounds()

    def area_bounds(self, eps: float, X0=None) -> tuple[float, float]:
        """``volume_bounds`` for n = 2: a guaranteed bracket of the area.

        Parameters
        ----------
        eps : float
            Largest width of an undecided box, positive.
        X0 : Box or array_like, optional
            Box searched (default :meth:`bounding_box`).

        Returns
        -------
        tuple of float
            ``(lower, upper)`` bracket of the area.

        Raises
        ------
        ValueError
            If the set is not 2-D, or ``X0`` is omitted and the lifting has no identity components.
        """
        if self.dim != 2:
            raise ValueError(f"area_bounds is for n = 2, this set has n = {self.dim}")
        return self.volume_bounds(eps, X0)

    def grid_area(self, resolution: int = 200, X0=None) -> float:
        """Fast (not guaranteed) area estimate: the fraction of grid cell centres inside P.

        Parameters
        ----------
        resolution : int, default 200
            Grid cells per side.
        X0 : Box or array_like, optional
            Box searched (default :meth:`bounding_box`).

        Returns
        -------
        float
            The estimated area.

        Raises
        ------
        ValueError
            If the set is not 2-D, or ``X0`` is omitted and the lifting has no identity components.
        """
        if self.dim != 2:
            raise ValueError(f"grid_area is for n = 2, this set has n = {self.dim}")
        box = self.bounding_box() if X0 is None else as_box("X0", X0)
        xs, ys = (
            box.lo[j] + (np.arange(resolution) + 0.5) / resolution * (box.hi[j] - box.lo[j])
            for j in range(2)
        )
        gx, gy = np.meshgrid(xs, ys)
        inside = self.contains(np.column_stack([gx.ravel(), gy.ravel()]))
        return float(np.mean(inside) * np.prod(box.hi - box.lo))

    def boundary(self, resolution: int = 400, X0=None) -> list[np.ndarray]:
        """Polylines tracing ``level = 1`` in 2-D (for plotting), each an (k, 2) array.

        Parameters
        ----------
        resolution : int, default 400
            Grid points per side of the contoured level field.
        X0 : Box or array_like, optional
            Box searched (default :meth:`bounding_box`).

        Returns
        -------
        list of ndarray
            One (k, 2) polyline per piece of the boundary.

        Raises
        ------
        ValueError
            If the set is not 2-D, or ``X0`` is omitted and the lifting has no identity components.
        """
        import contourpy

        if self.dim != 2:
            raise ValueError(f"boundary() is for 2-D sets, this one has n = {self.dim}")
        box = self.bounding_box() if X0 is None else as_box("X0", X0)
        pad = 0.02 * (box.hi - box.lo)
        xs = np.linspace(box.lo[0] - pad[0], box.hi[0] + pad[0], resolution)
        ys = np.linspace(box.lo[1] - pad[1], box.hi[1] + pad[1], resolution)
        gx, gy = np.meshgrid(xs, ys)
        level = self.level(np.column_stack([gx.ravel(), gy.ravel()])).reshape(gx.shape)
        return list(contourpy.contour_generator(gx, gy, level).lines(1.0))


@dataclass(frozen=True)
class CoverProof:
    """Outcome of :meth:`PseudoEllipsoid.prove_covers`.

    Parameters
    ----------
    proven : bool
        Every box is covered by P, up to parts proven outside the set.
    boxes : int
        Boxes given.
    direct : int
        Boxes proven inside at once, without bisection.
    refuted : bool
        A sub-box was proven in the set and outside P (a containment failure).
    """

    proven: bool
    boxes: int
    direct: int
    refuted: bool


def _bisect(boxes: np.ndarray) -> np.ndarray:
    """Halve every box along its widest side."""
    if boxes.shape[0] == 0:
        return boxes
    rows = np.arange(boxes.shape[0])
    axis = np.argmax(boxes[:, :, 1] - boxes[:, :, 0], axis=1)
    mid = 0.5 * (boxes[rows, axis, 0] + boxes[rows, axis, 1])
    left, right = boxes.copy(), boxes.copy()
    left[rows, axis, 1] = mid
    right[rows, axis, 0] = mid
    return np.concatenate([left, right])


def _dot(weights: np.ndarray, terms: list):
    """``sum_k weights[k] * terms[k]`` (terms float arrays or Intervals), skipping zeros."""
    acc = None
    for w, t in zip(weights, terms, strict=True):
        if w == 0.0:
            continue
        term = w * t
        acc = term if acc is None else acc + term
    return 0.0 * terms[0] if acc is None else acc
