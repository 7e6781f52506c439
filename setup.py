"""Which packages the distribution installs (the rest of the metadata is in pyproject.toml).

Everything under ``optbound/``, plus the repository's ``papers_repro/`` folder installed as
``optbound.papers_repro``, so that ``optbound repro`` works in any install while nothing is
installed under a generic top-level name. ``benchmarks/`` is not installed. Package data:
the scenarios' data files (``optbound/scenarios/_data/*.json``, e.g. CORA's 30-state tank).
"""

from setuptools import find_packages, setup

setup(
    packages=[*find_packages(include=["optbound", "optbound.*"]), "optbound.papers_repro"],
    package_dir={"optbound.papers_repro": "papers_repro"},
    package_data={"optbound.scenarios": ["_data/*.json"]},
)
