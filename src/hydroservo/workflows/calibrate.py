"""From rig records to a calibrated model (``hydroservo calibrate``), experiment design (``calibrate --plan``),
and the virtual rig that writes records of any model (``hydroservo rig``).

>>> from hydroservo.workflows import calibrate
>>> rig = calibrate.rig("robot-arm", ["load.x=200 Hz,0.02 mm", "cyl.pA=40 Hz,0.05 bar"], t_end="1 s", seed=1)
>>> sorted(rig.record.names), [a.name for a in rig.artifacts()]
(['cyl.pA', 'load.x'], ['robot-arm-rig-200Hz.csv', 'robot-arm-rig-40Hz.csv'])
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from hydroservo.errors import ParameterError, did_you_mean, shorten
from hydroservo.workflows.base import Artifact, Progress, Report, Workflow, load_with_sets, safe_name

if TYPE_CHECKING:
    from hydroservo.identification.calibration import Calibration, Experiment, ExperimentPlan, Prediction
    from hydroservo.identification.records import Record
    from hydroservo.io.html import Page
    from hydroservo.system.system import System

__all__ = ["Calibrate", "CalibrationReport", "PlanReport", "VirtualRig", "RigReport", "run", "rig", "parse_noise"]

RecordFiles = str | Path | Sequence[str | Path]


def parse_noise(items: Sequence[str] | Mapping[str, Any] | None, what: str = "--noise") -> dict[str, str]:
    """``["load.x=0.02 mm", ...]`` (or one string with commas) -> ``{"load.x": "0.02 mm"}``."""
    if not items:
        return {}
    if isinstance(items, Mapping):
        return {str(k): str(v) for k, v in items.items()}
    out = {}
    for item in items:
        for part in str(item).split(","):
            if not part.strip():
                continue
            if "=" not in part:
                raise ParameterError(f"{what} {shorten(part)!r}: expected SIGNAL=STANDARD DEVIATION, e.g. \"load.x=0.02 mm\"")
            key, val = part.split("=", 1)
            out[key.strip()] = val.strip()
    return out


def signal_list(items: Sequence[str]) -> list[str]:
    """Signal names given one by one or separated by commas (``["command.y,supply.p"]``)."""
    return [s.strip() for item in items for s in str(item).split(",") if s.strip()]


def _records(items: Sequence[RecordFiles] | None, what: str) -> list[Record]:
    from hydroservo.io.records import read_record

    records: list[Record] = []
    for k, item in enumerate(items or []):
        rec = read_record(item if not isinstance(item, Path) else [item])
        names = [r.name for r in records]
        if rec.name in names:
            rec.name = f"{rec.name}-{k + 1}"
        records.append(rec)
    if not records and what:
        raise ParameterError(f"{what}: no record given; expected one or more CSV files per record")
    return records


def _thinned(records: list[Record], most: int | None, what: str) -> tuple[list[Record], list[str]]:
    """``records`` with each channel of more than ``most`` samples (default
    :data:`~hydroservo.identification.records.MAX_SAMPLES`) thinned, and the lines that say so: the cost of a fit
    is bounded by the samples it uses, not by the record's length."""
    from hydroservo.identification.records import MAX_SAMPLES, thinned

    limit = MAX_SAMPLES if most is None else most
    if isinstance(limit, bool) or not isinstance(limit, int) or limit < 2:
        raise ParameterError(f"{what} {limit!r}: expected a whole number, 2 or more")
    out: list[Record] = []
    said: list[str] = []
    for record in records:
        kept, lines = thinned(record, limit)
        out.append(kept)
        said += lines
    return out, said


# -- calibrate ---------------------------------------------------------------------------
@dataclass
class CalibrationReport(Report):
    """A calibration, and its prediction of the records kept out of the fit."""

    command: ClassVar[str] = "calibrate"

    model: str
    calibration: Calibration
    prediction: Prediction | None = None

    def title(self) -> str:
        c = self.calibration
        return (f"{self.model}: {len(c.parameters)} parameter(s) calibrated on {len(c.experiments)} record(s)"
                + (f", checked on {len(self.prediction.experiments)}" if self.prediction is not None else ""))

    def lines(self) -> list[str]:
        out = [self.title(), "", *self.calibration.lines()]
        if self.prediction is not None:
            out += ["", "prediction of the records not fitted:", *self.prediction.lines()]
        if self.files:
            out.append(f"wrote {', '.join(self.files.values())}")
        return out

    def to_dict(self) -> dict[str, Any]:
        out = self.calibration.to_dict()
        out["validation"] = self.prediction.to_dict() if self.prediction is not None else {}
        out["model"] = self.model
        out["files"] = self.files
        return out

    def model_file(self) -> str:
        from hydroservo.io.model_file import model_to_toml
        from hydroservo.io.toml import toml_comment

        c = self.calibration
        head = [
            toml_comment(f"{self.model} calibrated by hydroservo on {', '.join(e.name for e in c.experiments)}:"),
            *(toml_comment(f"  {p.name} = {c.parameter(p.name)['value']:.6g} ± {c.parameter(p.name)['stderr']:.3g} {p.unit}")
              for p in c.parameters),
        ]
        return "\n".join(head) + "\n" + model_to_toml(c.system)

    def artifacts(self) -> list[Artifact]:
        import json

        c = self.calibration
        stem = safe_name(self.model)
        out = [Artifact("model", f"{stem}-calibrated.toml", lambda p: p.write_text(self.model_file(), encoding="utf-8"))]
        for k, e in enumerate(c.experiments):
            out.append(Artifact(f"fit_{k + 1}", f"fit-{safe_name(e.name)}.png", partial(_plot_fit, c, k)))
        if self.prediction is not None:
            for k, e in enumerate(self.prediction.experiments):
                out.append(Artifact(f"validation_{k + 1}", f"validation-{safe_name(e.name)}.png",
                                    partial(_plot_prediction, self.prediction, k)))
        out.append(Artifact("json", "calibration.json",
                            lambda p: p.write_text(json.dumps(self.to_dict(), indent=2, default=float), encoding="utf-8")))
        return out

    def document(self) -> Page:
        from hydroservo.io.html import Figure, Section, Table
        from hydroservo.units import si_unit
        from hydroservo.workflows import pages

        c = self.calibration
        rows = []
        for p in c.parameters:
            d = c.parameter(p.name)
            rows.append([p.name, d["value"], d["stderr"], d["ci95"][0], d["ci95"][1], d["start"], si_unit(p.unit)])
        params = Table(["parameter", "value", "± stderr", "95 % low", "95 % high", "start", "unit"], rows)
        n = len(c.parameters)
        corr = Table(["", *c.names[:n]], [[a, *(float(c.correlation[i, j]) for j in range(n))] for i, a in enumerate(c.names[:n])])
        sig = Table(["signal", "RMS residual", "noise", "noise given", "samples", "unit"],
                    [[s.name, s.rms, s.noise, "yes" if s.noise_given else "estimated", s.samples, si_unit(s.unit)] for s in c.signals])
        figures = [
            Figure(_fit_figure(e, trace, name, f"{e.name}: {name}"))
            for e, trace in zip(c.experiments, c.traces) for name in e.measured
        ]
        sections: list[Section | None] = [Section("Parameters", [params]), Section("Correlation", [corr]), Section("Residuals", [sig]),
                    Section("Measured and model", figures)]
        if self.prediction is not None:
            pr = self.prediction
            sections.append(Section("Prediction of records not fitted: measured and model", [
                Figure(_fit_figure(e, trace, name, f"{e.name}: {name} (not fitted)"))
                for e, trace in zip(pr.experiments, pr.traces) for name in e.measured]))
            prow = [[r["record"], r["signal"], r["rms"], r["rms_percent"], r["final_error_percent"], r["class"] or "-",
                     si_unit(r["unit"])] for r in pr.rows]
            sections.append(Section("Prediction of records not fitted", [
                Table(["record", "signal", "RMS error", "% of range", "final error [%]", "class (Efe2014 Table 5.3)", "unit"], prow)]))
        sections += [pages.references_section(["Efe2014"]), pages.files_section(self.files)]
        return pages.page(self.title(), "calibration against rig records", sections, self.warnings)


def _fit_figure(experiment: Experiment, trace: Mapping[str, Any], name: str, title: str) -> dict[str, Any]:
    """One signal of an experiment, measured (grey dots) and model (line), in the record's unit."""
    from hydroservo.plotting.interactive import xy_figure
    from hydroservo.units import si_unit

    factor, shown = experiment.shown(name)
    t = experiment.grid[experiment.index[name]]
    return xy_figure([(experiment.grid, trace[name] * factor, "model")], "t [s]", f"{name} [{si_unit(shown)}]", title=title,
                     markers=[(t, experiment.values[name] * factor, "measured")], marker_size=3)


def _plot_fit(calibration: Calibration, k: int, path: Path) -> Any:
    return calibration.plot(k, file=path)


def _plot_prediction(prediction: Prediction, k: int, path: Path) -> Any:
    from hydroservo.plotting.calibration import plot_fit

    e = prediction.experiments[k]
    return plot_fit(e, prediction.traces[k], title=f"prediction of {e.name} (not fitted)", file=path)


@dataclass
class PlanReport(Report):
    """What planned experiments would tell about the parameters."""

    command: ClassVar[str] = "calibrate --plan"

    model: str
    plan: ExperimentPlan

    def title(self) -> str:
        return f"{self.model}: what the planned experiments would determine ({self.plan.samples} samples)"

    def lines(self) -> list[str]:
        return [self.title(), "", *self.plan.lines(warnings=False)]  # the warnings go to stderr

    def to_dict(self) -> dict[str, Any]:
        return {"model": self.model, **self.plan.to_dict(), "files": self.files}


@dataclass
class Calibrate(Workflow):
    """Calibrate ``model`` against ``records`` (each one experiment: one CSV file, or several, one per sample rate).

    Parameters
    ----------
    model : str, Path or System
        A built-in model, a model file, or a system.
    records : list
        One entry per experiment: a file, a list of files, or a string of files separated by commas.
    fit : list of "comp.param[=LO..HI]" or mapping
        The parameters to fit, with optional bounds (units allowed).
    inputs : list of str
        Recorded signals that drive the model (``"command.y"``, ``"supply.p"``).
    noise : list of "signal=sigma" or mapping
        Each compared signal's noise (standard deviation, with its unit); others are estimated.
    validate : list
        Records kept out of the fit, to check the calibrated model's prediction.
    starts : int
        Starting points (the model's values, and the rest drawn over the bounds).
    plan : bool
        Do not fit: report what the records (as planned experiments) would determine at the model's values.
    max_samples : int, optional
        The most samples per channel used (default
        :data:`~hydroservo.identification.records.MAX_SAMPLES`, 20 000): a longer channel is thinned to every k-th
        sample, and a warning says so (rows in, rows used, how).
    """

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set", "records": "--record", "inputs": "--input", "validate": "--validate"}

    model: str | Path | System
    records: Sequence[RecordFiles] = field(default_factory=list)
    fit: Sequence[str] | Mapping[str, Any] = field(default_factory=list)
    inputs: Sequence[str] = ()
    noise: Sequence[str] | Mapping[str, Any] | None = None
    validate: Sequence[RecordFiles] = ()
    starts: int = 1
    initial: str = "estimate"
    sets: Sequence[str] | Mapping[str, Any] | None = None
    plan: bool = False
    gradient: str = "exact"
    accuracy: float | None = None
    max_evaluations: int = 200
    max_samples: int | None = None

    def __post_init__(self) -> None:
        from hydroservo.identification.calibration import CALIBRATION_ACCURACY

        if isinstance(self.max_evaluations, bool) or not isinstance(self.max_evaluations, int) or not 1 <= self.max_evaluations <= 100_000:
            raise ParameterError(f"{self.name('max_evaluations')} {self.max_evaluations!r}: expected a whole number from 1 to 100000")
        self.system = load_with_sets(self.model, self.sets, self.name("sets"))
        self.inputs = signal_list(self.inputs)
        self._records, said = _thinned(_records(self.records, self.name("records")), self.max_samples, self.name("max_samples"))
        self._validate, also = _thinned(_records(self.validate, ""), self.max_samples, self.name("max_samples"))
        self._notes = said + also
        self._noise = parse_noise(self.noise, self.name("noise"))
        if not self.fit:
            raise ParameterError(f"{self.name('fit')}: no parameter to fit; expected e.g. {self.name('fit')} valve.c_v")
        if isinstance(self.starts, bool) or not isinstance(self.starts, int) or not 1 <= self.starts <= 1000:
            raise ParameterError(f"{self.name('starts')} {self.starts!r}: expected a whole number from 1 to 1000")
        if self.initial not in ("estimate", "record", "trim", "model"):
            raise ParameterError(f"{self.name('initial')} {self.initial!r}: expected estimate, record, trim or model")
        self._accuracy = CALIBRATION_ACCURACY if self.accuracy is None else float(self.accuracy)

    def folder(self) -> str:
        return f"hydroservo-calibrate-{safe_name(self.system.name)}"

    def planned(self) -> list[str]:
        if self.plan:
            return []
        stem = safe_name(self.system.name)
        names = [f"{stem}-calibrated.toml", *(f"fit-{safe_name(r.name)}.png" for r in self._records)]
        names += [f"validation-{safe_name(r.name)}.png" for r in self._validate]
        return [*names, "calibration.json"]

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> CalibrationReport | PlanReport:
        from hydroservo.identification.calibration import calibrate, plan_experiment, predict

        name = self.system.name
        if self.plan:
            plan = plan_experiment(self.system, self._records, self.fit, self._noise, inputs=self.inputs,
                                   initial=self.initial, accuracy=self._accuracy)
            return PlanReport(name, plan, warnings=[*self._notes, *plan.warnings])
        result = calibrate(self.system, self._records, self.fit, inputs=self.inputs, noise=self._noise,
                           initial=self.initial, starts=self.starts, accuracy=self._accuracy, gradient=self.gradient,
                           max_evaluations=self.max_evaluations, progress=progress)
        prediction = None
        if self._validate:
            if progress:
                progress(f"predicting {len(self._validate)} record(s) not fitted")
            prediction = predict(result.system, self._validate, inputs=self.inputs, accuracy=self._accuracy)
        return CalibrationReport(name, result, prediction, warnings=[*self._notes, *result.warnings])


def run(model: str | Path | System, records: Sequence[RecordFiles], fit: Sequence[str] | Mapping[str, Any], **options: Any) -> CalibrationReport | PlanReport:
    """:class:`Calibrate` ``(model, records, fit, **options).run()``."""
    return Calibrate(model, records, fit, **options).run()


# -- rig ------------------------------------------------------------------------------------
@dataclass
class RigReport(Report):
    """A record of a model as a logger would make it."""

    command: ClassVar[str] = "rig"

    model: str
    record: Record

    def title(self) -> str:
        return f"{self.model}: virtual rig record {self.record.name!r}"

    def lines(self) -> list[str]:
        from hydroservo.units import si_unit

        out = [self.title()]
        for n, ch in self.record.channels.items():
            out.append(f"  {n:<16} {ch.rate:>8.4g} Hz  {ch.t.size:>6} samples  [{si_unit(ch.unit)}]")
        if self.files:
            out.append(f"wrote {', '.join(self.files.values())}")
        return out

    def to_dict(self) -> dict[str, Any]:
        return {
            "model": self.model, "record": self.record.name,
            "channels": {n: {"rate": c.rate, "samples": int(c.t.size), "unit": c.unit} for n, c in self.record.channels.items()},
            "files": self.files,
        }

    def artifacts(self) -> list[Artifact]:
        from hydroservo.io.records import record_files

        texts = record_files(self.record)
        return [Artifact(Path(name).stem, name, partial(_write_text, text)) for name, text in texts.items()]


def _write_text(text: str, path: Path) -> None:
    path.write_text(text, encoding="utf-8")


def parse_sensor(text: str, what: str = "--sensor") -> tuple[str, Any]:
    """``"cyl.pA=40 Hz,0.05 bar[,0.01 bar]"`` -> ``("cyl.pA", Sensor(40, "bar", 0.05, 0.01))``: rate, then noise and
    resolution (their unit is the one the file is written in; none: the model's unit)."""
    from hydroservo.identification.rig import Sensor
    from hydroservo.units import split_quantity, to_si

    if "=" not in text:
        raise ParameterError(f"{what} {shorten(text)!r}: expected SIGNAL=RATE[,NOISE[,RESOLUTION]], e.g. \"cyl.pA=40 Hz,0.05 bar\"")
    signal, spec = text.split("=", 1)
    parts = [s.strip() for s in spec.split(",")]
    rate = to_si(parts[0] if not parts[0].replace(".", "", 1).isdigit() else f"{parts[0]} Hz", "Hz", what=f"{what} {signal} rate")
    unit, values = None, []
    for part in parts[1:3]:
        value, u = split_quantity(part, what=f"{what} {signal}")
        if u:
            if unit is not None and u != unit:
                raise ParameterError(f"{what} {signal}: noise and resolution in {unit!r} and {u!r}; give both in one unit")
            unit = u
        values.append(value)
    noise = values[0] if values else 0.0
    resolution = values[1] if len(values) > 1 else 0.0
    try:
        return signal.strip(), Sensor(rate, unit, noise, resolution)
    except ParameterError as exc:
        raise ParameterError(f"{what} {signal.strip()}: {exc}") from None


@dataclass
class VirtualRig(Workflow):
    """Records of ``model`` as a logger makes them: each sensor ``"signal=RATE[,NOISE[,RESOLUTION]]"``."""

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set", "sensors": "--sensor"}

    model: str | Path | System
    sensors: Sequence[str] = ()
    t_end: float | str | None = None
    seed: int | None = None
    sets: Sequence[str] | Mapping[str, Any] | None = None
    name_: str | None = None

    def __post_init__(self) -> None:
        self.system = load_with_sets(self.model, self.sets, self.name("sets"))
        if not self.sensors:
            raise ParameterError(f"{self.name('sensors')}: no sensor; expected e.g. \"load.x=200 Hz,0.02 mm\"")
        self._sensors = dict(parse_sensor(s, self.name("sensors")) for s in self.sensors)
        known = set(self.system.build().units)
        for s in self._sensors:
            if s not in known:
                hint = did_you_mean(s, sorted(known))
                raise ParameterError(f"{self.name('sensors')} {s}: not a signal of {self.system.name!r}{hint}")

    def folder(self) -> str:
        return f"hydroservo-rig-{safe_name(self.system.name)}"

    def planned(self) -> list[str]:
        rates = sorted({s.rate for s in self._sensors.values()}, reverse=True)
        stem = self.name_ or f"{self.system.name}-rig"
        if len(rates) == 1:
            return [f"{stem}.csv"]
        return [f"{stem}-" + f"{round(r, 6):g}Hz".replace(".", "p") + ".csv" for r in rates]

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> RigReport:
        from hydroservo.identification.rig import virtual_rig

        record = virtual_rig(self.system, self._sensors, t_end=self.t_end, seed=self.seed, name=self.name_)
        return RigReport(self.system.name, record)


def rig(model: str | Path | System, sensors: Sequence[str], **options: Any) -> RigReport:
    """:class:`VirtualRig` ``(model, sensors, **options).run()``."""
    return VirtualRig(model, sensors, **options).run()

