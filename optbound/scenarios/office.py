"""Office scenario of the HS96 experiment [HS96, Sect. 5] (our design: the paper's Fig. 4 is lost).

A 14 m x 10 m open-plan office whose outer walls carry 22 identical retro-reflecting landmarks,
numbered counter-clockwise along the walls (so that, the room being convex, every robot inside
sees the unoccluded ones in index order [HS96, Sect. 2]); two partitions reach in from the outer
walls and a cross of partitions stands in the middle. The course is a rounded rectangle around
the cross, driven at 2 m/s with the heading along the path; 20 snapshot scans per second (a
scan is taken at one instant: the goniometer's rotation during the 50 ms is not modelled).

Error model (amplitude-bounded, as in the paper): bearing noise uniform in ``+-delta_alpha``
(0.02 deg); landmark positions off by a fixed unknown bias inside their error ellipse (1.5 cm
along the wall, 1 cm across: the dominant error); odometry errors proportional to the travelled
distance and turned angle with slowly varying, correlated factors (a constant bias plus a slow
sinusoid) bounded by ``OdometryBounds``.

Nothing here was tuned to reach the paper's numbers. The models it drives are
:class:`optbound.localization.tracker.SetTracker` (with its association gate
:func:`~optbound.localization.tracker.nearest_landmark`) and the association search of
:mod:`optbound.localization.association`.

References
----------
[HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
on an angle measurement technique", IFAC, 1996.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from optbound.localization.landmark_map import LandmarkMap
from optbound.localization.tracker import SetTracker, nearest_landmark, pose_level
from optbound.sets import Ellipsoid

ROOM = (14.0, 10.0)
N_LANDMARKS = 22
WALL_INSET = 0.01  # landmarks sit 1 cm in front of their wall: sight lines never graze it
LANDMARK_SIGMA = (0.015, 0.010)  # semi-axes of the error ellipse: along, across the wall (m)
DELTA_ALPHA = math.radians(0.02)
SPEED = 2.0  # m/s
SCAN_RATE = 20.0  # scans/s
COURSE = (3.0, 2.5, 11.0, 7.5, 1.0)  # x0, y0, x1, y1, corner radius of the rounded rectangle
WALLS = np.array(
    [
        [[4.5, 0.0], [4.5, 1.8]],  # partition from the south wall
        [[9.5, 10.0], [9.5, 8.2]],  # partition from the north wall
        [[5.5, 5.0], [8.5, 5.0]],  # central cross
        [[7.0, 4.0], [7.0, 6.0]],
    ]
)


@dataclass(frozen=True)
class OdometryBounds:
    """Amplitude bounds of the dead-reckoning errors per step.

    ``e_x, e_y <= along * d`` (d the travelled distance), ``e_psi <= drift * d + turn * |dpsi|``.

    Parameters
    ----------
    along : float, default 0.02
        Position error per metre travelled.
    drift : float, default 0.3° in radians
        Heading drift per metre travelled [rad/m].
    turn : float, default 0.02
        Heading error per radian turned.
    """

    along: float = 0.02
    drift: float = math.radians(0.3)  # rad per metre
    turn: float = 0.02

    def half_widths(self, step: np.ndarray) -> np.ndarray:
        """Bound the error box of a reported step ``(dx, dy, dpsi)``, with a 1 % margin.

        The true distance and turn are bounded from the reported ones (the errors are
        proportional to the true motion), then the class's bounds applied.

        Parameters
        ----------
        step : np.ndarray, shape (3,)
            The reported motion ``(dx, dy, dpsi)`` in the robot's frame.

        Returns
        -------
        np.ndarray, shape (3,)
            Half-widths of the error box in x, y and psi.
        """
        d = 1.01 * math.hypot(step[0], step[1]) / (1.0 - math.sqrt(2.0) * self.along)
        turn = 1.01 * (abs(step[2]) + self.drift * d) / (1.0 - self.turn)
        return np.array([self.along * d, self.along * d, self.drift * d + self.turn * turn])

    def shape(self, step: np.ndarray, floor: float = 1e-7) -> np.ndarray:
        """Build ``C^Delta``, the shape of an ellipsoid containing the error box.

        Parameters
        ----------
        step : np.ndarray, shape (3,)
            The reported motion ``(dx, dy, dpsi)``.
        floor : float, default 1e-7
            Added to every half-width, so the shape stays positive definite at rest.

        Returns
        -------
        np.ndarray, shape (3, 3)
            The diagonal shape matrix.

        Notes
        -----
        With ``h`` the :meth:`half_widths` plus ``floor``, ``C = 3 diag(h^2)``: the
        ellipsoid ``e^T C^{-1} e <= 1`` passes through the box's corners, since
        ``sum_i h_i^2 / (3 h_i^2) = 1`` in 3-D, so by convexity it contains the box.
        """
        h = self.half_widths(step) + floor
        return np.diag(3.0 * h**2)


def office_map() -> LandmarkMap:
    """Build the office's map: 22 landmarks, their error ellipses and the walls.

    Returns
    -------
    LandmarkMap
        Landmarks numbered counter-clockwise along the walls, :data:`WALL_INSET` in front
        of them, with error ellipses of semi-axes :data:`LANDMARK_SIGMA` (along, across the
        wall); walls: the outer ones and :data:`WALLS`.

    Examples
    --------
    >>> from optbound.scenarios import office
    >>> omap = office.office_map()
    >>> omap.size, omap.landmarks.shape, omap.shapes.shape
    (22, (22, 2), (22, 2, 2))
    """
    w, h = ROOM
    perimeter = 2.0 * (w + h)
    s = (np.arange(N_LANDMARKS) + 0.37) * perimeter / N_LANDMARKS  # off the corners
    pts, along = [], []
    for t in s:
        if t < w:
            pts.append((t, WALL_INSET))
            along.append(0.0)
        elif t < w + h:
            pts.append((w - WALL_INSET, t - w))
            along.append(np.pi / 2)
        elif t < 2 * w + h:
            pts.append((w - (t - w - h), h - WALL_INSET))
            along.append(0.0)
        else:
            pts.append((WALL_INSET, h - (t - 2 * w - h)))
            along.append(np.pi / 2)
    shapes = []
    for phi in along:
        R = np.array([[math.cos(phi), -math.sin(phi)], [math.sin(phi), math.cos(phi)]])
        shapes.append(R @ np.diag(np.square(LANDMARK_SIGMA)) @ R.T)
    outer = np.array([[[0, 0], [w, 0]], [[w, 0], [w, h]], [[w, h], [0, h]], [[0, h], [0, 0]]])
    return LandmarkMap(np.array(pts), np.concatenate([outer, WALLS]), np.array(shapes))


def course_pose(s: float | np.ndarray) -> np.ndarray:
    """Find the pose ``(x, y, psi)`` at arc length ``s`` along the course.

    Parameters
    ----------
    s : float or array_like, shape (m,)
        Arc lengths [m]; laps repeat.

    Returns
    -------
    np.ndarray, shape (m, 3)
        The poses, heading along the path, psi unwrapped (it grows by 2 pi per lap); a
        scalar ``s`` gives one row.
    """
    x0, y0, x1, y1, r = COURSE
    legs = np.array([x1 - x0 - 2 * r, y1 - y0 - 2 * r] * 2)
    arc = np.pi * r / 2
    lap = legs.sum() + 4 * arc
    s = np.atleast_1d(np.asarray(s, dtype=float))
    n_lap, u = np.divmod(s, lap)
    out = np.empty((s.size, 3))
    # Start at the south-west end of the south leg, heading east; corners counter-clockwise.
    starts = np.array([[x0 + r, y0], [x1, y0 + r], [x1 - r, y1], [x0, y1 - r]])
    centres = np.array([[x1 - r, y0 + r], [x1 - r, y1 - r], [x0 + r, y1 - r], [x0 + r, y0 + r]])
    for i, t in enumerate(u):
        for k in range(4):
            heading = k * np.pi / 2
            if t <= legs[k]:
                d = np.array([math.cos(heading), math.sin(heading)])
                out[i] = (*(starts[k] + t * d), heading)
                break
            t -= legs[k]
            if t <= arc or k == 3:
                phi = heading - np.pi / 2 + t / r
                out[i] = (
                    *(centres[k] + r * np.array([math.cos(phi), math.sin(phi)])),
                    heading + t / r,
                )
                break
            t -= arc
        out[i, 2] += 2 * np.pi * n_lap[i]
    return out


def lap_length() -> float:
    """Compute the length of one lap of the course.

    Returns
    -------
    float
        The rounded rectangle's perimeter [m].
    """
    x0, y0, x1, y1, r = COURSE
    return 2 * (x1 - x0 - 2 * r) + 2 * (y1 - y0 - 2 * r) + 2 * np.pi * r


def _relative(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Motion from pose ``a`` to ``b`` in ``a``'s robot frame."""
    c, s = math.cos(a[2]), math.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return np.array([c * dx + s * dy, -s * dx + c * dy, b[2] - a[2]])


def _correlated(rng: np.random.Generator, bound: float, t: np.ndarray) -> np.ndarray:
    """A slowly varying factor in ``[-bound, bound]``: bias + sinusoid (periods 5-40 s)."""
    bias = rng.uniform(-0.5, 0.5) * bound
    amp = (bound - abs(bias)) * rng.uniform(0.3, 0.95)
    return bias + amp * np.sin(2 * np.pi * t / rng.uniform(5.0, 40.0) + rng.uniform(0, 2 * np.pi))


@dataclass
class OfficeData:
    """One simulated experiment: true poses, odometry, scans, the true landmark positions.

    Parameters
    ----------
    landmark_map : LandmarkMap
        The nominal map (:func:`office_map`) the robot knows.
    true_landmarks : np.ndarray, shape (N, 2)
        The landmarks' true (biased) positions.
    times : np.ndarray, shape (K + 1,)
        Scan times [s].
    poses : np.ndarray, shape (K + 1, 3)
        True poses; scan ``k`` is taken at ``poses[k]``.
    odometry : np.ndarray, shape (K, 3)
        Reported motion from ``poses[k]`` to ``poses[k + 1]``, in the robot's frame.
    odometry_shapes : np.ndarray, shape (K, 3, 3)
        Shapes of ellipsoids containing each step's odometry error
        (:meth:`OdometryBounds.shape`).
    scans : list of tuple, optional
        ``(alphas, true landmark indices)`` per pose.
    """

    landmark_map: LandmarkMap
    true_landmarks: np.ndarray
    times: np.ndarray
    poses: np.ndarray  # (K + 1, 3): scan k is taken at poses[k]
    odometry: np.ndarray  # (K, 3): reported motion from poses[k] to poses[k + 1]
    odometry_shapes: np.ndarray  # (K, 3, 3)
    scans: list = field(default_factory=list)  # (alphas, true landmark indices) per pose


def simulate(laps: float = 10.0, seed: int = 0, bounds: OdometryBounds | None = None) -> OfficeData:
    """Simulate ``laps`` of the course: landmark biases, odometry and scans.

    Parameters
    ----------
    laps : float, default 10.0
        Laps driven at :data:`SPEED`, scanned at :data:`SCAN_RATE`.
    seed : int, default 0
        Fixes the landmark biases, the odometry error factors and the bearing noise.
    bounds : OdometryBounds, optional
        The odometry error bounds; ``OdometryBounds()`` if None.

    Returns
    -------
    OfficeData
        The experiment.

    Examples
    --------
    >>> from optbound.scenarios import office
    >>> data = office.simulate(laps=0.05, seed=0)
    >>> data.poses.shape, data.odometry.shape, len(data.scans)
    ((13, 3), (12, 3), 13)
    """
    rng = np.random.default_rng(seed)
    bounds = OdometryBounds() if bounds is None else bounds
    omap = office_map()
    # Landmark biases: uniform in 0.95 x their ellipse (fixed for the run).
    u = rng.normal(size=(omap.size, 2))
    u *= (0.95 * rng.uniform(0, 1, omap.size) ** 0.5 / np.linalg.norm(u, axis=1))[:, None]
    true_lm = omap.landmarks + np.einsum("mij,mj->mi", np.linalg.cholesky(omap.shapes), u)
    n_scans = round(laps * lap_length() / SPEED * SCAN_RATE)
    times = np.arange(n_scans + 1) / SCAN_RATE
    poses = course_pose(times * SPEED)
    factors = np.stack(
        [
            _correlated(rng, b, times)
            for b in (bounds.along, bounds.along, bounds.drift, bounds.turn)
        ]
    )
    odo = np.empty((n_scans, 3))
    shapes = np.empty((n_scans, 3, 3))
    for k in range(n_scans):
        true = _relative(poses[k], poses[k + 1])
        d = math.hypot(true[0], true[1])
        err = factors[:, k] * np.array([d, d, d, abs(true[2])])
        odo[k] = true + np.array([err[0], err[1], err[2] + err[3]])
        shapes[k] = bounds.shape(odo[k])
    data = OfficeData(omap, true_lm, times, poses, odo, shapes)
    true_map = LandmarkMap(true_lm, omap.walls)
    for pose in poses:
        seen = np.flatnonzero(true_map.visible(pose[0], pose[1]))
        bearing = np.arctan2(true_lm[seen, 1] - pose[1], true_lm[seen, 0] - pose[0]) - pose[2]
        noise = rng.uniform(-1.0, 1.0, seen.size) * DELTA_ALPHA
        data.scans.append((np.mod(bearing + noise, 2 * np.pi), seen))
    return data


def corrupt_scan(
    alphas, truth, spurious_rate: float, missing_rate: float, rng: np.random.Generator
) -> tuple[np.ndarray, np.ndarray]:
    """A scan with missing and spurious bearings injected ([HS96, Sect. 3]: false measurements).

    Each true bearing is dropped with probability ``missing_rate`` (an occluded or unseen
    reflector); then ``Binomial(n, spurious_rate)`` spurious bearings, ``n`` the scan's number
    of true bearings, are added uniformly in ``[0, 2 pi)`` (reflections off other objects).

    Parameters
    ----------
    alphas : array_like, shape (n,)
        The scan's bearings (``OfficeData.scans[k][0]``).
    truth : array_like of int, shape (n,)
        Their landmark indices (``OfficeData.scans[k][1]``).
    spurious_rate, missing_rate : float
        Rates in ``[0, 1]``.
    rng : numpy.random.Generator
        Draws the dropped and the spurious bearings.

    Returns
    -------
    alphas : np.ndarray, shape (m,)
        The corrupted scan: kept true bearings first, spurious ones after.
    labels : np.ndarray of int, shape (m,)
        Each bearing's landmark index, ``-1`` for a spurious bearing
        (``association.SPURIOUS``).

    Raises
    ------
    ValueError
        If ``alphas`` and ``truth`` are not 1-D of equal length, or a rate is outside
        ``[0, 1]``.

    References
    ----------
    [HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
    on an angle measurement technique", IFAC, 1996.
    """
    alphas = np.asarray(alphas, dtype=float)
    truth = np.asarray(truth, dtype=int)
    if alphas.ndim != 1 or truth.shape != alphas.shape:
        raise ValueError(
            f"alphas and truth must be 1-D of equal length, got {alphas.shape} and {truth.shape}"
        )
    for name, rate in (("spurious_rate", spurious_rate), ("missing_rate", missing_rate)):
        if not 0.0 <= rate <= 1.0:
            raise ValueError(f"{name} must be in [0, 1], got {rate}")
    keep = rng.uniform(size=alphas.size) >= missing_rate
    n_spurious = int(rng.binomial(alphas.size, spurious_rate))
    fake = rng.uniform(0.0, 2.0 * np.pi, n_spurious)
    return np.r_[alphas[keep], fake], np.r_[truth[keep], np.full(n_spurious, -1)]


@dataclass
class TrackResult:
    """Per-scan outputs of :func:`track` (after the scan's updates), over ``K`` scans.

    Parameters
    ----------
    centers : np.ndarray, shape (K + 1, 3)
        Centres of the pose ellipsoids.
    shapes : np.ndarray, shape (K + 1, 3, 3)
        Their shape matrices.
    levels : np.ndarray, shape (K + 1,)
        Level of the true pose in each ellipsoid; <= 1 means contained.
    updates : int
        Bearing updates made.
    inconsistent : int
        Updates whose bearing was inconsistent with the set.
    wrong_associations : int
        Bearings the gate paired with the wrong landmark (injected faults not counted).
    injected : int
        Outliers injected (``fault_rate``).
    seconds : float
        Wall time of the tracking loop.
    """

    centers: np.ndarray  # (K + 1, 3)
    shapes: np.ndarray  # (K + 1, 3, 3)
    levels: np.ndarray  # (K + 1,) level of the true pose; <= 1 means contained
    updates: int
    inconsistent: int
    wrong_associations: int
    injected: int
    seconds: float


def track(
    data: OfficeData,
    initial: Ellipsoid,
    criterion: str = "projection",
    fault_rate: float = 0.0,
    seed: int = 0,
    gate: float = math.radians(1.0),
    steps: int | None = None,
    on_update=None,
    phantom: float | None = None,
) -> TrackResult:
    """Run :class:`SetTracker` over the simulated scans (scan 0 was used for initialization).

    Each scan: one prediction with the odometry since the previous scan, then one update per
    measured bearing, associated by :func:`nearest_landmark`. With ``fault_rate`` > 0 a scan
    has, with that probability, one single outlier: a bearing deliberately paired with the
    wrong (next visible) landmark or, with ``phantom`` (metres), the bearing of a reflector
    that distance from the true landmark in a random direction, paired with that landmark.
    ``on_update(k, tracker, alpha, j)`` is called before each update (for sampled comparisons).

    Parameters
    ----------
    data : OfficeData
        The simulated experiment.
    initial : Ellipsoid
        The pose set after scan 0, in (x, y, psi).
    criterion : str, default "projection"
        The tracker's fusion criterion (:class:`SetTracker`).
    fault_rate : float, default 0.0
        Probability that a scan has one injected outlier.
    seed : int, default 0
        Draws the injected outliers.
    gate : float, default 1° in radians
        The association gate of :func:`nearest_landmark` [rad].
    steps : int, optional
        Track only the first ``steps`` scans after scan 0; all of them if None.
    on_update : callable, optional
        ``on_update(k, tracker, alpha, j)``, called before each update.
    phantom : float, optional
        With faults: the distance [m] of a phantom reflector from the true landmark; None
        pairs a bearing with the wrong landmark instead.

    Returns
    -------
    TrackResult
        The per-scan sets, the true pose's levels and the counts.

    References
    ----------
    [HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
    on an angle measurement technique", IFAC, 1996.
    """
    import time

    rng = np.random.default_rng(seed)
    tracker = SetTracker(initial, data.landmark_map, DELTA_ALPHA, criterion=criterion)
    n = len(data.odometry) if steps is None else min(steps, len(data.odometry))
    centers, shapes, levels = np.empty((n + 1, 3)), np.empty((n + 1, 3, 3)), np.empty(n + 1)
    centers[0], shapes[0] = initial.center, initial.shape
    levels[0] = pose_level(initial, data.poses[0])
    updates = inconsistent = wrong = injected = 0
    start = time.perf_counter()
    for k in range(n):
        tracker.predict(data.odometry[k], data.odometry_shapes[k])
        alphas, truth = data.scans[k + 1]
        fault = rng.uniform() < fault_rate and alphas.size > 1
        bad = int(rng.integers(alphas.size)) if fault else -1
        seen = np.flatnonzero(tracker.map.visible(*tracker.set.center[:2]))
        for i, alpha in enumerate(alphas):
            j = nearest_landmark(tracker, alpha, gate, seen)
            if i == bad and phantom is None:
                j = int(seen[(np.searchsorted(seen, truth[i]) + 1) % seen.size])
                injected += 1
            elif i == bad:
                pose, phi = data.poses[k + 1], rng.uniform(0, 2 * np.pi)
                fake = data.true_landmarks[truth[i]] + phantom * np.array(
                    [np.cos(phi), np.sin(phi)]
                )
                alpha = math.atan2(fake[1] - pose[1], fake[0] - pose[0]) - pose[2]
                j = int(truth[i])
                injected += 1
            if j is None:
                continue
            if i != bad and j != truth[i]:
                wrong += 1
            if on_update is not None:
                on_update(k, tracker, alpha, j)
            info = tracker.update(alpha, j)
            updates += 1
            inconsistent += info.case == "inconsistent"
        centers[k + 1], shapes[k + 1] = tracker.set.center, tracker.set.shape
        levels[k + 1] = pose_level(tracker.set, data.poses[k + 1])
    seconds = time.perf_counter() - start
    return TrackResult(centers, shapes, levels, updates, inconsistent, wrong, injected, seconds)


def dead_reckoning(data: OfficeData, start: np.ndarray) -> np.ndarray:
    """Integrate the odometry alone from ``start``.

    Parameters
    ----------
    data : OfficeData
        The simulated experiment.
    start : np.ndarray, shape (3,)
        The initial pose ``(x, y, psi)``.

    Returns
    -------
    np.ndarray, shape (K + 1, 3)
        The dead-reckoned poses, ``start`` first.
    """
    out = np.empty((len(data.odometry) + 1, 3))
    out[0] = start
    for k, step in enumerate(data.odometry):
        c, s = math.cos(out[k, 2]), math.sin(out[k, 2])
        out[k + 1] = out[k] + np.array(
            [c * step[0] - s * step[1], s * step[0] + c * step[1], step[2]]
        )
    return out


__all__ = [
    "COURSE",
    "DELTA_ALPHA",
    "LANDMARK_SIGMA",
    "N_LANDMARKS",
    "ROOM",
    "SCAN_RATE",
    "SPEED",
    "WALLS",
    "WALL_INSET",
    "OdometryBounds",
    "OfficeData",
    "TrackResult",
    "corrupt_scan",
    "course_pose",
    "dead_reckoning",
    "lap_length",
    "office_map",
    "simulate",
    "track",
]
