"""Linear discrete-time systems with bounded noise (issue 21's setting).

``x_{k+1} = A x_k + w_k``, ``y_k = C x_k + v_k``, ``w_k in W``, ``v_k in V``. Convention: the
set ``X0`` holds ``x_0`` (no measurement at k = 0) and ``ys[k-1]`` measures ``x_k``, so
``X_k = (A X_{k-1} + W) ∩ {x : ys[k-1] - C x in V}``.
"""

from __future__ import annotations

import numpy as np

from optbound._core import Box
from optbound._core import validate as v
from optbound.sets.zonotope import Zonotope, as_zonotope


class LinearSystem:
    """``x+ = A x + w, y = C x + v`` with ``w in W``, ``v in V`` (boxes or zonotopes).

    Parameters
    ----------
    A : array_like, shape (n, n)
        State matrix.
    C : array_like, shape (p, n)
        Output matrix (a vector is one output row).
    W : Box or Zonotope of dimension n
        Process noise set (centred anywhere).
    V : Box or Zonotope of dimension p
        Measurement noise set.
    """

    def __init__(self, A, C, W: Box | Zonotope, V: Box | Zonotope):
        A = v.finite_matrix("A", A)
        if A.shape[0] != A.shape[1]:
            raise ValueError(f"A must be square, got shape {A.shape}")
        n = A.shape[0]
        C = v.finite_matrix("C", np.atleast_2d(C), (None, n))
        self.A, self.C = A, C
        self.W = as_zonotope("W", W, n)
        self.V = as_zonotope("V", V, C.shape[0])

    @property
    def dim(self) -> int:
        return self.A.shape[0]

    @property
    def n_outputs(self) -> int:
        return self.C.shape[0]

    def measurements(self, ys) -> np.ndarray:
        """``ys`` as a finite (N, p) array (a 1-D array is one output per step when p = 1)."""
        ys = np.asarray(ys, dtype=float)
        if ys.ndim == 1 and self.n_outputs == 1:
            ys = ys[:, None]
        return v.finite_matrix("ys", ys, (None, self.n_outputs))

    def __repr__(self) -> str:
        return f"LinearSystem(n={self.dim}, p={self.n_outputs})"
