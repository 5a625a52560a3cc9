"""A sphinx-gallery image scraper for the docs' examples (docs/conf.py): the figures an example wrote to
``$HYDROSERVO_DOCS_IMG``, shown below the block that wrote them. hydroservo's plotting functions save and close a
figure given ``file=``, so matplotlib's own scraper never sees those; and a figure an example saves itself and
leaves open would be shown twice by both."""

from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path
from typing import Any


class WrittenFigures:
    """Called after each code block of an example: the PNG files written (or rewritten) since, as figures."""

    def __init__(self) -> None:
        self.seen: dict[Path, float] = {}

    def __repr__(self) -> str:  # sphinx-gallery keys its cache on the configuration's repr
        return "WrittenFigures()"

    def __call__(self, block: Any, block_vars: dict[str, Any], gallery_conf: dict[str, Any]) -> str:
        from sphinx_gallery.scrapers import figure_rst

        folder = Path(os.environ["HYDROSERVO_DOCS_IMG"])
        written = sorted(f for f in folder.glob("*.png") if self.seen.get(f) != f.stat().st_mtime)
        paths = []
        for figure, target in zip(written, block_vars["image_path_iterator"]):
            self.seen[figure] = figure.stat().st_mtime
            shutil.copyfile(figure, target)
            paths.append(target)
        if "matplotlib.pyplot" in sys.modules:  # what is not saved is not shown: free it
            sys.modules["matplotlib.pyplot"].close("all")
        return figure_rst(paths, gallery_conf["src_dir"])
