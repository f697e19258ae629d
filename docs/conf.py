"""Sphinx configuration of rbcli's API reference (``sphinx-build -W -b html docs docs/_build``)."""

from __future__ import annotations

import os
import sys

sys.path.insert(0, os.path.abspath(".."))

import rbcli  # noqa: E402

project = "rbcli"
author = "the rbcli developers"
release = version = rbcli.__version__
copyright = "2026, the rbcli developers"  # noqa: A001 - Sphinx's name

extensions = ["sphinx.ext.autodoc", "numpydoc"]
exclude_patterns = ["_build"]
html_theme = "alabaster"
html_static_path: list[str] = []

autodoc_member_order = "bysource"
autodoc_typehints = "none"  # the numpydoc sections say the types, with units
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False
nitpicky = False
