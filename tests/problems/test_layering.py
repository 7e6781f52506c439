"""problems sits above compare and the models, below bench/report/cli; compare below problems."""

import ast
from pathlib import Path

import pytest

import optbound

ROOT = Path(optbound.__file__).parent
FORBIDDEN = {
    "problems": ("optbound.cli", "optbound.report", "optbound.bench", "benchmarks"),
    "compare": (
        "optbound.problems",
        "optbound.localization",
        "optbound.scenarios",
        "optbound.cli",
        "optbound.report",
        "benchmarks",
        "cvxpy",
    ),
}


def _imports(path: Path) -> set[str]:
    names = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module)
    return names


@pytest.mark.parametrize("package", sorted(FORBIDDEN))
def test_no_upward_imports(package):
    for path in sorted((ROOT / package).glob("*.py")):
        for name in _imports(path):
            assert not name.startswith(FORBIDDEN[package]), f"{path.name} imports {name}"
