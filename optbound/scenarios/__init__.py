"""The papers' designed worlds: data and simulations, not models.

Each module is one world the reproductions, benchmarks and tests run the models of
:mod:`optbound.localization` in. The layering is one way: a scenario imports models, a model
never imports a scenario (it takes its world as an argument).

- :mod:`.office`: the office, course and error amplitudes of the HS96 experiment
  [HS96, Sect. 5], with the simulation of scans and odometry and the tracking run;
- :mod:`.arena`: the 10 m x 10 m room with 11 obstacles of [GLH12, Sect. 5];
- :mod:`.rooms`: the triangular room of [LJMW97, Sect. 4] and the chamfered room with a sonar
  belt of [KJWM00, Sect. 6];
- :mod:`.bh_geometry`: the landmarks and pairs of [BH, Sect. V], and random instances like it;
- :mod:`.alamo2005`: the linear system of Alamo, Bravo & Camacho (2005, Sect. 7.1), the
  paper's own data; :mod:`.linear_systems`: seeded random stable linear systems (ours).

These are **designed data**. The papers' figures that fixed the office (HS96 Fig. 4), the
arena (GLH12 Fig. 7) and the rooms (LJMW97 Fig. 4(a), KJWM00 Sect. 6) are lost: those worlds
are our designs, consistent with the surviving text, fixed before any result was seen and never
tuned to the papers' numbers (each module says what is the paper's and what is ours). The BH
geometry is the paper's own (its noise bound taken from BH Fig. 1); its random instances are
ours. Import a world by name, e.g. ``from optbound.scenarios import rooms``.

References
----------
[HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
on an angle measurement technique", IFAC, 1996.
[BH] K. Briechle, U. D. Hanebeck, "Localization of a mobile robot using relative
bearing measurements", IEEE Transactions on Robotics and Automation, 2004.
[LJMW97] O. Lévêque, L. Jaulin, D. Meizel, E. Walter, "Vehicle localization from
inaccurate telemetric data: a set inversion approach", IFAC SYROCO, 1997.
[KJWM00] M. Kieffer, L. Jaulin, E. Walter, D. Meizel, "Robust autonomous robot
localization using interval analysis", Reliable Computing, 2000.
[GLH12] R. Guyonneau, S. Lagrange, L. Hardouin, "Mobile robots pose tracking: a
set-membership approach using a visibility information", ICINCO, 2012.
"""

from __future__ import annotations

import importlib

__all__ = ["alamo2005", "arena", "bh_geometry", "linear_systems", "office", "rooms"]


def __getattr__(name: str):
    """Import a world on first access (PEP 562): ``optbound.scenarios.office`` etc."""
    if name in __all__:
        return importlib.import_module(f"{__name__}.{name}")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)
