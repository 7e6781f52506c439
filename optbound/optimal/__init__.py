"""Certified SDP reference solvers (cvxpy + Clarabel): the best ellipsoids that exist.

- ``outer_ellipsoid``: minimum-volume / -trace / -projection ellipsoid containing an
  intersection of ellipsoids, strips, half-spaces, boxes and quadratic sets (S-procedure);
- ``minkowski_outer``: the same for a Minkowski sum of ellipsoids;
- ``mvee``: minimum-volume ellipsoid enclosing a point set;
- ``optimal_pseudo_ellipsoid``: the minimum-lifted-volume pseudo-ellipsoid of a paved set
  [BH, eq. (10)], bracketed below by the MVEE of lifted points and certified above by
  interval proofs on the paving's boxes.

Every answer is certified in float64 and inflated if needed (``certify``), and comes as an
``OuterResult``. This is the only subpackage that imports cvxpy.
"""

from optbound import _fresh  # noqa: F401  (drops stale kernel caches before any is loaded)
from optbound._lazy import attach
from optbound.optimal.enclosing import mvee
from optbound.optimal.errors import CertificationError, EmptyIntersectionError, SolverError
from optbound.optimal.intersection import outer_ellipsoid
from optbound.optimal.minkowski import minkowski_outer
from optbound.optimal.pseudo import PseudoReference, optimal_pseudo_ellipsoid
from optbound.optimal.result import OuterResult

__all__ = [
    "CertificationError",
    "EmptyIntersectionError",
    "OuterResult",
    "PseudoReference",
    "SolverError",
    "minkowski_outer",
    "mvee",
    "optimal_pseudo_ellipsoid",
    "outer_ellipsoid",
]

__getattr__, __dir__ = attach(__name__, public=__all__, submodules=())
