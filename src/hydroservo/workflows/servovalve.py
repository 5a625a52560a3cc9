"""The first-principles two-stage servovalve of [GordicND] on its test bench, what moves each of its figures,
and the catalogue models fitted to it (``hydroservo servovalve bench``, ``design``, ``fit-catalogue``).

>>> from hydroservo.workflows import servovalve
>>> report = servovalve.bench(tests=["static"], points=5)
>>> [row[0] for row in report.bench.table()][:2]
['rated flow at +rated current', 'rated flow at -rated current']
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from hydroservo.errors import ParameterError
from hydroservo.workflows.base import Artifact, Progress, Report, Workflow

if TYPE_CHECKING:
    from hydroservo.analysis.servovalve_bench import Bode, StaticTests
    from hydroservo.analysis.servovalve_bench import Report as BenchReport
    from hydroservo.analysis.servovalve_design import DesignStudy
    from hydroservo.components.base import Component
    from hydroservo.identification.servovalve_catalogue import CatalogueFit
    from hydroservo.io.html import Page

__all__ = ["DesignPoint", "Bench", "BenchTestsReport", "Design", "DesignReport", "FitCatalogue", "CatalogueReport", "bench",
           "design", "fit_catalogue"]


@dataclass
class DesignPoint(Workflow):
    """A built-in servovalve at a design point: its supply and rated current, its fidelity, changes to Table 1.

    Parameters
    ----------
    valve : str
        A built-in servovalve (:func:`hydroservo.data.servovalves`).
    supply : float or str, optional
        Supply pressure (``"210 bar"``; default the valve's rating).
    current : float or str, optional
        Rated current (``"10 mA"``; default the valve's rating).
    sets : list of "NAME=VALUE" or dict, optional
        Changes to parameters of :class:`~hydroservo.components.TwoStageServovalve`, with units.
    first_stage : {"quasi-static", "compressible"}
        The flapper-nozzle stage: the paper's simplified model, or eqs. 20-22 whole.
    flapper : {"bent", "rigid"}
        The flapper tip from eqs. 13-14, or theta l_a.
    """

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set", "valve": "servovalve"}

    valve: str = "gordic-table1"
    supply: float | str | None = None
    current: float | str | None = None
    sets: Sequence[str] | Mapping[str, Any] | None = None
    first_stage: str = "quasi-static"
    flapper: str = "bent"

    def __post_init__(self) -> None:
        from hydroservo.analysis.servovalve_bench import BenchConditions
        from hydroservo.components import TwoStageServovalve
        from hydroservo.data import servovalves
        from hydroservo.workflows.base import parse_sets

        known = servovalves()
        if self.valve not in known:
            raise ParameterError(f"servovalve {self.valve!r}: unknown; built-in: {', '.join(known)}")
        entry = known[self.valve]
        self.description = entry["description"]
        component = TwoStageServovalve("sv", first_stage=self.first_stage, flapper=self.flapper)
        what = self.name("sets")
        for key, value in parse_sets(self.sets, what) if not isinstance(self.sets, Mapping) else self.sets.items():
            if key not in component.PARAMETERS:
                raise ParameterError(
                    f"{what} {key}={value}: expected NAME=VALUE with NAME a parameter of TwoStageServovalve "
                    f"({', '.join(sorted(component.PARAMETERS))})"
                )
            component.set(**{key: value})
        component.check()
        supply = entry["supply"] if self.supply is None else self.supply
        current = entry["current"] if self.current is None else self.current
        self.conditions = BenchConditions.of(component, supply, current,
                                             supply_what=self.name("supply"), current_what=self.name("current"))

    @property
    def component(self) -> Component:
        return self.conditions.valve

    def label(self) -> str:
        changes = [f"{k}={v}" for k, v in (self.sets.items() if isinstance(self.sets, Mapping) else
                                             (s.split("=", 1) for s in self.sets or []))]
        return f"{self.valve} ({self.first_stage}, {self.flapper} flapper)" + (f", {', '.join(changes)}" if changes else "")

    def changes(self) -> list[str]:
        if isinstance(self.sets, Mapping):
            return [f"{k}={v}" for k, v in self.sets.items()]
        return list(self.sets or [])


# -- the bench -----------------------------------------------------------------------------
@dataclass
class BenchTestsReport(Report):
    """Every bench test of one servovalve: figures, curves and plots."""

    command: ClassVar[str] = "servovalve bench"

    point: DesignPoint
    bench: BenchReport

    def title(self) -> str:
        c = self.point.conditions
        return f"{self.point.description}: bench tests at {c.p_s / 1e5:g} bar, rated current {c.i_rated * 1e3:g} mA"

    def artifacts(self) -> list[Artifact]:
        from hydroservo.io import servovalve as files
        from hydroservo.plotting import servovalve as plots

        report, label = self.bench, self.point.label()
        out = [Artifact("figures.csv", "figures.csv", lambda p: files.write_figures(report, p))]
        if report.static is not None:
            static = report.static
            out.append(Artifact("characteristic.csv", "characteristic.csv",
                                lambda p: files.write_static_characteristic(static, p)))
        if report.static is not None or report.hysteresis is not None:
            out.append(Artifact("flow-current.png", "flow-current.png",
                                lambda p: plots.plot_flow_current(report, title=label, file=p)))
        if report.hysteresis is not None:
            out.append(Artifact("hysteresis.csv", "hysteresis.csv", lambda p: files.write_hysteresis(report, p)))
        if report.blocked is not None:
            out += [Artifact("blocked.csv", "blocked.csv", lambda p: files.write_blocked(report, p)),
                    Artifact("blocked.png", "blocked.png", lambda p: plots.plot_blocked(report, title=label, file=p))]
        if report.steps:
            out += [Artifact("steps.csv", "steps.csv", lambda p: files.write_steps(report, p)),
                    Artifact("steps.png", "steps.png", lambda p: plots.plot_steps(report, title=label, file=p))]
        if report.bode is not None:
            out += [Artifact("bode.csv", "bode.csv", lambda p: files.write_bench_bode(report, p)),
                    Artifact("bode.png", "bode.png", lambda p: plots.plot_bench_bode(report, title=label, file=p))]
        return out

    def unsettled(self) -> list[tuple[float, float, str]]:
        return list(self.bench.bode.info["unsettled"]) if self.bench.bode is not None else []

    def to_dict(self) -> dict[str, Any]:
        p, c = self.point, self.point.conditions
        return {
            "valve": p.valve,
            "first_stage": p.first_stage,
            "flapper": p.flapper,
            "changes": p.changes(),
            "supply_bar": c.p_s / 1e5,
            "rated_current_mA": c.i_rated * 1e3,
            "figures": [{"figure": n, "value": float(v), "unit": u} for n, v, u in self.bench.table()],
            "not_periodic": [{"amplitude": a, "frequency_Hz": f} for a, f, _ in self.unsettled()],
            "files": list(self.files.values()),
        }

    def lines(self) -> list[str]:
        p = self.point
        out = [self.title(),
               f"model: first stage {p.first_stage}, {p.flapper} flapper"
               + (f"; changed: {', '.join(p.changes())}" if p.changes() else "")]
        rows = self.bench.table()
        width = max(len(n) for n, _, _ in rows)
        for name, value, unit in rows:
            out.append(f"  {name.ljust(width)}  {float(value):10.4g} {unit}")
        by_amp: dict[float, list[float]] = {}
        for a, f, _ in self.unsettled():
            by_amp.setdefault(a, []).append(f)
        for a, fs in by_amp.items():
            out.append(f"  no periodic response at +-{a * 100:g} % from {min(fs):.3g} Hz (the flapper bounces on the nozzles)")
        if self.files:
            out.append(f"wrote {', '.join(self.files.values())}")
        return out

    def document(self) -> Page:
        """The figures of every test, and the flow-current characteristic, steps and Bode (interactive)."""
        from hydroservo.io.html import Figure, Section, Table
        from hydroservo.plotting.interactive import bode_figure, xy_figure
        from hydroservo.workflows import pages

        b = self.bench
        figures = []
        if b.static is not None:
            figures.append(Figure(xy_figure([(b.static.currents * 1e3, b.static.flows * 6e4, "no-load flow")], "i [mA]",
                                            "Q [L/min]", title="flow against current at rest")))
        if b.steps:
            figures.append(Figure(xy_figure([(s.t * 1e3, s.flow * 6e4, f"±{s.fraction * 100:g} %") for s in b.steps],
                                            "t [ms]", "Q [L/min]", title="square-wave steps")))
        if b.bode is not None:
            figures.append(Figure(bode_figure(b.bode, title="no-load flow / current")))
        rows = [[n, float(v), u] for n, v, u in b.table()]
        return pages.page(self.title(), self.point.label(), [
            Section("Figures", [Table(["figure", "value", "unit"], rows)]),
            Section("Tests", figures) if figures else None,
            pages.references_section(["GordicND"]), pages.files_section(self.files),
        ], self.warnings)


@dataclass
class Bench(DesignPoint):
    """The bench's ``tests`` (some of :data:`hydroservo.analysis.servovalve_bench.TESTS`; default all) on the valve
    at its design point (:class:`DesignPoint`), ``points`` currents in the static characteristic."""

    tests: str | Sequence[str] = "static,blocked,steps,hysteresis,threshold,bode"
    points: int = 41

    def __post_init__(self) -> None:
        from hydroservo.analysis.servovalve_bench import TESTS

        super().__post_init__()
        text = self.tests if isinstance(self.tests, str) else ",".join(self.tests)
        self.chosen = [t.strip() for t in text.split(",") if t.strip()]
        if not self.chosen or any(t not in TESTS for t in self.chosen):
            raise ParameterError(f"{self.name('tests')} {text!r}: expected a comma-separated choice of {', '.join(TESTS)}")
        if not 5 <= self.points <= 401:
            raise ParameterError(f"{self.name('points')} {self.points}: expected 5 to 401 currents")

    def folder(self) -> str:
        return f"hydroservo-servovalve-{self.valve}"

    def planned(self) -> list[str]:
        from hydroservo.analysis.servovalve_bench import TESTS
        from hydroservo.io.servovalve import BENCH_FILES

        names = ["figures.csv"] + [f for t in TESTS if t in self.chosen for f in BENCH_FILES[t]]
        if "hysteresis" in self.chosen and "static" not in self.chosen:
            names.append("flow-current.png")
        return names

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> BenchTestsReport:
        from hydroservo.analysis.servovalve_bench import bench_report

        report = bench_report(self.conditions, tests=self.chosen, label=self.label(), progress=_TestStages(progress),
                              points=self.points)  # fmt: skip
        return BenchTestsReport(self, report)


class _TestStages:
    """The bench's progress as the command shows it: each test by name, and the orbits of the frequency test
    counted where the command's progress counts (``progress.count``, :class:`hydroservo.cli.progress.Bars`)."""

    def __init__(self, progress: Progress | None) -> None:
        self.progress = progress

    def __call__(self, name: str) -> None:
        if self.progress is not None:
            self.progress(f"running the {name} tests")

    def count(self, done: int, total: int) -> None:
        count = getattr(self.progress, "count", None)
        if count is not None:
            count(done, total)


# -- the design study ------------------------------------------------------------------------
@dataclass
class DesignReport(Report):
    """Elasticities of every bench figure to every physical parameter, ranked."""

    command: ClassVar[str] = "servovalve design"

    point: DesignPoint
    study: DesignStudy
    top: int = 8

    def title(self) -> str:
        c = self.point.conditions
        return f"{self.point.description}: what moves each figure at {c.p_s / 1e5:g} bar, {c.i_rated * 1e3:g} mA"

    def artifacts(self) -> list[Artifact]:
        from hydroservo.analysis.servovalve_design import FIGURES
        from hydroservo.io.servovalve import write_sensitivity
        from hydroservo.plotting.servovalve import plot_sensitivity

        shown = {k: v[:3] for k, v in FIGURES.items()}
        return [
            Artifact("sensitivity.csv", "sensitivity.csv", lambda p: write_sensitivity(self.study, p)),
            Artifact("sensitivity.png", "sensitivity.png", lambda p: plot_sensitivity(
                self.study, shown, top=self.top, title=f"{self.point.valve}: what moves each figure", file=p)),
        ]

    def to_dict(self) -> dict[str, Any]:
        from hydroservo.analysis.servovalve_design import FIGURES

        study = self.study
        return {
            "valve": self.point.valve,
            "changes": self.point.changes(),
            "figures": {
                k: {"value": study.figures[k] * FIGURES[k][2], "unit": FIGURES[k][1], "derivatives": FIGURES[k][3]}
                for k in study.figures
            },
            "elasticity": study.elasticity,
            "files": list(self.files.values()),
        }

    def lines(self) -> list[str]:
        from hydroservo.analysis.servovalve_design import FIGURES

        study = self.study
        out = [self.title(), "(elasticity: % change of the figure per % change of the parameter, the largest first)"]
        for key, (description, unit, scale, how) in FIGURES.items():
            if key not in study.figures:
                continue
            ranked = ", ".join(f"{n} {e:+.2f}" for n, e in study.ranked(key, self.top))
            out.append(f"  {description} = {study.figures[key] * scale:.4g} {unit} ({how}): {ranked}")
        if self.files:
            out.append(f"wrote {', '.join(self.files.values())}")
        return out

    def document(self) -> Page:
        """Each figure's largest elasticities (interactive bars) and the table."""
        from hydroservo.analysis.servovalve_design import FIGURES
        from hydroservo.io.html import Figure, Section
        from hydroservo.plotting.interactive import bar_figure
        from hydroservo.workflows import pages

        study = self.study
        groups = {FIGURES[k][0]: [(n, e, None) for n, e in study.ranked(k, self.top)] for k in study.figures}
        return pages.page(self.title(), "elasticity: % change of the figure per % change of the parameter", [
            Section("What moves each figure", [Figure(bar_figure(groups, "elasticity [-]", title=self.title()))]),
            pages.references_section(["GordicND"]), pages.files_section(self.files),
        ], self.warnings)


@dataclass
class Design(DesignPoint):
    """What moves each figure (``figures``: some of :data:`hydroservo.analysis.servovalve_design.FIGURES`, or
    ``"all"``): elasticities to every physical parameter, the ``top`` shown per figure."""

    top: int = 8
    figures: str | Sequence[str] = "all"

    def __post_init__(self) -> None:
        from hydroservo.analysis.servovalve_design import FIGURES

        super().__post_init__()
        if not 1 <= self.top <= 50:
            raise ParameterError(f"{self.name('top')} {self.top}: expected 1 to 50 parameters per figure")
        text = self.figures if isinstance(self.figures, str) else ",".join(self.figures)
        self.chosen = None if text == "all" else [f.strip() for f in text.split(",") if f.strip()]
        if self.chosen is not None and (not self.chosen or set(self.chosen) - set(FIGURES)):
            raise ParameterError(
                f"{self.name('figures')} {text!r}: expected 'all' or a comma-separated choice of {', '.join(FIGURES)}"
            )

    def folder(self) -> str:
        return f"hydroservo-servovalve-design-{self.valve}"

    def planned(self) -> list[str]:
        return ["sensitivity.csv", "sensitivity.png"]

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> DesignReport:
        from hydroservo.analysis.servovalve_design import design_study

        study = design_study(self.conditions, progress=progress, figures=self.chosen)
        return DesignReport(self, study, self.top)


# -- catalogue models ------------------------------------------------------------------------
@dataclass
class CatalogueReport(Report):
    """First- to third-order catalogue models fitted to the valve's small-signal response."""

    command: ClassVar[str] = "servovalve fit-catalogue"

    point: DesignPoint
    amplitude: float  #: fraction of rated current
    f_max: float  #: [Hz]
    static: StaticTests
    bode: Bode
    fits: list[CatalogueFit] = field(default_factory=list)

    def title(self) -> str:
        return (f"catalogue models of {self.point.label()}: +-{self.amplitude * 100:g} % of rated current, 5 Hz to "
                f"{self.f_max:g} Hz")

    def artifacts(self) -> list[Artifact]:
        from hydroservo.identification.servovalve_catalogue import ORDERS
        from hydroservo.io.component_file import component_file_text
        from hydroservo.io.servovalve import write_catalogue
        from hydroservo.plotting.servovalve import plot_catalogue_fits

        label = self.point.label()

        def table(path: Path) -> None:
            write_catalogue(self.fits, path, f"catalogue models of {label}, fitted at +-{self.amplitude * 100:g} % of "
                            f"rated current, 5 Hz to {self.f_max:g} Hz")

        def model_file(fit: CatalogueFit) -> Any:
            header = (f"CatalogueServovalve of order {fit.order} fitted to {label}\nat +-{self.amplitude * 100:g} % of "
                      f"rated current up to {self.f_max:g} Hz: within {fit.gain_error_db:.2f} dB and "
                      f"{fit.phase_error_deg:.1f} deg")
            used = ["Q_N", "dp_N", "i_N", *ORDERS[fit.order], "G_leak", "p_tr"]
            return lambda path: path.write_text(component_file_text(fit.valve, used, header=header))

        out = [Artifact("catalogue.csv", "catalogue.csv", table),
               Artifact("catalogue-bode.png", "catalogue-bode.png",
                        lambda p: plot_catalogue_fits(self.bode, self.fits, title=label, file=p))]
        return out + [Artifact(f"catalogue-order{f.order}.toml", f"catalogue-order{f.order}.toml", model_file(f))
                      for f in self.fits]

    def to_dict(self) -> dict[str, Any]:
        return {
            "valve": self.point.valve, "amplitude": self.amplitude, "f_max_Hz": self.f_max,
            "rated_flow_L_min": self.static.rated_flow * 6e4,
            "fits": [{"order": f.order, "params": f.params, "gain_error_dB": f.gain_error_db,
                      "phase_error_deg": f.phase_error_deg} for f in self.fits],
            "files": list(self.files.values()),
        }

    def lines(self) -> list[str]:
        static = self.static
        out = [self.title(),
               f"  rated flow {static.rated_flow * 6e4:.4g} L/min, internal leakage at null "
               f"{static.internal_leakage_null * 6e4:.3g} L/min"]
        for fit in self.fits:
            shown = ", ".join(f"{k} = {v * 1e3:.4g} ms" if k == "tau" else f"{k} = {v:.4g}" + (" rad/s" if k == "omega_n" else "")
                              for k, v in fit.params.items())
            out.append(f"  order {fit.order}: {shown}; within {fit.gain_error_db:.2f} dB and {fit.phase_error_deg:.1f} deg")
        if self.files:
            out.append(f"wrote {', '.join(self.files.values())}")
        return out

    def document(self) -> Page:
        """The bench's response beside each catalogue model (interactive Bode), and their parameters."""
        import numpy as np

        from hydroservo.analysis.frequency import FrequencyResponse
        from hydroservo.io.html import Figure, Section, Table
        from hydroservo.plotting.interactive import bode_figure
        from hydroservo.workflows import pages

        self.bode.label = "bench"
        responses = [self.bode] + [FrequencyResponse(np.array([self.amplitude]), f.frequencies, f.gain_db, f.phase_deg,
                                                     label=f"order {f.order}") for f in self.fits]
        rows = [[f.order, f.params.get("tau"), f.params.get("omega_n"), f.params.get("zeta"), f.gain_error_db,
                 f.phase_error_deg] for f in self.fits]
        return pages.page(self.title(), self.point.label(), [
            Section("Frequency response", [Figure(bode_figure(responses, title=self.title()))]),
            Section("Models", [Table(["order", "tau [s]", "omega_n [rad/s]", "zeta [-]", "gain error [dB]",
                                      "phase error [deg]"], rows)]),
            pages.references_section(["GordicND"]), pages.files_section(self.files),
        ], self.warnings)


@dataclass
class FitCatalogue(DesignPoint):
    """Catalogue models of ``orders`` (some of 1, 2, 3) fitted to the valve's response at ``amplitude`` (a fraction
    of rated current, ``"5 %"``) from 5 Hz to ``f_max``."""

    orders: str | Sequence[int | str] = "1,2,3"
    amplitude: float | str = "5 %"
    f_max: float | str = "150 Hz"

    def __post_init__(self) -> None:
        from hydroservo.identification.servovalve_catalogue import ORDERS
        from hydroservo.units import to_si

        super().__post_init__()
        text = self.orders if isinstance(self.orders, str) else ",".join(str(o) for o in self.orders)
        self.chosen = [o.strip() for o in text.split(",") if o.strip()]
        if not self.chosen or any(o not in ORDERS for o in self.chosen):
            raise ParameterError(f"{self.name('orders')} {text!r}: expected a comma-separated choice of 1, 2, 3")
        self.fraction = to_si(self.amplitude, "", what=self.name("amplitude"))
        if not 0 < self.fraction <= 1:
            raise ParameterError(f"{self.name('amplitude')} {self.amplitude!r}: expected a fraction of rated current, e.g. '5 %'")
        self.top = to_si(self.f_max, "Hz", what=self.name("f_max"))
        if not 10 <= self.top <= 2000:
            raise ParameterError(f"{self.name('f_max')} {self.f_max!r}: expected 10 Hz to 2 kHz")

    def folder(self) -> str:
        return f"hydroservo-servovalve-catalogue-{self.valve}"

    def planned(self) -> list[str]:
        return ["catalogue.csv", "catalogue-bode.png"] + [f"catalogue-order{o}.toml" for o in self.chosen]

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> CatalogueReport:
        import numpy as np

        from hydroservo.analysis.servovalve_bench import frequency_test, static_tests
        from hydroservo.identification.servovalve_catalogue import fit_catalogue

        c = self.conditions
        static = static_tests(c, points=11)
        bode = frequency_test(c, amplitudes=(self.fraction,), frequencies=np.geomspace(5.0, self.top, 12))
        fits = [
            fit_catalogue(bode, o, rated_flow=static.rated_flow, i_rated=c.i_rated, dp_rated=c.p_s - c.p_0,
                          leakage_null=static.internal_leakage_null)
            for o in self.chosen
        ]
        return CatalogueReport(self, self.fraction, self.top, static, bode, fits)


def bench(valve: str = "gordic-table1", **inputs: Any) -> BenchTestsReport:
    """The bench tests of ``valve`` (:class:`Bench`'s inputs as keywords)."""
    return Bench(valve, **inputs).run()


def design(valve: str = "gordic-table1", **inputs: Any) -> DesignReport:
    """The design study of ``valve`` (:class:`Design`'s inputs as keywords)."""
    return Design(valve, **inputs).run()


def fit_catalogue(valve: str = "gordic-table1", **inputs: Any) -> CatalogueReport:
    """Catalogue models of ``valve`` (:class:`FitCatalogue`'s inputs as keywords)."""
    return FitCatalogue(valve, **inputs).run()
