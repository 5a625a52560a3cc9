"""Which parameter matters: one at a time, Sobol indices or Morris screening (``hydroservo sensitivity``).

What to vary is written as the command takes it: ``"NAME": "LOW..HIGH"`` (a range, with units) or
``"NAME": "V1,V2,..."`` (levels or option choices, one at a time only); a tuple ``(low, high)`` or a
list of levels does the same from Python.

>>> from hydroservo.workflows import sensitivity
>>> report = sensitivity.run("robot-arm", vary={"valve.c_v": "1e-4..2e-4"}, levels=3, points=101)
>>> list(report.study.levels["valve.c_v"])
['0.0001', '0.00015', '0.0002']
"""

from __future__ import annotations

import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from hydroservo.errors import ParameterError, shorten
from hydroservo.units import plain_number
from hydroservo.workflows.base import (
    Artifact,
    Progress,
    Report,
    Workflow,
    asked_units,
    json_records,
    load_with_sets,
    safe_name,
)

if TYPE_CHECKING:
    from hydroservo.analysis.sensitivity import GlobalStudy, OneAtATime
    from hydroservo.io.html import Page
    from hydroservo.system.system import System
    from hydroservo.units import UnitChoice

__all__ = ["Sensitivity", "OneAtATimeReport", "GlobalReport", "run", "METHODS"]

#: The methods of a study.
METHODS = ("oat", "sobol", "morris")

#: ``progress(done, failed, total, elapsed)`` of a global study's runs.
RunsProgress = Callable[[int, int, int, float], None]


def _quantity(text: Any) -> Any:
    if not isinstance(text, str):
        return text
    value = plain_number(text)  # "2_0.0" is not 20: left as text, refused where it is read as a quantity
    return text if value is None else value


@dataclass(frozen=True)
class _Shown:
    """How a metric column is shown: its name with the unit shown, a value's conversion, a difference's factor."""

    name: str
    convert: Callable[[float], float]
    factor: float


def _converter(own: str, to: str) -> Callable[[float], float]:
    """A value in unit ``own`` to unit ``to``."""
    from hydroservo.units import convert

    if own == to:
        return float
    return lambda v: float(convert(v, own, to))


def _shown_metrics(system: System, columns: Sequence[str], choice: UnitChoice) -> dict[str, _Shown]:
    """For each metric column (``"final(xv) [m]"``), how it is shown in ``choice``'s units: a metric of a signal's
    value (final, at, peak, max, min, mean) in the signal's shown unit; times and overshoots as they are."""
    from hydroservo.analysis.metrics import KINDS, parse_metric
    from hydroservo.units import si_unit

    units = system.build().units
    out: dict[str, _Shown] = {}
    for column in columns:
        text = column.rsplit(" [", 1)[0]
        try:
            metric = parse_metric(text, units)
        except ParameterError:  # a metric of the user's own (custom_metric): shown as it is
            out[column] = _Shown(column, float, 1.0)
            continue
        own = units.get(metric.signal, "")
        if KINDS.get(metric.kind) != "signal" or not own:
            out[column] = _Shown(column, float, 1.0)
            continue
        to = choice.unit(metric.signal, own)
        factor = choice.scale(metric.signal, own)[0]
        out[column] = _Shown(f"{text} [{si_unit(to)}]", _converter(own, to), factor)
    return out


@dataclass
class OneAtATimeReport(Report):
    """The response family and the metrics of each level of each factor ([Efe2014] Figs. 5.14-5.19)."""

    command: ClassVar[str] = "sensitivity"

    system: System
    study: OneAtATime
    signals: list[str] | None = None
    #: the units signals and metrics are shown in (None: the model's)
    units: UnitChoice | None = None

    def title(self) -> str:
        return f"{self.study.model}: one factor at a time"

    def _choice(self) -> UnitChoice:
        return self.units if self.units is not None else self.system.unit_choice()

    def _metrics(self) -> list[str]:
        return [c for c in self.study.table.columns if c not in ("factor", "level", "status", "reason")]

    def table(self) -> Any:
        """The metrics of every level (a DataFrame), in the units they are shown in (:attr:`units`)."""
        shown = _shown_metrics(self.system, self._metrics(), self._choice())
        table = self.study.table.copy()
        for column, how in shown.items():
            table[column] = [how.convert(v) for v in table[column]]
        return table.rename(columns={c: how.name for c, how in shown.items()})

    def artifacts(self) -> list[Artifact]:
        from hydroservo.io.results import write_frame

        study = self.study
        out = [Artifact("oat.csv", "oat.csv", lambda p: write_frame(self.table(), p))]
        def family(factor: str) -> Any:
            return lambda path: study.plot(factor, self.signals, units=self._choice().units(study.units), file=path)

        for f in study.levels:
            name = f"oat-{safe_name(f)}.png"
            out.append(Artifact(name, name, family(f)))
        return out

    def to_dict(self) -> dict[str, Any]:
        return {"method": "oat", "table": json_records(self.table()), "files": self.files}

    def lines(self) -> list[str]:
        """A table per factor: a row per metric (its unit in brackets), a column per level."""
        from hydroservo.io.text import text_table

        study, table = self.study, self.table()
        metrics = [c for c in table.columns if c not in ("factor", "level", "status", "reason")]
        out = [self.title()]
        for factor in study.levels:
            rows = table[table["factor"] == factor]
            out.append(f"  {factor}:")
            out += text_table([[m, *rows[m]] for m in metrics], ["metric", *rows["level"]], indent=4, digits=4)
            for _, row in rows[rows["status"] != "ok"].iterrows():
                out.append(f"    FAILED at {row['level']}: {row['reason']}")
        for f, path in self.files.items():
            out.append(f"  {f}: {path}")
        return out

    def document(self) -> Page:
        """The metrics of each level, and each factor's response family (interactive)."""
        from hydroservo.io.html import Figure, Section
        from hydroservo.plotting.interactive import xy_figure
        from hydroservo.units import from_si, si_unit
        from hydroservo.workflows import pages

        study = self.study
        units = self._choice().units(study.units)
        figures = []
        for factor, levels in study.levels.items():
            for signal in (self.signals or [n for p in (self.system.plots or self.system.default_panels()) for n in p])[:4]:
                own = study.units.get(signal, "")
                unit = units.get(signal) or si_unit(own)
                scale = from_si(1.0, own, units[signal]) if signal in units else 1.0
                curves = [(study.t, study.responses[factor][k][signal] * scale, f"{factor} = {level}")
                          for k, level in enumerate(levels) if signal in study.responses[factor][k]]
                if curves:
                    figures.append(Figure(xy_figure(curves, "t [s]", f"{signal} [{unit}]", title=f"{signal}: {factor}")))
        return pages.page(self.title(), "one factor at a time, the others at their values", [
            Section("Metrics", [pages.dataframe_table(self.table())]),
            Section("Responses", figures) if figures else None,
            pages.circuit_section(self.system),
            pages.files_section(self.files),
        ], self.warnings)


@dataclass
class GlobalReport(Report):
    """Sobol indices or Morris screening of every metric, with the runs behind them."""

    command: ClassVar[str] = "sensitivity"

    system: System
    study: GlobalStudy
    wall_time: float  #: [s]
    #: where the runs were written as they finished (Parquet parts), if anywhere
    runs_folder: Path | None = None
    #: the units Morris' effects are shown in, those of their metrics (None: the model's)
    units: UnitChoice | None = None

    def title(self) -> str:
        return f"{self.system.name}: {self.study.method} ({self.study.runs.stats['runs']} runs)"

    def indices(self) -> Any:
        """The indices (a DataFrame); Morris' effects in the unit their metric is shown in (:attr:`units`),
        named in the ``metric`` column (Sobol's indices have no unit)."""
        study = self.study
        table = study.indices.copy()
        if table.empty:
            return table
        shown = _shown_metrics(self.system, list(dict.fromkeys(table["metric"])),
                               self.units if self.units is not None else self.system.unit_choice())
        if study.method == "morris":  # effects in the metric's unit; Sobol's indices have none
            for key in ("mu_star", "mu_star_conf", "sigma", "mu"):
                if key in table:
                    table[key] = [v * shown[m].factor for v, m in zip(table[key], table["metric"], strict=True)]
        table["metric"] = [shown[m].name for m in table["metric"]]
        return table

    def artifacts(self) -> list[Artifact]:
        from hydroservo.io.results import write_frame

        study = self.study
        return [
            Artifact("indices.csv", "indices.csv", lambda p: write_frame(self.indices(), p)),
            Artifact("indices.png", "indices.png", lambda p: study.plot(file=p, title=self.title())),
        ]

    def _files(self) -> dict[str, str]:
        return self.files | ({"runs": str(self.runs_folder)} if self.runs_folder is not None else {})

    def to_dict(self) -> dict[str, Any]:
        return {**self.study.to_dict(), "indices": json_records(self.indices()), "wall_time_s": self.wall_time,
                "files": self._files()}

    def lines(self) -> list[str]:
        from hydroservo.io.text import text_table

        result = self.study
        s = result.runs.stats
        out = [f"{result.method}: {s['runs']} runs ({s['run_now']} now, {s['resumed']} resumed), {s['failed']} failed, "
               f"{s['implausible']} implausible; {self.wall_time:.1f} s, {s['runs_per_s']:.0f} runs/s ({s['where']})"]
        sobol = result.method == "sobol"
        conf = f"± {100 * result.conf_level:g} %"
        for metric, rows in self.indices().groupby("metric", sort=False):
            out.append(f"  {metric}")
            rows = rows.sort_values("ST" if sobol else "mu_star", ascending=False)
            if sobol:
                out += text_table([[r["parameter"], r["S1"], r["S1_conf"], r["ST"], r["ST_conf"]] for _, r in rows.iterrows()],
                                  ["parameter", "S1", conf, "ST", conf], indent=4, digits=".3f")
            else:
                out += text_table([[r["parameter"], r["mu_star"], r["mu_star_conf"], r["sigma"]] for _, r in rows.iterrows()],
                                  ["parameter", "mu*", conf, "sigma"], indent=4, digits=[4, 4, 3, 4])
        for note in result.notes:
            out.append(f"  note: {note}")
        for f, path in self._files().items():
            out.append(f"  {f}: {path}")
        return out

    def document(self) -> Page:
        """The indices with their confidence intervals (a bar chart per metric), and the table."""
        from hydroservo.io.html import Figure, Notice, Section
        from hydroservo.plotting.interactive import bar_figure
        from hydroservo.workflows import pages

        study = self.study
        key, conf = ("ST", "ST_conf") if study.method == "sobol" else ("mu_star", "mu_star_conf")
        groups = {
            str(metric): [(str(r["parameter"]), float(r[key]), float(r[conf])) for _, r in rows.iterrows()]
            for metric, rows in study.indices.groupby("metric", sort=False)
        }
        label = "total Sobol index ST" if study.method == "sobol" else "Morris mu* (the metric's unit)"
        s = study.runs.stats
        return pages.page(self.title(), f"{s['runs']} runs, {s['failed']} failed, {self.wall_time:.1f} s", [
            Section("Indices", [Figure(bar_figure(groups, label, title=self.title()))]),
            Section("Table", [pages.dataframe_table(study.indices)]),
            Section("Notes", [Notice(n, "info") for n in study.notes]) if study.notes else None,
            pages.circuit_section(self.system),
            pages.references_section(sorted(set(self.system.references()) | {"Saltelli2010", "Campolongo2007"})),
            pages.files_section(self._files()),
        ], self.warnings)


@dataclass
class Sensitivity(Workflow):
    """Vary parameters of ``model`` and measure each run.

    Parameters
    ----------
    model : str, Path or System
        A built-in model's name, a model file or a system.
    vary : mapping or list of "NAME=..." texts
        What to vary (module notes): ranges for every method; levels and option choices for ``oat``.
    method : {"oat", "sobol", "morris"}
        One factor at a time (default), Sobol indices or Morris screening.
    sets : list of "COMPONENT.PARAMETER=VALUE" or dict, optional
        Changes to its parameters first.
    n : int, optional
        Sobol: the base sample, a power of two (runs: n (d + 2); default 256); Morris: trajectories (runs:
        n (d + 1); default 20).
    levels : int, optional
        oat: levels per range (default 5); Morris: grid levels, even (default 4).
    metrics : list of str, optional
        Metrics of each run (``"final(x_mm)"``, ``"mean(cyl.pA, 0.4 s, 0.6 s)"``); default the model's.
    signals : list of str, optional
        oat: the signals drawn (default the model's panels).
    t_end : float or str, optional
        Duration of each run (default the model's).
    points : int
        Output times per run.
    seed : int
        Seed of the sample (repeatable).
    threads, chunk : int, optional
        Local threads (default all cores); runs per chunk (default 128).
    scheduler : str, optional
        A Dask scheduler's address to run the chunks on.
    force : bool
        Replace the runs of another study found in the folder (otherwise refused).
    runs_progress : callable, optional
        ``runs_progress(done, failed, total, elapsed)`` as a global study's runs finish.
    units : str or dict, optional
        Units to show signals and metrics in, over the model's own (``"p=bar, mm"``;
        :class:`~hydroservo.units.UnitChoice`): the table, the CSV, the JSON and the plots.
    si : bool
        Show them in SI instead.
    """

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set", "metrics": "--metric", "levels": "--levels"}

    model: str | Path | System
    vary: Mapping[str, Any] | Sequence[str] = field(default_factory=dict)
    method: str = "oat"
    sets: Sequence[str] | Mapping[str, Any] | None = None
    n: int | None = None
    levels: int | None = None
    metrics: Sequence[str] | None = None
    signals: Sequence[str] | None = None
    t_end: float | str | None = None
    points: int = 301
    seed: int = 0
    threads: int | None = None
    chunk: int | None = None
    scheduler: str | None = None
    force: bool = False
    runs_progress: RunsProgress | None = field(default=None, repr=False)
    units: str | Mapping[str, str] | None = None
    si: bool = False

    def __post_init__(self) -> None:
        from hydroservo.units import to_si

        if self.method not in METHODS:
            raise ParameterError(f"{self.name('method')} {self.method!r}: expected one of {', '.join(METHODS)}")
        self.system = load_with_sets(self.model, self.sets, self.name("sets"))
        self.unit_choice = self.system.unit_choice(asked_units(self.system, self.units, self.si, self.name))
        self.grid_levels = self.levels if self.levels is not None else (4 if self.method == "morris" else 5)
        if self.grid_levels < 2 or (self.method == "morris" and self.grid_levels % 2):
            raise ParameterError(
                f"{self.name('levels')} {self.grid_levels}: expected at least 2"
                + (", even for morris" if self.method == "morris" else "")
            )
        self.factors, self.ranges = self._vary()
        self.duration = to_si(self.t_end, "s", what=self.name("t_end")) if self.t_end else self.system.t_end
        if not self.duration > 0:
            raise ParameterError(f"{self.name('t_end')} {self.t_end}: expected a positive duration")
        if self.points < 11:
            raise ParameterError(f"{self.name('points')} {self.points}: expected at least 11")
        if self.method != "oat":
            self._check_global()

    def _items(self) -> list[tuple[str, Any]]:
        what = self.name("vary")
        if isinstance(self.vary, Mapping):
            return [(str(k).strip(), v) for k, v in self.vary.items()]
        items, seen = [], set()
        for item in self.vary:
            if "=" not in item:
                raise ParameterError(f"{what} {shorten(item)!r}: expected NAME=LOW..HIGH or NAME=V1,V2,...")
            name, text = (s.strip() for s in item.split("=", 1))
            if name in seen:
                raise ParameterError(f"{what} {name}: given twice")
            seen.add(name)
            items.append((name, text))
        return items

    def _vary(self) -> tuple[dict[str, Any], dict[str, tuple[Any, Any]]]:
        """(levels of each factor for oat, ranges for sobol and morris), checked."""
        what = self.name("vary")
        items = self._items()
        if not items:
            raise ParameterError(f"{what}: no parameter to vary; expected e.g. {what} 'valve.c_v=1e-4..2e-4'")
        listed: dict[str, Any] = {}
        ranges: dict[str, tuple[Any, Any]] = {}
        for name, value in items:
            shown = f"{name}={value if isinstance(value, str) else value!r}"
            if isinstance(value, str) and ".." in value:
                lo, _, hi = value.partition("..")
                if not lo.strip() or not hi.strip():
                    raise ParameterError(f"{what} {shorten(shown)!r}: expected LOW..HIGH, e.g. 25bar..35bar")
                ranges[name] = (_quantity(lo.strip()), _quantity(hi.strip()))
            elif isinstance(value, tuple) and len(value) == 2:
                ranges[name] = (_quantity(value[0]), _quantity(value[1]))
            else:
                values = [v.strip() for v in value.split(",") if v.strip()] if isinstance(value, str) else list(value)
                if len(values) < 2:
                    raise ParameterError(
                        f"{what} {shorten(shown)!r}: expected LOW..HIGH or at least two levels V1,V2"
                    )
                if self.method != "oat":
                    raise ParameterError(
                        f"{what} {shorten(shown)!r}: {self.name('method')} {self.method} samples ranges; give "
                        "NAME=LOW..HIGH (levels and options are for --method oat)"
                    )
                listed[name] = values
        if self.method == "oat":
            for name, (lo, hi) in ranges.items():
                listed[name] = self._spaced(name, lo, hi)
            return {name: listed[name] for name, _ in items}, {}
        return {}, ranges

    def _spaced(self, name: str, lo: Any, hi: Any) -> list[str]:
        """``levels`` values evenly spaced from ``lo`` to ``hi``, in their unit."""
        import numpy as np

        from hydroservo.analysis.sensitivity import bounds

        _, ((a, b),), (unit,) = bounds({name: (lo, hi)})
        return [f"{v:.6g} {unit}".strip() for v in np.linspace(a, b, self.grid_levels)]

    def _check_global(self) -> None:
        """Everything a global study needs, checked before its runs folder is made (a refusal leaves nothing)."""
        from hydroservo.analysis.metrics import parse_metric
        from hydroservo.analysis.sensitivity import bounds

        self.size = self.n or (256 if self.method == "sobol" else 20)
        bounds(self.ranges)
        for k in self.ranges:
            self.system.parameter_key(k)
        units = self.system.build().units
        for m in self.metrics or []:
            parse_metric(m, units, self.duration)
        n = self.size
        if self.method == "sobol" and (n < 2 or n & (n - 1)):
            raise ParameterError(f"{self.name('n')} {n}: sobol: n = {n}: expected a power of two (the base sample), e.g. 256")
        if self.method == "morris" and n < 2:
            raise ParameterError(f"{self.name('n')} {n}: morris: expected at least 2 trajectories")

    def folder(self) -> str:
        return f"hydroservo-{safe_name(self.system.name)}-sensitivity"

    def planned(self) -> list[str]:
        if self.method == "oat":
            return ["oat.csv", *(f"oat-{safe_name(f)}.png" for f in self.factors)]
        return ["indices.csv", "indices.png"]

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> OneAtATimeReport | GlobalReport:
        """Run the study; a global study writes its runs to ``folder``/runs as they finish (the same study run
        again into the same folder resumes), or keeps them in memory without a folder."""
        from hydroservo.analysis.sensitivity import one_at_a_time

        metrics = list(self.metrics) if self.metrics else None
        if self.method == "oat":
            signals = list(self.signals) if self.signals else None
            study = one_at_a_time(self.system, self.factors, metrics=metrics, signals=signals, t_end=self.duration,
                                  n_points=self.points)
            return OneAtATimeReport(self.system, study, signals, self.unit_choice)
        return self._run_global(metrics, folder)

    def _run_global(self, metrics: list[str] | None, folder: Path | None) -> GlobalReport:
        from hydroservo.analysis.sensitivity import morris, sobol
        from hydroservo.io import RunStore

        system = self.system
        store = None
        made = folder is not None and not folder.exists()
        if folder is not None:
            fingerprint = {
                "model": system.name,
                "parameters": {k: repr(v) for k, v in sorted(system.parameter_values().items())},
                "method": self.method, "ranges": self.ranges, "n": self.size, "levels": self.grid_levels,
                "seed": self.seed, "metrics": metrics or system.metrics, "t_end": self.duration, "points": self.points,
            }
            store = RunStore(folder / "runs", fingerprint, force=self.force)
        kwargs: dict[str, Any] = {
            "metrics": metrics, "t_end": self.duration, "n_points": self.points, "seed": self.seed, "store": store,
            "progress": self.runs_progress, "chunk": self.chunk, "threads": self.threads, "scheduler": self.scheduler,
        }
        start = time.perf_counter()
        try:
            if self.method == "sobol":
                result = sobol(system, self.ranges, self.size, **kwargs)
            else:
                result = morris(system, self.ranges, self.size, levels=self.grid_levels, **kwargs)
        except BaseException:
            if store is not None and not store.parts():  # nothing run yet: leave nothing behind (runs are kept)
                store.remove()
                if made and folder is not None and folder.is_dir() and not any(folder.iterdir()):
                    folder.rmdir()
            raise
        wall = time.perf_counter() - start
        return GlobalReport(system, result, wall, None if folder is None else folder / "runs", self.unit_choice)


def run(model: str | Path | System, **inputs: Any) -> OneAtATimeReport | GlobalReport:
    """The study of ``model`` (:class:`Sensitivity`'s inputs as keywords), its runs kept in memory."""
    return Sensitivity(model, **inputs).run()
