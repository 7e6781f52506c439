"""Sphinx configuration of the optbound documentation.

Build: ``pip install -e ".[docs]" && sphinx-build -W -b html docs docs/_build/html``.
``OPTBOUND_DOCS_GALLERY=quick`` executes only the gallery examples whose name does not start
with ``plot_paper_`` (the CI build); the default executes every example.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the checkout's optbound wins over any other install

import optbound  # noqa: E402

project = "optbound"
author = "the optbound developers"
copyright = "2026, the optbound developers"
release = version = optbound.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "numpydoc",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
exclude_patterns = ["_build", "**/sg_execution_times.rst", "sg_execution_times.rst"]
myst_heading_anchors = 3
suppress_warnings = ["myst.header"]

# API reference: one page per public module of every public subpackage (recursively), written
# by ``api_pages`` below; ``api.rst`` lists the subpackages in an autosummary table. A
# package's page documents the names of its ``__all__`` defined in the package itself or in a
# private module; a name defined in a public submodule is documented on that submodule's page
# only (so every object has one description, and a function named like its module, e.g.
# ``optbound.interval.sivia``, does not hide the module's page).
SUBPACKAGES = [
    "sets",
    "analytic",
    "optimal",
    "compare",
    "interval",
    "localization",
    "scenarios",
    "problems",
    "estimation",
    "bench",
    "report",
]
autosummary_generate = False
autodoc_default_options = {"show-inheritance": True, "undoc-members": True}
autodoc_typehints = "none"  # numpydoc's Parameters sections carry the types
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False


def public_modules_of(name: str) -> list[str]:
    """The public submodules of package ``name`` (none for a plain module)."""
    import importlib
    import pkgutil

    module = importlib.import_module(name)
    paths = getattr(module, "__path__", [])
    return sorted(f"{name}.{i.name}" for i in pkgutil.iter_modules(paths) if i.name[0] != "_")


def public_modules() -> dict[str, list[str]]:
    """``{module: [public submodules]}`` for every public module under :data:`SUBPACKAGES`."""
    found: dict[str, list[str]] = {}

    def walk(name: str) -> None:
        found[name] = public_modules_of(name)
        for sub in found[name]:
            walk(sub)

    for package in SUBPACKAGES:
        walk(f"optbound.{package}")
    return found


def own_names(name: str) -> list[str]:
    """The names of package ``name``'s ``__all__`` that its own page documents: those no public
    submodule's page documents (defined in the package itself or in a private module, or left
    out of their module's ``__all__``)."""
    import importlib
    import types

    module = importlib.import_module(name)
    elsewhere = {  # documented on a public submodule's page (its __all__ re-exports it)
        attr
        for sub in public_modules_of(name)
        for attr in getattr(importlib.import_module(sub), "__all__", [])
    }
    names = []
    for attr in getattr(module, "__all__", []):
        obj = getattr(module, attr)
        if isinstance(obj, types.ModuleType) or attr in elsewhere:
            continue
        owner = getattr(obj, "__module__", None) or name
        private = any(part.startswith("_") for part in owner.split("."))
        listed = getattr(importlib.import_module(owner), "__all__", [attr])
        if owner == name or private or not owner.startswith("optbound.") or attr not in listed:
            names.append(attr)
    return names


def api_pages(app) -> None:
    """Write ``api/generated/<module>.rst`` for every public module (see above)."""
    out = Path(app.srcdir) / "api" / "generated"
    out.mkdir(parents=True, exist_ok=True)
    import importlib

    for name, subs in public_modules().items():
        lines = [name, "=" * len(name), "", f".. automodule:: {name}"]
        module = importlib.import_module(name)
        own = own_names(name) if subs else []
        code = [a for a in own if callable(getattr(module, a))]  # functions and classes
        if not subs:
            lines.append("   :members:")
        elif code:
            lines.append(f"   :members: {', '.join(code)}")
        lines.append("")
        # Constants a package re-exports (autodoc documents module data only where assigned).
        lines += [f".. autodata:: {name}.{a}\n   :no-value:\n" for a in own if a not in code]
        if subs:
            lines += [".. rubric:: Submodules", "", ".. toctree::", "   :maxdepth: 1", ""]
            lines += [f"   {sub}" for sub in subs]
        text = "\n".join(lines) + "\n"
        page = out / f"{name}.rst"
        if not page.is_file() or page.read_text() != text:  # unchanged pages stay cached
            page.write_text(text)


def setup(app) -> None:
    app.connect("builder-inited", api_pages)


html_theme = "pydata_sphinx_theme"
html_title = "optbound"
html_theme_options = {"navigation_with_keys": False, "show_toc_level": 2}

QUICK = os.environ.get("OPTBOUND_DOCS_GALLERY", "full") == "quick"
sphinx_gallery_conf = {
    "examples_dirs": str(ROOT / "examples"),
    "gallery_dirs": "auto_examples",
    # Every example runs in the full build; the CI build skips the paper reproductions.
    "filename_pattern": r"/plot_(?!paper_)" if QUICK else r"/plot_",
    "download_all_examples": False,
    "remove_config_comments": True,
    "within_subsection_order": "FileNameSortKey",
    "matplotlib_animations": False,
    "image_scrapers": ("matplotlib",),
    "reset_modules": ("matplotlib",),
    "min_reported_time": 1,
}
