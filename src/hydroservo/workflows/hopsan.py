"""``hydroservo import-hopsan``: a Hopsan model file (``.hmf``) as a hydroservo model file.

>>> from hydroservo.workflows.hopsan import ImportHopsan  # doctest: +SKIP
>>> ImportHopsan("Position Servo.hmf").run().write("out")  # doctest: +SKIP
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, ClassVar

from hydroservo.components.base import MAX_NAME
from hydroservo.errors import shorten
from hydroservo.io.text import one_line
from hydroservo.workflows.base import Progress, Report, Workflow

__all__ = ["ImportHopsan", "HopsanReport"]


@dataclass
class HopsanReport(Report):
    """A Hopsan model imported: the system, the model file's text, and what each Hopsan component became."""

    command: ClassVar[str] = "import-hopsan"

    imported: Any  #: :class:`hydroservo.io.hopsan_library.HopsanImport`
    text: str
    file_name: str

    def title(self) -> str:
        return f"{self.imported.system.name}: imported from Hopsan ({Path(self.imported.system.source).name})"

    def lines(self) -> list[str]:
        imp = self.imported
        out = [
            f"imported {Path(imp.system.source).name}: {len(imp.mapping)} Hopsan components as "
            f"{len(imp.system.components)} hydroservo components, {len(imp.system.aliases)} of Hopsan's variables as "
            f"aliases; t_end {imp.system.t_end:g} s (Hopsan's step {imp.system.meta['hopsan_timestep']})",
            "",
            "  Hopsan component -> hydroservo",
        ]
        shown = [(f"{shorten(one_line(path), 100)} ({kind})", became) for path, kind, became in imp.mapping]
        width = max((len(left) for left, _ in shown), default=0)
        out += [f"  {left:<{width}}  {became}" for left, became in shown]
        if imp.renamed:
            out += ["", f"  renamed (hydroservo's names are identifiers, not Python keywords, of at most {MAX_NAME} characters):"]
            out += [f"  {shorten(one_line(path), 100)} -> {name}" for path, name in imp.renamed.items()]
        if self.files:
            out += ["", f"wrote {self.files['model']}: hydroservo simulate {self.files['model']}"]
        return out

    def to_dict(self) -> dict[str, Any]:
        imp = self.imported
        return {
            "model": imp.system.name,
            "source": imp.system.source,
            "components": [{"hopsan": p, "type": k, "hydroservo": b} for p, k, b in imp.mapping],
            "renamed": dict(imp.renamed),
            "aliases": list(imp.system.aliases),
            "t_end": imp.system.t_end,
            "hopsan_timestep": imp.system.meta["hopsan_timestep"],
            "files": self.files,
        }

    def artifacts(self) -> list[Any]:
        from hydroservo.workflows.base import Artifact

        return [Artifact("model", self.file_name, lambda path: path.write_text(self.text, encoding="utf-8"))]


@dataclass
class ImportHopsan(Workflow):
    """The Hopsan model file ``file`` mapped to hydroservo's components (:func:`hydroservo.io.hopsan_library.import_hopsan`)."""

    OPTIONS: ClassVar[dict[str, str]] = {"file": "FILE.hmf"}

    file: str | Path
    #: the lumped segments of each transmission line and hose (None: ceil(5 T/Ts) for a delay T, at most 200)
    line_segments: int | None = None

    def __post_init__(self) -> None:
        from hydroservo.io.hopsan_library import import_hopsan, safe_name

        self.imported = import_hopsan(self.file, self.line_segments)  # refused here, before any folder is made
        self.file_name = f"{safe_name(Path(self.file).stem)}.toml"

    def folder(self) -> str:
        return f"hydroservo-{Path(self.file_name).stem}"

    def planned(self) -> list[str]:
        return [self.file_name]

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> HopsanReport:
        from hydroservo.io.model_file import checked_model_text, model_to_toml
        from hydroservo.io.toml import toml_comment

        imp = self.imported
        header = [
            toml_comment(f"Imported from the Hopsan model file {Path(self.file).name} by hydroservo import-hopsan."),
            "# Hopsan's pressures are absolute: they are written in Pa_abs. Its port variables are aliases named",
            "# as Hopsan logs them, with dots (Mass#P2#Position is Mass.P2.Position), in SI (docs/hopsan.md).",
            "# Hopsan component -> hydroservo:",
            *(toml_comment(f"  {path} ({kind}) -> {became}") for path, kind, became in imp.mapping),
        ]
        if imp.renamed:
            header += [
                f"# Renamed (hydroservo's names are identifiers, not Python keywords, of at most {MAX_NAME} characters):",
                *(toml_comment(f"  {path} -> {name}") for path, name in imp.renamed.items()),
            ]
        # what is written loads and is the model imported: checked before anything is written
        text = checked_model_text("\n".join([*header, ""]) + model_to_toml(imp.system), imp.system,
                                  f"the model file imported from {Path(self.file).name!r}")
        return HopsanReport(imp, text, self.file_name)
