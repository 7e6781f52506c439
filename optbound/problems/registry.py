"""Estimators by name: ``"pkg.module:callable"`` specs and the ``optbound.estimators`` entry points.

An installed package registers an estimator ``problem -> set`` in its ``pyproject.toml``::

    [project.entry-points."optbound.estimators"]
    my_box = "my_package.estimators:my_box"

and ``optbound bench --estimator all-registered`` then runs it beside optbound's own, which are
registered the same way (:mod:`optbound.problems.estimators`); ``--estimator my_box`` and
``optbound evaluate my_box`` run it alone. Any importable callable can also be named directly:
``optbound evaluate my_package.estimators:my_box``.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from importlib.metadata import entry_points
from typing import Any

#: The entry-point group under which packages register estimators.
GROUP = "optbound.estimators"
#: The ``--estimator`` value that stands for every registered estimator.
ALL_REGISTERED = "all-registered"


def load(spec: str) -> Callable[[Any], Any]:
    """Import the callable named by ``spec``.

    Parameters
    ----------
    spec : str
        ``"pkg.module:callable"``; ``callable`` may be dotted (``"pkg.module:Class.method"``).

    Returns
    -------
    callable
        The named object.

    Raises
    ------
    TypeError
        If ``spec`` is not a str.
    ValueError
        If ``spec`` is not of that form, the module cannot be imported (or raises while
        importing), it has no such attribute, or the attribute is not callable; the message
        names ``spec``.

    Examples
    --------
    >>> from optbound.problems.registry import load
    >>> load("optbound.problems.estimators:analytic_trace").__name__
    'analytic_trace'
    """
    if not isinstance(spec, str):
        raise TypeError(f"spec must be a str 'pkg.module:callable', got {type(spec).__name__}")
    module_name, sep, attr = spec.partition(":")
    if not sep or not module_name or not attr:
        raise ValueError(f"spec must be 'pkg.module:callable', got {spec!r}")
    try:
        target: Any = importlib.import_module(module_name)
    except Exception as exc:  # a missing module, or one that fails while importing
        raise ValueError(
            f"cannot import module {module_name!r} of {spec!r}: {type(exc).__name__}: {exc}"
        ) from None
    for part in attr.split("."):
        try:
            target = getattr(target, part)
        except AttributeError:
            raise ValueError(
                f"{spec!r}: module {module_name!r} has no attribute {attr!r}"
            ) from None
    if not callable(target):
        raise ValueError(f"{spec!r} is a {type(target).__name__}, not a callable estimator")
    return target


def registered() -> dict[str, str]:
    """List the estimators registered under :data:`GROUP` by installed distributions.

    Returns
    -------
    dict of str to str
        Entry-point name -> ``"pkg.module:callable"``, sorted by name (the entry points of
        every installed distribution).
    """
    return {ep.name: ep.value for ep in sorted(entry_points(group=GROUP), key=lambda e: e.name)}


def resolve(specs: list[str]) -> dict[str, Callable[[Any], Any]]:
    """Load the estimators named by ``--estimator`` values.

    Every callable is loaded here, so a bad spec fails before any work.

    Parameters
    ----------
    specs : list of str
        Each a ``"pkg.module:callable"`` spec (named by itself), the name of a registered
        estimator, or :data:`ALL_REGISTERED` (every one of :func:`registered`, by its
        entry-point name).

    Returns
    -------
    dict of str to callable
        Name -> estimator, in the order of ``specs``.

    Raises
    ------
    ValueError
        If a spec is neither ``"pkg.module:callable"`` nor a registered name, or :func:`load`
        rejects it.
    """
    named: dict[str, str] = {}
    for spec in specs:
        known = registered() if spec == ALL_REGISTERED or ":" not in spec else {}
        if spec == ALL_REGISTERED:
            named.update(known)
        elif ":" in spec or spec in known:
            named[spec] = known.get(spec, spec)
        else:
            raise ValueError(
                f"{spec!r} is neither 'pkg.module:callable' nor a registered estimator "
                f"(registered: {sorted(known)})"
            )
    return {name: load(spec) for name, spec in named.items()}
