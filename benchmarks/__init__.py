"""The optbound benchmark suite: seeded instance families and speed runs.

Each family lives in its own module and is listed in :mod:`benchmarks.registry`;
``optbound bench`` runs them through :mod:`benchmarks.runner` and hands the results to
:mod:`optbound.report`.
"""
