"""Simulate a built-in model or a model file, as ``hydroservo simulate`` does.

>>> from hydroservo.workflows import simulate
>>> report = simulate.run("flight-simulator", t_end="0.2 s", points=51, write="none")
>>> report.lines()[0].startswith("simulated 'flight-simulator' for 0.2 s")
True
>>> sorted(report.to_dict())
['departures', 'files', 'model', 'notes', 'signals', 'solver', 't_end_s', 'wall_time_s', 'warnings']
"""

from __future__ import annotations

import math
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from hydroservo.errors import ImplausibleResultError, ParameterError, did_you_mean, shorten
from hydroservo.io.files import plain_float
from hydroservo.workflows.base import Artifact, Progress, Report, Workflow, asked_units, load_with_sets, safe_name

if TYPE_CHECKING:
    from hydroservo.io.html import Page
    from hydroservo.system.result import Result
    from hydroservo.system.system import System

__all__ = ["Simulate", "SimulationReport", "run", "WRITABLE", "accuracy_of"]

#: The files a simulation writes, by the name ``write`` gives them.
WRITABLE = ("csv", "png", "mat")


def accuracy_of(text: float | str | None, what: str = "--accuracy") -> float | None:
    """An accuracy: a fraction (``1e-3``) or a percentage (``"0.1%"``) of each signal's range."""
    if text is None or isinstance(text, float | int):
        return None if text is None else float(text)
    stripped = text.strip()
    try:
        return plain_float(stripped[:-1]) / 100 if stripped.endswith("%") else plain_float(stripped)
    except ValueError:
        raise ParameterError(
            f"{what} {shorten(text)!r}: expected a fraction of each signal's range, e.g. 1e-3 or 0.1%"
        ) from None


@dataclass
class SimulationReport(Report):
    """One run of a system: its result, how long it took, and the files it writes (csv, png, mat)."""

    command: ClassVar[str] = "simulate"

    system: System
    result: Result
    t_end: float  #: [s]
    wall_time: float  #: the whole run, model build included [s]
    kinds: list[str] = field(default_factory=lambda: ["csv", "png"])
    #: the changes made to the model (``COMPONENT.PARAMETER=VALUE``), for the plot's title
    changes: list[str] = field(default_factory=list)
    #: the units results are shown in, over the model's (``"p=bar, mm"``, ``"si"``; :class:`~hydroservo.units.UnitChoice`)
    units: Any = None
    #: CSV unit names in ASCII (``m^3/s``), no byte-order mark
    ascii: bool = False
    #: the table lists every signal, not only the model's main ones
    all_signals: bool = False
    #: what this run changes of the model's default run, on which its notes were measured (empty: none)
    departures: list[str] = field(default_factory=list)
    #: the time taken to have the model as C before the run [s]: compiled into the cache folder the first time
    #: (seconds), loaded from it after (milliseconds); None where the run is not compiled (CVODES)
    compile_time: float | None = None

    def notes(self) -> list[str]:
        """The model's notes, each said to be of the default run where this run departs from it
        (:func:`hydroservo.io.notebook.scoped_notes`)."""
        from hydroservo.io.notebook import scoped_notes

        return scoped_notes(self.system, self.departures)

    def title(self) -> str:
        return f"{self.system.name}: simulated response" + (f" ({', '.join(self.changes)})" if self.changes else "")

    def lines(self) -> list[str]:
        from hydroservo.io.text import text_table

        result = self.result
        out = [
            f"simulated {self.system.name!r} for {self.t_end:g} s in {self.wall_time * 1e3:.1f} ms ("
            + (f"compile/load {self.compile_time * 1e3:.1f} ms, " if self.compile_time is not None else "")
            + f"integration {result.stats['wall_time_s'] * 1e3:.2f} ms, {result.stats.get('nsteps', '?')} steps"
            + (f", {result.stats['method']}" + (" compiled" if result.stats["method"] != "cvodes" else "")
               if "method" in result.stats else "")
            + ")"
        ]
        summary = result.summary(self.units)
        shown = list(summary) if self.all_signals else result.main_signals()
        rows = [(n, summary[n]["unit"], summary[n]["final"], summary[n]["min"], summary[n]["max"]) for n in shown]
        out += text_table(rows, ["signal", "unit", "final", "min", "max"])
        if len(shown) < len(summary):
            out.append(f"({len(summary) - len(shown)} more signals in the CSV and --json; --all lists them here)")
        out += [f"note: {text}" for text in self.notes()]
        if self.files:
            out.append(f"wrote {' and '.join(self.files.values())}")
        return out

    def to_dict(self) -> dict[str, Any]:
        result = self.result
        solver = {k: v for k, v in result.stats.items() if k != "wall_time_s"}
        solver["integration_wall_time_s"] = result.stats["wall_time_s"]
        if self.compile_time is not None:
            solver["compile_load_wall_time_s"] = self.compile_time
        own = _crossings(result)
        return {
            "model": self.system.name,
            "t_end_s": self.t_end,
            "signals": result.summary(self.units),
            "solver": solver,
            "wall_time_s": self.wall_time,
            "warnings": [w.to_dict() for w in result.warnings]
            + [{"message": text} for text in self.warnings if text not in own],
            "notes": self.notes(),
            "departures": list(self.departures),
            "files": self.files,
        }

    def solver_stats(self) -> dict[str, Any]:
        """The run's solver statistics, with the whole run's wall time and the compile (or cache load) time."""
        stats = {**self.result.stats, "run_wall_time_s": self.wall_time}
        if self.compile_time is not None:
            stats["compile_load_wall_time_s"] = self.compile_time
        return stats

    def artifacts(self) -> list[Artifact]:
        name = safe_name(self.system.name)
        writers = {
            "csv": lambda path: self.result.to_csv(path, units=self.units, ascii=self.ascii),
            "mat": self.result.to_mat,
            "png": lambda path: self.result.plot(units=self.units, file=path, title=self.title()),
        }
        return [Artifact(kind, f"{name}.{kind}", writers[kind]) for kind in self.kinds]

    def document(self) -> Page:
        """The run: the model and its notes, the circuit, the response (interactive), the signals, the parameters,
        the solver, references."""
        from hydroservo.io.html import Figure, Section
        from hydroservo.plotting.interactive import result_figure
        from hydroservo.workflows import pages

        system, result = self.system, self.result
        panels = system.plots or system.default_panels()
        return pages.page(self.title(), f"simulated for {self.t_end:g} s", [
            Section("Model", pages.system_summary(system)) if pages.system_summary(system) else None,
            pages.notes_section(self.notes()),
            pages.circuit_section(system),
            Section("Response", [Figure(result_figure(result, panels, result.shown_units(self.units), title=self.title()))]),
            Section("Signals", [pages.signal_table(result, result.shown_units(self.units))]),
            Section("Parameters", [pages.parameter_table(system)]),
            Section("Solver", [pages.solver_table(self.solver_stats())]),
            pages.references_section(system.references()),
            pages.files_section(self.files),
        ], self.warnings)


#: More crossings of one kind in one component than this are told as one line (a ladder of 200 segments)
GROUPED = 3


def _crossings(result: Result) -> list[str]:
    """The physical bounds the run crossed, one line each, or one line per component and kind where a component
    crossed more than :data:`GROUPED` (its worst named, with how many more)."""
    groups: dict[tuple[str, str, bool], list[Any]] = {}
    for w in result.warnings:
        groups.setdefault((w.signal.split(".")[0], w.unit, w.value < w.bound), []).append(w)
    found = []
    for (owner, _, low), crossed in groups.items():
        if len(crossed) <= GROUPED:
            found += [str(w) for w in crossed]
            continue
        worst = min(crossed, key=lambda w: w.value) if low else max(crossed, key=lambda w: w.value)
        found.append(f"{worst} (and {len(crossed) - 1} more signals of {owner} "
                     f"{'below' if low else 'beyond'} their bounds; all in the JSON report)")
    return found


def _warnings(result: Result) -> list[str]:
    """The physical bounds the run crossed, and signals (such as aliases) that are not finite."""
    import numpy as np

    found = _crossings(result)
    for name, values in result.data.items():
        bad = ~np.isfinite(values)
        if bad.any():
            found.append(f"{name} is NaN or infinite from t = {result.t[int(np.argmax(bad))]:.6g} s")
    return found


@dataclass
class Simulate(Workflow):
    """A run of ``model`` (a built-in model's name, a model file, or a :class:`~hydroservo.system.System`).

    Parameters
    ----------
    model : str, Path or System
        What to simulate.
    sets : list of "COMPONENT.PARAMETER=VALUE" or dict, optional
        Changes to its parameters and options, with units (``{"load.W": "3000 lbf"}``).
    t_end : float or str, optional
        Duration [s] (``"500 ms"``); default the model's.
    points : int
        Number of output times.
    initial : {"parameters", "trim"}
        Initial state from the parameters, or from an equilibrium.
    accuracy : float or str, optional
        Deviation wanted, relative to each signal's range (``1e-3`` or ``"0.1%"``); or ``rtol``.
    rtol : float, optional
        Relative tolerance (absolute: rtol/100).
    method : str
        ``auto`` (default: the compiled ``rodas3`` for a model of at most 20 states where a C compiler is found, else
        ``cvodes``), ``cvodes``, or
        the compiled ``rodas3``, ``ros23`` or ``dopri5`` (:meth:`~hydroservo.system.model.Model.simulate`).
    max_steps : int, optional
        The run's step budget, shared over the output intervals (default: 1e5 at the default accuracy,
        :func:`~hydroservo.system.integration.default_max_steps`): a long run of a stiff circuit needs more.
    strict : bool
        Refuse a physically implausible result (:class:`~hydroservo.errors.ImplausibleResultError`).
    write : str or list of str, optional
        Files the report writes: some of ``csv``, ``png``, ``mat``, or ``"none"`` (default csv and png).
    units : str or dict, optional
        Units to show results in, over the model's own (``"p=bar, mm, cyl.pA=psi"``;
        :class:`~hydroservo.units.UnitChoice`): the table, the JSON, the CSV and the plot.
    si : bool
        Show every result in SI instead.
    ascii : bool
        CSV unit names in ASCII (``m^3/s``) without a byte-order mark.
    all_signals : bool
        The table lists every signal, not only the model's main ones (the JSON and the CSV always hold all).
    """

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set", "all_signals": "--all"}

    model: str | Path | System
    sets: Sequence[str] | Mapping[str, Any] | None = None
    t_end: float | str | None = None
    points: int = 1001
    initial: str = "parameters"
    accuracy: float | str | None = None
    rtol: float | None = None
    strict: bool = False
    write: str | Sequence[str] | None = None
    method: str = "auto"
    max_steps: int | None = None
    units: str | Mapping[str, str] | None = None
    si: bool = False
    ascii: bool = False
    all_signals: bool = False

    def __post_init__(self) -> None:
        from hydroservo.units import to_si

        self._check_solver_options()
        self.kinds = self._kinds()
        self.system = load_with_sets(self.model, self.sets, self.name("sets"))
        if self.t_end is None:
            self.duration = self.system.t_end
        else:
            self.duration = to_si(self.t_end, "s", what=self.name("t_end"))
            if not (math.isfinite(self.duration) and self.duration > 0):
                raise ParameterError(f"{self.name('t_end')} {self.t_end}: expected a positive, finite duration")
        if self.initial not in ("parameters", "trim"):
            raise ParameterError(f"{self.name('initial')} {self.initial!r}: expected 'parameters' or 'trim'")
        self.unit_choice = asked_units(self.system, self.units, self.si, self.name)

    def _check_solver_options(self) -> None:
        """Refuse rtol, accuracy, method and points before anything is loaded or built."""
        from hydroservo.system.integration import MAX_POINTS, SolverSettings, check_method

        try:
            check_method(self.method)
        except ParameterError as exc:
            raise ParameterError(f"{self.name('method')} {shorten(str(self.method))!r}: {str(exc).split(': ', 1)[-1]}") from None

        if self.rtol is not None and self.accuracy is not None:
            raise ParameterError(
                f"{self.name('rtol')} {self.rtol:g} and {self.name('accuracy')} {self.accuracy}: "
                "give one of them, not both"
            )
        self.accuracy_value = accuracy_of(self.accuracy, self.name("accuracy"))
        try:
            SolverSettings.of(rtol=self.rtol, accuracy=self.accuracy_value)
        except ParameterError as exc:
            option = (
                f"{self.name('rtol')} {self.rtol:g}" if self.rtol is not None
                else f"{self.name('accuracy')} {self.accuracy}"
            )
            raise ParameterError(f"{option}: {str(exc).split(': ', 1)[-1]}") from None
        if self.max_steps is not None:
            try:
                SolverSettings.of(max_steps=self.max_steps)
            except ParameterError as exc:
                raise ParameterError(f"{self.name('max_steps')} {self.max_steps!r}: {str(exc).split(': ', 1)[-1]}") from None
        if not 2 <= self.points <= MAX_POINTS:
            raise ParameterError(
                f"{self.name('points')} {self.points}: expected a whole number of output times from 2 to {MAX_POINTS}"
            )

    def _kinds(self) -> list[str]:
        if self.write is None:
            return ["csv", "png"]
        text = self.write if isinstance(self.write, str) else ",".join(self.write)
        kinds = [k.strip().lower() for k in text.split(",") if k.strip()]
        if kinds == ["none"]:
            return []
        wrong = [k for k in kinds if k not in WRITABLE]
        if wrong or not kinds:
            raise ParameterError(
                f"{self.name('write')} {shorten(text)!r}: expected 'none' or a comma-separated list of "
                f"{', '.join(WRITABLE)}"
            )
        return list(dict.fromkeys(kinds))

    def folder(self) -> str:
        return f"hydroservo-{safe_name(self.system.name)}"

    def planned(self) -> list[str]:
        return [f"{safe_name(self.system.name)}.{kind}" for kind in self.kinds]

    def _check_plots(self) -> None:
        """Refuse, before the run, plot panels naming unknown signals and plot units of the wrong dimension."""
        from hydroservo.units import UnitChoice

        system = self.system
        model = system.build()
        signals = set(model.state_names) | set(model.output_names)
        where = system.source or system.name
        for name in (n for panel in system.plots for n in panel):
            if name not in signals:
                raise ParameterError(
                    f"{where}: [model] plots: no signal {name!r}{did_you_mean(name, signals)}; signals: "
                    f"{', '.join(sorted(signals))}"
                )
        UnitChoice(dict(system.plot_units)).check(model.units, f"{where}: [model] plot_units")

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> SimulationReport:
        if self.system.plots and "png" in self.kinds:
            self._check_plots()
        start = time.perf_counter()
        compile_time = self._compile()
        result = self.system.simulate(
            t_end=self.duration, n_points=self.points, initial=self.initial, rtol=self.rtol,
            accuracy=self.accuracy_value, method=self.method, max_steps=self.max_steps,
        )
        wall = time.perf_counter() - start
        found = _warnings(result)
        if self.strict and found:
            lines = "\n  ".join(found)
            raise ImplausibleResultError(
                f"{self.name('strict')}: the result of {result.model!r} is physically implausible "
                f"({len(found)} warning(s); margins: docs/reliability.md):\n  {lines}"
            )
        changes = _shown_sets(self.sets)
        return SimulationReport(
            self.system, result, self.duration, wall, list(self.kinds), changes, self.unit_choice, self.ascii,
            self.all_signals, self.departures(), compile_time, warnings=found,
        )

    def _compile(self) -> float | None:
        """Have the model compiled to C before the run, where its method runs it compiled, and say how long that
        took [s]: the first run of a model compiles it into the cache folder (seconds), a later one loads it
        (milliseconds), so that the time a run reports is not taken for integration. None for CVODES, and where
        the model cannot be compiled (the run itself says why, or falls back to CVODES with a warning)."""
        from hydroservo.errors import HydroservoError
        from hydroservo.system.integration import AUTO_MAX_STATES
        from hydroservo.system.native import native

        model = self.system.build()
        if self.method == "cvodes" or (self.method == "auto" and model.nx > AUTO_MAX_STATES):
            return None
        start = time.perf_counter()
        try:
            native(model)
        except HydroservoError:
            return None
        return time.perf_counter() - start

    def departures(self) -> list[str]:
        """What this run changes of the model's default run (the model as its file gives it, its duration, the
        initial state from its parameters, the default solver, accuracy and output times), by the names the
        user gave them: a note of the model's is of the default run only (:meth:`SimulationReport.notes`)."""
        from hydroservo.io.notebook import departures
        from hydroservo.system.integration import DEFAULT_ACCURACY

        found = departures(self.system)
        if self.duration != self.system.t_end:
            found.append(f"{self.name('t_end')} {self.t_end}")
        if self.initial != "parameters":
            found.append(f"{self.name('initial')} {self.initial}")
        if self.method != "auto":
            found.append(f"{self.name('method')} {self.method}")
        if self.accuracy_value is not None and self.accuracy_value != DEFAULT_ACCURACY:
            found.append(f"{self.name('accuracy')} {self.accuracy}")
        if self.rtol is not None:
            found.append(f"{self.name('rtol')} {self.rtol:g}")
        if self.points != type(self).points:
            found.append(f"{self.name('points')} {self.points}")
        return found


def _shown_sets(sets: Sequence[str] | Mapping[str, Any] | None) -> list[str]:
    """The changes as ``COMPONENT.PARAMETER=VALUE`` texts, for titles."""
    if not sets:
        return []
    if isinstance(sets, Mapping):
        return [f"{k}={v}" for k, v in sets.items()]
    return [s.strip() for s in sets]


def run(model: str | Path | System, **inputs: Any) -> SimulationReport:
    """Simulate ``model`` (:class:`Simulate`'s inputs as keywords) and return the report."""
    return Simulate(model, **inputs).run()
