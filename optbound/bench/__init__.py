"""The optbound benchmark suite: seeded instance families and speed runs.

Each family lives in its own module and is listed in :mod:`optbound.bench.registry`;
``optbound bench`` runs them through :mod:`optbound.bench.runner` and hands the results to
:mod:`optbound.report`. The modules are attributes, imported on first access.
"""

from optbound._lazy import attach

__all__: list[str] = []

__getattr__, __dir__ = attach(__name__)
