"""The linear estimation example of Alamo, Bravo & Camacho (Automatica 41, 2005), Sect. 7.1.

``x_{k+1} = A x_k + w_k``, ``y_k = C x_k + v_k`` with ``A = [[0, -0.5], [1, 1]]``,
``C = [-2, 1]``, ``|v_k| <= 0.2``, ``w_k in {0.02 [-6, 1]^T s : |s| <= 1}`` (a segment: W is
flat), ``X_0 = [-3, 3]^2`` and the 20 measurements below, as given in CORA's
``example_linearSysDT_observe_02_2dim.m`` (Althoff, *Guaranteed state estimation in CORA
2021*, ARCH 2021), which states that it reproduces the paper's example. These are the paper's
data, not a design of ours. Convention of ``optbound.estimation``: ``X0`` holds ``x_0`` and
``MEASUREMENTS[k-1]`` measures ``x_k``.
"""

from __future__ import annotations

import numpy as np

from optbound.estimation import LinearSystem
from optbound.sets import Box, Zonotope

__all__ = ["MEASUREMENTS", "REFERENCE", "X0", "A", "C", "V", "W", "system"]

A = np.array([[0.0, -0.5], [1.0, 1.0]])
C = np.array([[-2.0, 1.0]])
W = Zonotope([0.0, 0.0], 0.02 * np.array([[-6.0], [1.0]]))
V = Box([-0.2], [0.2])
X0 = Box([-3.0, -3.0], [3.0, 3.0])
MEASUREMENTS = np.array(
    [0.79, 5.00, 4.35, 1.86, -0.11, -1.13, -1.17, -0.76, -0.12, 0.72,
     0.29, 0.19, 0.09, -0.21, 0.05, -0.00, -0.16, 0.01, -0.08, 0.13]
)  # fmt: skip
REFERENCE = (
    "T. Alamo, J. M. Bravo, E. F. Camacho, Guaranteed state estimation by zonotopes, "
    "Automatica 41(6):1035-1043, 2005, Sect. 7.1"
)


def system() -> LinearSystem:
    """Build the example's system ``(A, C, W, V)`` [ABC05, Sect. 7.1].

    Returns
    -------
    LinearSystem
        ``x_{k+1} = A x_k + w_k``, ``y_k = C x_k + v_k`` with ``w_k`` in :data:`W` and
        ``v_k`` in :data:`V`.

    References
    ----------
    [ABC05] T. Alamo, J. M. Bravo, E. F. Camacho, "Guaranteed state estimation by
    zonotopes", Automatica 41(6):1035-1043, 2005.

    Examples
    --------
    >>> from optbound.scenarios import alamo2005
    >>> sys = alamo2005.system()
    >>> sys.A.tolist(), len(alamo2005.MEASUREMENTS)
    ([[0.0, -0.5], [1.0, 1.0]], 20)
    """
    return LinearSystem(A, C, W, V)
