"""Package attributes imported on first access (PEP 562) and a ``dir()`` of public names only.

A package calls :func:`attach` and binds the two functions it returns as its module-level
``__getattr__`` and ``__dir__``: its submodules (and re-exported names) become attributes
without being imported up front, and ``dir(package)`` lists ``__all__`` plus those attributes
instead of the helpers a module namespace also holds (``annotations``, ``importlib``, ...).
"""

from __future__ import annotations

import importlib
import importlib.util
import pkgutil
import sys
from collections.abc import Callable, Iterable, Mapping


def public_submodules(package: str) -> list[str]:
    """The submodules of ``package`` whose names do not start with an underscore."""
    path = sys.modules[package].__path__
    return sorted(m.name for m in pkgutil.iter_modules(path) if not m.name.startswith("_"))


def attach(
    package: str,
    public: Iterable[str] = (),
    submodules: Iterable[str] | None = None,
    attributes: Mapping[str, str] | None = None,
) -> tuple[Callable[[str], object], Callable[[], list[str]]]:
    """``(__getattr__, __dir__)`` for ``package``.

    Parameters
    ----------
    package : str
        The package's ``__name__``.
    public : iterable of str
        Its ``__all__``: the names ``dir`` lists besides the lazy ones.
    submodules : iterable of str, optional
        Submodules reachable as attributes, imported on first access; a name whose module is
        absent from this install is not an attribute. Default: every public submodule found
        in the package's folder (:func:`public_submodules`).
    attributes : mapping of str to str, optional
        ``name -> module``: ``package.name`` is ``module.name``, imported on first access.
    """
    public = tuple(public)
    attributes = dict(attributes or {})

    def names() -> list[str]:
        if submodules is None:
            return public_submodules(package)
        return [n for n in submodules if importlib.util.find_spec(f"{package}.{n}")]

    def __getattr__(name: str) -> object:
        if name in attributes:
            value = getattr(importlib.import_module(attributes[name]), name)
            setattr(sys.modules[package], name, value)  # later lookups skip __getattr__
            return value
        if not name.startswith("_") and name in names():
            # import_module also binds the attribute on the package: this runs once per name.
            return importlib.import_module(f"{package}.{name}")
        raise AttributeError(f"module {package!r} has no attribute {name!r}")

    def __dir__() -> list[str]:
        return sorted({*public, *attributes, *names()})

    return __getattr__, __dir__
