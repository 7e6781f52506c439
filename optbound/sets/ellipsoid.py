"""Ellipsoids ``{x : (x - c)^T Q^{-1} (x - c) <= 1}`` with symmetric positive-definite Q.

The convention matches [HS96, eq. (7)] and [BH, eq. (4)]: ``shape`` is the matrix C (not its
inverse), so semi-axes are the square roots of its eigenvalues and the support function is
``c^T d + sqrt(d^T C d)``.

References
----------
[HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
on an angle measurement technique", IFAC, 1996.

[BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
bearing measurements", IEEE Transactions on Robotics and Automation, 2004.
"""

from __future__ import annotations

from functools import cached_property
from math import lgamma, log, pi

import numpy as np

from optbound._core import Box, check_ellipsoid, raise_for, real_array
from optbound._core import validate as v
from optbound.sets._triangular import lower_inverse
from optbound.sets.base import ConvexSet, QuadraticDescription


class Ellipsoid(ConvexSet):
    """Ellipsoid with centre ``center`` (n,) and shape matrix ``shape`` (n, n), SPD.

    Parameters
    ----------
    center : array_like, shape (n,)
        Centre c.
    shape : array_like, shape (n, n)
        Symmetric positive-definite shape matrix C. Asymmetry at rounding level is removed.

    Raises
    ------
    ValueError
        If either argument is non-finite, the dimensions disagree, ``shape`` is not symmetric
        positive definite, or the ellipsoid lies outside the supported domain (condition
        number, magnitudes, centre against size: see ``optbound._core.domain``).
    TypeError
        If an argument is complex or not numeric.

    Examples
    --------
    >>> from optbound.sets import Ellipsoid
    >>> E = Ellipsoid([0.0, 0.0], [[4.0, 0.0], [0.0, 1.0]])
    >>> E.semi_axes().tolist()
    [1.0, 2.0]
    >>> E.contains([[1.9, 0.0], [0.0, 1.1]]).tolist()
    [True, False]
    >>> E.extent([1.0, 0.0])
    (-2.0, 2.0)
    """

    def __init__(self, center, shape):
        c = real_array("center", center)
        C = real_array("shape", shape)
        if c.ndim != 1 or c.size == 0:
            raise ValueError(f"center must be a non-empty 1-D vector, got shape {c.shape}")
        n = c.shape[0]
        if C.shape != (n, n):
            raise ValueError(f"shape must have shape {(n, n)}, got {C.shape}")
        # The stored copies, C-ordered and writable until ``_set``, are what is checked: the
        # compiled check then sees one array type whatever the input's layout and flags.
        c, C = np.array(c, order="C"), np.array(C, order="C")
        L = np.zeros((n, n))
        raise_for(check_ellipsoid(c, C, L), "center", "shape")
        if not np.array_equal(C, C.T):  # asymmetry at rounding level: symmetrize, refactor
            C = 0.5 * (C + C.T)
            raise_for(check_ellipsoid(c, C, L), "center", "shape")
        self._set(c, C, L)

    def _set(self, center: np.ndarray, shape: np.ndarray, chol: np.ndarray) -> None:
        self._center, self._shape, self._chol = center, shape, chol
        for arr in (center, shape, chol):
            arr.setflags(write=False)

    @classmethod
    def _trusted(cls, center: np.ndarray, shape: np.ndarray, chol: np.ndarray) -> Ellipsoid:
        """Wrap arrays already validated by ``check_ellipsoid`` (the analytic kernels' fast path:
        they validate their outputs in the same compiled pass that computes them)."""
        E = cls.__new__(cls)
        E._set(center, shape, chol)
        return E

    @classmethod
    def _from_kernel(cls, center, shape, chol, status: int) -> Ellipsoid:
        """An analytic kernel's output: wrapped as is when the kernel's own ``check_ellipsoid``
        passed (``status == 0``), else through ``__init__`` (which raises the precise error)."""
        return cls._trusted(center, shape, chol) if status == 0 else cls(center, shape)

    @classmethod
    def _from_floats(cls, center: np.ndarray, shape: np.ndarray) -> Ellipsoid:
        """The checks of ``__init__`` for float64 arrays of matching shapes built by our own
        code (e.g. from a solver's answer), in one compiled pass without conversions; any
        failure goes through ``__init__`` for its error message."""
        shape = 0.5 * (shape + shape.T)
        L = np.zeros_like(shape)
        if check_ellipsoid(center, shape, L) != 0:
            return cls(center, shape)
        return cls._trusted(center, shape, L)

    # ----------------------------------------------------------------- basic attributes
    @property
    def center(self) -> np.ndarray:
        return self._center

    @property
    def shape(self) -> np.ndarray:
        return self._shape

    @property
    def chol(self) -> np.ndarray:
        """Lower Cholesky factor L with ``shape = L L^T`` (maps the unit ball onto the set)."""
        return self._chol

    @property
    def dim(self) -> int:
        return self._center.shape[0]

    @cached_property
    def chol_inv(self) -> np.ndarray:
        """``L^{-1}``: maps the set onto the unit ball (computed once, then reused)."""
        return lower_inverse(self._chol)

    @cached_property
    def shape_inv(self) -> np.ndarray:
        """Inverse shape matrix ``C^{-1}`` (the quadratic form's matrix)."""
        return self.chol_inv.T @ self.chol_inv

    def __repr__(self) -> str:
        return f"Ellipsoid(center={self._center.tolist()}, shape={self._shape.tolist()})"

    # ----------------------------------------------------------------------- size
    def log_volume(self) -> float:
        """Natural log of the n-dimensional volume (stable for tiny or huge ellipsoids).

        Returns
        -------
        float
            ``log vol(unit ball) + sum(log diag L)``, i.e. ``log(vol(unit ball) sqrt(det C))``.
        """
        n = self.dim
        log_unit_ball = 0.5 * n * log(pi) - lgamma(0.5 * n + 1.0)
        return log_unit_ball + float(np.sum(np.log(np.diag(self._chol))))

    def volume(self) -> float:
        """The n-dimensional volume ``vol(unit ball) * sqrt(det C)``.

        Returns
        -------
        float
            The volume, ``exp(log_volume())`` (may underflow to 0 or overflow to inf).
        """
        return float(np.exp(self.log_volume()))

    def semi_axes(self) -> np.ndarray:
        """Semi-axis lengths in ascending order (square roots of the eigenvalues of C).

        Returns
        -------
        ndarray, shape (n,)
            The semi-axis lengths, ascending.
        """
        return np.sqrt(np.linalg.eigvalsh(self._shape))

    # ----------------------------------------------------------------- membership
    def level(self, X) -> np.ndarray | float:
        """Quadratic form ``(x - c)^T C^{-1} (x - c)`` per row of X (<= 1 means inside).

        Parameters
        ----------
        X : array_like, shape (m, n) or (n,)
            Points, one per row; a single point gives a float.

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
        # One cached triangular inverse, then a plain product: a LAPACK call per query costs
        # more than the arithmetic for the small dimensions used here.
        w = self.chol_inv @ (pts - self._center).T
        q = np.einsum("ij,ij->j", w, w)
        return float(q[0]) if single else q

    def contains(self, X, tol: float = 1e-9) -> np.ndarray | bool:
        """Membership test ``level(x) <= 1 + tol`` per row of X (a float64 test, not a proof).

        Parameters
        ----------
        X : array_like, shape (m, n) or (n,)
            Points, one per row; a single point gives a bool.
        tol : float, default 1e-9
            Slack on the level so that boundary points pass.

        Returns
        -------
        ndarray of bool, shape (m,), or bool
            True where the point is inside.

        Raises
        ------
        ValueError
            If ``X`` is non-finite or its dimension is not ``dim``.
        """
        q = self.level(X)
        inside = np.asarray(q) <= 1.0 + tol
        return bool(inside) if np.ndim(q) == 0 else inside

    def support(self, d) -> np.ndarray | float:
        """Support function ``h(d) = c^T d + sqrt(d^T C d)`` per row of d.

        Parameters
        ----------
        d : array_like, shape (m, n) or (n,)
            Directions, one per row; a single direction gives a float.

        Returns
        -------
        ndarray, shape (m,), or float
            ``max {d^T x : x in the ellipsoid}`` per direction.

        Raises
        ------
        ValueError
            If ``d`` is non-finite or its dimension is not ``dim``.
        """
        dirs, single = v.points("d", d, self.dim)
        h = dirs @ self._center + np.sqrt(np.einsum("ij,jk,ik->i", dirs, self._shape, dirs))
        return float(h[0]) if single else h

    def extent(self, a) -> tuple[float, float]:
        """Range ``[c^T a - sqrt(a^T C a), c^T a + sqrt(a^T C a)]`` of ``a^T x``.

        Parameters
        ----------
        a : array_like, shape (n,)
            Direction of the linear functional.

        Returns
        -------
        tuple of float
            ``(min a^T x, max a^T x)`` over the ellipsoid.

        Raises
        ------
        ValueError
            If ``a`` is non-finite or its length is not ``dim``.
        """
        return self._extent(v.finite_vector("a", a, self.dim))

    def _extent(self, a: np.ndarray) -> tuple[float, float]:
        """``extent`` of a finite float64 ``a`` of length ``dim`` (unchecked)."""
        mid, half = float(a @ self._center), float(np.sqrt(a @ self._shape @ a))
        return mid - half, mid + half

    # ------------------------------------------------------------- the SDP protocol
    def quadratic_description(self) -> QuadraticDescription:
        """One form, ``(x - c)^T C^{-1} (x - c) - 1 <= 0`` (``QuadraticSet.from_ellipsoid``).

        Returns
        -------
        QuadraticDescription
            The ellipsoid exactly, as one quadratic form and no linear range.
        """
        from optbound.sets.quadratic import QuadraticSet  # quadratic.py imports this module

        return QuadraticDescription(forms=(QuadraticSet.from_ellipsoid(self),))

    def enclosing_ellipsoid(self) -> Ellipsoid:
        """The ellipsoid itself.

        Returns
        -------
        Ellipsoid
            ``self``.
        """
        return self

    # ---------------------------------------------------------------- operations
    def project(self, dims) -> Ellipsoid:
        """Orthogonal projection onto the coordinates ``dims`` (a sub-block of C).

        Parameters
        ----------
        dims : sequence of int
            Distinct coordinate indices to keep, in the order wanted.

        Returns
        -------
        Ellipsoid
            The projection, of dimension ``len(dims)``.

        Raises
        ------
        ValueError
            If ``dims`` is empty, repeats an index or indexes outside ``range(dim)``.
        """
        idx = v.dims_index("dims", dims, self.dim)
        return Ellipsoid(self._center[idx], self._shape[np.ix_(idx, idx)])

    def affine_map(self, A, t=None) -> Ellipsoid:
        """Image ``{A x + t}``; A must have full row rank so that the image is an ellipsoid.

        The image has centre ``A c + t`` and shape ``A C A^T``.

        Parameters
        ----------
        A : array_like, shape (k, n)
            Linear map, full row rank.
        t : array_like, shape (k,), optional
            Translation (zero if omitted).

        Returns
        -------
        Ellipsoid
            The image, of dimension k.

        Raises
        ------
        ValueError
            If ``A`` or ``t`` is non-finite or mis-shaped, or ``A`` has not full row rank
            (the image would be degenerate).
        """
        A = v.finite_matrix("A", A, (None, self.dim))
        t = np.zeros(A.shape[0]) if t is None else v.finite_vector("t", t, A.shape[0])
        shape = A @ self._shape @ A.T
        try:
            return Ellipsoid(A @ self._center + t, shape)
        except ValueError:
            raise ValueError(
                "A must have full row rank: the image is a degenerate ellipsoid"
            ) from None

    def scaled(self, factor: float) -> Ellipsoid:
        """Same centre, every semi-axis multiplied by ``factor`` > 0.

        Parameters
        ----------
        factor : float
            Positive scale of the semi-axes (the shape matrix is scaled by ``factor**2``).

        Returns
        -------
        Ellipsoid
            The scaled ellipsoid.

        Raises
        ------
        ValueError
            If ``factor`` is not a positive finite number, or the scaled ellipsoid leaves the
            supported domain.
        """
        factor = v.finite_scalar("factor", factor)
        if factor <= 0:
            raise ValueError(f"factor must be positive, got {factor}")
        with np.errstate(over="ignore", under="ignore"):
            shape = self._shape * factor * factor
        try:
            # Float64 arrays of matching shapes: the checks of ``__init__`` without conversions.
            # A writable centre: the compiled check's array type for new ellipsoids.
            return Ellipsoid._from_floats(self._center.copy(), shape)
        except ValueError as err:
            raise ValueError(
                f"factor={factor} takes the ellipsoid out of the domain: {err}"
            ) from None

    def bounding_box(self) -> Box:
        """Tightest axis-aligned box: half-widths ``sqrt(diag C)``.

        Returns
        -------
        Box
            ``[c - sqrt(diag C), c + sqrt(diag C)]``.
        """
        half = np.sqrt(np.diag(self._shape))
        return Box(self._center - half, self._center + half)

    # ------------------------------------------------------------------- points
    def sample(self, m: int, rng) -> np.ndarray:
        """``m`` points uniformly distributed in the ellipsoid, shape (m, n).

        Uniform in the unit ball (Gaussian direction, radius ``U^{1/n}``), mapped by L.

        Parameters
        ----------
        m : int
            Number of points.
        rng : numpy.random.Generator or int
            Random generator or integer seed (None is refused: results must be seeded).

        Returns
        -------
        ndarray, shape (m, n)
            The sampled points.
        """
        gen = v.rng_of(rng)
        n = self.dim
        g = gen.standard_normal((m, n))
        g /= np.linalg.norm(g, axis=1, keepdims=True)
        r = gen.random(m) ** (1.0 / n)
        return self._center + (g * r[:, None]) @ self._chol.T

    def sample_boundary(self, m: int, rng) -> np.ndarray:
        """``m`` points on the boundary surface (uniform on the unit sphere, then mapped).

        Parameters
        ----------
        m : int
            Number of points.
        rng : numpy.random.Generator or int
            Random generator or integer seed (None is refused: results must be seeded).

        Returns
        -------
        ndarray, shape (m, n)
            Points with ``level == 1`` up to rounding.
        """
        gen = v.rng_of(rng)
        g = gen.standard_normal((m, self.dim))
        g /= np.linalg.norm(g, axis=1, keepdims=True)
        return self._center + g @ self._chol.T

    def boundary(self, m: int = 200) -> np.ndarray:
        """``m`` points tracing the boundary of a 2-D ellipse in order (for plotting).

        Parameters
        ----------
        m : int, default 200
            Number of points; the first and last coincide (a closed curve).

        Returns
        -------
        ndarray, shape (m, 2)
            The boundary points, counter-clockwise.

        Raises
        ------
        ValueError
            If the ellipsoid is not 2-D.
        """
        if self.dim != 2:
            raise ValueError(f"boundary() is for 2-D ellipsoids, this one has dim {self.dim}")
        t = np.linspace(0.0, 2.0 * np.pi, m)
        circle = np.column_stack([np.cos(t), np.sin(t)])
        return self._center + circle @ self._chol.T
