"""The example files the README's commands use (``hydroservo examples DIR``), and a Hopsan model to import.

>>> from hydroservo.workflows import examples
>>> "pump_circuit.toml" in examples.run().texts
True
>>> "hopsan_servo.hmf" in examples.run().texts
True
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, ClassVar

from hydroservo.workflows.base import Artifact, Progress, Report, Workflow

__all__ = ["Examples", "ExamplesReport", "run"]


@dataclass
class ExamplesReport(Report):
    """The example files: model files, a datasheet, synthetic curves and Bode data, and a Hopsan model file
    (``hopsan_servo.hmf``, written for hydroservo in Hopsan's format) for ``hydroservo import-hopsan``."""

    command: ClassVar[str] = "examples"

    texts: dict[str, str]

    def title(self) -> str:
        return "hydroservo's example files"

    def artifacts(self) -> list[Artifact]:
        def writer(text: str) -> Any:
            return lambda path: path.write_text(text, encoding="utf-8")

        return [Artifact(name, name, writer(text)) for name, text in self.texts.items()]

    def lines(self) -> list[str]:
        folder = str(Path(next(iter(self.files.values()))).parent) if self.files else ""
        out = [f"wrote {len(self.texts)} example files to {folder}: {', '.join(self.texts)}"]
        for name in (n for n in self.texts if n.endswith(".hmf")):
            out.append(f"{name} is a Hopsan model: hydroservo import-hopsan {name} --out DIR writes it as a hydroservo "
                       "model file (docs/hopsan.md)")
        return out

    def to_dict(self) -> dict[str, Any]:
        return {"files": self.files}


@dataclass
class Examples(Workflow):
    """The example files (:func:`hydroservo.data.example_files`)."""

    def planned(self) -> list[str]:
        from hydroservo.data import example_files

        return list(example_files())

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> ExamplesReport:
        from hydroservo.data import example_files

        return ExamplesReport(example_files())


def run() -> ExamplesReport:
    """The example files, ready to :meth:`~hydroservo.workflows.base.Report.write` into a folder."""
    return Examples().run()
