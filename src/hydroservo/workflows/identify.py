"""[Efe2014]'s identification procedures on rig records (``hydroservo identify friction|leakage|flow-coefficient``).

Each reads one or more records, applies the procedure with the model's own
laws and dimensions, and writes a component parameter file the model file
includes (``[components.load] file = "friction.toml"``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np

from hydroservo.errors import ParameterError
from hydroservo.workflows.base import Artifact, Progress, Report, Workflow, load_with_sets, safe_name
from hydroservo.workflows.calibrate import RecordFiles, _records, _thinned, signal_list

if TYPE_CHECKING:
    from hydroservo.identification.flow_coefficient import FlowCoefficientTables
    from hydroservo.identification.friction import FrictionPoints, StribeckFit
    from hydroservo.identification.leakage import LeakageEstimate
    from hydroservo.system.system import System

__all__ = ["IdentifyFriction", "FrictionReport", "IdentifyLeakage", "LeakageReport", "IdentifyFlowCoefficient",
           "FlowCoefficientReport", "friction", "leakage", "flow_coefficient"]


def _header(what: str, model: str, records: Sequence[str], component: str, file: str, keys: Sequence[str]) -> str:
    return (
        f"{what} identified by hydroservo (Efe2014) from {', '.join(records)} on the model {model}.\n"
        f'Use it in a model file: [components.{component}] file = "{file}". A key the model file also gives in\n'
        f"that table overrides this file's: delete {', '.join(keys)} there."
    )


@dataclass
class _Procedure(Workflow):
    """What the procedures share: a model (with ``sets`` changes), its ``records`` (each one file or several, one per
    rate), the cylinder and load they concern; the output folder and files named after the procedure."""

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set", "inputs": "--input"}
    #: The procedure's name (its folder: ``hydroservo-NAME-MODEL``) and the files its report writes.
    NAME: ClassVar[str] = ""
    FILES: ClassVar[tuple[str, ...]] = ()

    model: str | Path | System
    records: Sequence[RecordFiles] = field(default_factory=list)
    cylinder: str = "cyl"
    load: str = "load"
    sets: Sequence[str] | Mapping[str, Any] | None = None
    #: The most samples per channel used (default :data:`~hydroservo.identification.records.MAX_SAMPLES`): a longer
    #: channel is thinned to every k-th sample, and the report's warnings say so.
    max_samples: int | None = None

    def __post_init__(self) -> None:
        self.system = load_with_sets(self.model, self.sets, self.name("sets"))
        self._records, self._notes = _thinned(_records(self.records, "RECORD"), self.max_samples, self.name("max_samples"))
        for what in ("cylinder", "load"):
            name = getattr(self, what)
            if name not in self.system.components:
                raise ParameterError(f"{self.name(what)} {name!r}: not a component of {self.system.name!r}")

    def folder(self) -> str:
        return f"hydroservo-{self.NAME}-{safe_name(self.system.name)}"

    def planned(self) -> list[str]:
        return list(self.FILES)


# -- friction ------------------------------------------------------------------------------
@dataclass
class FrictionReport(Report):
    """Friction points from records and the Stribeck law fitted to them."""

    command: ClassVar[str] = "identify friction"

    model: str
    component: str
    component_type: str
    points: FrictionPoints
    fit: StribeckFit
    records: list[str] = field(default_factory=list)

    def title(self) -> str:
        return f"{self.model}: Stribeck friction of {self.component} from {len(self.points)} speeds (Efe2014 eqs. 4.24, 3.47)"

    def lines(self) -> list[str]:
        from hydroservo.identification.friction import STRIBECK_PARAMETERS
        from hydroservo.units import si_unit

        out = [self.title(), f"{'speed [m/s]':>12} {'measured [N]':>13} {'law [N]':>9} {'error':>8}"]
        for v, f, s, e in zip(self.fit.velocity, self.fit.force, self.fit.simulated, self.fit.relative_error):
            out.append(f"{v:>12.4g} {f:>13.5g} {s:>9.5g} {e:>+7.2f} %")
        out.append("")
        for k, val in self.fit.parameters.items():
            se = self.fit.stderr[k]
            shown = ("held at the model's value" if k in self.fit.held
                     else "not determined" if not math.isfinite(se) or se > abs(val) else f"± {se:.3g}")
            out.append(f"  {self.component}.{k:<5} = {val:.6g} {si_unit(STRIBECK_PARAMETERS[k])}  ({shown})")
        if self.files:
            out.append(f"wrote {', '.join(self.files.values())}")
        return out

    def to_dict(self) -> dict[str, Any]:
        return {"model": self.model, "component": self.component, **self.fit.to_dict(), "files": self.files}

    def parameter_file(self) -> str:
        from hydroservo.identification.friction import STRIBECK_PARAMETERS
        from hydroservo.io.component_file import component_toml

        fit = self.fit
        determined = {k: v for k, v in fit.parameters.items()
                      if k not in fit.held and math.isfinite(fit.stderr[k]) and fit.stderr[k] <= abs(v)}
        left = [k for k in fit.parameters if k not in determined]
        header = _header("Stribeck friction (eq. 3.47)", self.model, self.records, self.component, "friction.toml",
                         list(determined))
        if left:
            header += ("\nNot determined by the records, so not written (the model keeps its own): "
                       + ", ".join(f"{k} (held at the model's {fit.parameters[k]:.4g} {STRIBECK_PARAMETERS[k]})" if k in fit.held
                        else f"{k} (the fit ended at {fit.parameters[k]:.4g} {STRIBECK_PARAMETERS[k]})" for k in left))
        return component_toml(
            self.component_type, determined, STRIBECK_PARAMETERS,
            comments={k: f"± {fit.stderr[k]:.3g}" for k in determined},
            header=header,
            extra={"points": {"velocity": fit.velocity.tolist(), "force": fit.force.tolist()}},
        )

    def artifacts(self) -> list[Artifact]:
        return [Artifact("parameters", "friction.toml", lambda p: p.write_text(self.parameter_file(), encoding="utf-8")),
                Artifact("plot", "friction.png", self._plot)]

    def _plot(self, path: Path) -> Any:
        from hydroservo.plotting.identification import plot_friction

        return plot_friction(self.points, self.fit, title=self.title(), file=path)


@dataclass
class IdentifyFriction(_Procedure):
    """Friction forces from ``records`` of the rod at several held valve signals (``command``), and the Stribeck law."""

    NAME: ClassVar[str] = "friction"
    FILES: ClassVar[tuple[str, ...]] = ("friction.toml", "friction.png")

    command: str = "command.y"
    settle: float = 0.25

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> FrictionReport:
        from hydroservo.identification.friction import FrictionPoints, fit_stribeck, friction_from_record

        parts = [friction_from_record(self.system, r, command=self.command, position=f"{self.load}.x",
                                      pressures=(f"{self.cylinder}.pA", f"{self.cylinder}.pB"), cylinder=self.cylinder,
                                      load=self.load, settle=self.settle) for r in self._records]
        order = np.argsort(np.concatenate([p.velocity for p in parts]))
        points = FrictionPoints(
            np.concatenate([p.velocity for p in parts])[order], np.concatenate([p.force for p in parts])[order],
            np.concatenate([p.spread for p in parts])[order], np.concatenate([p.command for p in parts])[order],
            [iv for p in parts for iv in p.intervals], ", ".join(r.name for r in self._records),
        )
        fit = fit_stribeck(points.velocity, points.force)
        comp = self.system[self.load]
        notes = list(fit.warnings)
        static = [k for k in ("F_s0", "c_s") if not fit.stderr[k] <= abs(fit.parameters[k])]
        own: dict[str, float] = {k: float(comp.values[k]) for k in ("F_s0", "c_s") if k in comp.values}
        if static and len(own) == 2 and own["c_s"] > 0:
            # The static term is not determined: left free it trades with the Coulomb and viscous terms along a
            # flat valley and drags them off (a c_s above every speed makes F_s0 a second F_c0). It is not written,
            # so the model keeps its own; B and F_c0 are fitted again with it held there, as the model will use them.
            fit = fit_stribeck(points.velocity, points.force, held=own)
            notes = [  # the free fit's notes are superseded: its other terms were dragged along the valley
                "F_s0 and c_s are not determined by these points (the static term needs speeds near and below the "
                "Stribeck velocity); B and F_c0 were fitted with them held at the model's own values "
                f"(F_s0 = {own['F_s0']:.4g} N, c_s = {own['c_s']:.4g} m/s), which are not written",
                *fit.warnings,
            ]
        return FrictionReport(self.system.name, self.load, type(comp).__name__, points, fit,
                              [r.name for r in self._records], warnings=[*self._notes, *notes])


# -- leakage -------------------------------------------------------------------------------
@dataclass
class LeakageReport(Report):
    """The internal leakage coefficient from a locked-piston record."""

    command: ClassVar[str] = "identify leakage"

    model: str
    component: str
    component_type: str
    estimate: LeakageEstimate
    records: list[str] = field(default_factory=list)

    def title(self) -> str:
        return f"{self.model}: internal leakage of {self.component} from a locked piston (Efe2014 section 4.5.5, eq. 3.42)"

    def lines(self) -> list[str]:
        e = self.estimate
        out = [
            self.title(),
            f"  {e.parameter} = {e.value:.5g} ± {e.stderr:.2g} m³/s/Pa  ({e.value * 6e4 * 1e5:.4g} L/min/bar)",
            f"  from chamber B's balance: {e.from_b:.5g} m³/s/Pa" if math.isfinite(e.from_b) else "  chamber B: no balance",
            (f"  law sensitivity: the plain turbulent orifice law gives {e.turbulent:.5g} m³/s/Pa ({100 * e.law_sensitivity:+.2f} %)"
             + (f"; the supply edge drops {e.edge_drop / 1e5:.3g} bar, {e.edge_drop / e.transition:.2g} times the law's "
                f"laminar transition ({e.transition / 1e5:.3g} bar)" if math.isfinite(e.edge_drop) and e.transition > 0 else ""))
            if math.isfinite(e.law_sensitivity) else "  law sensitivity: the model's valve has no laminar transition to vary",
            f"  settled over {e.interval[0]:g}..{e.interval[1]:g} s: "
            + ", ".join(f"{k} = {v / 1e5:.4g} bar" for k, v in e.conditions.items() if k.endswith((".pA", ".pB"))),
        ]
        if self.files:
            out.append(f"wrote {', '.join(self.files.values())}")
        return out

    def to_dict(self) -> dict[str, Any]:
        return {"model": self.model, **self.estimate.to_dict(), "files": self.files}

    def parameter_file(self) -> str:
        from hydroservo.io.component_file import component_toml

        e = self.estimate
        return component_toml(
            self.component_type, {"C_Li": e.value}, {"C_Li": "m^3/s/Pa"},
            comments={"C_Li": f"± {e.stderr:.3g} m^3/s/Pa; = {e.value * 6e9:.4g} L/min/bar"
                      + (f"; the plain turbulent orifice law gives {100 * e.law_sensitivity:+.1f} %" if math.isfinite(e.law_sensitivity) else "")},
            header=_header("Internal leakage (eq. 3.42)", self.model, self.records, self.component, "leakage.toml", ["C_Li"]),
        )

    def artifacts(self) -> list[Artifact]:
        return [Artifact("parameters", "leakage.toml", lambda p: p.write_text(self.parameter_file(), encoding="utf-8"))]


@dataclass
class IdentifyLeakage(_Procedure):
    """The cylinder's internal leakage from a locked-piston ``record``, driven by ``inputs``."""

    NAME: ClassVar[str] = "leakage"
    FILES: ClassVar[tuple[str, ...]] = ("leakage.toml",)

    inputs: Sequence[str] = ("command.y",)
    window: tuple[float, float] | None = None

    def __post_init__(self) -> None:
        super().__post_init__()
        if len(self._records) != 1:
            raise ParameterError(f"RECORD: {len(self._records)} records; the locked-piston test reads one")
        self.inputs = signal_list(self.inputs)

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> LeakageReport:
        from hydroservo.identification.leakage import leakage_from_record

        rec = self._records[0]
        est = leakage_from_record(self.system, rec, inputs=self.inputs, cylinder=self.cylinder, load=self.load, window=self.window)
        comp = self.system[self.cylinder]
        return LeakageReport(self.system.name, self.cylinder, type(comp).__name__, est, [rec.name], warnings=[*self._notes, *est.warnings])


# -- flow coefficient ------------------------------------------------------------------------
@dataclass
class FlowCoefficientReport(Report):
    """K(x_v) and H(x_v, d_f) tables from swept records."""

    command: ClassVar[str] = "identify flow-coefficient"

    model: str
    result: FlowCoefficientTables
    component_type: str = "FourWayValve"
    records: list[str] = field(default_factory=list)

    def title(self) -> str:
        return f"{self.model}: flow-coefficient compensation K(x_v) and hysteresis H(x_v, d_f) of {self.result.valve} (Efe2014 eqs. 3.22-3.23)"

    def lines(self) -> list[str]:
        t = self.result.tables
        out = [self.title(), f"{'x_v/x_v,max':>12} {'K':>7} {'H closing':>10}"]
        closing = dict(zip(t.get("H_x", []), t.get("H_closing", [])))
        for x, k in zip(t["K_x"], t["K"]):
            h = closing.get(x)
            out.append(f"{x:>12.3f} {k:>7.3f} {'' if h is None else f'{h:>10.3f}'}")
        out.append(f"  {self.result.signal.size} samples ({int(self.result.opening.sum())} opening, {int((~self.result.opening).sum())} closing)")
        if self.files:
            out.append(f"wrote {', '.join(self.files.values())}")
        return out

    def to_dict(self) -> dict[str, Any]:
        return {"model": self.model, **self.result.to_dict(), "files": self.files}

    def parameter_file(self) -> str:
        from hydroservo.io.toml import toml_comments, toml_string, toml_table, toml_value

        header = _header("Flow-coefficient compensation K(x_v) and hysteresis H(x_v, d_f) (eqs. 3.22-3.23)",
                         self.model, self.records, self.result.valve, "flow-coefficient.toml", ["tables"])
        lines = toml_comments(header)
        tables = {k: [round(float(v), 6) for v in vals] for k, vals in self.result.tables.items()}
        lines += toml_table("component", {"type": toml_string(self.component_type), "tables": toml_value(tables)})
        return "\n".join(lines) + "\n"

    def artifacts(self) -> list[Artifact]:
        return [Artifact("parameters", "flow-coefficient.toml", lambda p: p.write_text(self.parameter_file(), encoding="utf-8")),
                Artifact("plot", "flow-coefficient.png", self._plot)]

    def _plot(self, path: Path) -> Any:
        from hydroservo.plotting.identification import plot_flow_coefficient

        return plot_flow_coefficient(self.result, title=self.title(), file=path)


@dataclass
class IdentifyFlowCoefficient(_Procedure):
    """K(x_v) and H(x_v, d_f) of the model's valve from ``records`` of a slowly swept valve signal."""

    NAME: ClassVar[str] = "flow-coefficient"
    FILES: ClassVar[tuple[str, ...]] = ("flow-coefficient.toml", "flow-coefficient.png")

    inputs: Sequence[str] = ("command.y",)
    valve: str = "valve"
    bin_width: float = 0.05

    def __post_init__(self) -> None:
        super().__post_init__()
        self.inputs = signal_list(self.inputs)
        if self.valve not in self.system.components:
            raise ParameterError(f"{self.name('valve')} {self.valve!r}: not a component of {self.system.name!r}")

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> FlowCoefficientReport:
        from hydroservo.identification.flow_coefficient import flow_coefficient_tables

        result = flow_coefficient_tables(self.system, self._records, inputs=self.inputs, valve=self.valve,
                                         cylinder=self.cylinder, load=self.load, bin_width=self.bin_width)
        return FlowCoefficientReport(self.system.name, result, type(self.system[self.valve]).__name__,
                                     [r.name for r in self._records], warnings=[*self._notes, *result.warnings])


def friction(model: str | Path | System, records: Sequence[RecordFiles], **options: Any) -> FrictionReport:
    """:class:`IdentifyFriction` ``(model, records, **options).run()``."""
    return IdentifyFriction(model, records, **options).run()


def leakage(model: str | Path | System, record: RecordFiles, **options: Any) -> LeakageReport:
    """:class:`IdentifyLeakage` ``(model, [record], **options).run()``."""
    return IdentifyLeakage(model, [record], **options).run()


def flow_coefficient(model: str | Path | System, records: Sequence[RecordFiles], **options: Any) -> FlowCoefficientReport:
    """:class:`IdentifyFlowCoefficient` ``(model, records, **options).run()``."""
    return IdentifyFlowCoefficient(model, records, **options).run()
