"""Polynomial liftings ``T : R^n -> R^L`` given by monomials [BH, eq. (9)].

A lifting maps a point ``x`` to ``T(x) = p(u)`` with ``u = (x - offset) / scale`` and each
component ``p_l(u) = sum_k coef[l, k] u^{e_k}`` a polynomial over the shared monomials
``u^{e_k} = prod_j u_j^{e_kj}``. The L = 4 map ``[x, y, x^2, y^2]`` of [BH, eq. (22)] and the
L = 8 map of [BH, eq. (23)] are instances (:meth:`PolynomialLifting.bh4`,
:meth:`PolynomialLifting.bh8`).

Why the affine pre-map ``u = (x - offset) / scale``: the lifted filter runs in floating point
with monomials up to degree 4, and coordinates of size ``|x| ~ 10`` give lifted entries of
size ``10^4`` beside entries of size 10, which makes the lifted shape matrices
ill-conditioned ("BH filter numerics" in the documentation's *Guarantees and numerics* page).
Centring and scaling
the plane first keeps every monomial of order one. The span of the BH monomials (with 1) is
closed under translations and scalings, so nothing is lost.

One formula serves points and boxes: :meth:`PolynomialLifting.components` takes the
coordinates as float arrays or as :class:`~optbound.interval.Interval` arrays (outward-rounded
interval arithmetic), so the image of a box is a guaranteed enclosure.

References
----------
[BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
bearing measurements", IEEE Transactions on Robotics and Automation, 2004.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

from optbound._core import box_array
from optbound._core import validate as v


class PolynomialLifting:
    """The lifting ``T(x) = coef @ [u^{e_k}]_k`` with ``u = (x - offset) / scale``.

    Parameters
    ----------
    exponents : array_like of int, shape (K, n)
        Non-negative exponents of the K monomials.
    coefficients : array_like, shape (L, K)
        Each row is one component of T; no row may be zero.
    offset : array_like, shape (n,), optional
        Centre of the normalization (default 0).
    scale : float, optional
        Positive length of the normalization (default 1).

    Raises
    ------
    ValueError
        Negative or non-integer exponents, a zero component, non-finite values, a
        non-positive scale or mismatched dimensions.

    Examples
    --------
    >>> import numpy as np
    >>> from optbound.sets.lifting import PolynomialLifting
    >>> T = PolynomialLifting.bh4()  # [x, y, x^2, y^2] [BH, eq. (22)]
    >>> T([2.0, 3.0]).tolist()
    [2.0, 3.0, 4.0, 9.0]
    >>> image = T.box_image([[[1.0, 2.0], [-1.0, 1.0]]])[0]  # rounded outward
    >>> np.round(image, 12).tolist()
    [[1.0, 2.0], [-1.0, 1.0], [1.0, 4.0], [0.0, 1.0]]
    """

    def __init__(self, exponents, coefficients, offset=None, scale: float = 1.0):
        exps = np.asarray(exponents)
        if exps.ndim != 2 or exps.size == 0 or not np.issubdtype(exps.dtype, np.integer):
            raise ValueError(f"exponents must be a (K, n) integer array, got {exponents!r}")
        if np.any(exps < 0):
            raise ValueError("exponents must be non-negative")
        coef = v.finite_matrix("coefficients", coefficients, (None, exps.shape[0]))
        if np.any(~np.any(coef != 0, axis=1)):
            raise ValueError("coefficients: every component must have a non-zero coefficient")
        n = exps.shape[1]
        self._exps = exps.astype(np.int64)
        self._coef = coef
        self._offset = np.zeros(n) if offset is None else v.finite_vector("offset", offset, n)
        self._scale = v.finite_scalar("scale", scale)
        if self._scale <= 0:
            raise ValueError(f"scale must be positive, got {self._scale}")
        for arr in (self._exps, self._coef, self._offset):
            arr.setflags(write=False)

    # ----------------------------------------------------------------------- constructors
    @classmethod
    def from_components(
        cls, components: Sequence[Mapping[tuple[int, ...], float]], offset=None, scale=1.0
    ) -> PolynomialLifting:
        """Build from one ``{exponent tuple: coefficient}`` mapping per component.

        Parameters
        ----------
        components : sequence of mapping
            Per component, its monomials' exponent tuples (length n) and coefficients.
        offset : array_like, shape (n,), optional
            Centre of the normalization (default 0).
        scale : float, default 1.0
            Positive length of the normalization.

        Returns
        -------
        PolynomialLifting
            The lifting, over the union of the components' monomials.

        Raises
        ------
        ValueError
            If ``components`` is empty, or as for the constructor.
        """
        if len(components) == 0:
            raise ValueError("components must not be empty")
        monomials = sorted({e for comp in components for e in comp})
        index = {e: k for k, e in enumerate(monomials)}
        coef = np.zeros((len(components), len(monomials)))
        for row, comp in enumerate(components):
            for e, c in comp.items():
                coef[row, index[e]] = c
        return cls(np.array(monomials, dtype=np.int64), coef, offset, scale)

    @classmethod
    def bh4(cls, offset=None, scale: float = 1.0) -> PolynomialLifting:
        """``[x, y, x^2, y^2]`` (in normalized coordinates) [BH, eq. (22)].

        Parameters
        ----------
        offset : array_like, shape (2,), optional
            Centre of the normalization (default 0).
        scale : float, default 1.0
            Positive length of the normalization.

        Returns
        -------
        PolynomialLifting
            The L = 4 lifting.
        """
        comps = [{(1, 0): 1.0}, {(0, 1): 1.0}, {(2, 0): 1.0}, {(0, 2): 1.0}]
        return cls.from_components(comps, offset, scale)

    @classmethod
    def bh8(cls, offset=None, scale: float = 1.0) -> PolynomialLifting:
        """``[x, y, xy, x^2, y^2, x^3 + x y^2, x^2 y + y^3, (x^2 + y^2)^2]`` [BH, eq. (23)].

        Parameters
        ----------
        offset : array_like, shape (2,), optional
            Centre of the normalization (default 0).
        scale : float, default 1.0
            Positive length of the normalization.

        Returns
        -------
        PolynomialLifting
            The L = 8 lifting.
        """
        comps = [
            {(1, 0): 1.0},
            {(0, 1): 1.0},
            {(1, 1): 1.0},
            {(2, 0): 1.0},
            {(0, 2): 1.0},
            {(3, 0): 1.0, (1, 2): 1.0},
            {(2, 1): 1.0, (0, 3): 1.0},
            {(4, 0): 1.0, (2, 2): 2.0, (0, 4): 1.0},
        ]
        return cls.from_components(comps, offset, scale)

    # ------------------------------------------------------------------------ attributes
    @property
    def dim(self) -> int:
        """Dimension n of the original space."""
        return self._exps.shape[1]

    @property
    def size(self) -> int:
        """Dimension L of the lifted space."""
        return self._coef.shape[0]

    @property
    def exponents(self) -> np.ndarray:
        return self._exps

    @property
    def coefficients(self) -> np.ndarray:
        return self._coef

    @property
    def offset(self) -> np.ndarray:
        return self._offset

    @property
    def scale(self) -> float:
        return self._scale

    def __repr__(self) -> str:
        return (
            f"PolynomialLifting(L={self.size}, n={self.dim}, offset={self._offset.tolist()}, "
            f"scale={self._scale})"
        )

    def identity_components(self) -> np.ndarray:
        """Index of the component equal to ``u_j`` for each j, or -1 where there is none.

        Returns
        -------
        np.ndarray of int, shape (n,)
            Component index per coordinate, -1 where none.
        """
        out = np.full(self.dim, -1)
        for j in range(self.dim):
            unit = np.zeros(self.dim, dtype=np.int64)
            unit[j] = 1
            k = np.flatnonzero(np.all(self._exps == unit, axis=1))
            if k.size == 0:
                continue
            rows = np.flatnonzero(
                (self._coef[:, k[0]] == 1.0) & (np.count_nonzero(self._coef, axis=1) == 1)
            )
            if rows.size:
                out[j] = rows[0]
        return out

    # ------------------------------------------------------------------------ evaluation
    def normalize(self, *coords) -> list:
        """``u_j = (x_j - offset_j) / scale`` for float arrays or ``Interval`` arrays.

        Parameters
        ----------
        *coords : ndarray or Interval
            One array per coordinate x_1, ..., x_n, all of one shape.

        Returns
        -------
        list
            The n normalized coordinates, of the type of the input.

        Raises
        ------
        ValueError
            If the number of coordinates is not ``dim``.
        """
        if len(coords) != self.dim:
            raise ValueError(f"expected {self.dim} coordinates, got {len(coords)}")
        return [(x - o) / self._scale for x, o in zip(coords, self._offset, strict=True)]

    def components(self, *coords) -> list:
        """The L components of T at the coordinates (float arrays or ``Interval`` arrays).

        With intervals each returned value encloses the component's range over the boxes.

        Parameters
        ----------
        *coords : ndarray or Interval
            One array per coordinate x_1, ..., x_n, all of one shape.

        Returns
        -------
        list
            The L components, floats or Intervals of the shape of the coordinates.

        Raises
        ------
        ValueError
            If the number of coordinates is not ``dim``.
        """
        return _polynomials(self._exps, self._coef, self.normalize(*coords))

    def jacobian(self, *coords) -> list[list]:
        """``dT_l / dx_j`` as a nested list ``[l][j]`` (float arrays or ``Interval`` arrays).

        Parameters
        ----------
        *coords : ndarray or Interval
            One array per coordinate x_1, ..., x_n, all of one shape.

        Returns
        -------
        list of list
            ``L`` rows of ``n`` partial derivatives (enclosures for Intervals).

        Raises
        ------
        ValueError
            If the number of coordinates is not ``dim``.
        """
        u = self.normalize(*coords)
        cols = []
        for j in range(self.dim):
            exps, coef = self._derivative(j)
            cols.append(_polynomials(exps, coef / self._scale, u))
        return [[cols[j][row] for j in range(self.dim)] for row in range(self.size)]

    def _derivative(self, j: int) -> tuple[np.ndarray, np.ndarray]:
        """Monomials and coefficients of ``dp / du_j`` (a lifting of the same length)."""
        exps = self._exps.copy()
        factor = exps[:, j].astype(float)
        exps[:, j] = np.maximum(exps[:, j] - 1, 0)
        return exps, self._coef * factor[None, :]

    def __call__(self, X) -> np.ndarray:
        """``T(x)`` for each row of ``X`` (shape (m, n) or (n,)) -> (m, L) or (L,)."""
        pts, single = v.points("X", X, self.dim)
        out = np.stack(self.components(*pts.T), axis=-1)
        return out[0] if single else out

    def box_image(self, boxes) -> np.ndarray:
        """Guaranteed enclosure of ``T(box)`` per box: (m, n, 2) boxes -> (m, L, 2).

        Parameters
        ----------
        boxes : array_like, shape (m, n, 2)
            Boxes as ``[lo, hi]`` rows per coordinate.

        Returns
        -------
        np.ndarray, shape (m, L, 2)
            ``[lo, hi]`` of each component over each box, rounded outward.

        Raises
        ------
        ValueError
            If ``boxes`` is mis-shaped, non-finite or has ``lo > hi``.
        """
        from optbound.interval import Interval  # on first use: keeps `import optbound` light

        B = box_array("boxes", boxes, self.dim)
        comps = self.components(*(Interval(B[:, j, 0], B[:, j, 1]) for j in range(self.dim)))
        return np.stack([np.stack([c.lo, c.hi], axis=-1) for c in comps], axis=1)


def _polynomials(exps: np.ndarray, coef: np.ndarray, u: list) -> list:
    """``sum_k coef[l, k] prod_j u_j^{exps[k, j]}`` per row l; one pass over the monomials."""
    monos = []
    for e in exps:
        mono = None
        for j, power in enumerate(e):
            if power == 0:
                continue
            factor = u[j] if power == 1 else u[j] ** int(power)
            mono = factor if mono is None else mono * factor
        monos.append(mono)  # None stands for the constant monomial 1
    out = []
    for row in coef:
        acc = None
        for c, mono in zip(row, monos, strict=True):
            if c == 0:
                continue
            term = c if mono is None else (mono if c == 1.0 else c * mono)
            acc = term if acc is None else acc + term
        # Constant (or zero) rows still get the shape and type of the coordinates.
        out.append(0.0 * u[0] if acc is None else acc + 0.0 * u[0] if np.isscalar(acc) else acc)
    return out
