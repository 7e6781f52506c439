"""Set-membership state estimation of linear systems (issue 21).

``LinearSystem(A, C, W, V)``, the exact sets (:func:`exact_sets`, constrained zonotopes
without reduction) and guaranteed observers (:func:`observe` with a method of
:data:`METHODS`).
"""

from optbound._lazy import attach
from optbound.estimation.exact import exact_sets
from optbound.estimation.observers import METHODS, observe
from optbound.estimation.system import LinearSystem

__all__ = ["METHODS", "LinearSystem", "exact_sets", "observe"]

__getattr__, __dir__ = attach(__name__, public=__all__, submodules=())
