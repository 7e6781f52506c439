"""Validate the numpydoc sections of optbound's public API.

Every public function, class and method (a name in a public module's ``__all__``, or a public
module-level name without ``__all__``, defined in that module) is checked with
:func:`numpydoc.validate.validate` for the checks in :data:`CHECKS`. Run::

    python docs/check_docstrings.py [optbound.sets optbound.interval ...]

It prints one line per failure and exits 1 if there is any. ``tests/test_docs.py`` runs it on
the packages listed in :data:`ENFORCED` (numpydoc comes with the ``docs`` extra; the test
is skipped without it).
"""

from __future__ import annotations

import importlib
import inspect
import pkgutil
import sys

# GL08 a docstring; SS01 a summary; SS03 ending with a period; PR01 every parameter documented;
# PR02 no unknown parameter; RT01 a Returns section where something is returned.
CHECKS = ("GL08", "SS01", "SS03", "PR01", "PR02", "RT01")
ENFORCED = [
    "optbound.sets",
    "optbound.analytic",
    "optbound.optimal",
    "optbound.compare",
    "optbound.interval",
    "optbound.localization",
    "optbound.scenarios",
    "optbound.problems",
    "optbound.report",
    "optbound.estimation",
    "optbound.bench",
]


def public_modules(package: str) -> list[str]:
    """``package`` and its public submodules, recursively (names starting with ``_`` skipped)."""
    module = importlib.import_module(package)
    found = [package]
    for info in pkgutil.iter_modules(getattr(module, "__path__", [])):
        if not info.name.startswith("_"):
            found += public_modules(f"{package}.{info.name}")
    return found


def public_objects(module_name: str) -> list[str]:
    """Qualified names of the functions, classes and methods defined in ``module_name``."""
    module = importlib.import_module(module_name)
    names = getattr(module, "__all__", [n for n in vars(module) if not n.startswith("_")])
    found = []
    for name in names:
        obj = getattr(module, name, None)
        if not (inspect.isfunction(obj) or inspect.isclass(obj)):
            continue
        if getattr(obj, "__module__", None) != module_name:
            continue  # documented where it is defined
        found.append(f"{module_name}.{name}")
        if inspect.isclass(obj):
            for attr, member in vars(obj).items():
                if attr.startswith("_") or not inspect.isfunction(member):
                    continue
                found.append(f"{module_name}.{name}.{attr}")
    return found


def protocol(qualified: str) -> bool:
    """Whether ``qualified`` names a ``typing.Protocol`` class."""
    module_name, _, attr = qualified.rpartition(".")
    try:
        obj = getattr(importlib.import_module(module_name), attr)
    except (ImportError, AttributeError):
        return False
    return inspect.isclass(obj) and getattr(obj, "_is_protocol", False)


def failures(packages: list[str]) -> list[str]:
    """``"name: CODE message"`` for every failed check in ``packages``."""
    from numpydoc.validate import validate

    lines = []
    for package in packages:
        for module_name in public_modules(package):
            for name in public_objects(module_name):
                try:
                    errors = validate(name)["errors"]
                except Exception as error:  # numpydoc cannot read it (e.g. a generated method)
                    errors = [("GL08", f"not validated: {type(error).__name__}")]
                for code, message in errors:
                    if code == "PR01" and protocol(name):
                        continue  # typing.Protocol's generated ``__init__(*args, **kwargs)``
                    if code in CHECKS:
                        lines.append(f"{name}: {code} {message}")
    return lines


if __name__ == "__main__":
    found = failures(sys.argv[1:] or ENFORCED)
    print("\n".join(found) or "all checks pass")
    print(f"{len(found)} failures", file=sys.stderr)
    sys.exit(1 if found else 0)
