"""The papers' localization models, built only from the lower layers (sets, analytic, interval).

Shared planar geometry lives in :mod:`optbound.localization.geometry`; each model is a module of
its own, reachable as an attribute (``ob.localization.relative_bearing``, imported on first
access) or by name (``from optbound.localization import relative_bearing``).
"""

from optbound import _fresh  # noqa: F401  (drops stale kernel caches before any is loaded)
from optbound._lazy import attach

__all__: list[str] = []

__getattr__, __dir__ = attach(__name__)
