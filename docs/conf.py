"""Sphinx configuration: MyST Markdown, API from docstrings, math rendered by a MathJax copy
shipped with the build (sphinx-mathjax-offline), pages from code written by _ext/."""

import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE / "_ext"), str(HERE.parent)]  # the extension and the derive package

from symimpact import __version__  # noqa: E402

project = "symimpact"
author = "symimpact developers"
copyright = "2026, symimpact developers"
release = version = __version__

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
    "sphinx-mathjax-offline",  # copies MathJax 3 into _static: no CDN, math renders offline
    "symimpact_pages",
]
source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
myst_enable_extensions = ["dollarmath", "amsmath"]
myst_heading_anchors = 3
exclude_patterns = ["_build", "_generated/report/*.md"]
html_theme = "alabaster"
html_title = f"symimpact {__version__}"
autodoc_member_order = "bysource"
autodoc_typehints = "description"
napoleon_numpy_docstring = True
suppress_warnings = ["myst.header"]
html_static_path = ["_static"]
html_css_files = ["symimpact.css"]
