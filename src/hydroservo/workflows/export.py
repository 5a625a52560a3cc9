"""A system written out: as an editable model file (``hydroservo export``).

>>> from hydroservo.workflows import export
>>> text = export.model_file("flight-simulator").text
>>> text.splitlines()[0].startswith("#") and "[components.cyl]" in text
True
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from hydroservo.workflows.base import Progress, Report, Workflow, load_with_sets

if TYPE_CHECKING:
    from hydroservo.system.system import System

__all__ = ["ExportModel", "ModelFileReport", "model_file"]


@dataclass
class ModelFileReport(Report):
    """A system as the text of a model file, every value in the unit it was given in."""

    command: ClassVar[str] = "export"

    system: System
    text: str

    def title(self) -> str:
        return f"{self.system.name}: model file"

    def lines(self) -> list[str]:
        return self.text.splitlines()

    def to_dict(self) -> dict[str, Any]:
        return {"model": self.system.name, "toml": self.text}


@dataclass
class ExportModel(Workflow):
    """``model`` (a name, a file or a system) with ``sets`` applied, as a model file."""

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set"}

    model: str | Path | System
    sets: Sequence[str] | Mapping[str, Any] | None = None

    def __post_init__(self) -> None:
        self.system = load_with_sets(self.model, self.sets, self.name("sets"))

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> ModelFileReport:
        from hydroservo.io.model_file import model_to_toml

        return ModelFileReport(self.system, model_to_toml(self.system))


def model_file(model: str | Path | System, sets: Sequence[str] | Mapping[str, Any] | None = None) -> ModelFileReport:
    """``model`` as a model file's text (:class:`ModelFileReport`)."""
    return ExportModel(model, sets).run()
