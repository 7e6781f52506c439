"""Linear discrete-time systems with bounded noise (issue 21's setting).

``x_{k+1} = A x_k + w_k``, ``y_k = C x_k + v_k``, ``w_k in W``, ``v_k in V``. Convention: the
set ``X0`` holds ``x_0`` (no measurement at k = 0) and ``ys[k-1]`` measures ``x_k``, so
``X_k = (A X_{k-1} + W) ∩ {x : ys[k-1] - C x in V}``.
"""

from __future__ import annotations

from functools import cached_property

import numpy as np

from optbound._core import validate as v
from optbound.estimation.noise import NoiseSet, as_noise, zonotope_of
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.zonotope import Zonotope


class LinearSystem:
    """``x+ = A x + w, y = C x + v`` with ``w in W``, ``v in V`` (boxes, zonotopes or
    ellipsoids).

    Parameters
    ----------
    A : array_like, shape (n, n)
        State matrix.
    C : array_like, shape (p, n)
        Output matrix (a vector is one output row).
    W : Box, Zonotope or Ellipsoid of dimension n
        Process noise set (centred anywhere), stored as given.
    V : Box, Zonotope or Ellipsoid of dimension p
        Measurement noise set.

    Notes
    -----
    With ellipsoidal noise the exact sets are not polytopes: :func:`exact_sets` refuses them,
    and the polytopic observers use :attr:`W_zonotope` / :attr:`V_zonotope`, the certified
    parallelotopes around the ellipsoids (``optbound.estimation.noise``).

    The model is ``x_{k+1} = A x_k + w_k``, ``y_k = C x_k + v_k``; its exact set obeys
    ``X_k = (A X_{k-1} + W) ∩ {x : y_k - C x in V}`` (module docstring), the setting of
    Alamo, Bravo & Camacho [1]_ and Scott et al. [2]_.

    Raises
    ------
    ValueError
        If A is not square, C does not have n columns, a matrix is not finite, a Box noise set
        is unbounded or a noise set has the wrong dimension (the message names the argument).
    TypeError
        If W or V is not a Box, Zonotope or Ellipsoid.

    References
    ----------
    .. [1] T. Alamo, J. M. Bravo, E. F. Camacho, "Guaranteed state estimation by zonotopes",
       Automatica 41(6), 2005.
    .. [2] J. K. Scott, D. M. Raimondo, G. R. Marseglia, R. D. Braatz, "Constrained zonotopes:
       A new tool for set-based estimation and fault detection", Automatica 69, 2016.

    Examples
    --------
    >>> from optbound import Box
    >>> from optbound.estimation import LinearSystem
    >>> A, C = [[1.0, 0.5], [0.0, 1.0]], [[1.0, 0.0]]
    >>> system = LinearSystem(A, C, W=Box([-0.1, -0.1], [0.1, 0.1]), V=Box([-0.2], [0.2]))
    >>> system, system.polytopic
    (LinearSystem(n=2, p=1), True)
    """

    def __init__(self, A, C, W: NoiseSet, V: NoiseSet):
        A = v.finite_matrix("A", A)
        if A.shape[0] != A.shape[1]:
            raise ValueError(f"A must be square, got shape {A.shape}")
        n = A.shape[0]
        C = v.finite_matrix("C", np.atleast_2d(C), (None, n))
        self.A, self.C = A, C
        self.W = as_noise("W", W, n)
        self.V = as_noise("V", V, C.shape[0])

    @property
    def polytopic(self) -> bool:
        """Whether both noise sets are boxes or zonotopes (then the exact sets are polytopes)."""
        return not isinstance(self.W, Ellipsoid) and not isinstance(self.V, Ellipsoid)

    @cached_property
    def W_zonotope(self) -> Zonotope:
        """``W`` as a zonotope (a box's radii rounded up; an ellipsoid's certified
        parallelotope)."""
        return zonotope_of(self.W)

    @cached_property
    def V_zonotope(self) -> Zonotope:
        """``V`` as a zonotope (a box's radii rounded up; an ellipsoid's certified
        parallelotope)."""
        return zonotope_of(self.V)

    @property
    def dim(self) -> int:
        """The state dimension n."""
        return self.A.shape[0]

    @property
    def n_outputs(self) -> int:
        """The number of outputs p (rows of C)."""
        return self.C.shape[0]

    def measurements(self, ys) -> np.ndarray:
        """``ys`` as a finite (N, p) array (a 1-D array is one output per step when p = 1).

        Parameters
        ----------
        ys : array_like, shape (N, p) or (N,) when p = 1
            The measurements; ``ys[k-1]`` measures ``x_k``.

        Returns
        -------
        numpy.ndarray, shape (N, p)
            The measurements as floats.

        Raises
        ------
        ValueError
            If ``ys`` is not finite or does not have p columns.
        """
        ys = np.asarray(ys, dtype=float)
        if ys.ndim == 1 and self.n_outputs == 1:
            ys = ys[:, None]
        return v.finite_matrix("ys", ys, (None, self.n_outputs))

    def __repr__(self) -> str:
        return f"LinearSystem(n={self.dim}, p={self.n_outputs})"
