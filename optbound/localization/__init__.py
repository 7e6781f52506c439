"""The papers' localization models, built only from the lower layers (sets, analytic, interval).

Shared planar geometry lives in :mod:`optbound.localization.geometry`; each model is a module of
its own (import it by name, e.g. ``from optbound.localization import geometry``).
"""
