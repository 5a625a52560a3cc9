"""The component reference: every component type by kind, and one type's equations, parameters, ports and
options (``hydroservo components``, ``hydroservo describe``).

>>> from hydroservo.workflows import components
>>> components.describe("Cylinder").reference.name
'Cylinder'
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from hydroservo.workflows.base import Progress, Report, Workflow

if TYPE_CHECKING:
    from hydroservo.components.reference import Reference
    from hydroservo.io.html import Page

__all__ = ["Catalogue", "CatalogueReport", "Describe", "DescriptionReport", "catalogue", "describe"]


@dataclass
class CatalogueReport(Report):
    """Every component type, by kind, with its one-line summary."""

    command: ClassVar[str] = "components"

    references: list[Reference]

    def title(self) -> str:
        return "hydroservo's component types"

    def to_dict(self) -> dict[str, Any]:  # a list, as the command has always printed it
        return {"components": [{"name": r.name, "kind": r.kind, "summary": r.summary} for r in self.references]}

    def to_json(self) -> str:
        import json

        return json.dumps(self.to_dict()["components"], indent=2, default=float)

    def lines(self) -> list[str]:
        refs = self.references
        width = max(len(r.name) for r in refs)
        out: list[str] = []
        kind = None
        for r in refs:
            group = r.kind.split(".")[0]
            if group != kind:
                out.append(f"{'' if kind is None else chr(10)}{group}:")
                kind = group
            out.append(f"  {r.name.ljust(width)}  {r.summary}")
        out.append("\nhydroservo describe TYPE: equations, parameters, ports and options of one")
        return out


@dataclass
class Catalogue(Workflow):
    """List every component type."""

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> CatalogueReport:
        from hydroservo.components.reference import catalogue

        return CatalogueReport(catalogue())


@dataclass
class DescriptionReport(Report):
    """One component type: its equations, parameters (unit, default, range), ports and options."""

    command: ClassVar[str] = "describe"

    reference: Reference

    def title(self) -> str:
        return f"{self.reference.name}: {self.reference.summary}"

    def to_dict(self) -> dict[str, Any]:
        return self.reference.to_dict()

    def lines(self) -> list[str]:
        from hydroservo.components.reference import text

        return text(self.reference).splitlines()

    def text(self) -> str:
        """The description as the command prints it."""
        from hydroservo.components.reference import text

        return text(self.reference)

    def document(self) -> Page:
        """The component's description as the command prints it."""
        from hydroservo.io.html import Section, Text
        from hydroservo.workflows import pages

        return pages.page(self.reference.name, self.reference.summary, [Section("Reference", [Text(self.text(), True)])])


@dataclass
class Describe(Workflow):
    """Describe component type ``type`` (a class name, e.g. ``"Cylinder"``)."""

    type: str

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> DescriptionReport:
        from hydroservo.components.reference import reference

        return DescriptionReport(reference(self.type))


def catalogue() -> CatalogueReport:
    """Every component type."""
    return Catalogue().run()


def describe(type_name: str) -> DescriptionReport:
    """Component type ``type_name``."""
    return Describe(type_name).run()
