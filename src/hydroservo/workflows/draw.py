"""A system's circuit diagram after ISO 1219-1 (``hydroservo draw MODEL``): SVG, PNG or PDF.

>>> from hydroservo.workflows import draw
>>> drawing = draw.run("position-servo", formats="svg")
>>> drawing.planned_names()
['position-servo.svg']
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from hydroservo.errors import ParameterError, shorten
from hydroservo.workflows.base import Artifact, Progress, Report, Workflow, load_with_sets, safe_name

if TYPE_CHECKING:
    from hydroservo.io.html import Page
    from hydroservo.system.system import System

__all__ = ["Draw", "DrawingReport", "run", "FORMATS"]

#: The formats a drawing is written in.
FORMATS = ("svg", "png", "pdf")


@dataclass
class DrawingReport(Report):
    """A system's schematic, ready to write in each format asked for."""

    command: ClassVar[str] = "draw"

    system: System
    schematic: Any  #: :class:`hydroservo.plotting.schematic.Schematic`
    formats: list[str]

    def title(self) -> str:
        return f"{self.system.name}: circuit"

    def planned_names(self) -> list[str]:
        return [f"{safe_name(self.system.name)}.{f}" for f in self.formats]

    def artifacts(self) -> list[Artifact]:
        return [Artifact(f, name, self.schematic.save) for f, name in zip(self.formats, self.planned_names())]

    def lines(self) -> list[str]:
        s = self.schematic
        out = [f"{self.system.name}: {len(s.components)} components, {len(s.connections)} connections"]
        if self.files:
            out.append(f"wrote {', '.join(self.files.values())}")
        return out

    def to_dict(self) -> dict[str, Any]:
        return {"model": self.system.name, "components": list(self.schematic.components),
                "connections": list(self.schematic.connections), "files": self.files}

    def document(self) -> Page:
        from hydroservo.io.html import Drawing, Page, Section
        from hydroservo.workflows.base import footer

        return Page(self.title(), self.system.description, [Section("Circuit", [Drawing(self.schematic.svg)])], footer())


@dataclass
class Draw(Workflow):
    """Draw ``model`` (a built-in model's name, a model file or a system) with ``sets`` applied.

    ``formats``: some of :data:`FORMATS` (a list or ``"svg,png"``); ``parameters``: show each component's main
    parameters (in the units they were given in) beside its name.
    """

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set", "formats": "--format", "parameters": "--names-only"}

    model: str | Path | System
    sets: Sequence[str] | Mapping[str, Any] | None = None
    formats: str | Sequence[str] = ("svg", "png")
    parameters: bool = True

    def __post_init__(self) -> None:
        text = self.formats if isinstance(self.formats, str) else ",".join(self.formats)
        kinds = [k.strip().lower() for k in text.split(",") if k.strip()]
        if not kinds or any(k not in FORMATS for k in kinds):
            raise ParameterError(
                f"{self.name('formats')} {shorten(text)!r}: expected a comma-separated choice of {', '.join(FORMATS)}"
            )
        self.kinds = list(dict.fromkeys(kinds))
        self.system = load_with_sets(self.model, self.sets, self.name("sets"))

    def folder(self) -> str:
        return f"hydroservo-{safe_name(self.system.name)}-circuit"

    def planned(self) -> list[str]:
        return [f"{safe_name(self.system.name)}.{f}" for f in self.kinds]

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> DrawingReport:
        return DrawingReport(self.system, self.system.diagram(parameters=self.parameters), self.kinds)


def run(model: str | Path | System, **inputs: Any) -> DrawingReport:
    """The drawing of ``model`` (:class:`Draw`'s inputs as keywords)."""
    return Draw(model, **inputs).run()
