"""The staged-slot valve of [MareAttarND] on its test bench: characteristics across temperature, and the
two-step identification from measured curves (``hydroservo valve characteristics``, ``valve identify``).

>>> from hydroservo.workflows import staged_slot
>>> report = staged_slot.characteristics("aerospace-example", temperatures=[32], points=41)
>>> sorted(report.table["metrics"][32])[:2]
['flow_gain_high', 'flow_gain_low']
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from hydroservo.errors import ParameterError
from hydroservo.workflows.base import Artifact, Progress, Report, Workflow, numbers, safe_name

if TYPE_CHECKING:
    from hydroservo.analysis.static_bench import Bench, BenchCurves
    from hydroservo.components.valves.staged_slot import StagedSlotValve
    from hydroservo.identification.staged_slot import StagedSlotIdentification
    from hydroservo.io.html import Page

__all__ = ["Characteristics", "CharacteristicsReport", "Identify", "IdentificationReport", "characteristics",
           "identify", "MAX_OPENINGS"]

#: Most openings per test curve (each is a bridge solved at every opening).
MAX_OPENINGS = 10_001

_PLOTS = ("characteristics", "pressure_flow", "discharge_coefficient")


def temperatures_of(value: str | Sequence[float], what: str) -> list[float]:
    """Finite temperatures [degC]: comma-separated bare numbers, or a sequence; whether the fluid model holds at
    them is its own check (``Fluid.check_range``)."""
    import math

    if not isinstance(value, str):
        temps = [float(v) for v in value]
        bad = [t for t in temps if not math.isfinite(t)]
        if not temps or bad:
            raise ParameterError(f"{what} {value!r}: expected at least one finite temperature")
    else:
        if value.strip().lower().endswith(("degc", "°c", "c")):
            raise ParameterError(f"{what} {value!r}: give bare numbers in degC, e.g. -40,-15,32")
        temps = numbers(value, what)
    return temps


def metrics_table(table: dict[str, Any]) -> list[str]:
    """The Table-2 metrics at each temperature and their change from the reference, as text lines."""
    from hydroservo.analysis.static_bench import METRICS

    temps = sorted(table["metrics"])
    ref = table["reference"]
    lines = [f"{'':44s}" + "".join(f"{t:>11g} °C" for t in temps)]
    for key, (label, unit) in METRICS.items():
        lines.append(f"{label + ' [' + unit + ']':44s}" + "".join(f"{table['metrics'][t][key]:>14.4g}" for t in temps))
        lines.append(
            f"{'  change from ' + format(ref, 'g') + ' °C':44s}"
            + "".join(f"{'-':>14s}" if t == ref else f"{table['change'][t][key] * 100:>+13.0f}%" for t in temps)
        )
    return lines


def metrics_dict(table: dict[str, Any]) -> dict[str, Any]:
    """The same as plain data (temperatures as text keys)."""
    return {
        "reference_degC": table["reference"],
        "Q_n_m3_s": table["Q_n"],
        "metrics": {f"{t:g}": v for t, v in table["metrics"].items()},
        "change_from_reference": {f"{t:g}": v for t, v in table["change"].items()},
    }


# -- characteristics ------------------------------------------------------------------
@dataclass
class CharacteristicsReport(Report):
    """The bench curves at each temperature, the pressure-flow family, the Table-2 metrics and their change."""

    command: ClassVar[str] = "valve characteristics"

    source: str  #: the valve file, or the built-in valve's name
    valve: StagedSlotValve
    bench: Bench
    curves: list[BenchCurves]
    table: dict[str, Any]  #: :func:`hydroservo.analysis.static_bench.temperature_table`

    def title(self) -> str:
        stem, bench = Path(self.source).stem, self.bench
        return f"{stem}: {self.valve.fluid.name}, P_s = {bench.P_s / 1e5:.4g} bar, X_n = {bench.X_n * 1e3:g} mm"

    def artifacts(self) -> list[Artifact]:
        from hydroservo.analysis.static_bench import pressure_flow
        from hydroservo.io.curves import bench_tables, write_bench_table
        from hydroservo.plotting import staged_slot as plots

        out = [
            Artifact(f"T{c.temperature:g}_{name}", f"T{c.temperature:g}_{name}.csv", partial(write_bench_table, c, name))
            for c in self.curves for name in bench_tables(c)
        ]
        stem, bench, reference = Path(self.source).stem, self.bench, self.table["reference"]
        openings = [f * bench.X_n for f in (-1.0, -0.5, -0.25, -0.1, 0.1, 0.25, 0.5, 1.0)]

        def family(path: Path) -> None:
            P_L, Q_L = pressure_flow(self.valve, reference, bench, openings)
            plots.plot_pressure_flow_family(P_L, Q_L, openings, bench, title=f"{stem}: pressure-flow at {reference:g} °C",
                                            file=path)

        writers = {
            "characteristics": lambda p: plots.plot_bench_characteristics(self.curves, title=self.title(), file=p),
            "pressure_flow": family,
            "discharge_coefficient": lambda p: plots.plot_discharge_coefficient(self.valve.bridge_parameters(), file=p),
        }
        return out + [Artifact(k, f"{k}.png", writers[k]) for k in _PLOTS]

    def to_dict(self) -> dict[str, Any]:
        return {"valve": self.source, **metrics_dict(self.table), "files": self.files}

    def lines(self) -> list[str]:
        qn_note = "" if self.bench.Q_n is not None else f" (computed: no-load flow at X_n, {self.bench.T_rated:g} °C)"
        out = [f"{self.title()}, Q_n = {self.table['Q_n'] * 6e4:.4g} L/min{qn_note}", *metrics_table(self.table)]
        if self.files:
            folder = Path(next(iter(self.files.values()))).parent
            out.append(f"wrote {len(self.files)} files to {folder}")
        return out

    def document(self) -> Page:
        """The Table-2 metrics across temperature and the bench curves of each temperature (interactive)."""
        from hydroservo.analysis.static_bench import METRICS
        from hydroservo.io.html import Figure, Section, Table
        from hydroservo.plotting.interactive import xy_figure
        from hydroservo.workflows import pages

        temps = sorted(self.table["metrics"])
        metrics = Table(["metric", "unit", *(f"{t:g} °C" for t in temps)], [
            [label, unit, *(self.table["metrics"][t][key] for t in temps)] for key, (label, unit) in METRICS.items()
        ], f"changes from {self.table['reference']:g} °C: the JSON and the command's text")
        flow = [(c.X_flow * 1e6, c.Q_L * 6e4, f"{c.temperature:g} °C") for c in self.curves if c.X_flow is not None
                and c.Q_L is not None]
        leak = [(c.X_blocked * 1e6, c.Q_lk * 6e4, f"{c.temperature:g} °C") for c in self.curves
                if c.X_blocked is not None and c.Q_lk is not None]
        figures = [Figure(xy_figure(flow, "X [um]", "Q_L [L/min]", title="flow gain (connected ports)"))] if flow else []
        if leak:
            figures.append(Figure(xy_figure(leak, "X [um]", "Q_lk [L/min]", title="leakage (blocked ports)")))
        return pages.page(self.title(), "staged-slot valve on the ARP490 bench ([MareAttarND])", [
            Section("Metrics", [metrics]), Section("Curves", figures),
            pages.references_section(["MareAttarND", "SAEARP490"]), pages.files_section(self.files),
        ], self.warnings)


@dataclass
class Characteristics(Workflow):
    """The staged-slot valve ``params`` (a StagedSlotValve file with a [bench] table, or ``"aerospace-example"``)
    on its bench at each of ``temperatures`` [degC]; metrics changes from ``reference`` (default the first)."""

    OPTIONS: ClassVar[dict[str, str]] = {"temperatures": "--temperature"}

    params: str | Path
    temperatures: str | Sequence[float] = (-15.0, -40.0, 32.0)
    reference: float | None = None
    points: int = 401
    strict: bool = False

    def __post_init__(self) -> None:
        import numpy as np

        from hydroservo.io.component_file import read_staged_slot_valve

        self.valve, bench = read_staged_slot_valve(str(self.params))
        if bench is None:
            raise ParameterError(f"{self.params}: no [bench] table; expected P_s and X_n (the test conditions)")
        self.bench = bench
        what = self.name("temperatures")
        self.temps = temperatures_of(self.temperatures, what)
        if not 21 <= self.points <= MAX_OPENINGS:
            raise ParameterError(f"{self.name('points')} {self.points}: expected 21 to {MAX_OPENINGS} openings")
        if self.reference is not None and self.reference not in self.temps:
            raise ParameterError(
                f"{self.name('reference')} {self.reference:g}: expected one of the temperatures "
                f"{', '.join(f'{t:g}' for t in self.temps)}"
            )
        try:  # every temperature, before any is computed
            self.valve.fluid.check_range(np.array([bench.P_r, bench.P_s]), np.array(self.temps), self.strict)
        except ParameterError as exc:
            shown = self.temperatures if isinstance(self.temperatures, str) else ",".join(f"{t:g}" for t in self.temps)
            raise ParameterError(f"{what} {shown!r}: {exc}") from None

    def folder(self) -> str:
        return f"hydroservo-characteristics-{safe_name(Path(str(self.params)).stem)}"

    def planned(self) -> list[str]:
        tables = [f"T{t:g}_{name}.csv" for t in self.temps for name in ("flow_gain", "blocked_ports")]
        return tables + [f"{k}.png" for k in _PLOTS]

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> CharacteristicsReport:
        from hydroservo.analysis.static_bench import bench_curves, temperature_table

        curves = [bench_curves(self.valve, t, self.bench, n=self.points, strict=self.strict) for t in self.temps]
        table = temperature_table(self.valve, self.bench, self.temps, self.reference)
        return CharacteristicsReport(str(self.params), self.valve, self.bench, curves, table)


# -- identification -------------------------------------------------------------------
@dataclass
class IdentificationReport(Report):
    """The identified valve, each step's misfit, the largest relative errors and the predicted metrics."""

    command: ClassVar[str] = "valve identify"

    sources: list[str]  #: the curve files
    start: StagedSlotValve
    result: StagedSlotIdentification
    fixed: tuple[str, ...]
    model_curves: list[BenchCurves]  #: the identified valve on the bench, at the curves' temperature and each predicted
    table: dict[str, Any]

    def title(self) -> str:
        return (f"identified at {self.result.curves.temperature:g} °C from {len(self.sources)} file(s); held: "
                f"{', '.join(self.fixed) or 'none'}")

    def names(self) -> list[str]:
        from hydroservo.identification.staged_slot import HIGH_GAIN, LOW_GAIN

        return [n for n in LOW_GAIN + HIGH_GAIN if n not in self.fixed]

    def artifacts(self) -> list[Artifact]:
        from hydroservo.io.component_file import staged_slot_valve_toml
        from hydroservo.plotting.staged_slot import plot_bench_characteristics

        res = self.result
        header = (
            f"Identified by hydroservo from {', '.join(Path(c).name for c in self.sources)} at "
            f"{res.curves.temperature:g} degC\n(MareAttarND eqs. 21-24); max relative errors: "
            + ", ".join(f"{k} {v * 100:.2f} %" for k, v in res.errors.items())
        )
        title = "Identified model and the curves it was identified from"
        return [
            Artifact("parameters", "identified.toml",
                     lambda p: p.write_text(staged_slot_valve_toml(res.valve, res.curves.bench, header=header))),
            Artifact("plot", "identification.png",
                     lambda p: plot_bench_characteristics(self.model_curves, measured=res.curves, title=title, file=p)),
        ]

    def to_dict(self) -> dict[str, Any]:
        res, names = self.result, self.names()
        return {
            "temperature_degC": res.curves.temperature,
            "start": {n: self.start.values[n] for n in names},
            "identified": {n: res.valve.values[n] for n in names},
            "steps": res.steps,
            "max_relative_errors": res.errors,
            "prediction": metrics_dict(self.table),
            "files": self.files,
        }

    def lines(self) -> list[str]:
        res, start = self.result, self.start
        out = [self.title()]
        for n in self.names():
            unit, scale = ("µm", 1e6) if n.startswith(("X_", "r", "c")) and n != "Cq_inf" else ("", 1.0)
            out.append(f"  {n:10s} {start.values[n] * scale:>12.5g} -> {res.valve.values[n] * scale:>12.5g} {unit}")
        for s in res.steps[-2:]:
            out.append(
                f"  {s['step']}: rms {s['rms']:.3g} (full-scale units), condition {s['condition']:.3g}, round {s['round']}"
            )
        out.append("max relative errors: " + ", ".join(f"{k} {v * 100:.2f} %" for k, v in res.errors.items()))
        out += metrics_table(self.table)
        if self.files:
            out.append(f"wrote {self.files['parameters']} and {self.files['plot']}")
        return out

    def document(self) -> Page:
        """The identified parameters beside the start, the steps, and the predicted metrics."""
        from hydroservo.io.html import Section, Table
        from hydroservo.workflows import pages

        res = self.result
        params = Table(["parameter", "start", "identified"],
                       [[n, self.start.values[n], res.valve.values[n]] for n in self.names()], "SI")
        errors = Table(["curve", "largest relative error [%]"], [[k, 100 * v] for k, v in res.errors.items()])
        temps = sorted(self.table["metrics"])
        rows = [[key, *(self.table["metrics"][t][key] for t in temps)] for key in self.table["metrics"][temps[0]]]
        return pages.page(self.title(), "[MareAttarND] eqs. 21-24", [
            Section("Parameters", [params, errors]),
            Section("Predicted metrics", [Table(["metric", *(f"{t:g} °C" for t in temps)], rows)]),
            pages.references_section(["MareAttarND"]), pages.files_section(self.files),
        ], self.warnings)


@dataclass
class Identify(Workflow):
    """Identify a staged-slot valve from bench curves at one temperature ([MareAttarND] eqs. 21-24).

    ``curves``: CSV files (flow gain, pressure gain, leakage); ``start``: a StagedSlotValve file (starting values,
    n, widths); ``predict``: temperatures [degC] to predict the Table-2 metrics at; ``weights``: of the pressure and
    leakage residuals; ``fit_widths``: also fit w_L and w_H (not separable from C_q_inf).
    """

    curves: Sequence[str | Path]
    start: str | Path
    predict: str | Sequence[float] | None = None
    weights: Sequence[float] = (1.0, 1.0)
    high_laps: str = "pairs"
    fit_widths: bool = False
    strict: bool = False

    def __post_init__(self) -> None:
        import numpy as np

        from hydroservo.io.component_file import read_staged_slot_valve
        from hydroservo.io.curves import read_bench_curves

        self.data = read_bench_curves([str(c) for c in self.curves])
        self.start_valve, _ = read_staged_slot_valve(str(self.start))
        bench = self.data.bench
        self.start_valve.fluid.check_range(np.array([bench.P_r, bench.P_s]), self.data.temperature, self.strict)
        if len(self.weights) != 2 or min(self.weights) < 0:
            raise ParameterError(
                f"{self.name('weights')} {','.join(f'{w:g}' for w in self.weights)!r}: expected two non-negative "
                "numbers W_P,W_LK"
            )
        self.fixed: tuple[str, ...] = () if self.fit_widths else ("w_L", "w_H")
        self.predicted = temperatures_of(self.predict, self.name("predict")) if self.predict else []
        try:
            self.start_valve.fluid.check_range(np.array([bench.P_r, bench.P_s]), np.array(self.predicted), self.strict)
        except ParameterError as exc:
            raise ParameterError(f"{self.name('predict')} {self.predict!r}: {exc}") from None

    def folder(self) -> str:
        return f"hydroservo-identify-{safe_name(Path(str(self.curves[0])).stem)}"

    def planned(self) -> list[str]:
        return ["identified.toml", "identification.png"]

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> IdentificationReport:
        from hydroservo.analysis.static_bench import bench_curves, temperature_table
        from hydroservo.identification.staged_slot import identify_staged_slot

        data = self.data
        res = identify_staged_slot(data, self.start_valve, weights=(self.weights[0], self.weights[1]),
                                   high_laps=self.high_laps, fixed=self.fixed)
        temps = [data.temperature, *self.predicted]
        model = [bench_curves(res.valve, t, data.bench) for t in temps]
        table = temperature_table(res.valve, data.bench, temps, data.temperature)
        return IdentificationReport([str(c) for c in self.curves], self.start_valve, res, self.fixed, model, table)


def characteristics(params: str | Path, **inputs: Any) -> CharacteristicsReport:
    """The valve ``params`` on its bench (:class:`Characteristics`'s inputs as keywords)."""
    return Characteristics(params, **inputs).run()


def identify(curves: Sequence[str | Path], start: str | Path, **inputs: Any) -> IdentificationReport:
    """The identification from ``curves`` (:class:`Identify`'s inputs as keywords)."""
    return Identify(curves, start, **inputs).run()
