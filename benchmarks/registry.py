"""The list of benchmark families, in report order.

To add a family, write a module exposing ``FAMILY = Family(...)`` (see
:mod:`benchmarks.family`) and add its module name here.
"""

from __future__ import annotations

import importlib

from benchmarks.family import Family

FAMILY_MODULES = (
    "benchmarks.strip_tightness",
    "benchmarks.minkowski_tightness",
    "benchmarks.recursive_tightness",
    "benchmarks.localization_tightness",
    "benchmarks.speed_analytic",
    "benchmarks.speed_sdp",
    "benchmarks.speed_sivia",
    "benchmarks.speed_hs96",
    "benchmarks.speed_glh12",
    "benchmarks.speed_sonar",
    "benchmarks.papers",
)


def families() -> list[Family]:
    """All registered families, in report order."""
    return [importlib.import_module(name).FAMILY for name in FAMILY_MODULES]
