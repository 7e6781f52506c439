"""The benchmark families, in report order: their names and where each one is defined.

The names are declared here as plain strings, so the command line lists them (``optbound
bench --family``) without importing any family: importing one loads numba kernels, cvxpy or
scipy, seconds of start-up. A family module is imported when :func:`families` is called.

To add a family, write a module exposing ``FAMILY = Family(...)`` (see
:mod:`optbound.bench.family`) and add ``name: "module:FAMILY"`` to :data:`FAMILIES`.
"""

from __future__ import annotations

import importlib

from optbound.bench.family import Family

#: Family name -> ``"module:attribute"`` of its :class:`Family`, in report order.
FAMILIES: dict[str, str] = {
    "strip": "optbound.bench.strip_tightness:FAMILY",
    "minkowski": "optbound.bench.minkowski_tightness:FAMILY",
    "recursive": "optbound.bench.recursive_tightness:FAMILY",
    "localization": "optbound.bench.localization_tightness:FAMILY",
    "linear_estimation": "optbound.bench.linear_estimation:FAMILY",
    "speed_analytic": "optbound.bench.speed_analytic:FAMILY",
    "speed_sdp": "optbound.bench.speed_sdp:FAMILY",
    "speed_sivia": "optbound.bench.speed_sivia:FAMILY",
    "speed_hs96": "optbound.bench.speed_hs96:FAMILY",
    "speed_glh12": "optbound.bench.speed_glh12:FAMILY",
    "speed_sonar": "optbound.bench.speed_sonar:FAMILY",
    "papers": "optbound.bench.papers:FAMILY",
}

#: Keys of the papers whose results the ``papers`` family reproduces (``papers_repro/``), in
#: report order, declared here for the same reason: ``optbound repro --help`` lists them.
PAPERS = ("HS96", "BH", "LJMW97", "KJWM00", "GLH12", "ABC05")


def families() -> list[Family]:
    """Import and return all registered families, in report order.

    Returns
    -------
    list of Family
        One :class:`~optbound.bench.family.Family` per entry of :data:`FAMILIES`.

    Raises
    ------
    ValueError
        If an entry of :data:`FAMILIES` points at a family with another name.
    """
    return [_load(name, target) for name, target in FAMILIES.items()]


def _load(name: str, target: str) -> Family:
    module, _, attr = target.partition(":")
    family = getattr(importlib.import_module(module), attr)
    if family.name != name:
        raise ValueError(f"FAMILIES[{name!r}] points at the family named {family.name!r}")
    return family
