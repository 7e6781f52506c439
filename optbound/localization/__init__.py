"""The papers' localization models, built only from the lower layers (sets, analytic, interval).

Each model is a module of its own, reachable as an attribute (``optbound.localization.sonar``)
or by import (``from optbound.localization import sonar``); shared planar geometry lives in
:mod:`optbound.localization.geometry`. The worlds the papers ran them in (office, arena,
rooms, the BH geometry) are data, not models: they live one layer up, in
:mod:`optbound.scenarios`, and a model never imports them (a world is always an argument).

Model contract
--------------
A model module (``landmarks`` [HS96], ``tracker`` [HS96], ``association`` [HS96],
``relative_bearing`` [BH], ``linearized_bearing`` [HS96 on BH data], ``sonar``
[LJMW97, KJWM00], ``visibility`` [GLH12]) follows these rules.

It **must** define:

- ``__all__``: the model's public API (validation helpers shared inside the package are not
  part of it);
- a module docstring that cites the paper, states the measurement equation and says whether
  each bound is guaranteed (a linearized one says **not guaranteed** and is measured);
- the common verbs below for every concept the model has, under these names (a module that
  had another name first keeps it as an alias of the same object):

  ``localize(data..., ...)``
      One batch of measurements -> the model's bound of the feasible set: a set object
      (``sets.Box``, ``interval.Paving``) or a frozen result deriving from
      :class:`optbound.sets.result.BoundResult` (``.set`` the bound, ``.certified`` whether it
      is guaranteed, plus the by-products). ``landmarks``, ``relative_bearing``, ``sonar``,
      ``linearized_bearing`` (not guaranteed).
  ``exact_paving(data..., X0, eps)``
      An :class:`~optbound.interval.Paving` of the exact feasible set,
      ``inner ⊂ set ⊂ inner ∪ boundary`` in outward-rounded arithmetic. ``landmarks``,
      ``relative_bearing``, ``sonar`` (whose ``localize`` is already this paving),
      ``visibility`` (one robot's consistent positions at one step).
  ``exact_tests(...)``
      The three-valued interval tests whose conjunction is the exact set, as
      :func:`optbound.interval.pave` takes them. ``relative_bearing``, ``sonar``.
  ``measure(state, world...)``
      The noise-free measurement function (the paper's observation equation) at a true
      state, for simulations and tests. ``relative_bearing``, ``sonar``, ``visibility``.
  ``track(...)`` / a tracker class with ``predict`` and ``update``
      Recursive bounds over a sequence of measurements. ``visibility.track``,
      ``tracker.SetTracker``.

- bad input answered with a ``ValueError`` / ``TypeError`` naming the argument.

It **gets for free**:

- every geometric predicate once, in point and interval form (:mod:`.geometry`): called on
  floats it simulates, called on :class:`~optbound.interval.Interval` boxes it is its own
  inclusion function, so the same formula gives ``measure`` and ``exact_tests``;
- set inversion and its results from :mod:`optbound.interval` (``pave``, relaxed
  intersections for outliers, ``Paving.volume_bounds`` / ``components`` / ``hull``);
- the closed-form bound updates of :mod:`optbound.analytic` and the certified SDP references
  of :mod:`optbound.optimal` (a model never re-derives a formula a lower layer has);
- containment proofs of its bound over a paving via the set types' ``tri_contains``
  (e.g. ``relative_bearing.certify_contains``).

``environment`` (E⁻ ⊂ E ⊂ E⁺ [GLH12]) and ``landmark_map`` (landmarks, error ellipses and walls
[HS96]) are the world representations the models take, not models.
"""

from __future__ import annotations

import importlib
import warnings

from optbound import _fresh  # noqa: F401  (drops stale kernel caches before any is loaded)

__all__ = [
    "association",
    "environment",
    "geometry",
    "landmark_map",
    "landmarks",
    "linearized_bearing",
    "relative_bearing",
    "sonar",
    "tracker",
    "visibility",
]

#: Worlds that lived here before :mod:`optbound.scenarios`: deprecated aliases for one release.
_MOVED = {name: f"optbound.scenarios.{name}" for name in ("arena", "office", "rooms")}


def __getattr__(name: str):
    """Import a model module on first access (PEP 562); warn for a world that moved."""
    if name in __all__:
        return importlib.import_module(f"{__name__}.{name}")
    if name in _MOVED:
        warnings.warn(
            f"optbound.localization.{name} moved to {_MOVED[name]}; the old name will be removed",
            DeprecationWarning,
            stacklevel=2,
        )
        module = importlib.import_module(_MOVED[name])
        globals()[name] = module  # one warning per import statement, not one per lookup
        return module
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)
