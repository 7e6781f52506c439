"""The layering of optbound (DESIGN.md) holds: import-linter's contracts and a cycle check.

The contracts live in ``pyproject.toml`` (``[tool.importlinter]``): the layers ``_core`` <-
``interval`` <- ``sets`` <- ``analytic``, ``optimal`` <- ``compare`` <- ``localization`` <- ...
<- ``cli``, private modules imported only inside their package, cvxpy only under ``optimal``,
nothing importing the command line, and no import cycle between packages.
"""

from __future__ import annotations

import graphlib
from pathlib import Path

import grimp
import pytest
from importlinter.api import read_configuration
from importlinter.application.use_cases import lint_imports

PYPROJECT = Path(__file__).resolve().parents[1] / "pyproject.toml"


@pytest.fixture(scope="module")
def graph() -> grimp.ImportGraph:
    return grimp.build_graph("optbound", cache_dir=None)


def _package(module: str) -> str:
    """The child of ``optbound`` that ``module`` belongs to (``optbound`` for the root)."""
    parts = module.split(".")
    return ".".join(parts[:2])


def test_the_import_contracts_are_kept(capsys):
    kept = lint_imports(config_filename=str(PYPROJECT), no_logo=True, cache_dir=None)
    assert kept, capsys.readouterr().out


def test_every_package_of_optbound_is_in_the_layers(graph):
    # A new package outside the layers contract would escape it: list it where it belongs.
    contracts = read_configuration(str(PYPROJECT))["contracts_options"]
    (layers,) = [c for c in contracts if c["type"] == "layers"]
    listed = {
        name.strip().strip("()")
        for layer in layers["layers"]
        for name in layer.replace(":", "|").split("|")
    }
    children = {module.split(".")[1] for module in graph.find_children("optbound")}
    assert children <= listed, sorted(children - listed)


def test_no_import_cycle_between_the_packages_of_optbound(graph):
    edges: dict[str, set[str]] = {}
    for importer in graph.modules:
        for imported in graph.find_modules_directly_imported_by(importer):
            a, b = _package(importer), _package(imported)
            if a != b:
                edges.setdefault(a, set()).add(b)
    assert len(edges) > 5  # the graph is the real one, with its packages and their imports
    graphlib.TopologicalSorter(edges).prepare()  # raises CycleError naming a cycle
