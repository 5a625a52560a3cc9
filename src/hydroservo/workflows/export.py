"""A system written out: as an editable model file (``hydroservo export``), as C code with a real-time stepper
(``export-c``), as an FMI 2.0 FMU (``export-fmu``).

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

from hydroservo.errors import ParameterError
from hydroservo.workflows.base import Progress, Report, Workflow, load_with_sets, safe_name

if TYPE_CHECKING:
    from hydroservo.system.system import System

__all__ = ["ExportModel", "ModelFileReport", "model_file", "ExportC", "CReport", "ExportFmu", "FmuReport"]


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
    """``model`` (a name, a file or a system) with ``sets`` applied, as a model file: the model's own file with
    the values set written in (its comments, order and layout kept; former type and parameter names written as
    they are now called), or with ``full`` every parameter of every component with its description."""

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set"}

    model: str | Path | System
    sets: Sequence[str] | Mapping[str, Any] | None = None
    #: every component's every parameter, as the system holds it, instead of the model's own file edited
    full: bool = False

    def __post_init__(self) -> None:
        self.system = load_with_sets(self.model, self.sets, self.name("sets"))

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> ModelFileReport:
        from hydroservo.io.model_file import checked_model_text, model_to_toml
        from hydroservo.io.notebook import departures, scoped_notes
        from hydroservo.io.toml import edit_toml, toml_value

        # the model's notes were measured on it as its file gives it: a file that changes it says so in each note,
        # which then travels with the file (a run of it is otherwise a default run, whose notes are shown as true)
        changes = departures(self.system)
        if changes:
            self.system.notes = scoped_notes(self.system, changes, "file")
        text = None if self.full else self._edited()
        if text is not None and changes and self.system.notes:
            text = edit_toml(text, {("model", "notes"): toml_value(self.system.notes)})
        text = text if text is not None else model_to_toml(self.system)
        # what is written loads and is this model, whatever its names and descriptions hold: checked before writing
        return ModelFileReport(self.system, checked_model_text(text, self.system, "the exported model file"))

    def _edited(self) -> str | None:
        """The file the model was read from (a model file, a built-in model's), its comments and layout kept, with
        the values set written in; None for a system made in Python or a file that cannot hold them."""
        from hydroservo.data import model_text
        from hydroservo.io.files import read_text
        from hydroservo.io.model_file import edited_model_text
        from hydroservo.system.system import System
        from hydroservo.workflows.base import parse_sets

        if isinstance(self.model, System):  # made or changed in Python: its file may no longer describe it
            return None
        source = str(self.system.source or "")
        if source.startswith("built-in:"):
            text = model_text(source.removeprefix("built-in:"))
        elif source:
            text = read_text(source, "model file")
        else:
            return None
        keys = [key for key, _ in parse_sets(self.sets, self.name("sets"))]
        return edited_model_text(text, self.system, keys, where=source)


def model_file(
    model: str | Path | System, sets: Sequence[str] | Mapping[str, Any] | None = None, full: bool = False
) -> ModelFileReport:
    """``model`` as a model file's text (:class:`ModelFileReport`): the model's own file with ``sets`` written in,
    its comments and layout kept, or with ``full`` (or for a system made in Python) every parameter of every
    component, each with its description."""
    return ExportModel(model, sets, full=full).run()


# -- C code with a real-time stepper ------------------------------------------------------------
@dataclass
class _CodeExport(Workflow):
    """What the C and FMU exports share: the model with its changes, the step, the C identifier, the inputs."""

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set"}
    #: The export writes its own files (all or nothing) while it runs, into the folder it is given.
    WRITES_ITSELF: ClassVar[bool] = True

    model: str | Path | System
    sets: Sequence[str] | Mapping[str, Any] | None = None
    step: float | str | None = 1e-4
    method: str = "rk4"
    inputs: Sequence[str] = ()
    c_name: str | None = None
    force: bool = False

    def __post_init__(self) -> None:
        from hydroservo.codegen.c import check_inputs, check_name, check_step

        if self.step is None:
            if not getattr(self, "main", False):
                raise ParameterError(
                    f"{self.name('step')}: missing; expected the fixed step of the real-time stepper, e.g. 1e-4 or "
                    "'0.1 ms' (only the standalone simulator, --main, runs without one: its solvers choose their steps)"
                )
            self.step = 1e-4
        self.h = check_step(self.step, what=self.name("step"))
        self.identifier = check_name(self.c_name, what=self.name("c_name")) if self.c_name is not None else None
        self.system = load_with_sets(self.model, self.sets, self.name("sets"))
        self.targets = check_inputs(self.system, list(self.inputs), what=self.name("inputs"))


@dataclass
class CReport(Report):
    """The C code written: its folder, files, method, and every parameter, input, state and output by index."""

    command: ClassVar[str] = "export-c"

    export: Any  #: :class:`hydroservo.codegen.c.CExport`
    built: bool = False

    def title(self) -> str:
        return f"{self.export.model}: C code ({self.export.method}, step {self.export.step:g} s)"

    def lines(self) -> list[str]:
        e = self.export
        out = [
            f"exported {e.model!r} as C ({e.method}, step {e.step:g} s"
            + (", with the standalone simulator main.c" if e.main else "")
            + f") to {e.directory}: parameters "
            f"{len(e.parameters)}, inputs {len(e.inputs)}, states {len(e.states)}, outputs {len(e.outputs)}",
            f"  API: {e.directory / f'{e.name}.h'}; build: cd {e.directory} && cc -O2 -c *.c (or make)",
        ]
        if e.inputs:
            out.append(f"  inputs (each added to what drives it in the system): {', '.join(e.inputs)}")
        if self.built:
            out.append(f"  built: {e.library}")
            if e.main:
                out.append(f"  simulator: {e.executable} (--help; e.g. {e.executable} --points 301 > run.csv)")
        return out

    def to_dict(self) -> dict[str, Any]:
        e = self.export

        def named(names: tuple[str, ...]) -> list[dict[str, Any]]:
            return [{"index": i, "name": n, "unit": e.units[n]} for i, n in enumerate(names)]

        report: dict[str, Any] = {
            "model": e.model,
            "name": e.name,
            "directory": str(e.directory),
            "method": e.method,
            "step_s": e.step,
            "files": list(e.files),
            "parameters": [
                {"index": i, "name": n, "unit": e.units[n], "default": v}
                for i, (n, v) in enumerate(zip(e.parameters, e.defaults, strict=True))
            ],
            "inputs": named(e.inputs),
            "states": named(e.states),
            "outputs": named(e.outputs),
        }
        if e.method == "bdf2":
            report["newton_tolerance"] = e.newton_tolerance
        if e.library.name in e.files:
            report["library"] = str(e.library)
        if e.main and e.executable.name in e.files:
            report["executable"] = str(e.executable)
        return report


@dataclass
class ExportC(_CodeExport):
    """``model`` as C code with a fixed-step stepper (``method`` rk4 or bdf2, step ``step``) and a C API; the host
    sets ``inputs`` (component inputs); ``main`` adds the standalone simulator (``main.c``); ``build`` also
    compiles a shared library (and the simulator) (docs/realtime.md)."""

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set", "c_name": "--name"}

    build: bool = False
    main: bool = False

    def folder(self) -> str:
        return f"hydroservo-{safe_name(self.system.name)}-c"

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> CReport:
        from hydroservo.codegen.c import c_identifier, export_c

        directory = folder if folder is not None else Path(self.identifier or c_identifier(self.system.name))
        export = export_c(self.system, directory, step=self.h, method=self.method, inputs=self.targets,
                          name=self.identifier, force=self.force, build=self.build, main=self.main)
        return CReport(export, self.build)


# -- FMI 2.0 FMUs ---------------------------------------------------------------------------------
@dataclass
class FmuReport(Report):
    """The FMU written: its file, GUID, co-simulation stepper and every variable with its value reference."""

    command: ClassVar[str] = "export-fmu"

    export: Any  #: :class:`hydroservo.codegen.fmu.FmuExport`

    def title(self) -> str:
        return f"{self.export.model}: FMI 2.0 FMU"

    def lines(self) -> list[str]:
        e = self.export
        built = f"binary for {e.platform} and sources" if e.platform else "sources only (no binary)"
        out = [
            f"exported {e.model!r} as an FMI 2.0 FMU (Model Exchange and Co-Simulation) to {e.path}: {built}; "
            f"parameters {len(e.parameters)} ({sum(e.tunable)} tunable), inputs {len(e.inputs)}, states "
            f"{len(e.states)}, outputs {len(e.outputs)}",
            (f"  co-simulation: {e.method}, variable steps with error control (any communication step)"
             if e.method in ("rodas3", "ros23", "dopri5")
             else f"  co-simulation: {e.method}, fixed step {e.step:g} s (communication steps a whole number of it)"),
        ]
        renamed = [v for v in e.variables if v.name != v.signal and v.kind != "derivative"]
        if renamed:
            out.append("  renamed (FMI needs unique names): "
                       + ", ".join(f"{v.signal} ({v.kind}) -> {v.name}" for v in renamed))
        return out

    def to_dict(self) -> dict[str, Any]:
        e = self.export
        variables = []
        for vr, v in enumerate(e.variables):
            item: dict[str, Any] = {"value_reference": vr, "name": v.name, "kind": v.kind, "unit": v.unit}
            if v.name != v.signal:
                item["signal"] = v.signal
            if v.kind == "parameter":
                item["start"] = e.defaults[vr]
                item["variability"] = "tunable" if e.tunable[vr] else "fixed"
            variables.append(item)
        return {
            "model": e.model,
            "fmu": str(e.path),
            "model_identifier": e.name,
            "guid": e.guid,
            "fmi_version": "2.0",
            "interfaces": ["ModelExchange", "CoSimulation"],
            "platform": e.platform,
            "co_simulation": {"method": e.method, "step_s": e.step},
            "files": list(e.files),
            "variables": variables,
        }


@dataclass
class ExportFmu(_CodeExport):
    """``model`` as the FMI 2.0 FMU ``NAME.fmu`` (Model Exchange and Co-Simulation, ``method`` and ``step`` of the
    co-simulation stepper); ``binary`` builds it for this machine beside the sources (docs/fmu.md)."""

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set", "c_name": "--name", "folder": "--out"}

    binary: bool = True
    accuracy: float | str | None = None

    def __post_init__(self) -> None:
        from hydroservo.codegen.c import ADAPTIVE_METHODS
        from hydroservo.codegen.fmu import check_cosimulation_method
        from hydroservo.system.integration import DEFAULT_ACCURACY, tolerances
        from hydroservo.workflows.simulate import accuracy_of

        check_cosimulation_method(self.method, self.name("method"))
        value = accuracy_of(self.accuracy, self.name("accuracy"))
        if value is not None and self.method not in ADAPTIVE_METHODS:
            raise ParameterError(
                f"{self.name('accuracy')} {self.accuracy}: only for a variable-step co-simulation method (rodas3, "
                f"ros23 or dopri5); {self.method} steps at the fixed {self.name('step')}"
            )
        self.accuracy_value = DEFAULT_ACCURACY if value is None else value
        try:
            tolerances(self.accuracy_value, self.method)
        except ParameterError as exc:
            raise ParameterError(f"{self.name('accuracy')} {self.accuracy}: {str(exc).split(': ', 1)[-1]}") from None
        super().__post_init__()

    def folder(self) -> str:
        return f"hydroservo-{safe_name(self.system.name)}-fmu"

    def planned(self) -> list[str]:
        from hydroservo.codegen.c import c_identifier

        return [f"{self.identifier or c_identifier(self.system.name)}.fmu"]

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> FmuReport:
        from hydroservo.codegen.fmu import export_fmu

        export = export_fmu(self.system, folder if folder is not None else Path("."), step=self.h, method=self.method,
                            inputs=self.targets, name=self.identifier, binary=self.binary, force=self.force,
                            accuracy=self.accuracy_value)
        return FmuReport(export)
