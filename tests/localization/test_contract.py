"""The model contract of :mod:`optbound.localization`: ``__all__``, common verbs, layering."""

import ast
import importlib
import inspect
import pkgutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import optbound
import optbound.localization as loc
from optbound.interval import Paving
from optbound.sets import Box, Ellipsoid, PseudoEllipsoid
from optbound.sets.result import BoundResult

MODULES = sorted(
    m.name for m in pkgutil.walk_packages(loc.__path__, prefix="optbound.localization.")
)
MODELS = [
    "association",
    "landmarks",
    "linearized_bearing",
    "relative_bearing",
    "sonar",
    "tracker",
    "visibility",
]
#: The common verbs each model defines (the package docstring's table).
VERBS = {
    "landmarks": {"localize", "exact_paving"},
    "linearized_bearing": {"localize"},
    "relative_bearing": {"localize", "exact_paving", "exact_tests", "measure"},
    "sonar": {"localize", "exact_paving", "exact_tests", "measure"},
    "visibility": {"measure", "track", "exact_paving"},
}
#: Names a module had first for a verb: they stay, as the same object.
ALIASES = {
    ("landmarks", "localize"): "linear_position_bound",
    ("landmarks", "exact_paving"): "pose_paving",
    ("linearized_bearing", "localize"): "linearized_localize",
    ("relative_bearing", "measure"): "bearings",
    ("sonar", "exact_paving"): "localize",
    ("sonar", "exact_tests"): "sonar_tests",
    ("sonar", "measure"): "simulate_ranges",
}


@pytest.mark.parametrize("name", MODULES)
def test_every_module_declares_existing_public_names(name):
    module = importlib.import_module(name)
    names = module.__all__
    assert len(set(names)) == len(names)
    assert all(not n.startswith("_") and hasattr(module, n) for n in names)


@pytest.mark.parametrize("name", MODELS)
def test_every_public_function_and_class_of_a_model_is_in_all(name):
    """Validation helpers (``as_*``) are package helpers, not a model's API."""
    module = importlib.import_module(f"optbound.localization.{name}")
    defined = {
        n
        for n, obj in vars(module).items()
        if (inspect.isfunction(obj) or inspect.isclass(obj))
        and obj.__module__ == module.__name__
        and not n.startswith(("_", "as_"))
    }
    assert defined <= set(module.__all__)


@pytest.mark.parametrize(("name", "verbs"), sorted(VERBS.items()))
def test_models_define_their_common_verbs(name, verbs):
    module = importlib.import_module(f"optbound.localization.{name}")
    for verb in verbs:
        assert verb in module.__all__ and callable(getattr(module, verb))


@pytest.mark.parametrize(("where", "old"), sorted(ALIASES.items()))
def test_old_names_are_the_verbs_themselves(where, old):
    module = importlib.import_module(f"optbound.localization.{where[0]}")
    assert getattr(module, where[1]) is getattr(module, old)
    assert old in module.__all__


def test_localize_returns_the_bound_and_exact_paving_a_paving():
    from optbound.localization import landmarks, linearized_bearing
    from optbound.localization import relative_bearing as rb
    from optbound.scenarios import bh_geometry as bh

    L = np.array([[4.0, 0.0], [0.0, 4.0], [-4.0, -1.0]])
    pose = np.array([0.5, 0.2, 0.3])
    alphas = np.arctan2(L[:, 1] - pose[1], L[:, 0] - pose[0]) - pose[2]
    assert isinstance(landmarks.localize(L, alphas, 1e-3), Box)
    paving = landmarks.exact_paving(L, alphas, 1e-3, X0=[[-1, 1], [-1, 1], [0, 0.6]], eps=0.05)
    assert isinstance(paving, Paving)

    data = bh.sect5_instance()[:4]
    bh_result = rb.localize(*data)
    assert isinstance(bh_result, BoundResult) and bh_result.certified
    assert bh_result.set is bh_result.bound and isinstance(bh_result.set, PseudoEllipsoid)
    assert bh_result.margin == max(bh_result.margins) >= 0.0
    linearized = linearized_bearing.localize(*data)
    assert isinstance(linearized, BoundResult) and not linearized.certified
    assert isinstance(linearized.set, Ellipsoid) and linearized.set is linearized.ellipse
    assert isinstance(rb.exact_paving(*data, [[-0.3, 0.3], [-0.3, 0.3]], 0.05), Paving)


def _imports(path: Path) -> set[str]:
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            found.add(node.module)
    return found


def test_models_and_lower_layers_never_import_scenarios():
    root = Path(optbound.__file__).parent
    below = ["_core", "interval", "sets", "analytic", "optimal", "compare"]
    below += ["localization", "estimation"]
    files = [f for d in below if (root / d).is_dir() for f in (root / d).rglob("*.py")]
    assert files
    for f in files:
        assert not any(m.startswith("optbound.scenarios") for m in _imports(f)), f


def test_model_modules_are_lazy_attributes():
    code = (
        "import sys, optbound.localization as L\n"
        "assert 'optbound.localization.sonar' not in sys.modules\n"
        "assert L.relative_bearing.localize is L.relative_bearing.__dict__['localize']\n"
        "assert sorted(dir(L)) == sorted(L.__all__)\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True, cwd=Path(optbound.__file__).parents[1])


def test_unknown_attribute_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no_such_model"):
        _ = loc.no_such_model


@pytest.mark.parametrize("name", ["arena", "office", "rooms"])
def test_moved_worlds_warn_and_resolve_to_scenarios(name, monkeypatch):
    monkeypatch.delitem(vars(loc), name, raising=False)
    with pytest.warns(DeprecationWarning, match=f"optbound.scenarios.{name}"):
        module = loc.__getattr__(name)
    assert module is importlib.import_module(f"optbound.scenarios.{name}")
