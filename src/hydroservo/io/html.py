"""Reports as one self-contained HTML file: a page of sections holding text, tables, figures and drawings.

A :class:`Page` is what a workflow's report holds to show itself
(:meth:`hydroservo.workflows.base.Report.document`): a title, and sections of
:class:`Text`, :class:`Table`, :class:`Figure` (an interactive plot, given as
a plotly figure in its JSON form, so that this writer needs no plotting
library), :class:`Drawing` (SVG markup: the circuit's schematic) and
:class:`Notice` (a warning or a verdict). :func:`render_html` makes the page,
:func:`write_html` writes it.

The file opens from disk or as an e-mail attachment with no network: its
styles, the plots' JavaScript (plotly.js, once per file) and its drawings are
all inside it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

__all__ = ["Page", "Section", "Text", "Table", "Figure", "Drawing", "Notice", "Item", "render_html", "write_html"]


@dataclass
class Text:
    """A paragraph of plain text (no markup: it is escaped)."""

    text: str
    #: ``True``: shown as it is, in a fixed-width font (a table the command line prints)
    preformatted: bool = False


@dataclass
class Table:
    """A table: a header row and rows of cells; numbers are shown with ``digits`` significant digits."""

    columns: list[str]
    rows: list[list[Any]]
    caption: str = ""
    digits: int = 5


@dataclass
class Figure:
    """An interactive plot: a plotly figure as a dict with ``data`` and ``layout`` (``fig.to_plotly_json()``)."""

    spec: dict[str, Any]
    caption: str = ""


@dataclass
class Drawing:
    """SVG markup drawn as it is (a schematic), with a caption."""

    svg: str
    caption: str = ""


@dataclass
class Notice:
    """A line that must be seen: a warning, an error, or a verdict that holds (``ok``)."""

    text: str
    level: Literal["info", "ok", "warning", "error"] = "warning"


Item = Text | Table | Figure | Drawing | Notice


@dataclass
class Section:
    """A titled part of a page."""

    title: str
    items: list[Item] = field(default_factory=list)


@dataclass
class Page:
    """A report: a title, a subtitle (what was run), the sections, and a footer line (who made it, when)."""

    title: str
    subtitle: str = ""
    sections: list[Section] = field(default_factory=list)
    footer: str = ""


def render_html(page: Page) -> str:
    """The page as one self-contained HTML document."""
    raise NotImplementedError("render_html: the HTML writer is not written yet")


def write_html(page: Page, path: str | Path) -> Path:
    """Write :func:`render_html` of ``page`` to ``path`` (UTF-8) and return the path."""
    path = Path(path)
    path.write_text(render_html(page), encoding="utf-8")
    return path
