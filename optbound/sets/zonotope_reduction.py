"""Order reduction of zonotopes: replace the least important generators by a box.

Both methods keep ``max_generators - n`` generators unchanged and enclose the sum of the others,
``{sum_j g_j xi_j}``, in its interval hull ``diag(sum_j |g_j|)`` (``n`` axis-aligned
generators, radii rounded up, so the result contains the input in exact arithmetic). They
differ in which generators are boxed:

- ``"girard"``: the smallest ``||g||_1 - ||g||_inf`` (Girard, *Reachability of uncertain
  linear systems using zonotopes*, HSCC 2005, Sect. 3.4): a generator nearly parallel to an
  axis loses little when boxed;
- ``"combastel"``: the smallest Euclidean norm (Combastel, *A state bounding observer based on
  zonotopes*, ECC 2003, Sect. 3).
"""

from __future__ import annotations

import numpy as np

from optbound._core import validate as v
from optbound.sets.certified import error_generators, row_sum_up

REDUCTION_METHODS = ("girard", "combastel")


def _scores(G: np.ndarray, method: str) -> np.ndarray:
    if method == "girard":
        return np.abs(G).sum(axis=0) - np.abs(G).max(axis=0, initial=0.0)
    if method == "combastel":
        return np.linalg.norm(G, axis=0)
    raise ValueError(f"method must be one of {REDUCTION_METHODS}, got {method!r}")


def reduce_generators(G: np.ndarray, max_generators: int, method: str = "girard") -> np.ndarray:
    """Generators of a zonotope containing ``<0, G>`` with at most ``max_generators`` columns.

    Parameters
    ----------
    G : np.ndarray, shape (n, m)
        Generators (finite).
    max_generators : int
        Budget, at least ``n`` (the box alone has ``n`` generators).
    method : {"girard", "combastel"}
        Which generators are boxed (module docstring).

    Returns
    -------
    np.ndarray, shape (n, k), k <= max_generators
        The kept generators (in their original order) followed by the box generators with a
        non-zero radius. ``G`` itself when it already fits the budget.

    Raises
    ------
    TypeError
        If ``max_generators`` is not an integer.
    ValueError
        If ``max_generators < n`` or ``method`` is unknown.
    """
    n, m = G.shape
    scores = _scores(G, method)
    if isinstance(max_generators, bool) or not isinstance(max_generators, int | np.integer):
        raise TypeError(f"max_generators must be an integer, got {max_generators!r}")
    if max_generators < n:
        raise ValueError(f"max_generators must be >= {n} (the dimension), got {max_generators}")
    if m <= max_generators:
        return G
    keep_count = max_generators - n
    order = np.argsort(scores, kind="stable")
    boxed, kept = order[: m - keep_count], np.sort(order[m - keep_count :])
    radii = row_sum_up(np.abs(G[:, boxed]))
    return np.hstack([G[:, kept], error_generators(radii)])


def generator_budget(order, n: int) -> int:
    """``floor(order * n)`` for a finite ``order >= 1`` (the usual order parameter).

    Parameters
    ----------
    order : float
        Generators per dimension, at least 1.
    n : int
        Dimension.

    Returns
    -------
    int
        The generator budget.

    Raises
    ------
    ValueError
        If ``order`` is not finite or below 1.
    """
    order = v.finite_scalar("order", order)
    if order < 1.0:
        raise ValueError(f"order must be >= 1, got {order}")
    return int(np.floor(order * n))
