"""The user guide where hydroservo is installed, as ``hydroservo docs`` lists and shows its pages.

The package's messages name pages of the guide (``docs/validation.md``); a wheel carries them
(:func:`hydroservo.data.guide_folder`), so each exists wherever hydroservo runs.

>>> from hydroservo.workflows.docs import Docs
>>> report = Docs("validation", path_only=True).run()
>>> report.page.name
'validation.md'
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, ClassVar

from hydroservo.errors import ParameterError, did_you_mean, shorten
from hydroservo.workflows.base import Progress, Report, Workflow

__all__ = ["Docs", "DocsReport"]


@dataclass
class DocsReport(Report):
    """The guide's pages and their titles, or one page (its text, or only where it is)."""

    command: ClassVar[str] = "docs"

    folder: Path
    pages: dict[str, str] = field(default_factory=dict)  #: file name -> title
    page: Path | None = None
    text: str | None = None

    def title(self) -> str:
        return "hydroservo's user guide"

    def lines(self) -> list[str]:
        if self.page is not None:
            return [str(self.page)] if self.text is None else self.text.rstrip("\n").splitlines()
        width = max(len(n) for n in self.pages)
        return [f"the user guide, in {self.folder}:"] + [f"  {n.ljust(width)}  {t}" for n, t in self.pages.items()] + [
            "hydroservo docs NAME prints a page (--path: where it is)"]

    def to_dict(self) -> dict[str, Any]:
        found: dict[str, Any] = {"folder": str(self.folder), "pages": self.pages}
        if self.page is not None:
            found["page"] = str(self.page)
        return found


@dataclass
class Docs(Workflow):
    """List the guide's pages, or show ``page`` (``validation``, ``validation.md`` or ``docs/validation.md``)."""

    OPTIONS: ClassVar[dict[str, str]] = {"page": "PAGE", "path_only": "--path"}

    page: str | None = None
    path_only: bool = False

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> DocsReport:
        from hydroservo.data import guide_folder

        where = guide_folder()
        if where is None:
            raise ParameterError("the user guide is not installed with this copy of hydroservo (built without docs/); "
                                 "expected hydroservo/docs in the package or docs/ in the repository")
        pages = {p.name: _title(p) for p in sorted(where.glob("*.md")) if p.name not in ("index.md", "api.md")}
        if self.page is None:
            return DocsReport(where, pages)
        name = Path(self.page.strip()).name
        name = name if name.endswith(".md") else f"{name}.md"
        if name not in pages:
            raise ParameterError(
                f"{self.name('page')} {shorten(self.page)!r}: no such page{did_you_mean(name, pages)}; pages: "
                f"{', '.join(pages)}"
            )
        path = where / name
        return DocsReport(where, pages, path, None if self.path_only else path.read_text(encoding="utf-8"))


def _title(page: Path) -> str:
    for line in page.read_text(encoding="utf-8").splitlines():
        if line.startswith("# "):
            return line[2:].strip()
    return page.stem
