"""Sphinx configuration of hydroservo's documentation site.

Build: ``python -m sphinx -W --keep-going -b html docs docs/_build/html`` (what ``.ci/run`` does; warnings are
errors). Sphinx, not MkDocs, because the package's docstrings cross-reference with Sphinx roles
(``:class:`~hydroservo.system.System```, ``:func:``, ``:meth:``, ``:data:``), which autodoc resolves into links and
MkDocs' mkdocstrings would print raw; the user guide stays Markdown (MyST), the examples are executed at build
time by sphinx-gallery with their figures, and the component reference is generated from the components'
declarations (``docs/tools/generated.py``) with its equations rendered by MathJax.

MathJax is served from the built site, never from a CDN, so that the site reads offline (a copy on a laptop, a
download of CI's build): the extension ``sphinx-mathjax-offline`` (PyPI, in the ``[docs]`` extra) carries MathJax
3.2.2, copies it to ``_static/mathjax/`` at the end of the build and points ``mathjax_path`` there
(``tests/integration/test_docs_site.py`` keeps it so).
"""

from __future__ import annotations

import os
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "src"))
sys.path.insert(0, str(HERE / "tools"))

from written_figures import WrittenFigures  # noqa: E402

import hydroservo  # noqa: E402

project = "hydroservo"
author = "the hydroservo developers"
copyright = "2026, the hydroservo developers"
release = hydroservo.__version__
version = release

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
    "sphinx-mathjax-offline",  # MathJax from the package, not a CDN (above)
    "sphinx.ext.viewcode",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
root_doc = "index"
exclude_patterns = ["_build", "tools", "examples", "auto_examples/*.ipynb", "auto_examples/*.py"]

# -- the user guide (Markdown) ---------------------------------------------------------------------------------
myst_enable_extensions = ["dollarmath", "amsmath", "deflist", "colon_fence"]
myst_heading_anchors = 3
# links from the guide to the repository's files (tests, benchmarks, sources) are links to files, not pages
suppress_warnings = ["myst.xref_missing", "myst.header"]
# type hints name protocols by what they stand for (a writer's ``Result`` protocol beside the result class):
# a name with two targets links to one of them, which is no error of the docs
suppress_warnings += ["ref.python"]

# -- the API reference ---------------------------------------------------------------------------------------------
autosummary_generate = True
autosummary_imported_members = False
autodoc_default_options = {"members": True, "show-inheritance": True, "ignore-module-all": True}
autodoc_member_order = "bysource"
autodoc_typehints = "description"
autodoc_preserve_defaults = True
napoleon_numpy_docstring = True
napoleon_google_docstring = False
napoleon_use_rtype = False

# -- the examples, run at build time -----------------------------------------------------------------------------
# The scripts write their figures for the guide to docs/img when run by hand; here into a folder of the build's.
os.environ.setdefault("HYDROSERVO_DOCS_IMG", tempfile.mkdtemp(prefix="hydroservo-docs-img-"))
os.environ.setdefault("HYDROSERVO_CACHE", str(HERE / "_build" / "cache"))



sphinx_gallery_conf = {
    "image_scrapers": (WrittenFigures(),),  # every example saves its figures for the guide: those are shown
    "examples_dirs": "examples",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r"/plot_",
    "ignore_pattern": r"make_example_files|spool_|__init__",
    "download_all_examples": False,
    "remove_config_comments": True,
    "abort_on_example_error": True,
    "matplotlib_animations": False,
    "within_subsection_order": "FileNameSortKey",
    # no pages of the examples' run times: sphinx-gallery styles their tables with scripts from CDNs (jQuery,
    # DataTables), and the site reads offline (above); the times are the build machine's, not the reader's
    "write_computation_times": False,
}

# -- the pages -----------------------------------------------------------------------------------------------------
html_theme = "furo"
html_title = f"hydroservo {release}"
html_static_path: list[str] = []
html_show_sourcelink = False


# -- members matplotlib writes for each subclass -------------------------------------------------------------------
def _skip_matplotlib_set(app, what, name, obj, skip, options):
    """matplotlib gives every Artist subclass a generated ``set`` whose docstring uses matplotlib's own roles
    (``:mpltype:``), unknown here: plotting's ShownFigure (a Figure) would fail the build; its ``set`` is
    matplotlib's, documented there."""
    if name == "set" and getattr(obj, "__module__", "") == "matplotlib.artist":
        return True
    return None


def setup(app):
    app.connect("autodoc-skip-member", _skip_matplotlib_set)
