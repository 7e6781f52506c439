"""The package's lazy subpackage attributes (PEP 562) and the light ``import optbound``."""

import importlib.util
import subprocess
import sys

import pytest

import optbound


def _present() -> list[str]:
    return [n for n in optbound.SUBMODULES if importlib.util.find_spec(f"optbound.{n}")]


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


def test_import_is_light_and_attributes_import_on_first_access():
    code = (
        "import sys, optbound as ob\n"
        "assert 'cvxpy' not in sys.modules and 'optbound.analytic' not in sys.modules\n"
        "ob.analytic, ob.interval, ob.compare\n"
        "assert 'optbound.analytic' in sys.modules and 'cvxpy' not in sys.modules\n"
        "ob.optimal.outer_ellipsoid\n"
        "assert 'cvxpy' in sys.modules\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)
