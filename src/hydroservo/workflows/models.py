"""The built-in models, as ``hydroservo models`` lists them.

>>> from hydroservo.workflows import models
>>> "flight-simulator" in models.run().models
True
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, ClassVar

from hydroservo.workflows.base import Progress, Report, Workflow

__all__ = ["Models", "ModelsReport", "run"]


@dataclass
class ModelsReport(Report):
    """Each built-in model: its description, source, status and validation."""

    command: ClassVar[str] = "models"

    models: dict[str, dict[str, str]]

    def title(self) -> str:
        return "hydroservo's built-in models"

    def lines(self) -> list[str]:
        width = max(len(n) for n in self.models)
        out = []
        for name, meta in self.models.items():
            source = f" [{meta['citation']}, {meta['status']}]" if meta["citation"] else ""
            out.append(f"{name.ljust(width)}  {meta['description']}{source}")
            out.append(f"{' ' * width}  validation: {meta['validation']}")
        return out

    def to_dict(self) -> dict[str, Any]:
        return {"models": self.models}


@dataclass
class Models(Workflow):
    """List the built-in models."""

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> ModelsReport:
        from hydroservo.io.model_file import builtin_models

        return ModelsReport(builtin_models())


def run() -> ModelsReport:
    """The built-in models."""
    return Models().run()
