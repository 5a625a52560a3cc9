"""The servo-solenoid valve of [FerreiraND]: pseudo-sections from a datasheet or measured curves, the
amplitude-dependent Bode of its spool, and spool dynamics fitted to Bode data (``hydroservo valve fit``,
``valve bode``, ``valve fit-dynamics``).

>>> from hydroservo.workflows import valve
>>> report = valve.fit("KBSDG4V-3")
>>> report.fit.structure, sorted(report.artifact_names())[-1]
('variable', 'valve.toml')
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from hydroservo.errors import HydroservoError, ParameterError
from hydroservo.workflows.base import Artifact, Progress, Report, Workflow, finite_or_none, safe_name

if TYPE_CHECKING:
    import numpy as np

    from hydroservo.analysis.frequency import FrequencyResponse
    from hydroservo.identification.datasheet import PseudoSectionFit
    from hydroservo.identification.spool_dynamics import SpoolFit
    from hydroservo.io.html import Page

__all__ = ["ValveFit", "ValveFitReport", "SpoolBode", "SpoolBodeReport", "FitDynamics", "DynamicsReport", "fit", "bode",
           "fit_dynamics"]

#: The null characteristics and the units they are shown in.
CHARACTERISTIC_UNITS = {"Q_n": "L/min", "Q_L1": "L/min", "K_q0": "L/min", "K_p0": "", "q_lk0": "L/min"}
NULL = ("Q_n", "K_q0", "K_p0", "q_lk0")
_FIT_PLOTS = ("pseudo_sections", "null_characteristics", "load_flow", "pressure_flow")


def _shown(values: Mapping[str, float]) -> dict[str, float]:
    """Characteristics in their display units (L/min)."""
    from hydroservo.units import from_si

    return {k: from_si(v, "m^3/s", CHARACTERISTIC_UNITS[k]) if CHARACTERISTIC_UNITS[k] else v for k, v in values.items()}


# -- valve fit -------------------------------------------------------------------------
@dataclass
class ValveFitReport(Report):
    """Pseudo-sections fitted to a datasheet (two null characteristics matched) or to measured curves."""

    command: ClassVar[str] = "valve fit"

    name: str  #: the valve's name
    fit: PseudoSectionFit
    curves: dict[str, Any] | None = None  #: the measured curves fitted, if any

    def how(self) -> str:
        return ("least squares on the measured curves" if self.curves is not None
                else f"matching {' and '.join(self.fit.match)}")

    def title(self) -> str:
        return f"{self.name}: {self.fit.structure} structure, {self.how()}"

    def shown(self) -> dict[str, float]:
        return _shown(self.fit.characteristics())

    def given(self) -> dict[str, float]:
        ds = self.fit.datasheet
        return _shown({k: getattr(ds, k) for k in NULL if ds is not None and getattr(ds, k) is not None})

    def artifact_names(self) -> list[str]:
        return [a.name for a in self.artifacts()]

    def artifacts(self) -> list[Artifact]:
        from hydroservo.plotting import pseudo_section as plots

        fit, curves = self.fit, self.curves
        ds = fit.datasheet
        assert ds is not None
        measured = fit.measured_sections(curves) if curves is not None else None
        writers = {
            "pseudo_sections": lambda p: plots.plot_pseudo_sections(fit.valve, measured=measured, title=self.title(),
                                                                    file=p),
            "null_characteristics": lambda p: plots.plot_null_characteristics(fit.valve, ds.P_s, measured=curves, file=p),
            "load_flow": lambda p: plots.plot_load_flow(fit.valve, ds.P_n, measured=curves, title=self.title(), file=p),
            "pressure_flow": lambda p: plots.plot_pressure_flow(fit.valve, ds.P_s, file=p),
        }
        out = [Artifact(k, f"{k}.png", writers[k]) for k in _FIT_PLOTS]
        return out + [Artifact("parameters", "valve.toml", lambda p: p.write_text(self.parameter_file()))]

    def parameter_file(self) -> str:
        """The fitted valve as a component file a model file includes with ``file = "valve.toml"``."""
        from hydroservo.io.component_file import component_toml
        from hydroservo.laws.pseudo_section import PARAMETER_UNITS, PRINTED_UNITS
        from hydroservo.units import from_si

        fit = self.fit
        comments = {
            k: f"= {from_si(v, PARAMETER_UNITS[k], PRINTED_UNITS[k]):.6g} {PRINTED_UNITS[k]}"
            for k, v in fit.params.items()
            if PRINTED_UNITS[k]
        }
        assert fit.datasheet is not None
        return component_toml(
            "PseudoSectionValve",
            fit.params,
            PARAMETER_UNITS,
            options={"structure": fit.structure},
            comments=comments,
            header=(
                f"{self.name}: pseudo-section valve fitted by hydroservo (FerreiraND, {fit.structure} structure),\n"
                f"nominal flow exact, {self.how()}.\n"
                'Use it in a model file: [components.valve] file = "valve.toml"  (type may be\n'
                "overridden with ServoSolenoidValve to add the spool dynamics)."
            ),
            extra={
                "datasheet": fit.datasheet.as_mapping(),
                "fit": {"match": list(fit.match)},
                "characteristics": {k: f"{v:.6g} {CHARACTERISTIC_UNITS[k]}".strip() for k, v in self.shown().items()},
            },
        )

    def lines(self) -> list[str]:
        from hydroservo.laws.pseudo_section import PRINTED_UNITS

        fit, shown, given = self.fit, self.shown(), self.given()
        out = [f"{self.name}: {fit.structure}-structure pseudo-sections (FerreiraND), Q_n exact, {self.how()}"]
        for k, v in fit.in_paper_units().items():
            out.append(f"  {k:>6} = {v:.6g} {PRINTED_UNITS[k]}")
        out.append("characteristic     model     datasheet  deviation")
        for k in NULL:
            u = CHARACTERISTIC_UNITS[k] or "-"
            g = given.get(k)
            dev = f"{100 * fit.deviation[k]:+.2f} %" if k in fit.deviation else ""
            note = "  (not matched: eq. 23)" if self.curves is None and abs(fit.deviation.get(k, 0.0)) > 1e-6 else ""
            out.append(f"  {k:<6} {shown[k]:>10.5g} {'' if g is None else f'{g:>10.5g}':>10} {u:<6} {dev}{note}")
        for k, v in fit.deviation.items():
            if k.startswith("rms_"):
                out.append(f"  misfit of {k[4:]}: {100 * v:.2f} % rms of its largest value")
        if self.files:
            out.append(f"wrote {', '.join(self.files.values())}")
        return out

    def to_dict(self) -> dict[str, Any]:
        from hydroservo.laws.pseudo_section import PRINTED_UNITS

        fit, shown = self.fit, self.shown()
        paper = fit.in_paper_units()
        return {
            "valve": self.name,
            "structure": fit.structure,
            "match": list(fit.match),
            "parameters": paper,
            "units": {k: PRINTED_UNITS[k] or "-" for k in paper},
            "characteristics": {k: shown[k] for k in NULL},
            "characteristic_units": {k: CHARACTERISTIC_UNITS[k] or "-" for k in NULL},
            "datasheet": self.given(),
            "deviation": fit.deviation,
            "files": self.files,
        }

    def document(self) -> Page:
        """The fitted parameters, the characteristics beside the datasheet, and the valve's curves (interactive)."""
        import numpy as np

        from hydroservo.io.html import Figure, Section, Table
        from hydroservo.laws.pseudo_section import PRINTED_UNITS
        from hydroservo.plotting.interactive import xy_figure
        from hydroservo.workflows import pages

        fit, shown, given = self.fit, self.shown(), self.given()
        valve, ds = fit.valve, fit.datasheet
        assert ds is not None
        params = Table(["parameter", "value", "unit"], [[k, v, PRINTED_UNITS[k] or "-"] for k, v in fit.in_paper_units().items()])
        chars = Table(["characteristic", "model", "datasheet", "unit", "deviation [%]"], [
            [k, shown[k], given.get(k), CHARACTERISTIC_UNITS[k] or "-",
             100 * fit.deviation[k] if k in fit.deviation else None] for k in NULL])
        x = np.linspace(-1.0, 1.0, 801)
        a_p, a_n = valve.sections(x)
        k = 6e4 / np.sqrt(1e-5)  # m^3/s/Pa^0.5 -> L/min/bar^0.5
        sections = [(x, a_p * k, "A_p"), (x, a_n * k, "A_n")]
        measured = []
        if self.curves is not None:
            m = fit.measured_sections(self.curves)
            measured = [(m["x_s"], m["A_p"] * k, "A_p from curves (eq. 17)"), (m["x_s"], m["A_n"] * k, "A_n from curves (eq. 16)")]
        near = np.linspace(-0.06, 0.06, 401)
        p_l, q_lk = valve.blocked_ports(near, ds.P_s)
        figures = [
            Figure(xy_figure(sections, "x_s [-]", "pseudo-section [L/min/bar^0.5]", title="pseudo-sections ([FerreiraND] Figs. 2-3)",
                             markers=measured)),
            Figure(xy_figure([(near, p_l, "P_L [-]"), (near, q_lk * 6e4, "q_lk [L/min]")], "x_s [-]", "P_L [-], q_lk [L/min]",
                             title=f"blocked ports at {ds.P_s / 1e5:g} bar (Figs. 4, 7)")),
            Figure(xy_figure([(x, valve.no_load_flow(x, ds.P_n) * 6e4, "Q_L")], "x_s [-]", "Q_L [L/min]",
                             title=f"no-load flow, {ds.P_n / 1e5:g} bar per edge (Figs. 5-6, 8-9)")),
        ]
        return pages.page(self.title(), "pseudo-section valve ([FerreiraND])", [
            Section("Parameters", [params]), Section("Characteristics", [chars]), Section("Curves", figures),
            pages.references_section(["FerreiraND"]), pages.files_section(self.files),
        ], self.warnings)


@dataclass
class ValveFit(Workflow):
    """Pseudo-sections of the valve ``datasheet`` (a TOML file with a [datasheet] table, or a built-in valve such as
    ``"KBSDG4V-3"``), of ``structure`` "variable" or "fixed": the two null characteristics of ``match`` reproduced
    (default pressure gain and leakage, when given), or, with ``curves`` (a CSV of measured x_s, P_L, q_lk and
    Q_L), every curve fitted by least squares."""

    datasheet: str | Path
    structure: str = "variable"
    match: str | Sequence[str] | None = None
    curves: str | Path | None = None

    def __post_init__(self) -> None:
        from hydroservo.io.curves import read_static_curves
        from hydroservo.io.datasheet import read_datasheet

        if self.structure not in ("variable", "fixed"):
            raise ParameterError(f"{self.name('structure')} {self.structure!r}: expected 'variable' or 'fixed'")
        self.sheet = read_datasheet(str(self.datasheet))
        self.measured = read_static_curves(str(self.curves)) if self.curves else None
        if self.measured is not None and self.match:
            raise ParameterError(
                f"{self.name('match')} applies to a datasheet fit; with {self.name('curves')} every curve is fitted "
                "by least squares"
            )
        self.valve_name = self.sheet.name or Path(str(self.datasheet)).stem

    def folder(self) -> str:
        stem = "".join(ch if ch.isalnum() or ch in "-_" else "-" for ch in Path(str(self.datasheet)).stem)
        return f"hydroservo-valve-{stem}"

    def planned(self) -> list[str]:
        return [f"{k}.png" for k in _FIT_PLOTS] + ["valve.toml"]

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> ValveFitReport:
        from hydroservo.identification import fit_curves, fit_datasheet

        match = self.match.split(",") if isinstance(self.match, str) else self.match
        if self.measured is not None:
            result = fit_curves(self.measured, self.sheet, self.structure)
        else:
            result = fit_datasheet(self.sheet, self.structure, ",".join(match) if match else None)
        return ValveFitReport(self.valve_name, result, self.measured)


# -- valve bode -------------------------------------------------------------------------
def _dynamics(source: str, what: str) -> tuple[str, dict[str, Any]]:
    """The spool model and its parameters: a built-in valve's published dynamics, or a component file's."""
    from hydroservo.components import REGISTRY
    from hydroservo.data import parameter_set
    from hydroservo.identification.spool_dynamics import SPOOL_COMPONENTS, SPOOL_MODELS, fidelity_of
    from hydroservo.io.component_file import read_component_file
    from hydroservo.io.datasheet import BUILTIN_VALVES
    from hydroservo.units import is_bare_number

    if source in BUILTIN_VALVES:
        table = parameter_set(BUILTIN_VALVES[source]).table("dynamics")
        return "rate-limited", {k: float(v) if is_bare_number(v) else v for k, v in table.items()}
    comp = read_component_file(source)
    kind = comp.pop("type")
    cls = REGISTRY.resolve(kind)
    model = None if cls is None else fidelity_of(cls)
    if model is None:
        kinds = ", ".join(c.__name__ for c in SPOOL_COMPONENTS.values())
        raise ParameterError(f"{source}: component type {kind!r} has no spool dynamics; expected one of {kinds}")
    keep = set(SPOOL_MODELS[model]) | {"delay"} | set(SPOOL_COMPONENTS[model].RENAMED)
    return model, {k: v for k, v in comp.items() if k in keep}


def bandwidths(resp: FrequencyResponse) -> dict[str, dict[str, float | None]]:
    """The -3 dB and -90 deg frequencies [Hz] of each amplitude (None where the response does not reach them)."""
    f3, f90 = resp.bandwidth(), resp.phase_crossing()
    return {
        f"{100 * a:g} %": {"f_-3dB_Hz": finite_or_none(float(f3[i])), "f_-90deg_Hz": finite_or_none(float(f90[i]))}
        for i, a in enumerate(resp.amplitudes)
    }


@dataclass
class SpoolBodeReport(Report):
    """The amplitude-dependent Bode of a spool model, with each amplitude's bandwidths."""

    command: ClassVar[str] = "valve bode"

    source: str
    model: str
    params: dict[str, Any]
    response: FrequencyResponse

    def title(self) -> str:
        return f"{Path(self.source).stem}: spool position / command ({self.model})"

    def artifacts(self) -> list[Artifact]:
        from hydroservo.io.bode import write_bode

        return [
            Artifact("csv", "bode.csv", lambda p: write_bode(self.response, p)),
            Artifact("plot", "bode.png", lambda p: self.response.plot(title=self.title(), file=p)),
        ]

    def to_dict(self) -> dict[str, Any]:
        resp = self.response
        return {
            "model": self.model,
            "parameters": self.params,
            "amplitudes_percent": (100 * resp.amplitudes).tolist(),
            "frequencies_Hz": resp.frequencies.tolist(),
            "gain_dB": resp.gain_db.tolist(),
            "phase_deg": resp.phase_deg.tolist(),
            "bandwidth": bandwidths(resp),
            "files": self.files,
        }

    def lines(self) -> list[str]:
        top = self.response.frequencies[-1]
        out = [f"{Path(self.source).stem}: {self.model} spool model, {', '.join(f'{k}={v}' for k, v in self.params.items())}"]
        for amp, bw in bandwidths(self.response).items():
            f3, f90 = bw["f_-3dB_Hz"], bw["f_-90deg_Hz"]
            out.append(
                f"  ±{amp:>6}: -3 dB at {'>' + str(top) if f3 is None else f'{f3:.1f}'} Hz, "
                f"-90 deg at {'>' + str(top) if f90 is None else f'{f90:.1f}'} Hz"
            )
        if self.files:
            out.append(f"wrote {self.files['csv']} and {self.files['plot']}")
        return out

    def document(self) -> Page:
        """The Bode plot (interactive) and each amplitude's bandwidths."""
        from hydroservo.io.html import Figure, Section, Table
        from hydroservo.plotting.interactive import bode_figure
        from hydroservo.workflows import pages

        rows = [[a, bw["f_-3dB_Hz"], bw["f_-90deg_Hz"]] for a, bw in bandwidths(self.response).items()]
        return pages.page(self.title(), ", ".join(f"{k} = {v}" for k, v in self.params.items()), [
            Section("Frequency response", [Figure(bode_figure(self.response, title=self.title()))]),
            Section("Bandwidths", [Table(["amplitude", "-3 dB [Hz]", "-90 deg [Hz]"], rows, "– : not reached")]),
            pages.references_section(["FerreiraND"]), pages.files_section(self.files),
        ], self.warnings)


@dataclass
class SpoolBode(Workflow):
    """Bode of the spool dynamics of ``params`` (a built-in valve such as ``"KBSDG4V-3"``, or a spool component
    file) at ``amplitudes`` (fractions of the stroke, (0, 1]) and ``frequencies`` [Hz]."""

    params: str | Path
    amplitudes: Sequence[float] = (0.05, 0.25, 1.0)
    frequencies: Sequence[float] | np.ndarray = field(default_factory=lambda: [float(f) for f in range(5, 401, 5)])

    def __post_init__(self) -> None:
        import numpy as np

        self.model, self.values = _dynamics(str(self.params), self.name("params"))
        self.amps = np.asarray(self.amplitudes, dtype=float)
        if self.amps.size == 0 or not np.all((self.amps > 0) & (self.amps <= 1)):
            raise ParameterError(f"{self.name('amplitudes')}: expected fractions of the stroke in (0, 1]")
        self.freqs = np.asarray(self.frequencies, dtype=float)

    def folder(self) -> str:
        return f"hydroservo-bode-{Path(str(self.params)).stem}"

    def planned(self) -> list[str]:
        return ["bode.csv", "bode.png"]

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> SpoolBodeReport:
        from hydroservo.identification.spool_dynamics import spool_response

        resp = spool_response(self.values, self.amps, self.freqs, self.model, label=self.model)
        return SpoolBodeReport(str(self.params), self.model, self.values, resp)


# -- valve fit-dynamics ----------------------------------------------------------------------
@dataclass
class DynamicsReport(Report):
    """Spool models fitted to Bode data ([FerreiraND] eq. 43, then the delay)."""

    command: ClassVar[str] = "valve fit-dynamics"

    source: str
    fits: dict[str, SpoolFit]

    def title(self) -> str:
        return f"{Path(self.source).stem}: Bode data and fitted models"

    def parameter_file(self, fit: SpoolFit) -> str:
        """The parameter file of a fitted spool model; the delay is recorded beside a component that has none."""
        from hydroservo.identification.spool_dynamics import SPOOL_COMPONENTS, SPOOL_MODELS
        from hydroservo.io.component_file import component_toml

        cls = SPOOL_COMPONENTS[fit.model]
        has_delay = "delay" in cls.PARAMETERS
        header = (
            f"Spool dynamics fitted by hydroservo to {Path(self.source).name} (FerreiraND eq. 43, then the delay)\n"
            f"max gain error up to 200 Hz: {fit.max_gain_error(200.0):.3g} dB"
        )
        if not has_delay:
            header += f"\nthe fitted delay, {fit.params['delay']:.4g} s, is not a parameter of {cls.__name__}"
        return component_toml(
            cls.__name__,
            {k: v for k, v in fit.params.items() if has_delay or k != "delay"},
            {**SPOOL_MODELS[fit.model], "delay": "s"},
            header=header,
            extra=None if has_delay else {"fit": {"delay_s": fit.params["delay"]}},
        )

    def artifacts(self) -> list[Artifact]:
        first = next(iter(self.fits.values()))

        def plot(path: Path) -> None:
            data = first.data
            data.label = "data"
            data.plot([f.response for f in self.fits.values()], title=self.title(), file=path, f_max=200.0)

        def parameters(fit: SpoolFit) -> Any:
            return lambda path: path.write_text(self.parameter_file(fit))

        return [Artifact("plot", "fit.png", plot)] + [
            Artifact(f"parameters_{m}", f"spool_{m}.toml", parameters(f)) for m, f in self.fits.items()
        ]

    def to_dict(self) -> dict[str, Any]:
        return {"fits": {m: f.summary() for m, f in self.fits.items()}, "files": self.files}

    def lines(self) -> list[str]:
        out = []
        for m, fit in self.fits.items():
            s = fit.summary()
            params = ", ".join(f"{k} = {v:.5g} {s['units'][k]}".replace(" -", "") for k, v in fit.params.items())
            out.append(f"{m}: {params}")
            out.append(
                f"  gain error up to 200 Hz: max {s['max_gain_error_dB_to_200Hz']:.3f} dB; rms per amplitude: "
                + ", ".join(f"{a} {r:.3f} dB" for a, r in s["gain_rms_dB"].items())
            )
        if self.files:
            out.append(f"wrote {', '.join(self.files.values())}")
        return out

    def document(self) -> Page:
        """The data and the fitted models (interactive Bode), and each model's parameters and errors."""
        from hydroservo.io.html import Figure, Section, Table
        from hydroservo.plotting.interactive import bode_figure
        from hydroservo.workflows import pages

        first = next(iter(self.fits.values()))
        first.data.label = "data"
        responses = [first.data] + [f.response for f in self.fits.values()]
        for m, f in self.fits.items():
            f.response.label = m
        tables = [Table(["parameter", "value", "unit"],
                        [[k, v, f.summary()["units"].get(k, "")] for k, v in f.params.items()], m)
                  for m, f in self.fits.items()]
        return pages.page(self.title(), "[FerreiraND] eq. 43, then the delay", [
            Section("Fit", [Figure(bode_figure(responses, title=self.title()))]),
            Section("Parameters", tables),
            pages.references_section(["FerreiraND"]), pages.files_section(self.files),
        ], self.warnings)


@dataclass
class FitDynamics(Workflow):
    """Fit spool ``models`` (some of :data:`hydroservo.identification.spool_dynamics.SPOOL_MODELS`, or ``"all"``)
    to the Bode data of ``bode`` (CSV); ``start``: starting values of one model (``{"omega_n": "700 rad/s"}``)."""

    OPTIONS: ClassVar[dict[str, str]] = {"models": "--model"}

    bode: str | Path
    models: str | Sequence[str] = "rate-limited"
    start: Mapping[str, Any] | None = None

    def __post_init__(self) -> None:
        from hydroservo.identification.spool_dynamics import SPOOL_MODELS, check_start
        from hydroservo.io.bode import read_bode

        self.data = read_bode(str(self.bode))
        if isinstance(self.models, str):
            self.kinds = list(SPOOL_MODELS) if self.models == "all" else [self.models]
        else:
            self.kinds = list(self.models)
        for m in self.kinds:
            if m not in SPOOL_MODELS:
                raise ParameterError(f"{self.name('models')} {m!r}: expected one of {', '.join(SPOOL_MODELS)} or all")
        if self.start and len(self.kinds) > 1:
            raise ParameterError(
                f"{self.name('start')} {self._start_text()!r}: starting values apply to one model; expected "
                f"{self.name('models')} with one"
            )
        if self.start:
            try:
                check_start(self.kinds[0], dict(self.start))
            except HydroservoError as exc:
                raise ParameterError(f"{self.name('start')} {self._start_text()!r}: {exc}") from None

    def _start_text(self) -> str:
        return ",".join(f"{k}={v}" for k, v in (self.start or {}).items())

    def folder(self) -> str:
        return f"hydroservo-fit-{safe_name(Path(str(self.bode)).stem)}"

    def planned(self) -> list[str]:
        return ["fit.png"] + [f"spool_{m}.toml" for m in self.kinds]

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> DynamicsReport:
        from hydroservo.identification.spool_dynamics import fit_spool_dynamics

        start = dict(self.start) if self.start and len(self.kinds) == 1 else None
        fits = {m: fit_spool_dynamics(self.data, m, start) for m in self.kinds}
        return DynamicsReport(str(self.bode), fits)


def fit(datasheet: str | Path, **inputs: Any) -> ValveFitReport:
    """Pseudo-sections of ``datasheet`` (:class:`ValveFit`'s inputs as keywords)."""
    return ValveFit(datasheet, **inputs).run()


def bode(params: str | Path, **inputs: Any) -> SpoolBodeReport:
    """Bode of the spool dynamics of ``params`` (:class:`SpoolBode`'s inputs as keywords)."""
    return SpoolBode(params, **inputs).run()


def fit_dynamics(bode_file: str | Path, **inputs: Any) -> DynamicsReport:
    """Spool dynamics fitted to ``bode_file`` (:class:`FitDynamics`'s inputs as keywords)."""
    return FitDynamics(bode_file, **inputs).run()
