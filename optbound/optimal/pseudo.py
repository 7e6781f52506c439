"""The optimal pseudo-ellipsoid of a paved set: the best any lifted-ellipsoid bound can do.

For a lifting T and a set X known by a paving (``inner ⊂ X ⊂ inner ∪ boundary``), the
reference is the minimum-volume ellipsoid of R^L containing ``T(X)`` [BH, eq. (10)], the target
the lifted filter [BH, eq. (16)] approximates. It is bracketed:

- **lower**: every corner of an inner box is a point of X, so any lifted ellipsoid containing
  ``T(X)`` contains their images. ``mvee`` of those images (solved on an active set of the
  points farthest out, grown until every image is inside) is the best such ellipsoid, and
  ``optimal.lower.volume_lower_bound`` (a weak-duality bound, no solver involved) is a
  rigorous lower bound on its volume, hence on the reference;
- **upper**: the ``mvee`` ellipsoid, inflated about its centre by the smallest factor (a
  geometric search, then bisection) for which ``PseudoEllipsoid.tri_contains`` *proves* every
  inner and boundary box inside (``prove_covers``: boxes are bisected where needed, and with
  the set's own test the parts proven outside the set are dropped). It contains X, so its
  lifted volume bounds the reference from above; the bracket closes as the paving is refined.
  The reference is nearly flat in some lifted directions (the lifted set lies close to the
  zero set of a few polynomials), so a coarse paving, whose boundary boxes protrude to first
  order in their width, needs a large inflation.

References
----------
[BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
bearing measurements", IEEE Transactions on Robotics and Automation, 2004.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from optbound._core import box_array
from optbound.optimal.certify import certify_points
from optbound.optimal.enclosing import mvee
from optbound.optimal.khachiyan import khachiyan_mvee
from optbound.optimal.lower import volume_lower_bound
from optbound.sets import Ellipsoid, PolynomialLifting, PseudoEllipsoid
from optbound.sets.result import BoundResult

# Points passed to the SDP at first (the farthest out in a rough enclosing ellipsoid), and
# how many rounds may add the points the SDP's ellipsoid still misses.
ACTIVE_POINTS = 300
ACTIVE_ROUNDS = 6
# Geometric step of the inflation search, its cap, and the bisection steps that follow.
INFLATE_STEP = 1.05
INFLATE_MAX = 100.0
BISECTIONS = 8


@dataclass(frozen=True)
class PseudoReference(BoundResult):
    """Bracket of the optimal pseudo-ellipsoid (lifted volumes) and the certified upper set.

    ``lower <= optimum <= upper``. As a ``BoundResult``: ``set`` is ``bound`` and ``margin``
    is ``inflation - 1``.

    Parameters
    ----------
    bound : PseudoEllipsoid
        Proven to contain every inner and boundary box.
    lower : float
        Lower bound of the optimal lifted volume.
    upper : float
        ``bound.lifted.volume()``.
    sample_volume : float
        Volume of the MVEE of the lifted inner-box corners (certified to enclose them).
    inflation : float
        The factor applied to its semi-axes to make ``bound``.
    """

    set_attribute = "bound"
    certified = True

    bound: PseudoEllipsoid
    lower: float
    upper: float
    sample_volume: float
    inflation: float

    @property
    def margin(self) -> float:
        """Relative enlargement of the lifted semi-axes, ``inflation - 1``."""
        return self.inflation - 1.0


def _corners(inner: np.ndarray) -> np.ndarray:
    """All distinct corners of the inner boxes (points of the set)."""
    n = inner.shape[1]
    grids = np.stack(np.meshgrid(*([[0, 1]] * n), indexing="ij"), axis=-1).reshape(-1, n)
    pts = np.concatenate([inner[:, np.arange(n), g] for g in grids])
    return np.unique(pts, axis=0)


def _active_mvee(Y: np.ndarray) -> Ellipsoid:
    """MVEE of the rows of Y, solved on a growing active set (exact for the full set).

    The lifted points are nearly flat in some directions (condition numbers ~1e9 for L = 8),
    so they are whitened first, ``Y' = (Y - mean) A`` with ``A = cov^{-1/2}``; the MVEE is
    affine-equivariant, and the answer is mapped back.
    """
    mean = Y.mean(axis=0)
    w, V = np.linalg.eigh(np.cov(Y.T))
    A = V / np.sqrt(w)
    Z = (Y - mean) @ A
    rough = khachiyan_mvee(Z, tol=1e-3)
    order = np.argsort(rough.level(Z))[::-1]
    active = order[: min(ACTIVE_POINTS, Z.shape[0])]
    for _ in range(ACTIVE_ROUNDS):
        E = mvee(Z[active]).ellipsoid
        level = E.level(Z)
        missed = np.flatnonzero(level > 1.0)
        if missed.size == 0:
            break
        worst = missed[np.argsort(level[missed])[::-1][:ACTIVE_POINTS]]
        active = np.union1d(active, worst)
    E = certify_points(E, Z)[0]
    back = np.linalg.inv(A)  # A^{-1} = diag(sqrt(w)) V^T
    return Ellipsoid(mean + E.center @ back, back.T @ E.shape @ back)


def optimal_pseudo_ellipsoid(
    lift: PolynomialLifting, inner, boundary, set_test=None
) -> PseudoReference:
    """Certified bracket of the minimum-lifted-volume pseudo-ellipsoid containing a paved set.

    Parameters
    ----------
    lift : PolynomialLifting
        The lifting T (use the analytic bound's own, so that lifted volumes compare).
    inner, boundary : array_like, shape (m, n, 2)
        Inner and boundary boxes of a paving of the set.
    set_test : callable, optional
        Three-valued test of the set on ``Interval`` coordinates (the paving's own). With it,
        parts of boxes proven outside the set need not be covered
        (``PseudoEllipsoid.prove_covers``); without it every box must be proven inside.

    Returns
    -------
    PseudoReference
        The certified upper set and the bracket ``lower <= optimum <= upper`` of lifted volumes.

    Raises
    ------
    TypeError
        If ``lift`` is not a PolynomialLifting.
    ValueError
        Too few inner boxes to span the lifted space, or no inflation up to ``INFLATE_MAX``
        proves every box inside (boxes too wide for the interval test).
    """
    if not isinstance(lift, PolynomialLifting):
        raise TypeError(f"lift must be a PolynomialLifting, got {type(lift).__name__}")
    inner = box_array("inner", inner, lift.dim)
    boxes = np.concatenate([inner, box_array("boundary", boundary, lift.dim)])
    Y = lift(_corners(inner))
    E = _active_mvee(Y)
    lower = volume_lower_bound(Y)

    def proven(alpha: float) -> bool:
        P = PseudoEllipsoid(lift, E.center, E.shape * alpha**2)
        return P.prove_covers(boxes, set_test).proven

    hi = 1.0
    while not proven(hi):
        hi *= INFLATE_STEP
        if hi > INFLATE_MAX:
            raise ValueError(
                f"no inflation up to {INFLATE_MAX} proves the boxes inside: refine the paving"
            )
    lo = hi / INFLATE_STEP if hi > 1.0 else hi
    for _ in range(BISECTIONS if hi > 1.0 else 0):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if proven(mid) else (mid, hi)
    bound = PseudoEllipsoid(lift, E.center, E.shape * hi**2)
    return PseudoReference(bound, lower, bound.lifted.volume(), E.volume(), hi)
