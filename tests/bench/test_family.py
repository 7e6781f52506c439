"""Task lists are seeded, reproducible and distinct across families and suite seeds."""

import pytest

from optbound.bench.family import SUITES
from optbound.bench.registry import families
from optbound.problems.generators import task_seeds


def test_task_seeds_are_reproducible_and_depend_on_seed_and_family():
    assert task_seeds(0, "strip", 5) == task_seeds(0, "strip", 5)
    assert task_seeds(0, "strip", 5) != task_seeds(1, "strip", 5)
    assert set(task_seeds(0, "strip", 5)).isdisjoint(task_seeds(0, "minkowski", 5))


# Families too slow for the tiny and quick suites (codac's side takes minutes).
FULL_ONLY = {"speed_sonar"}


@pytest.mark.parametrize("suite", SUITES)
def test_every_family_has_seeded_tasks_in_every_suite(suite):
    names = [fam.name for fam in families()]
    assert len(names) == len(set(names))
    assert FULL_ONLY <= set(names)
    for fam in families():
        tasks = fam.tasks(suite, 0)
        assert bool(tasks) == (suite == "full" or fam.name not in FULL_ONLY), fam.name
        assert all(isinstance(t["seed"], int) for t in tasks)
        assert tasks == fam.tasks(suite, 0)


def test_suites_grow_from_tiny_to_full():
    for fam in families():
        sizes = [len(fam.tasks(suite, 0)) for suite in SUITES]
        assert sizes == sorted(sizes), fam.name


def test_family_kind_is_validated():
    from optbound.bench.family import Family

    with pytest.raises(ValueError, match="kind"):
        Family("x", "X", "fancy", (), lambda suite, seed: [], lambda task: {})


def test_missing_requirements_are_named():
    from optbound.bench.family import Family

    fam = Family("x", "X", "speed", ("optbound:nope", "no_such_module:run"), list, dict)
    assert fam.missing() == ["optbound:nope", "no_such_module:run"]
