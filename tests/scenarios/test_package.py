"""The scenarios package: one module per world, reachable as lazy attributes."""

import importlib

import pytest

import optbound.scenarios as scenarios


def test_worlds_are_lazy_attributes_and_dir_lists_only_them():
    assert sorted(dir(scenarios)) == [
        "alamo2005",
        "arena",
        "bh_geometry",
        "linear_systems",
        "office",
        "rooms",
    ]
    for name in scenarios.__all__:
        assert getattr(scenarios, name) is importlib.import_module(f"optbound.scenarios.{name}")


def test_unknown_world_is_an_attribute_error():
    with pytest.raises(AttributeError, match="kitchen"):
        _ = scenarios.kitchen


@pytest.mark.parametrize(
    "name", ["alamo2005", "arena", "bh_geometry", "linear_systems", "office", "rooms"]
)
def test_every_world_declares_existing_public_names(name):
    module = importlib.import_module(f"optbound.scenarios.{name}")
    assert all(hasattr(module, n) for n in module.__all__)
    assert len(set(module.__all__)) == len(module.__all__)
