"""The package's lazy attributes (PEP 562), its ``dir()`` and the light ``import optbound``."""

import importlib
import os
import subprocess
import sys
from pathlib import Path

import pytest

import optbound

SUBPACKAGES = (
    "analytic",
    "bench",
    "compare",
    "estimation",
    "interval",
    "localization",
    "localization.geometry",
    "optimal",
    "problems",
    "report",
    "scenarios",
    "sets",
)


def _present() -> list[str]:
    return [n for n in dir(optbound) if n not in optbound.__all__]


def test_the_named_subpackages_exist_in_this_tree():
    assert {"analytic", "optimal", "interval", "compare"} <= set(_present())


@pytest.mark.parametrize("name", _present())
def test_every_present_subpackage_is_an_attribute(name):
    module = getattr(optbound, name)
    assert module is sys.modules[f"optbound.{name}"]
    assert name in dir(optbound)


def test_unknown_attribute_raises_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'nope'"):
        optbound.nope  # noqa: B018
    assert not hasattr(optbound, "nope")


def test_dir_lists_the_public_names_only():
    names = dir(optbound)
    assert names == sorted({*optbound.__all__, *_present()})
    assert {"importlib", "annotations", "SUBMODULES", "attach"}.isdisjoint(names)
    for name in names:
        assert getattr(optbound, name) is not None


@pytest.mark.parametrize("name", SUBPACKAGES)
def test_every_subpackage_dir_lists_all_and_its_lazy_modules_only(name):
    package = importlib.import_module(f"optbound.{name}")
    names = dir(package)
    assert set(package.__all__) <= set(names)
    extra = set(names) - set(package.__all__)
    for attr in names:
        assert not attr.startswith("_"), attr
        assert getattr(package, attr) is not None
    for attr in extra:  # anything beyond __all__ is a submodule imported on access
        assert getattr(package, attr) is sys.modules[f"optbound.{name}.{attr}"]
    assert {"annotations", "importlib", "attach"}.isdisjoint(names)


def test_localization_modules_are_attributes_imported_on_first_access():
    code = (
        "import sys, optbound as ob\n"
        "assert 'relative_bearing' in dir(ob.localization)\n"
        "assert 'optbound.localization.relative_bearing' not in sys.modules\n"
        "module = ob.localization.relative_bearing\n"
        "assert module is sys.modules['optbound.localization.relative_bearing']\n"
        "assert callable(module.localize)\n"
        "for name in dir(ob.localization):\n"
        "    assert getattr(ob.localization, name).__name__ == f'optbound.localization.{name}'\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)


def test_import_is_light_and_attributes_import_on_first_access():
    code = (
        "import sys, optbound as ob\n"
        "assert 'cvxpy' not in sys.modules and 'optbound.analytic' not in sys.modules\n"
        "assert 'numba' not in sys.modules and 'numpy' not in sys.modules\n"
        "ob.analytic, ob.interval, ob.compare\n"
        "assert 'optbound.analytic' in sys.modules and 'cvxpy' not in sys.modules\n"
        "ob.optimal.outer_ellipsoid\n"
        "assert 'cvxpy' in sys.modules\n"
        "from optbound import Ellipsoid\n"
        "assert Ellipsoid is ob.sets.Ellipsoid is ob.Ellipsoid\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)


def _snapshot(*roots: Path) -> dict[Path, tuple[int, int]]:
    return {
        path: (path.stat().st_mtime_ns, path.stat().st_size)
        for root in roots
        for path in root.rglob("*")
    }


def test_import_writes_no_file(tmp_path):
    """``import optbound`` leaves the package folder and numba's cache folder untouched
    (``-B``: Python's own bytecode files are not optbound's writes)."""
    root = Path(optbound.__file__).resolve().parent
    cache = tmp_path / "numba-cache"
    cache.mkdir()
    before = _snapshot(root)
    env = {**os.environ, "NUMBA_CACHE_DIR": str(cache)}
    code = "import optbound, sys; assert 'optbound._fresh' not in sys.modules"
    subprocess.run([sys.executable, "-B", "-c", code], check=True, env=env)
    assert _snapshot(root) == before
    assert not any(cache.iterdir())
