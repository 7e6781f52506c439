"""Certified affine image of an ellipsoid: ``{A x + t : x in E}`` as floats that contain it.

The exact image of ``E(c, C)`` is ``E(A c + t, A C A^T)``. The float product rounds, so the
centre and shape are enclosed in outward-rounded interval arithmetic
(``optbound.sets.certified.matmul``) and the rounded member is inflated by the certified
margin of ``optbound.analytic._kernels.midrad.inflate`` (Weyl for the shape radii,
Schweppe's segment bound for the centre radii). A rank-deficient ``A`` (a flat image) is
widened to the supported domain's condition number (``midrad.inflate`` never refuses a
near-degenerate result), so the result is always a full-dimensional outer ellipsoid.
"""

from __future__ import annotations

import numpy as np

from optbound._core import check_ellipsoid
from optbound._core import validate as v
from optbound.analytic._kernels.midrad import inflate
from optbound.sets.certified import magnitude, matmul, point
from optbound.sets.ellipsoid import Ellipsoid


def affine_map(E: Ellipsoid, A, t=None) -> Ellipsoid:
    """An ellipsoid containing ``{A x + t : x in E}`` exactly (floats read as exact numbers).

    Parameters
    ----------
    E : Ellipsoid
        The set mapped, dimension n.
    A : array_like, shape (m, n)
        The linear part (any rank; a flat image is widened, module docstring).
    t : array_like, shape (m,), optional
        The offset (default 0).

    Returns
    -------
    Ellipsoid
        ``E(c, T)`` with ``c`` the rounded image centre and ``T >= A C A^T`` inflated by the
        certified margin; ``Ellipsoid.affine_map`` is the plain float image.

    Raises
    ------
    TypeError
        ``E`` not an Ellipsoid.
    ValueError
        Non-finite or mis-shaped ``A`` / ``t``, or an image outside the supported domain.

    Examples
    --------
    Swapping the coordinates and shifting: the image's shape is ``A C A^T``, enlarged by a
    certified margin of a few rounding units.

    >>> import numpy as np
    >>> from optbound.analytic.affine import affine_map
    >>> from optbound.sets import Ellipsoid
    >>> E = Ellipsoid([1.0, 2.0], np.diag([4.0, 1.0]))
    >>> F = affine_map(E, [[0.0, 1.0], [1.0, 0.0]], [1.0, 0.0])
    >>> np.round(F.center, 12).tolist(), np.round(F.shape, 9).tolist()
    ([3.0, 1.0], [[1.0, 0.0], [0.0, 4.0]])
    """
    if not isinstance(E, Ellipsoid):
        raise TypeError(f"E must be an Ellipsoid, got {type(E).__name__}")
    A = v.finite_matrix("A", A, (None, E.dim))
    m = A.shape[0]
    t = np.zeros(m) if t is None else v.finite_vector("t", t, m)
    c_iv = matmul(A, E.center[:, None])[:, 0] + point(t)
    S_iv = matmul(matmul(A, E.shape), point(A.T))
    c = c_iv.midpoint()
    S = np.tril(S_iv.midpoint())
    S = S + np.tril(S, -1).T
    D = magnitude(S_iv - S)
    d = magnitude(c_iv - c)
    T, L = np.empty((m, m)), np.empty((m, m))
    if inflate(S, D, c, d, T, L) < 0 or check_ellipsoid(c, T, L) != 0:
        raise ValueError("the image of E under A lies outside the supported domain")
    return Ellipsoid._trusted(c, T, L)
