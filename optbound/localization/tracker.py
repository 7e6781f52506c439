"""Recursive set-theoretic pose tracker from dead reckoning and bearings [HS96, Sect. 4].

The posture set is an ellipsoid in ``(x, y, psi)`` [HS96, eq. (7)]. :meth:`SetTracker.predict`
propagates it with a dead-reckoning set of relative motions [HS96, eqs. (8)-(14)];
:meth:`SetTracker.update` intersects it with the linearized strip of one bearing
[HS96, eqs. (18)-(23)] and bounds the intersection by [HS96, eq. (24)] with a selectable choice
of lambda (eqs. (26)-(30)).

**Not guaranteed.** Both steps linearize: the prediction replaces the rotation of the relative
motion by its Jacobian at the nominal heading [HS96, eq. (11)], and the bearing equation (18) is
linearized around the predicted centre. The exact sets are not ellipsoids, and the true pose can
leave the tracked set when the heading uncertainty times the travelled distance, or the position
uncertainty over the landmark distance, is not small. Only the ellipsoid operations themselves
(:func:`optbound.analytic.minkowski_sum`, :func:`optbound.analytic.intersect_strip`) are outer
bounds. The office reproduction (``papers_repro/hs96_office.py``) measures how often the true
pose leaves the set.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np

from optbound import analytic
from optbound._core import validate as v
from optbound.localization.geometry import wrap_angle
from optbound.localization.landmark_map import LandmarkMap
from optbound.localization.landmarks import as_bound
from optbound.sets import Ellipsoid, Strip

CRITERIA = ("projection", "volume", "robust")
XY = (0, 1)


@dataclass(frozen=True)
class UpdateInfo:
    """Outcome of one :meth:`SetTracker.update`: the fusion case, consistency and lambda.

    Parameters
    ----------
    case : str
        The configuration of strip and ellipsoid [HS96, Fig. 1] (``"inconsistent"`` when the
        measurement was rejected).
    consistency : float
        The consistency measure of the measurement [HS96, eq. (29)].
    lam : float
        The lambda of [HS96, eq. (24)] chosen by the criterion.
    """

    case: str
    consistency: float
    lam: float


class SetTracker:
    """Ellipsoidal posture tracker [HS96, Fig. 3] (linearized: *not* a guaranteed bound).

    Parameters
    ----------
    initial : Ellipsoid
        Initial posture set of ``(x, y, psi)`` (e.g. from the association search).
    landmark_map : LandmarkMap
        Landmarks, their error ellipses [HS96, eq. (2)] (used in eq. (20)) and walls.
    delta_alpha : float
        Bearing error bound ``|d alpha| < delta_alpha`` (radians).
    criterion : {"projection", "volume", "robust"}
        Choice of lambda in [HS96, eq. (24)]: minimum area of the (x, y) projection
        [HS96, eqs. (27)-(28)] (default, as the paper recommends), minimum volume
        [HS96, eq. (26)], or the consistency-weighted robust lambda [HS96, eqs. (29)-(30)]
        (with the projection-optimal lambda as lambda_OPT).
    relinearize : int
        Extra linearizations of eq. (18) around the fused centre (the feedback of
        [HS96, Fig. 3]); each re-fuses the *predicted* set with the new strip.

    Notes
    -----
    The strip half-width of eq. (20) is taken as ``sqrt(d^T C d) + |c3| delta_alpha``: the
    printed eq. (20) puts ``|c3| delta_alpha`` under the square root, which is not a bound of
    ``|e_k|`` (the two error terms add).

    References
    ----------
    .. [HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
       on an angle measurement technique", IFAC, 1996.

    Examples
    --------
    One dead-reckoning step of 0.5 m, then the bearing of landmark 1:

    >>> from optbound.localization.landmark_map import LandmarkMap
    >>> L = np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]])
    >>> start = np.array([1.0, 1.0, 0.2])
    >>> tracker = SetTracker(Ellipsoid(start, np.diag([0.01, 0.01, 0.001])), LandmarkMap(L), 0.01)
    >>> _ = tracker.predict([0.5, 0.0, 0.0], np.diag([1e-3, 1e-3, 1e-4]))
    >>> truth = start + [0.5 * np.cos(0.2), 0.5 * np.sin(0.2), 0.0]
    >>> alpha = np.arctan2(L[1, 1] - truth[1], L[1, 0] - truth[0]) - truth[2]
    >>> tracker.update(alpha, 1).case
    'consistent'
    >>> bool(pose_level(tracker.set, truth) <= 1)
    True
    """

    def __init__(
        self,
        initial: Ellipsoid,
        landmark_map: LandmarkMap,
        delta_alpha: float,
        criterion: str = "projection",
        relinearize: int = 0,
    ):
        if not isinstance(initial, Ellipsoid) or initial.dim != 3:
            raise TypeError("initial must be a 3-D Ellipsoid of (x, y, psi)")
        if not isinstance(landmark_map, LandmarkMap):
            raise TypeError(f"landmark_map must be a LandmarkMap, got {type(landmark_map)}")
        if criterion not in CRITERIA:
            raise ValueError(f"criterion must be one of {CRITERIA}, got {criterion!r}")
        if int(relinearize) != relinearize or relinearize < 0:
            raise ValueError(f"relinearize must be a non-negative integer, got {relinearize}")
        self.set = initial
        self.map = landmark_map
        self.delta_alpha = as_bound("delta_alpha", delta_alpha)
        self.criterion = criterion
        self.relinearize = int(relinearize)

    def predict(self, odometry, odometry_shape) -> Ellipsoid:
        """Propagate the set by one dead-reckoning step [HS96, eqs. (9)-(14)].

        Parameters
        ----------
        odometry : array_like, shape (3,)
            Nominal relative motion ``(dx, dy, dpsi)`` in the robot frame at the previous pose
            (the centre of Omega^Delta, [HS96, eq. (8)]).
        odometry_shape : array_like, shape (3, 3)
            Shape matrix ``C^Delta`` of the dead-reckoning set (positive definite).

        Returns
        -------
        Ellipsoid
            The predicted set: the Schweppe outer ellipsoid, kappa by the ``tr(proj_xy) *
            proj_psi`` size [HS96, eqs. (15)-(17)], of ``J Omega^E + B Omega^Delta``, with
            ``B`` the rotation by the nominal heading [eq. (10)] and ``J`` the Jacobian
            [eq. (12)].
        """
        step = v.finite_vector("odometry", odometry, 3)
        try:
            delta = Ellipsoid(step, odometry_shape)
        except ValueError as err:
            raise ValueError(f"odometry_shape: {err}") from None
        c = self.set.center
        cos, sin = math.cos(c[2]), math.sin(c[2])
        B = np.array([[cos, -sin, 0.0], [sin, cos, 0.0], [0.0, 0.0, 1.0]])
        move = B @ delta.center
        J = np.array([[1.0, 0.0, -move[1]], [0.0, 1.0, move[0]], [0.0, 0.0, 1.0]])
        moved = self.set.affine_map(J, move + c - J @ c)  # centre c + B dz, shape J C J^T
        self.set = analytic.minkowski_sum(
            moved, delta.affine_map(B, -B @ delta.center), criterion="size_xy_psi"
        ).ellipsoid
        return self.set

    def strip(self, alpha: float, landmark: int, about: np.ndarray | None = None) -> Strip:
        """Linearized measurement strip of one bearing [HS96, eqs. (19)-(23)].

        ``|D^T z - r| <= e_max`` with ``c1 = sin(alpha + psi)``, ``c2 = cos(alpha + psi)``,
        ``c3 = c2 (x_LM - x) + c1 (y_LM - y)`` at the linearization point ``about`` (default
        the current centre), ``D = (c1, -c2, -c3)``, ``r = c1 x_LM - c2 y_LM - c3 psi``.

        Parameters
        ----------
        alpha : float
            Measured bearing [rad], relative to the robot's heading.
        landmark : int
            Index of the landmark in the map.
        about : array_like, shape (3,), optional
            Linearization point ``(x, y, psi)``; default the current centre.

        Returns
        -------
        Strip
            The strip ``|D^T z - r| <= e_max``, normalized to half-width 1.

        Raises
        ------
        ValueError
            If the strip has zero width (``delta_alpha = 0`` and a point landmark).

        Notes
        -----
        The half-width is ``e_max = sqrt(d^T C_LM d) + |c3| delta_alpha`` with
        ``d = (-c1, c2)`` (eq. (20) with the two error terms added, see the class Notes).
        """
        # Python floats: scalar arithmetic on numpy scalars costs several times more.
        x, y, psi = (self.set.center if about is None else np.asarray(about, float)).tolist()
        lx, ly = self.map.landmarks[landmark].tolist()
        c1, c2 = math.sin(alpha + psi), math.cos(alpha + psi)
        c3 = c2 * (lx - x) + c1 * (ly - y)
        (s11, s12), (s21, s22) = self.map.shapes[landmark].tolist()
        dCd = c1 * c1 * s11 - c1 * c2 * (s12 + s21) + c2 * c2 * s22  # d^T C d, d = (-c1, c2)
        e_max = math.sqrt(max(dCd, 0.0)) + abs(c3) * self.delta_alpha
        r = c1 * lx - c2 * ly - c3 * psi
        if e_max <= 0.0:
            raise ValueError("the strip has zero width: give delta_alpha > 0 or landmark shapes")
        return Strip(np.array([c1 / e_max, -c2 / e_max, -c3 / e_max]), r / e_max)

    def update(self, alpha: float, landmark: int) -> UpdateInfo:
        """Fuse one bearing ``alpha`` of landmark index ``landmark`` [HS96, eqs. (18)-(30)].

        The set becomes the member of [HS96, eq. (24)] chosen by the criterion; if the strip
        misses the set ("inconsistent", [HS96, Fig. 1 d)]) the measurement is rejected and the
        set is kept.

        Parameters
        ----------
        alpha : float
            Measured bearing [rad], relative to the robot's heading.
        landmark : int
            Index of the landmark in the map.

        Returns
        -------
        UpdateInfo
            The fusion case, consistency measure and lambda of this update.

        Raises
        ------
        TypeError
            If ``landmark`` is not an integer index.
        ValueError
            If ``alpha`` is not finite or ``landmark`` is out of range.

        Notes
        -----
        The fused set is the member ``{z : (z - c)^T C^{-1} (z - c) + lam (D^T z - r)^2 /
        e_max^2 <= 1 + lam}`` of [HS96, eqs. (24)-(25)] (computed with a certified margin by
        :func:`optbound.analytic.intersect_strip`), lam from eq. (26) (volume), eqs. (27)-(28)
        (projection) or eqs. (29)-(30) (robust).
        """
        alpha = v.finite_scalar("alpha", alpha)
        if isinstance(landmark, bool) or not isinstance(landmark, numbers.Real):
            raise TypeError(f"landmark must be an integer index, got {type(landmark).__name__}")
        if not float(landmark).is_integer() or not 0 <= landmark < self.map.size:
            raise ValueError(f"landmark must be an index in [0, {self.map.size}), got {landmark}")
        predicted = self.set
        about = predicted.center
        for _ in range(self.relinearize + 1):
            fused = analytic.intersect_strip(
                predicted,
                self.strip(alpha, int(landmark), about),
                criterion=self.criterion,
                dims=XY,
            )
            if fused.ellipsoid is None:
                break
            about = fused.ellipsoid.center
        if fused.ellipsoid is not None:
            self.set = fused.ellipsoid
        return UpdateInfo(fused.case, fused.consistency, fused.lam)


def pose_level(E: Ellipsoid, pose) -> float:
    """``E.level`` of ``pose`` with its heading taken modulo 2 pi nearest to E's centre.

    ``<= 1`` means the pose is in the posture set ``E`` of ``(x, y, psi)``: the test of
    whether a tracked set still holds the true pose.

    Parameters
    ----------
    E : Ellipsoid
        Posture set of ``(x, y, psi)``.
    pose : array_like, shape (3,)
        ``(x, y, psi)``.

    Returns
    -------
    float
        ``(p - c)^T C^{-1} (p - c)`` with the heading difference wrapped to ``[-pi, pi)``.

    Raises
    ------
    ValueError
        If ``pose`` is not three finite numbers.
    """
    pose = v.finite_vector("pose", pose, 3)
    d = np.array([pose[0], pose[1], float(wrap_angle(pose[2] - E.center[2]))])
    d[:2] -= E.center[:2]
    return float(d @ np.linalg.solve(E.shape, d))


def nearest_landmark(tracker: SetTracker, alpha: float, gate: float, seen: np.ndarray):
    """Association during tracking: the landmark of ``seen`` whose predicted bearing is nearest.

    The predicted bearing is taken from the centre of ``tracker.set``.

    Parameters
    ----------
    tracker : SetTracker
        The tracker whose set centre predicts the bearings.
    alpha : float
        Measured bearing [rad], relative to the robot's heading.
    gate : float
        Largest accepted difference [rad] between predicted and measured bearing.
    seen : numpy.ndarray of int
        Indices of the candidate landmarks.

    Returns
    -------
    int or None
        The landmark index; ``None`` when no landmark is within ``gate`` or the runner-up is
        within twice the gate (ambiguous).
    """
    x, y, psi = tracker.set.center
    lm = tracker.map.landmarks
    off = np.abs(wrap_angle(np.arctan2(lm[seen, 1] - y, lm[seen, 0] - x) - psi - alpha))
    if off.size == 0:
        return None
    order = np.argsort(off)
    if off[order[0]] > gate or (off.size > 1 and off[order[1]] < 2 * gate):
        return None
    return int(seen[order[0]])


__all__ = ["CRITERIA", "SetTracker", "UpdateInfo", "nearest_landmark", "pose_level"]
