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

import functools
import html
import json
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

__all__ = [
    "Page", "Section", "Text", "Table", "Figure", "Drawing", "Picture", "Notice", "Item", "render_html", "write_html",
    "fragment",
]


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
class Picture:
    """A raster image (PNG bytes, a static plot) put inside the page, with a caption."""

    png: bytes
    caption: str = ""


@dataclass
class Notice:
    """A line that must be seen: a warning, an error, or a verdict that holds (``ok``)."""

    text: str
    level: Literal["info", "ok", "warning", "error"] = "warning"


Item = Text | Table | Figure | Drawing | Picture | Notice


@dataclass
class Section:
    """A titled part of a page."""

    title: str
    items: Sequence[Item] = field(default_factory=list)


@dataclass
class Page:
    """A report: a title, a subtitle (what was run), the sections, and a footer line (who made it, when)."""

    title: str
    subtitle: str = ""
    sections: list[Section] = field(default_factory=list)
    footer: str = ""


_CSS = """
:root { --ink: #1b1f24; --muted: #5b6470; --line: #d9dee4; --band: #f4f6f8; --accent: #0b5cad; }
* { box-sizing: border-box; }
body { margin: 0; color: var(--ink); background: #fff;
       font: 14px/1.5 system-ui, -apple-system, "Segoe UI", Roboto, Helvetica, Arial, sans-serif; }
header { padding: 22px 32px 14px; border-bottom: 3px solid var(--accent); background: var(--band); }
header h1 { margin: 0 0 4px; font-size: 24px; }
header p { margin: 0; color: var(--muted); }
nav { padding: 8px 32px; border-bottom: 1px solid var(--line); font-size: 13px; }
nav a { margin-right: 14px; color: var(--accent); text-decoration: none; white-space: nowrap; }
main { padding: 8px 32px 24px; max-width: 1200px; }
section { margin-top: 22px; }
h2 { font-size: 18px; margin: 0 0 10px; padding-bottom: 4px; border-bottom: 1px solid var(--line); }
p.text { margin: 6px 0; max-width: 900px; }
pre { background: var(--band); padding: 10px 12px; border: 1px solid var(--line); overflow-x: auto; font-size: 12px; }
.scroll { max-height: 520px; overflow: auto; border: 1px solid var(--line); }
table { border-collapse: collapse; font-size: 13px; margin: 4px 0 10px; }
.scroll table { margin: 0; }
th, td { padding: 4px 10px; border-bottom: 1px solid var(--line); text-align: left; vertical-align: top; }
th { background: var(--band); position: sticky; top: 0; font-weight: 600; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
tr:hover td { background: #fafbfc; }
caption { caption-side: bottom; text-align: left; color: var(--muted); font-size: 12px; padding-top: 4px; }
figure { margin: 8px 0 16px; }
figcaption { color: var(--muted); font-size: 12px; }
.plot { width: 100%; min-height: 300px; }
.drawing { overflow-x: auto; border: 1px solid var(--line); padding: 8px; background: #fff; }
.drawing svg { max-width: 100%; height: auto; }
.notice { padding: 8px 12px; margin: 6px 0; border-left: 4px solid; border-radius: 2px; }
.notice.warning { background: #fff6e5; border-color: #e69f00; }
.notice.error { background: #fdecea; border-color: #c62828; }
.notice.ok { background: #eaf6ee; border-color: #2e7d32; }
.notice.info { background: #eaf2fb; border-color: var(--accent); }
footer { padding: 14px 32px; color: var(--muted); font-size: 12px; border-top: 1px solid var(--line); }
@media print { nav { display: none; } .scroll { max-height: none; overflow: visible; } th { position: static; } }
"""


def _cell(value: Any, digits: int) -> tuple[str, bool]:
    """A table cell's text and whether it is a number (right-aligned)."""
    import math

    if value is None:
        return "–", False
    if isinstance(value, bool):
        return ("yes" if value else "no"), False
    if isinstance(value, int | float) or hasattr(value, "dtype"):
        v = float(value)
        if math.isnan(v):
            return "–", True
        return f"{v:.{digits}g}", True
    return html.escape(str(value)), False


def _table(t: Table) -> str:
    head = "".join(f"<th>{html.escape(c)}</th>" for c in t.columns)
    rows = []
    for row in t.rows:
        cells = []
        for v in row:
            text, number = _cell(v, t.digits)
            cells.append(f'<td class="num">{text}</td>' if number else f"<td>{text}</td>")
        rows.append("<tr>" + "".join(cells) + "</tr>")
    caption = f"<caption>{html.escape(t.caption)}</caption>" if t.caption else ""
    body = f"<table>{caption}<thead><tr>{head}</tr></thead><tbody>{''.join(rows)}</tbody></table>"
    return f'<div class="scroll">{body}</div>' if len(t.rows) > 25 else body


def _script_json(value: Any) -> str:
    """JSON safe inside a <script> element: ASCII (U+2028 escaped), and no ``<`` at all (``</script>`` and
    ``<!--`` in a name cannot end or change the element), every ``<`` being inside a JSON string, as ``\\u003c``."""
    return json.dumps(value, default=_plain).replace("<", "\\u003c")


def _plain(value: Any) -> Any:
    if hasattr(value, "tolist"):
        return value.tolist()
    raise TypeError(f"not JSON: {type(value).__name__}")


def _svg(markup: str) -> str:
    """SVG markup to put inline: without its XML declaration and doctype."""
    text = re.sub(r"<\?xml[^>]*\?>", "", markup)
    text = re.sub(r"<!DOCTYPE[^>]*>", "", text, flags=re.I)
    return text.strip()


def _item(item: Item, figures: list[tuple[str, Figure]]) -> str:
    if isinstance(item, Text):
        if item.preformatted:
            return f"<pre>{html.escape(item.text)}</pre>"
        return "".join(f'<p class="text">{html.escape(p)}</p>' for p in item.text.split("\n\n"))
    if isinstance(item, Table):
        return _table(item)
    if isinstance(item, Figure):
        ident = f"figure-{len(figures) + 1}"
        figures.append((ident, item))
        caption = f"<figcaption>{html.escape(item.caption)}</figcaption>" if item.caption else ""
        return f'<figure><div class="plot" id="{ident}"></div>{caption}</figure>'
    if isinstance(item, Drawing):
        caption = f"<figcaption>{html.escape(item.caption)}</figcaption>" if item.caption else ""
        return f'<figure><div class="drawing">{_svg(item.svg)}</div>{caption}</figure>'
    if isinstance(item, Picture):
        import base64

        caption = f"<figcaption>{html.escape(item.caption)}</figcaption>" if item.caption else ""
        data = base64.b64encode(item.png).decode("ascii")
        return f'<figure><img alt="{html.escape(item.caption)}" style="max-width: 100%" src="data:image/png;base64,{data}">{caption}</figure>'
    if isinstance(item, Notice):
        level = item.level if item.level in ("info", "ok", "warning", "error") else "warning"
        return f'<div class="notice {level}">{html.escape(item.text)}</div>'
    raise TypeError(f"a page item: {type(item).__name__}")


#: The styles of a notebook fragment: the page's tables and notices, scoped to the fragment.
_FRAGMENT_CSS = """
.hydroservo table { border-collapse: collapse; font-size: 12px; margin: 4px 0 8px; }
.hydroservo th, .hydroservo td { padding: 2px 8px; border-bottom: 1px solid #d9dee4; text-align: left; }
.hydroservo td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
.hydroservo .scroll { max-height: 320px; overflow: auto; }
.hydroservo .notice { padding: 4px 10px; margin: 4px 0; border-left: 4px solid #0b5cad; background: #eaf2fb; }
.hydroservo .notice.warning { background: #fff6e5; border-color: #e69f00; }
.hydroservo .drawing svg { max-width: 100%; height: auto; }
.hydroservo figure { margin: 4px 0; }
.hydroservo figcaption, .hydroservo caption { color: #5b6470; font-size: 11px; }
.hydroservo summary { cursor: pointer; color: #0b5cad; }
"""


def fragment(title: str, items: Sequence[Item], more: Sequence[tuple[str, Sequence[Item]]] = ()) -> str:
    """HTML to show inside a notebook (``_repr_html_``): a title line, ``items``, and each of ``more`` as a
    part folded under its heading; no scripts, so interactive figures are left out."""
    figures: list[tuple[str, Figure]] = []
    body = "".join(_item(i, figures) for i in items if not isinstance(i, Figure))
    folded = "".join(
        f"<details><summary>{html.escape(head)}</summary>{''.join(_item(i, figures) for i in part if not isinstance(i, Figure))}</details>"
        for head, part in more
    )
    return f'<div class="hydroservo"><style>{_FRAGMENT_CSS}</style><strong>{html.escape(title)}</strong>{body}{folded}</div>'


def _anchor(k: int, title: str) -> str:
    return f"s{k}-" + re.sub(r"[^a-z0-9]+", "-", title.lower()).strip("-")[:40]


def render_html(page: Page) -> str:
    """The page as one self-contained HTML document: styles, drawings and plotly.js (when it has figures) inside.

    Nothing is fetched when it is viewed: no fonts, no scripts, no MathJax from the network.
    """
    figures: list[tuple[str, Figure]] = []
    sections = []
    for k, section in enumerate(page.sections):
        body = "\n".join(_item(item, figures) for item in section.items)
        sections.append(f'<section id="{_anchor(k, section.title)}"><h2>{html.escape(section.title)}</h2>{body}</section>')
    nav = " ".join(f'<a href="#{_anchor(k, s.title)}">{html.escape(s.title)}</a>' for k, s in enumerate(page.sections))
    scripts = ""
    if figures:
        config = {"responsive": True, "displaylogo": False, "modeBarButtonsToRemove": ["lasso2d", "select2d"],
                  "toImageButtonOptions": {"format": "png", "scale": 2}}
        calls = "\n".join(
            f"Plotly.newPlot({json.dumps(ident)}, {_script_json(f.spec.get('data', []))}, "
            f"{_script_json(f.spec.get('layout', {}))}, {json.dumps(config)});"
            for ident, f in figures
        )
        scripts = (f"<script>window.PlotlyConfig = {{MathJaxConfig: 'local'}};</script>\n"
                   f"<script>{_plotly_js()}</script>\n<script>\n{calls}\n</script>")
    subtitle = f"<p>{html.escape(page.subtitle)}</p>" if page.subtitle else ""
    footer = f"<footer>{html.escape(page.footer)}</footer>" if page.footer else ""
    return (
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
        '<meta name="generator" content="hydroservo">\n'
        f"<title>{html.escape(page.title)}</title>\n<style>{_CSS}</style>\n</head>\n<body>\n"
        f"<header><h1>{html.escape(page.title)}</h1>{subtitle}</header>\n<nav>{nav}</nav>\n"
        f"<main>\n{''.join(sections)}\n</main>\n{footer}\n{scripts}\n</body>\n</html>\n"
    )


@functools.cache
def _plotly_js() -> str:
    """plotly.js, as the ``plotly`` package ships it, safe inside a <script> element."""
    from plotly.offline import get_plotlyjs

    return str(get_plotlyjs()).replace("</script", "<\\/script")


def write_html(page: Page, path: str | Path) -> Path:
    """Write :func:`render_html` of ``page`` to ``path`` (UTF-8) and return the path."""
    path = Path(path)
    path.write_text(render_html(page), encoding="utf-8")
    return path
