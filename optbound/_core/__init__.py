"""The declared core of optbound: input validation, the supported domain, ``Box`` and box arrays.

Every package of optbound builds on this vocabulary, so it lives below all of them (the layers,
checked by ``lint-imports`` with the contracts in ``pyproject.toml``, are ``_core`` <-
``interval`` <- ``sets`` <- ``analytic``, ``optimal`` <- ``compare`` <- ``localization`` <-
... <- ``cli``).

- :mod:`~optbound._core.validate`: ``real_array``, ``finite_vector``, ``spd_matrix``, ... turn
  user input into float64 arrays or raise a ``ValueError`` / ``TypeError`` naming the argument.
- :mod:`~optbound._core.domain`: the supported domain of ellipsoids and strips (magnitude and
  condition limits) and its compiled check ``check_ellipsoid`` / ``raise_for``.
- :mod:`~optbound._core.convex`: ``ConvexSet`` and ``QuadraticDescription``, the required part
  of the set protocol (written down in :mod:`optbound.sets.base`).
- :mod:`~optbound._core.jit`: ``njit``, numba's decorator with the options every kernel
  shares (no C-callable wrapper, which no kernel uses and which cost compile time).
- :mod:`~optbound._core.compiled_copy`: ``copy_into``, the array copy of compiled kernels
  (slice assignment would compile numba's string machinery for its error message).
- :mod:`~optbound._core.linear_program`: ``solve_lp`` and ``least_inf_norm``, the float LPs
  of the zonotope types and the estimators (HiGHS through highspy; callers certify what they
  return).
- :mod:`~optbound._core.box`: ``Box`` and the validators of boxes (``as_box``, ``box_rows``)
  and of ``(m, n, 2)`` box arrays (``box_array``).

Rules:

1. ``_core`` imports nothing from the rest of optbound (numpy, numba and highspy only), except
   :mod:`optbound._fresh`, first, because :mod:`~optbound._core.domain` and
   :mod:`~optbound._core.compiled_copy` define kernels.
2. Other packages import these names from ``optbound._core`` (or its modules, e.g.
   ``from optbound._core import validate as v``); ``_core`` is the one private package they may
   reach into. Anything else private (``optbound.x._y``) is imported only inside ``optbound.x``.
3. A helper belongs here only if several packages need it and no package owns it as its API;
   one helper per job (one ``real_array``, one box-array validator), never a local twin.
4. Users do not import ``_core``: ``Box`` and ``ConvexSet`` are public as ``optbound.Box`` and
   ``optbound.sets.Box`` (the same class).
"""

from optbound import _fresh  # noqa: F401  (drops stale kernel caches before any is loaded)
from optbound._core import validate
from optbound._core.box import Box, as_box, box_array, box_rows
from optbound._core.convex import ConvexSet, QuadraticDescription
from optbound._core.domain import (
    COND_MAX,
    COND_OUT,
    MAG,
    MAX_DIAG,
    MIN_PIVOT,
    RATIO_MAX,
    RATIO_OUT,
    SYMMETRY_RTOL,
    check_ellipsoid,
    cholesky,
    raise_for,
)
from optbound._core.validate import NotRealError, real_array

__all__ = [
    "COND_MAX",
    "COND_OUT",
    "MAG",
    "MAX_DIAG",
    "MIN_PIVOT",
    "RATIO_MAX",
    "RATIO_OUT",
    "SYMMETRY_RTOL",
    "Box",
    "ConvexSet",
    "NotRealError",
    "QuadraticDescription",
    "as_box",
    "box_array",
    "box_rows",
    "check_ellipsoid",
    "cholesky",
    "raise_for",
    "real_array",
    "validate",
]
