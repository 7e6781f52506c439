"""Association of measured bearings with indistinguishable landmarks [HS96, Sect. 3].

Step 1, :func:`visibility_matrix`: which landmark may have caused each bearing, examined on a
polar grid over the prior's (x, y) projection, with occlusion by partitioning walls and the
prior's heading range at each grid point. Step 2, :func:`associate`: an interpretation tree
(Drumheller 1987) over the bearings, pruned by the visibility matrix and by the
counter-clockwise ordering of the map; spurious bearings are handled by the "least bad data"
rule (Grimson and Lozano-Perez 1985): the search first looks for interpretations with the
fewest spurious bearings and stops at the first count that has a consistent one. Every leaf is
checked with :func:`~optbound.localization.landmarks.linear_position` against the error
bounds, the prior and joint visibility.

Both steps are heuristics of the paper, not guaranteed sets: the grid samples the prior and the
leaf test uses the linear estimate with a slack factor (see :func:`associate`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from optbound.localization.landmark_map import LandmarkMap
from optbound.localization.landmarks import as_angles, as_bound, linear_position
from optbound.sets import Ellipsoid

SPURIOUS = -1


def _wrap(angle):
    """Angle(s) wrapped to [-pi, pi)."""
    return (np.asarray(angle) + np.pi) % (2.0 * np.pi) - np.pi


def _check_prior(prior) -> Ellipsoid:
    if not isinstance(prior, Ellipsoid):
        raise TypeError(f"prior must be an Ellipsoid of (x, y, psi), got {type(prior).__name__}")
    if prior.dim != 3:
        raise ValueError(f"prior must be 3-D (x, y, psi), got dimension {prior.dim}")
    return prior


def _check_map(landmark_map) -> LandmarkMap:
    if not isinstance(landmark_map, LandmarkMap):
        raise TypeError(f"landmark_map must be a LandmarkMap, got {type(landmark_map).__name__}")
    return landmark_map


def _grid(prior: Ellipsoid, grid) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Polar grid over the prior's xy projection: points (G, 2), heading centre/half (G,), cell.

    The heading range at a point is the prior's slice there: centre ``psi_c + C_pq C_qq^-1 d``
    and half-width ``sqrt(schur (1 - d^T C_qq^-1 d))`` [HS96, Sect. 3: psi_LOW, psi_HIGH].
    """
    try:
        n_r, n_theta = (int(g) for g in grid)
    except (TypeError, ValueError):
        raise TypeError(f"grid must be a pair (n_r, n_theta) of integers, got {grid!r}") from None
    if n_r < 1 or n_theta < 1:
        raise ValueError(f"grid must have n_r >= 1 and n_theta >= 1, got {grid!r}")
    C, c = prior.shape, prior.center
    Cq = C[:2, :2]
    Lq = np.linalg.cholesky(Cq)
    r = np.linspace(0.0, 1.0, n_r + 1)[1:] if n_r > 1 else np.array([0.0])
    theta = np.linspace(0.0, 2.0 * np.pi, n_theta, endpoint=False)
    unit = np.column_stack(
        [
            np.r_[0.0, np.outer(r, np.cos(theta)).ravel()],
            np.r_[0.0, np.outer(r, np.sin(theta)).ravel()],
        ]
    )
    pts = c[:2] + unit @ Lq.T
    gain = np.linalg.solve(Cq, C[:2, 2])
    schur = max(C[2, 2] - C[2, :2] @ gain, 0.0)
    d2 = np.sum(unit**2, axis=1)
    psi_c = c[2] + unit @ Lq.T @ gain
    psi_half = np.sqrt(schur * np.maximum(1.0 - d2, 0.0))
    # Sampling margin: the largest distance from any point of the ellipse to its nearest node.
    step = max(1.0 / max(n_r, 1), 2.0 * np.sin(np.pi / n_theta)) if n_r > 1 else 1.0
    cell = step * float(np.sqrt(np.linalg.eigvalsh(Cq)[-1]))
    return pts, psi_c, psi_half, cell


def visibility_matrix(
    prior: Ellipsoid,
    alphas,
    landmark_map: LandmarkMap,
    grid=(6, 24),
    delta_alpha: float = 0.0,
) -> np.ndarray:
    """Step 1 of [HS96, Sect. 3]: ``V[i, j]`` TRUE if bearing ``i`` may come from landmark ``j``.

    At every point of a polar grid over the prior's (x, y) projection, landmark ``j`` is a
    candidate for bearing ``alpha_i`` if the sight line to it crosses no wall and its bearing
    ``alpha_hyp`` satisfies ``alpha_i + psi_LOW < alpha_hyp < alpha_i + psi_HIGH`` (mod 2 pi)
    with the prior's heading range at that point. The range is widened by ``delta_alpha``, the
    landmark's error radius and the grid cell size seen from the landmark, so that a pose
    between grid nodes is not lost (the grid is still a sample: not a guarantee).

    Parameters
    ----------
    prior : Ellipsoid
        3-D prior set of (x, y, psi).
    alphas : array_like, shape (N,)
        Measured bearings (radians, robot frame, counter-clockwise).
    landmark_map : LandmarkMap
    grid : (n_r, n_theta)
        Radial and angular counts of the polar grid (plus the centre).
    delta_alpha : float
        Bearing error bound.

    Returns
    -------
    ndarray of bool, shape (N, M)
        Rows without a TRUE are false measurements [HS96, Sect. 3].
    """
    prior, landmark_map = _check_prior(prior), _check_map(landmark_map)
    a = as_angles("alphas", alphas)
    delta = as_bound("delta_alpha", delta_alpha)
    pts, psi_c, psi_half, cell = _grid(prior, grid)
    L = landmark_map.landmarks
    dx = L[None, :, 0] - pts[:, 0, None]
    dy = L[None, :, 1] - pts[:, 1, None]
    dist = np.hypot(dx, dy)
    hyp = np.arctan2(dy, dx)  # (G, M)
    seen = landmark_map.visible(pts[:, 0], pts[:, 1])  # (G, M)
    with np.errstate(divide="ignore"):
        spread = np.arcsin(np.minimum(1.0, (cell + landmark_map.radii[None, :]) / dist))
    half = psi_half[:, None] + delta + spread  # (G, M)
    # (N, G, M): alpha_hyp - alpha_i - psi_c within the widened heading range.
    off = _wrap(hyp[None] - a[:, None, None] - psi_c[None, :, None])
    return np.any((np.abs(off) <= half[None]) & seen[None], axis=1)


@dataclass(frozen=True)
class Association:
    """One consistent interpretation: ``pairs[i]`` is bearing i's landmark (-1: spurious).

    Parameters
    ----------
    pairs : numpy.ndarray of int, shape (N,)
        Landmark index of each bearing, -1 for a spurious bearing.
    pose : tuple of float
        ``(x, y, psi)`` fitted to the paired bearings.
    max_residual : float
        Largest bearing residual [rad] of the fitted pose over the paired bearings.
    """

    pairs: np.ndarray
    pose: tuple[float, float, float]
    max_residual: float


@dataclass(frozen=True)
class AssociationResult:
    """All consistent associations with the fewest spurious bearings, and search statistics.

    Parameters
    ----------
    associations : list of Association
        Empty when no association fits.
    visibility : ndarray (N, M)
        The visibility matrix of Step 1.
    spurious : int
        Number of spurious bearings in every returned association (the least bad data count).
    nodes_expanded : int
        Interpretation-tree nodes generated by the pruned search (all counts tried).
    nodes_unpruned : int
        Nodes of the unpruned tree (every bearing paired with any landmark or none):
        ``sum_{d=1..N} (M + 1)^d``.
    leaves_tested : int
        Leaves checked with the linear solver.
    """

    associations: list[Association]
    visibility: np.ndarray
    spurious: int
    nodes_expanded: int
    nodes_unpruned: int
    leaves_tested: int


class _Search:
    """Depth-first interpretation tree with a fixed number of spurious bearings."""

    def __init__(self, alphas, V, landmark_map, prior, delta, slack, min_pairs):
        self.alphas, self.V, self.map, self.prior = alphas, V, landmark_map, prior
        self.delta, self.slack, self.min_pairs = delta, slack, min_pairs
        self.candidates = [np.flatnonzero(row) for row in V]
        self.nodes = self.leaves = 0

    def run(self, n_spurious: int) -> list[Association]:
        self.found: list[Association] = []
        self.pairs = np.full(self.alphas.shape[0], SPURIOUS)
        self._expand(0, n_spurious, None, None, False)
        return self.found

    def _expand(self, i: int, spurious_left: int, first, last, wrapped: bool) -> None:
        n = self.alphas.shape[0]
        if i == n:
            if spurious_left == 0:
                self._leaf()
            return
        if spurious_left > 0:  # bearing i is spurious
            self.nodes += 1
            self.pairs[i] = SPURIOUS
            self._expand(i + 1, spurious_left - 1, first, last, wrapped)
        if n - i - 1 < spurious_left:  # pairing i would leave too few bearings to be spurious
            return
        used = self.pairs[:i]
        for j in self.candidates[i]:
            # Counter-clockwise ordering: landmark indices increase cyclically, one wrap at most.
            if first is None:
                nxt_wrapped = False
            elif not wrapped and j > last:
                nxt_wrapped = False
            elif j < first and (not wrapped or j > last):
                nxt_wrapped = True
            else:
                continue
            if np.any(used == j):
                continue
            self.nodes += 1
            self.pairs[i] = j
            self._expand(i + 1, spurious_left, j if first is None else first, j, nxt_wrapped)
        self.pairs[i] = SPURIOUS

    def _leaf(self) -> None:
        paired = np.flatnonzero(self.pairs >= 0)
        if paired.size < self.min_pairs:
            return
        self.leaves += 1
        idx = self.pairs[paired]
        L = self.map.landmarks[idx]
        a = self.alphas[paired]
        try:
            x, y, psi = linear_position(L, a)
        except ValueError:
            return
        dist = np.hypot(L[:, 0] - x, L[:, 1] - y)
        resid = np.abs(_wrap(np.arctan2(L[:, 1] - y, L[:, 0] - x) - psi - a))
        with np.errstate(divide="ignore", invalid="ignore"):
            spread = np.arcsin(np.minimum(1.0, self.map.radii[idx] / dist))
        if np.any(resid > self.slack * (self.delta + spread)):
            return
        psi_near = self.prior.center[2] + float(_wrap(psi - self.prior.center[2]))
        if self.prior.level(np.array([x, y, psi_near])) > 1.0:
            return
        if not np.all(self.map.visible(x, y)[idx]):
            return
        self.found.append(Association(self.pairs.copy(), (x, y, psi), float(resid.max())))


def associate(
    prior: Ellipsoid,
    alphas,
    landmark_map: LandmarkMap,
    delta_alpha: float,
    grid=(6, 24),
    max_spurious: int | None = None,
    slack: float = 3.0,
    min_pairs: int = 3,
) -> AssociationResult:
    """Step 2 of [HS96, Sect. 3]: every consistent association of bearings with landmarks.

    Bearings are examined in counter-clockwise order (sorted modulo 2 pi). A bearing may be
    paired with a landmark its visibility-matrix row allows, provided the paired landmark
    indices increase cyclically (at most one wrap) -- the map's ordering assumption
    [HS96, Sect. 2] -- or declared spurious. Least bad data: the search runs with 0, 1, 2, ...
    spurious bearings (starting at the number of empty rows of the visibility matrix) and
    returns the consistent leaves of the first count that has any. A leaf with at least
    ``min_pairs`` pairs is consistent when :func:`linear_position` succeeds and (a) every paired
    bearing's residual is at most ``slack * (delta_alpha + asin(r_j / d_j))`` (``r_j`` the
    landmark's error radius, ``d_j`` its distance), (b) the pose lies in the prior, (c) every
    paired landmark is visible from it.

    Parameters
    ----------
    prior : Ellipsoid
        3-D prior (x, y, psi) [HS96: Omega_a-priori].
    alphas : array_like, shape (N,)
        Measured bearings.
    landmark_map : LandmarkMap
    delta_alpha : float
        Bearing error bound.
    grid : (n_r, n_theta)
        Polar grid of :func:`visibility_matrix`.
    max_spurious : int, optional
        Largest number of spurious bearings tried; default ``N - min_pairs``.
    slack : float
        Factor on the residual bound of the leaf test (the linear estimate is not exact with
        noisy data, so the residuals may exceed the per-bearing bounds).
    min_pairs : int
        Fewest pairs a leaf needs (3: the linear solver's minimum).

    Returns
    -------
    AssociationResult
        ``associations`` holds ``pairs`` in the caller's bearing order.
    """
    prior, landmark_map = _check_prior(prior), _check_map(landmark_map)
    a = as_angles("alphas", alphas)
    delta = as_bound("delta_alpha", delta_alpha)
    slack = as_bound("slack", slack)
    if int(min_pairs) != min_pairs or min_pairs < 3:
        raise ValueError(f"min_pairs must be an integer >= 3, got {min_pairs}")
    n, m = a.shape[0], landmark_map.size
    limit = n - min_pairs if max_spurious is None else int(max_spurious)
    if limit < 0:
        raise ValueError(f"max_spurious must be >= 0, got {max_spurious}")
    order = np.argsort(np.mod(a, 2.0 * np.pi), kind="stable")
    V = visibility_matrix(prior, a, landmark_map, grid, delta)
    search = _Search(a[order], V[order], landmark_map, prior, delta, slack, min_pairs)
    found: list[Association] = []
    start = int(np.sum(~V.any(axis=1)))
    spurious = start
    for spurious in range(start, limit + 1):
        found = search.run(spurious)
        if found:
            break
    inverse = np.argsort(order)
    out = [Association(f.pairs[inverse], f.pose, f.max_residual) for f in found]
    unpruned = sum((m + 1) ** d for d in range(1, n + 1))
    return AssociationResult(out, V, spurious, search.nodes, unpruned, search.leaves)


@dataclass(frozen=True)
class AssociationScore:
    """How an association compares with the true one (:func:`score`).

    Parameters
    ----------
    paired : int
        True bearings paired with their own landmark.
    true_bearings : int
        Bearings that came from a landmark.
    discarded : int
        Spurious bearings declared spurious.
    spurious : int
        Spurious bearings.
    """

    paired: int
    true_bearings: int
    discarded: int
    spurious: int

    @property
    def accuracy(self) -> float:
        """Fraction of all bearings correctly associated or correctly discarded."""
        return (self.paired + self.discarded) / (self.true_bearings + self.spurious)


def score(pairs, labels) -> AssociationScore:
    """Compare an association with the truth, bearing by bearing.

    Parameters
    ----------
    pairs : array_like of int, shape (N,)
        The association's landmark per bearing (``Association.pairs``; ``SPURIOUS`` = -1).
    labels : array_like of int, shape (N,)
        The true landmark per bearing, ``SPURIOUS`` for a false measurement.

    Returns
    -------
    AssociationScore
        A true bearing counts as correct only when paired with its own landmark; a spurious
        one only when declared ``SPURIOUS`` [HS96, Sect. 3: "discards false measurements"].
    """
    p = np.asarray(pairs)
    t = np.asarray(labels)
    if p.ndim != 1 or t.shape != p.shape:
        raise ValueError(f"pairs and labels must be 1-D of equal length, got {p.shape}, {t.shape}")
    if p.size == 0:
        raise ValueError("pairs is empty: there is no bearing to score")
    false = t == SPURIOUS
    return AssociationScore(
        paired=int(np.sum((p == t) & ~false)),
        true_bearings=int(np.sum(~false)),
        discarded=int(np.sum((p == SPURIOUS) & false)),
        spurious=int(np.sum(false)),
    )


__all__ = [
    "SPURIOUS",
    "Association",
    "AssociationResult",
    "AssociationScore",
    "associate",
    "score",
    "visibility_matrix",
]
