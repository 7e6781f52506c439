"""Quadratic sets ``{x : [x; 1]^T F [x; 1] <= 0}`` with F symmetric (n + 1) x (n + 1).

One quadratic inequality describes an ellipsoid, a strip, a half-space, the outside of a ball
(rings are the intersection of a ball with such an outside [BH, eqs. (20)-(21)]) and many more;
it is the common currency of the S-procedure [Boyd, El Ghaoui, Feron & Balakrishnan 1994,
Sect. 2.6.3]. Writing ``F = [[A, b], [b^T, c]]`` the inequality reads
``q(x) = x^T A x + 2 b^T x + c <= 0``.

The set need not be convex (``A`` may be indefinite), so this class offers the ``ConvexSet``
methods (``dim``, ``contains``, ``support``, ``extent``) without claiming convexity: its
``support`` is the support function of the closed convex hull.

References
----------
[HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
on an angle measurement technique", IFAC, 1996.

[BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
bearing measurements", IEEE Transactions on Robotics and Automation, 2004.
"""

from __future__ import annotations

import numpy as np

from optbound._core import validate as v
from optbound._core.jit import njit
from optbound.sets._triangular import lower_inverse
from optbound.sets.base import ConvexSet, EmptySetError, QuadraticDescription
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.strip import Halfspace, Strip

# Eigenvalues of A below this fraction of its largest magnitude count as zero.
_EIG_RTOL = 1e-12


# The kernels below build and test the forms of one SDP call: as numpy, each would be a few
# tiny calls whose overhead exceeds their arithmetic (``optbound/bench/sdp_cache.py``).
@njit(cache=True)
def _ellipsoid_form(center: np.ndarray, chol: np.ndarray) -> np.ndarray:
    """``[[P, -P c], [-c^T P, c^T P c - 1]]`` with ``P = C^{-1} = L^{-T} L^{-1}`` (exactly
    symmetric), for ``C = L L^T``."""
    n = center.shape[0]
    X = lower_inverse(chol)
    F = np.empty((n + 1, n + 1))
    for i in range(n):
        for j in range(i + 1):
            total = 0.0  # X is lower triangular; in order from 0.0, as np.sum of the products
            for p in range(i, n):
                total += X[p, i] * X[p, j]
            F[i, j] = F[j, i] = total
    offset = -1.0
    for i in range(n):
        Pc = 0.0
        for j in range(n):
            Pc += F[i, j] * center[j]
        F[i, n] = F[n, i] = -Pc
        offset += center[i] * Pc
    F[n, n] = offset
    return F


@njit(cache=True)
def _bounds_form(a: np.ndarray, lo: float, hi: float) -> np.ndarray:
    """``[[a a^T, -(lo + hi) a / 2], [-(lo + hi) a^T / 2, lo hi]]``."""
    n = a.shape[0]
    F = np.empty((n + 1, n + 1))
    mid = -0.5 * (lo + hi)
    for i in range(n):
        for j in range(n):
            F[i, j] = a[i] * a[j]
        F[i, n] = F[n, i] = mid * a[i]
    F[n, n] = lo * hi
    return F


@njit(cache=True)
def _positive_definite_part(F: np.ndarray, rtol: float) -> bool:
    """Whether the smallest eigenvalue of ``A = F[:-1, :-1]`` exceeds ``rtol max |F|`` (the
    maximum taken in a loop: numba's ``np.max`` would be one more compiled helper)."""
    n = F.shape[0] - 1
    A = np.empty((n, n))  # copied in loops (no slice copy)
    top = 0.0
    for i in range(n + 1):
        for j in range(n + 1):
            top = max(top, abs(F[i, j]))
            if i < n and j < n:
                A[i, j] = F[i, j]
    return np.linalg.eigvalsh(A)[0] > rtol * top


class QuadraticSet:
    """The set ``{x : [x; 1]^T F [x; 1] <= 0}`` for a symmetric, non-zero F.

    Parameters
    ----------
    F : array_like, shape (n + 1, n + 1)
        Symmetric matrix ``[[A, b], [b^T, c]]``; asymmetry at rounding level is removed.

    Raises
    ------
    ValueError
        If ``F`` is non-finite, not square, smaller than 2 x 2, not symmetric, or zero.

    Examples
    --------
    The unit disc ``x^T x - 1 <= 0``:

    >>> import numpy as np
    >>> from optbound.sets import QuadraticSet
    >>> q = QuadraticSet.from_parts(np.eye(2), [0.0, 0.0], -1.0)
    >>> q.contains([[0.5, 0.5], [1.0, 1.0]]).tolist()
    [True, False]
    >>> q.support([1.0, 0.0])
    1.0
    >>> q.as_ellipsoid().shape.tolist()
    [[1.0, 0.0], [0.0, 1.0]]
    """

    def __init__(self, F):
        F = v.finite_matrix("F", F)
        if F.shape[0] != F.shape[1] or F.shape[0] < 2:
            raise ValueError(f"F must be square of size n + 1 >= 2, got shape {F.shape}")
        if not np.any(F):
            raise ValueError("F must not be zero")
        self._F = v.symmetric_matrix("F", F)
        self._F.setflags(write=False)
        self._ellipsoid: Ellipsoid | None = None

    @classmethod
    def _trusted(cls, F: np.ndarray) -> QuadraticSet:
        """Wrap an F that a constructor below assembled from validated parts: finite, exactly
        symmetric and non-zero by construction, so ``__init__``'s checks are skipped."""
        q = cls.__new__(cls)
        F.setflags(write=False)
        q._F, q._ellipsoid = F, None
        return q

    # ------------------------------------------------------------------ constructors
    @classmethod
    def from_parts(cls, A, b, c: float) -> QuadraticSet:
        """Assemble ``F = [[A, b], [b^T, c]]``, i.e. ``x^T A x + 2 b^T x + c <= 0``.

        Parameters
        ----------
        A : array_like, shape (n, n)
            Symmetric quadratic part.
        b : array_like, shape (n,)
            Linear part (half the gradient at 0).
        c : float
            Constant.

        Returns
        -------
        QuadraticSet
            The set.

        Raises
        ------
        ValueError
            As for the constructor (the assembled F is checked).
        """
        A = np.asarray(A, dtype=float)
        b = np.asarray(b, dtype=float)
        return cls(np.block([[A, b[:, None]], [b[None, :], np.array([[float(c)]])]]))

    @classmethod
    def from_ellipsoid(cls, E: Ellipsoid) -> QuadraticSet:
        """``(x - c)^T C^{-1} (x - c) - 1 <= 0``.

        Parameters
        ----------
        E : Ellipsoid
            The ellipsoid.

        Returns
        -------
        QuadraticSet
            The ellipsoid as one quadratic form (``as_ellipsoid`` returns ``E``).
        """
        q = cls._trusted(_ellipsoid_form(E.center, E.chol))
        q._ellipsoid = E  # the validated original, returned by ``as_ellipsoid``
        return q

    @classmethod
    def from_bounds(cls, a, lo: float, hi: float) -> QuadraticSet:
        """Product form ``(a^T x - lo)(a^T x - hi) <= 0`` of ``lo <= a^T x <= hi``.

        For ``Strip(a, b)`` (lo, hi = b -+ 1) this is the same polynomial as
        ``(a^T x - b)^2 - 1 <= 0`` [HS96, eq. (23)], so the two forms are one quadratic.

        Parameters
        ----------
        a : array_like, shape (n,)
            Non-zero direction.
        lo, hi : float
            Bounds of ``a^T x``, ``lo <= hi``.

        Returns
        -------
        QuadraticSet
            The product form.

        Raises
        ------
        ValueError
            If an argument is non-finite, ``a`` is zero, or ``lo > hi``.
        """
        a = v.finite_vector("a", a)
        lo, hi = v.finite_scalar("lo", lo), v.finite_scalar("hi", hi)
        if not lo <= hi:
            raise ValueError(f"lo must be <= hi, got lo={lo}, hi={hi}")
        if not np.any(a):
            raise ValueError("a must be a non-zero vector")
        return cls._from_valid_bounds(a, lo, hi)

    @classmethod
    def _from_valid_bounds(cls, a: np.ndarray, lo: float, hi: float) -> QuadraticSet:
        """``from_bounds`` for a finite non-zero float64 ``a`` and finite ``lo <= hi`` that
        the caller has validated (e.g. a clipped ``Strip``). ``a`` is passed to the compiled
        form as a C-ordered writable copy, one array type whatever the caller's flags."""
        F = _bounds_form(np.array(a, order="C"), lo, hi)
        # Finite inputs can still overflow (lo * hi): then the checking constructor refuses F.
        return cls._trusted(F) if np.isfinite(F).all() else cls(F)

    @classmethod
    def from_strip(cls, S: Strip) -> QuadraticSet:
        """``(a^T x - b)^2 - 1 <= 0`` [HS96, eq. (23)].

        Parameters
        ----------
        S : Strip
            The strip.

        Returns
        -------
        QuadraticSet
            The strip as one quadratic form.
        """
        return cls.from_bounds(S.a, S.b - 1.0, S.b + 1.0)

    @classmethod
    def from_halfspace(cls, H: Halfspace) -> QuadraticSet:
        """The affine form ``a^T x - b <= 0`` (A = 0).

        Parameters
        ----------
        H : Halfspace
            The half-space.

        Returns
        -------
        QuadraticSet
            The half-space as one (affine) form.
        """
        return cls.from_parts(np.zeros((H.dim, H.dim)), 0.5 * H.a, -H.b)

    # --------------------------------------------------------------------- attributes
    @property
    def F(self) -> np.ndarray:
        return self._F

    @property
    def dim(self) -> int:
        return self._F.shape[0] - 1

    @property
    def A(self) -> np.ndarray:
        return self._F[:-1, :-1]

    @property
    def b(self) -> np.ndarray:
        return self._F[:-1, -1]

    @property
    def c(self) -> float:
        return float(self._F[-1, -1])

    def __repr__(self) -> str:
        return f"QuadraticSet(F={self._F.tolist()})"

    # --------------------------------------------------------------------- membership
    def value(self, X) -> np.ndarray | float:
        """``q(x) = [x; 1]^T F [x; 1]`` per row of X (<= 0 means inside).

        Parameters
        ----------
        X : array_like, shape (m, n) or (n,)
            Points, one per row; a single point gives a scalar.

        Returns
        -------
        ndarray, shape (m,), or float
            The value of the form per point.

        Raises
        ------
        ValueError
            If ``X`` is non-finite or its dimension is not ``dim``.
        """
        pts, single = v.points("X", X, self.dim)
        q = np.einsum("ij,jk,ik->i", pts, self.A, pts) + 2.0 * pts @ self.b + self.c
        return float(q[0]) if single else q

    def contains(self, X, tol: float = 1e-9) -> np.ndarray | bool:
        """Membership per row; ``tol`` is relative to ``|[x;1]|^T |F| |[x;1]|``.

        Parameters
        ----------
        X : array_like, shape (m, n) or (n,)
            Points, one per row; a single point gives a scalar.
        tol : float, default 1e-9
            Relative slack: inside when ``q(x) <= tol |[x;1]|^T |F| |[x;1]|``.

        Returns
        -------
        ndarray of bool, shape (m,), or bool
            True where the point is inside (a float test).

        Raises
        ------
        ValueError
            If ``X`` is non-finite or its dimension is not ``dim``.
        """
        pts, single = v.points("X", X, self.dim)
        lifted = np.abs(np.column_stack([pts, np.ones(pts.shape[0])]))
        scale = np.einsum("ij,jk,ik->i", lifted, np.abs(self._F), lifted)
        inside = np.asarray(self.value(pts)) <= tol * scale
        return bool(inside[0]) if single else inside

    # --------------------------------------------------------------------- geometry
    def as_ellipsoid(self) -> Ellipsoid | None:
        """The set as an ``Ellipsoid`` when A is positive definite (None if it is empty).

        ``q(x) = (x - x0)^T A (x - x0) - r`` with ``x0 = -A^{-1} b`` and
        ``r = b^T A^{-1} b - c``, so the shape matrix is ``r A^{-1}``.

        Returns
        -------
        Ellipsoid or None
            The ellipsoid with centre ``x0`` and shape ``r A^{-1}``; None if r < 0 (empty).

        Raises
        ------
        ValueError
            If A is not positive definite or the set is a single point (r = 0).
        """
        if self._ellipsoid is not None:  # built by ``from_ellipsoid``
            return self._ellipsoid
        _, chol = v.spd_matrix("A (quadratic part of F)", self.A)
        x0 = -np.linalg.solve(self.A, self.b)
        w = np.linalg.solve(chol, self.b)
        r = float(w @ w - self.c)
        if r < 0:
            return None
        if r == 0:
            raise ValueError(
                "the quadratic set is a single point, not a full-dimensional ellipsoid"
            )
        return Ellipsoid(x0, r * np.linalg.inv(self.A))

    # -------------------------------------------------------------- the SDP protocol
    def quadratic_description(self) -> QuadraticDescription:
        """The set's own form, used as it is.

        Returns
        -------
        QuadraticDescription
            One form, ``self``, and no linear range.
        """
        return QuadraticDescription(forms=(self,))

    def enclosing_ellipsoid(self) -> Ellipsoid | None:
        """The set as an ellipsoid when A is positive definite (``as_ellipsoid``), else None.

        Returns
        -------
        Ellipsoid or None
            The set itself as an ellipsoid, or None if it is unbounded.

        Raises
        ------
        EmptySetError
            If A is positive definite and the set is empty.
        """
        if not self.is_bounded:
            return None
        ellipsoid = self.as_ellipsoid()
        if ellipsoid is None:
            raise EmptySetError(f"the quadratic set {self!r} is empty")
        return ellipsoid

    def support(self, d) -> np.ndarray | float:
        """Support function of the set's closed convex hull, ``max {d^T x : q(x) <= 0}``.

        One quadratic constraint has no duality gap (S-lemma, Slater point assumed; Boyd &
        Vandenberghe, App. B.1), so ``h(d) = min_{mu >= 0} g(mu)`` with the dual function
        ``g(mu) = sup_x d^T x - mu q(x)``. In the eigenbasis ``A = V diag(w) V^T``
        (``e = V^T d``, ``f = V^T b``) it separates:
        ``g(mu) = sum_{w_j > 0} (e_j - 2 mu f_j)^2 / (4 mu w_j) - mu c``, finite only if
        ``e_j = 2 mu f_j`` wherever ``w_j = 0`` and no ``w_j`` is negative.

        - any ``w_j < 0``: the set is unbounded along that eigenvector in both senses, and
          the convex hull is all of R^n: ``+inf``;
        - ``f_j = 0`` on the zero eigenvalues (ellipsoid, cylinder, strip): ``d`` must vanish
          there, then ``g = alpha / mu - beta + gamma mu`` is minimised in closed form;
        - otherwise (paraboloid, half-space) ``mu`` is pinned to ``e_j / (2 f_j)``.

        An empty set gives ``-inf``.

        Parameters
        ----------
        d : array_like, shape (m, n) or (n,)
            Directions, one per row; a single direction gives a float.

        Returns
        -------
        ndarray, shape (m,), or float
            ``h(d)`` per direction (``+inf`` where unbounded, ``-inf`` if empty).

        Raises
        ------
        ValueError
            If ``d`` is non-finite or its dimension is not ``dim``.
        """
        dirs, single = v.points("d", d, self.dim)
        w, V = np.linalg.eigh(self.A)
        tol = _EIG_RTOL * max(float(np.max(np.abs(w))), float(np.max(np.abs(self._F))))
        E, f = dirs @ V, V.T @ self.b
        h = np.array([self._support_eig(e, w, f, tol) for e in E])
        return float(h[0]) if single else h

    def _support_eig(self, e: np.ndarray, w: np.ndarray, f: np.ndarray, tol: float) -> float:
        """``h(d)`` for one direction in A's eigenbasis (see ``support``)."""
        if np.any(w < -tol):
            return np.inf
        pos, zero = w > tol, w <= tol
        dtol = tol * max(1.0, float(np.max(np.abs(e))))
        if np.all(np.abs(f[zero]) <= tol):
            if np.any(np.abs(e[zero]) > dtol):
                return np.inf
            alpha = float(np.sum(e[pos] ** 2 / (4.0 * w[pos])))
            beta = float(np.sum(e[pos] * f[pos] / w[pos]))
            gamma = float(np.sum(f[pos] ** 2 / w[pos])) - self.c
            if gamma < 0:
                return -np.inf
            return 2.0 * np.sqrt(alpha * gamma) - beta
        # Zero eigen-directions with a linear term pin the multiplier: e_Z = 2 mu f_Z.
        fz, ez = f[zero], e[zero]
        k = int(np.argmax(np.abs(fz)))
        mu = ez[k] / (2.0 * fz[k])
        if mu <= 0 or np.any(np.abs(ez - 2.0 * mu * fz) > dtol):
            return np.inf
        return float(np.sum((e[pos] - 2.0 * mu * f[pos]) ** 2 / (4.0 * mu * w[pos])) - mu * self.c)

    # Only support is needed, so the convex sets' extent applies unchanged.
    extent = ConvexSet.extent

    @property
    def is_bounded(self) -> bool:
        """True when A is positive definite (then the set is an ellipsoid, a point or empty)."""
        return bool(_positive_definite_part(self._F, _EIG_RTOL))
