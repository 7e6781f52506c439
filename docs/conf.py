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
templates_path = ["_templates"]
myst_heading_anchors = 3
suppress_warnings = ["myst.header"]

# API reference: every public subpackage, recursively, as its ``__all__`` lists.
autosummary_generate = True
autosummary_ignore_module_all = False
autosummary_imported_members = False
autodoc_default_options = {"show-inheritance": True}
autodoc_typehints = "none"  # numpydoc's Parameters sections carry the types
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False

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
