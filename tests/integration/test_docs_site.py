"""The documentation site reads offline: its equations are typeset by a MathJax served from the built site, never
from a CDN (docs/conf.py: the extension sphinx-mathjax-offline, in the ``[docs]`` extra), and no page loads a
script from elsewhere (sphinx-gallery's pages of run times, which do, are not written).

Sphinx's own default loads MathJax from a CDN, so that a copy of the site read without a network shows every
equation as raw LaTeX. The first tests read docs/conf.py and pyproject.toml (no Sphinx needed: they run with the
``[test]`` extra); the last builds a page with equations under docs/conf.py's extensions and reads its HTML, where
Sphinx and the ``[docs]`` extra are installed (CI builds the whole site after the tests).
"""

from __future__ import annotations

import ast
import importlib
import importlib.util
import re
import subprocess
import sys
import tomllib
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
CONF = ROOT / "docs" / "conf.py"
OFFLINE = "sphinx-mathjax-offline"


def conf_assignments() -> dict[str, Any]:
    """The literal values docs/conf.py assigns at its top level (name -> value), read without running it."""
    values: dict[str, Any] = {}
    for node in ast.parse(CONF.read_text(encoding="utf-8")).body:
        targets = node.targets if isinstance(node, ast.Assign) else [node.target] if isinstance(node, ast.AnnAssign) else []
        value = getattr(node, "value", None)
        for target in targets:
            if isinstance(target, ast.Name) and value is not None:
                try:
                    values[target.id] = ast.literal_eval(value)
                except ValueError:
                    values[target.id] = ast.unparse(value)
    return values


def test_conf_serves_mathjax_from_the_built_site() -> None:
    conf = conf_assignments()
    extensions = conf["extensions"]
    assert "sphinx.ext.mathjax" in extensions and OFFLINE in extensions
    # nothing in the configuration points MathJax elsewhere (a mathjax_path or a config naming a URL)
    for name, value in conf.items():
        if "mathjax" in name.lower():
            assert not re.search(r"https?://|//cdn", str(value)), f"{name} = {value!r}"
    assert not re.search(r"https?://[^\s\"']*mathjax", CONF.read_text(encoding="utf-8"), flags=re.I)
    # sphinx-gallery's pages of run times load jQuery and DataTables from CDNs: not written
    assert re.search(r"[\"']write_computation_times[\"']\s*:\s*False", str(conf["sphinx_gallery_conf"]))


def test_the_docs_extra_installs_the_mathjax_it_serves() -> None:
    extra = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]["optional-dependencies"]
    assert any(re.match(rf"{OFFLINE}\b", requirement) for requirement in extra["docs"])


@pytest.mark.skipif(importlib.util.find_spec(OFFLINE) is None, reason=f"{OFFLINE} not installed (the [docs] extra)")
def test_the_extension_points_mathjax_at_its_own_copy() -> None:
    """The extension, set up, points mathjax_path at a file of the site's _static folder, which it carries."""
    module = importlib.import_module(OFFLINE)

    class Config:
        mathjax_path = "https://cdn.example/mathjax.js"

    class App:
        config = Config()
        hooks: list[str] = []

        def connect(self, event: str, callback: Any) -> None:
            self.hooks.append(event)

    app = App()
    module.setup(app)
    path = app.config.mathjax_path
    assert not re.match(r"\w+:|//", path), path  # relative to _static: served from the site
    assert (Path(module.__file__).parent / "static" / path).is_file()
    assert "build-finished" in app.hooks  # where it copies MathJax into the built site


@pytest.mark.slow
@pytest.mark.skipif(
    importlib.util.find_spec("sphinx") is None or importlib.util.find_spec("myst_parser") is None,
    reason="Sphinx and MyST not installed (the [docs] extra)",
)
def test_a_page_with_equations_loads_mathjax_from_the_site(tmp_path: Path) -> None:
    """A page with equations built under docs/conf.py (its extensions, less those that read the package and run
    the examples): every script it loads is the site's own, MathJax among them, and the file is there."""
    extensions = [e for e in conf_assignments()["extensions"] if not e.startswith(("sphinx_gallery", "sphinx.ext.auto"))]
    source = tmp_path / "src"
    source.mkdir()
    (source / "index.md").write_text(
        "# Equations\n\nThe orifice law $Q = c_v x_v \\sqrt{\\Delta p}$ and\n\n$$\n\\dot x = A x + B u\n$$\n",
        encoding="utf-8",
    )
    out = tmp_path / "html"
    done = subprocess.run(
        [sys.executable, "-m", "sphinx", "-q", "-b", "html", "-c", str(CONF.parent), "-D",
         f"extensions={','.join(extensions)}", str(source), str(out)],
        capture_output=True, text=True, timeout=600,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    html = (out / "index.html").read_text(encoding="utf-8")
    scripts = re.findall(r"<script[^>]*\bsrc=\"([^\"]+)\"", html)
    assert scripts and [s for s in scripts if re.match(r"\w+:|//", s)] == []
    mathjax = [s for s in scripts if "mathjax" in s.lower()]
    assert mathjax == ["_static/mathjax/tex-chtml.js"]
    assert (out / "_static" / "mathjax" / "tex-chtml.js").is_file()
    assert (out / "_static" / "mathjax" / "output" / "chtml" / "fonts" / "woff-v2").is_dir()  # its fonts too
