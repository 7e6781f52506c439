"""Set-membership state estimation of linear systems (issue 21).

``LinearSystem(A, C, W, V)``, the exact sets (:func:`exact_sets`, constrained zonotopes
without reduction; :func:`exact_polytopes`, rational polytopes with exact vertices and volume
for n <= 4) and guaranteed observers (:func:`observe` with a method of :data:`METHODS`).
The references per step are in ``optbound.estimation.references``.
"""

from optbound._lazy import attach
from optbound.estimation.exact import exact_sets
from optbound.estimation.exact_polytope import exact_polytopes
from optbound.estimation.observers import METHODS, observe
from optbound.estimation.system import LinearSystem

__all__ = ["METHODS", "LinearSystem", "exact_polytopes", "exact_sets", "observe"]

__getattr__, __dir__ = attach(__name__, public=__all__, submodules=())
