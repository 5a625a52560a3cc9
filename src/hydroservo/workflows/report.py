"""One page to show a colleague: a model's notes, circuit, parameters, response, warnings, solver statistics,
validation verdicts and references, or a result file's signals (``hydroservo report MODEL|RESULT``).

The page is one self-contained HTML file (:mod:`hydroservo.io.html`): it opens from disk or an e-mail
attachment with no network, its plots zoom, pan and show each value with its unit.

>>> from hydroservo.workflows import report
>>> page = report.run("flight-simulator", t_end="0.2 s", validation=False)
>>> [s.title for s in page.document().sections][:3]
['Model', 'Notes', 'Circuit']
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from hydroservo.errors import HydroservoError, ParameterError
from hydroservo.workflows.base import Artifact, Progress, Report, Workflow, footer, safe_name

if TYPE_CHECKING:
    from hydroservo.io.html import Page, Section
    from hydroservo.system.result import Result
    from hydroservo.system.system import System
    from hydroservo.workflows.simulate import SimulationReport
    from hydroservo.workflows.validate import ValidationReport

__all__ = ["ModelReport", "ResultReport", "ReportOf", "run", "result_panels"]


def result_panels(result: Result, limit: int = 8) -> list[list[str]]:
    """Panels of a result without a model: one per unit, in the order the signals come (at most ``limit``)."""
    panels: dict[str, list[str]] = {}
    for name in result.names:
        panels.setdefault(result.units.get(name, ""), []).append(name)
    return list(panels.values())[:limit]


def _response(result: Result, panels: list[list[str]], units: Mapping[str, str], title: str) -> Section:
    from hydroservo.io.html import Figure, Section
    from hydroservo.plotting.interactive import result_figure

    return Section("Response", [Figure(result_figure(result, panels, units, title=title),
                                       "drag to zoom (double-click to reset); every panel shares the time axis")])


@dataclass
class ModelReport(Report):
    """A model's run with everything a colleague needs to trust it."""

    command: ClassVar[str] = "report"

    simulation: SimulationReport
    validation: ValidationReport | None = None

    @property
    def system(self) -> System:
        return self.simulation.system

    def title(self) -> str:
        return self.simulation.title()

    def artifacts(self) -> list[Artifact]:
        return [Artifact("html", f"{safe_name(self.system.name)}.html", self.to_html)]

    def lines(self) -> list[str]:
        sim = self.simulation
        out = [f"{self.system.name}: simulated for {sim.t_end:g} s ({sim.result.stats.get('nsteps', '?')} steps), "
               f"{len(self.system.components)} components, {len(sim.warnings)} warning(s)"]
        if self.validation is not None:
            checks = [c for cs in self.validation.checks.values() for c in cs]
            ok = sum(c.verdict == "reproduced" for c in checks)
            out.append(f"  validation: {ok} of {len(checks)} published figures reproduced"
                       f" ({sum(c.verdict == 'info' for c in checks)} for information)")
        if self.files:
            out.append(f"wrote {', '.join(self.files.values())}")
        return out

    def to_dict(self) -> dict[str, Any]:
        simulation = {k: v for k, v in self.simulation.to_dict().items() if k != "files"}
        out: dict[str, Any] = {"model": self.system.name, "simulation": simulation,
                               "references": self.system.references(), "files": self.files}
        if self.validation is not None:
            out["validation"] = self.validation.to_dict()
        return out

    def document(self) -> Page:
        from hydroservo.io.html import Page, Section
        from hydroservo.workflows import pages

        sim, system = self.simulation, self.system
        panels = system.plots or system.default_panels()
        shown = [n for panel in panels for n in panel]
        sections: list[Section] = []
        about = pages.system_summary(system)
        if about:
            sections.append(Section("Model", about))
        noted = pages.notes_section(sim.notes())
        if noted is not None:
            sections.append(noted)
        warned = pages.warnings_section(sim.warnings)
        if warned is not None:
            sections.append(warned)
        sections.append(pages.circuit_section(system))
        units = sim.result.shown_units(sim.units)
        sections.append(_response(sim.result, panels, units, sim.title()))
        sections.append(Section("Signals", [pages.signal_table(sim.result, units, shown)]))
        sections.append(Section("Parameters", [pages.parameter_table(system)]))
        if self.validation is not None:
            sections += self.validation.document().sections
        sections.append(Section("Solver", [pages.solver_table(sim.solver_stats())]))
        sections.append(pages.references_section(system.references()))
        subtitle = f"simulated for {sim.t_end:g} s" + (f" with {', '.join(sim.changes)}" if sim.changes else "")
        return Page(system.name, subtitle, sections, footer())


@dataclass
class ResultReport(Report):
    """A result file's signals: their plots and their final, smallest and largest values."""

    command: ClassVar[str] = "report"

    source: str
    result: Result
    panels: list[list[str]]
    units: dict[str, str]

    def title(self) -> str:
        return f"{self.result.model}: recorded signals"

    def artifacts(self) -> list[Artifact]:
        return [Artifact("html", f"{safe_name(self.result.model)}.html", self.to_html)]

    def lines(self) -> list[str]:
        r = self.result
        out = [f"{self.source}: {len(r.names)} signals over {r.t[0]:g} to {r.t[-1]:g} s ({r.t.size} times)"]
        if self.files:
            out.append(f"wrote {', '.join(self.files.values())}")
        return out

    def to_dict(self) -> dict[str, Any]:
        return {"result": self.source, "signals": self.result.summary(self.units), "files": self.files}

    def document(self) -> Page:
        from hydroservo.io.html import Page, Section
        from hydroservo.workflows import pages

        r = self.result
        return Page(self.title(), f"from {self.source}", [
            _response(r, self.panels, self.units, self.title()),
            Section("Signals", [pages.signal_table(r, self.units)]),
        ], footer())


@dataclass
class ReportOf(Workflow):
    """The report of ``source``: a built-in model's name, a model file or a system (run, then shown), or a
    result file (``*.csv`` with ``t [s]`` and ``signal [unit]`` columns, shown as it is).

    Parameters
    ----------
    source : str, Path or System
        What to report.
    sets : list of "COMPONENT.PARAMETER=VALUE" or dict, optional
        Changes to the model's parameters first.
    t_end : float or str, optional
        Duration of the run [s] (default the model's).
    accuracy : float or str, optional
        Deviation wanted, relative to each signal's range (default 1e-4).
    validation : bool
        Also check the published figures of a built-in model that has a validation (:mod:`hydroservo.validation`).
    units : str or dict, optional
        Units to show the signals in, over the model's own (a result file's: those it is written in);
        ``"si"`` for SI (:class:`~hydroservo.units.UnitChoice`).
    """

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set", "validation": "--no-validation"}

    source: str | Path | System
    sets: Sequence[str] | Mapping[str, Any] | None = None
    t_end: float | str | None = None
    accuracy: float | str | None = None
    validation: bool = True
    units: str | Mapping[str, str] | None = None

    def __post_init__(self) -> None:
        from hydroservo.system.system import System
        from hydroservo.workflows.simulate import Simulate

        self.is_result = not isinstance(self.source, System) and str(self.source).lower().endswith(".csv")
        if self.is_result:
            from hydroservo.io.results import read_csv

            self.result = read_csv(str(self.source))
            self.stem = safe_name(self.result.model)
            try:
                self.shown = self.result.shown_units(self.units)
            except HydroservoError as exc:
                raise ParameterError(f"{self.name('units')}: {str(exc).split(': ', 1)[-1]}") from None
        else:
            self.job = Simulate(self.source, self.sets, t_end=self.t_end, accuracy=self.accuracy, write="none",
                                units=self.units, cli=self.cli)
            self.stem = safe_name(self.job.system.name)

    def folder(self) -> str:
        return f"hydroservo-{self.stem}-report"

    def planned(self) -> list[str]:
        return [f"{self.stem}.html"]

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> ModelReport | ResultReport:
        if self.is_result:
            return ResultReport(str(self.source), self.result, result_panels(self.result), self.shown)
        if progress is not None:
            progress("simulating")
        simulation = self.job.run()
        validation = None
        name = self.job.system.name
        from hydroservo.validation import VALIDATIONS

        if self.validation and name in VALIDATIONS and str(self.job.system.source).startswith("built-in:"):
            from hydroservo.workflows.validate import Validate

            if progress is not None:
                progress(f"checking the published figures of {name}")
            validation = Validate(name).run()
        return ModelReport(simulation, validation, warnings=list(simulation.warnings))


def run(source: str | Path | System, **inputs: Any) -> ModelReport | ResultReport:
    """The report of ``source`` (:class:`ReportOf`'s inputs as keywords)."""
    return ReportOf(source, **inputs).run()
