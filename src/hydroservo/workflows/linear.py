"""The linear model of a system at an operating point, its modes and valve coefficients (``hydroservo linearize``).

>>> from hydroservo.workflows import linear
>>> report = linear.run("robot-arm", t="0.35 s", free=["load.x"], write=False)
>>> len(report.model.states), report.model.inputs
(5, ['spool.u', 'load.F_ext'])
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from hydroservo.errors import ParameterError, shorten
from hydroservo.workflows.base import (
    Artifact,
    Progress,
    Report,
    Workflow,
    asked_units,
    check_names,
    load_with_sets,
    safe_name,
)

if TYPE_CHECKING:
    import numpy as np

    from hydroservo.analysis.frequency import FrequencyResponse
    from hydroservo.analysis.linear import LinearModel, ValveCoefficients
    from hydroservo.io.html import Page
    from hydroservo.system.system import System
    from hydroservo.units import UnitChoice

__all__ = ["Linearize", "LinearReport", "run", "operating_point"]


def operating_point(at: str | Mapping[str, Any] | Path, what: str = "--at") -> Any:
    """``"trim"``, ``"run"``, ``"initial"``, ``"STATE=VALUE,..."``, a mapping of states, or an operating-point file
    (TOML)."""
    from hydroservo.io import read_operating_point

    if isinstance(at, Mapping):
        return dict(at)
    text = str(at)
    if text in ("trim", "run", "initial"):
        return text
    if "=" in text and not Path(text).exists():
        point = {}
        for item in text.split(","):
            if "=" not in item:
                raise ParameterError(
                    f"{what} {shorten(text)!r}: {shorten(item)!r}: expected STATE=VALUE, e.g. cyl.pA=6.5bar"
                )
            key, val = item.split("=", 1)
            point[key.strip()] = val.strip()
        return point
    return read_operating_point(text)


#: the units of the valve coefficients in the JSON, which is SI as the linear model's matrices are
_SI_COEFFICIENTS = {"K_Qx": "m^2/s", "K_Qp": "m^3/(s*Pa)", "K_px": "Pa/m"}


@dataclass
class LinearReport(Report):
    """A linear model with its modes, the valves' coefficients, and optionally the simulated sines beside it."""

    command: ClassVar[str] = "linearize"

    system: System
    model: LinearModel
    valves: list[ValveCoefficients]
    frequencies: np.ndarray | None = None  #: [Hz], of the Bode plot and the JSON's frequency response
    simulated: FrequencyResponse | None = None
    write_files: bool = True
    #: the units the operating point and the valve coefficients are shown in (None: the model's)
    units: UnitChoice | None = None

    def _choice(self) -> UnitChoice:
        return self.units if self.units is not None else self.system.unit_choice()

    def _point(self) -> list[tuple[str, float, str, float]]:
        """The operating point as shown: state, value, unit, rate (in that unit per second)."""
        choice, lin = self._choice(), self.model
        rows = []
        for s, v in lin.x0.items():
            value, unit = choice.shown(s, v, lin.units[s])
            rows.append((s, value, unit, lin.drift[s] * choice.scale(s, lin.units[s])[0]))
        return rows

    def _coefficients(self) -> list[tuple[str, str, float]]:
        """The valve coefficients' names, the unit each is shown in and its factor from SI: the model's units of
        flow, stroke and pressure composed ((L/min)/mm), SI when it chooses none."""
        from hydroservo.units import si_unit

        choice = self._choice()
        (fq, q), (fx, x), (fp, p) = (choice.scale("", u) for u in ("m^3/s", "m", "Pa"))
        si = {"m^3/s", "m", "Pa"}

        def ratio(a: str, b: str, fa: float, fb: float, si_text: str) -> tuple[str, float]:
            if {a, b} <= si:
                return si_text, 1.0
            if b in a.split("^")[0]:  # in^3/s per in: in²/s
                return si_unit(f"{a}/{b}"), fa / fb
            return (f"({si_unit(a)})/{si_unit(b)}" if "/" in a else f"{si_unit(a)}/{si_unit(b)}"), fa / fb

        return [
            ("K_Qx", *ratio(q, x, fq, fx, "m²/s")),
            ("K_Qp", *ratio(q, p, fq, fp, "m³/(s·Pa)")),
            ("K_px", *ratio(p, x, fp, fx, "Pa/m")),
        ]

    def _valve_point(self, vc: ValveCoefficients) -> str:
        from hydroservo.units import si_unit

        choice = self._choice()
        parts = []
        for key, label, unit in (("xv", "x_v", "m"), ("pA", "p_A", "Pa"), ("pB", "p_B", "Pa")):
            value, shown = choice.shown("", vc.point[key], unit)
            parts.append(f"{label} = {value:.4g} {si_unit(shown)}")
        return ", ".join(parts)

    def title(self) -> str:
        at = self.model.info.get("at", "")
        return f"{self.model.name}: linear model at {'the state of a run' if at == 'run' else at} (t = {self.model.t:g} s)"

    def _stem(self) -> str:
        return safe_name(self.system.name)

    def artifacts(self) -> list[Artifact]:
        if not self.write_files:
            return []
        import numpy as np

        from hydroservo.io import write_linear_model
        from hydroservo.plotting.linear import plot_linear_bode, plot_poles

        lin, name = self.model, self._stem()
        grid = self.frequencies if self.frequencies is not None else np.logspace(-1, 3, 400)
        pairs = [(i, o) for i in lin.inputs[:1] for o in lin.outputs[:4]]
        out = [
            Artifact("json", f"{name}-linear.json",
                     lambda p: write_linear_model(lin, p, {"valves": self.to_dict()["valves"]})),
            Artifact("poles", f"{name}-poles.png", lambda p: plot_poles(lin, file=p)),
            Artifact("bode", f"{name}-bode.png", lambda p: plot_linear_bode(lin, grid, pairs, file=p)),
        ]
        sim = self.simulated
        if sim is not None:
            def bode_simulated(path: Path) -> None:
                linear_fr = lin.bode(sim.frequencies, lin.inputs[0], lin.outputs[0])
                sim.plot([linear_fr], file=path,
                         title=f"{lin.outputs[0]} / {lin.inputs[0]}: simulated sines (markers) and the linear model")

            out.append(Artifact("bode_simulated", f"{name}-bode-simulated.png", bode_simulated))
        return out

    def to_dict(self) -> dict[str, Any]:
        lin, f, sim = self.model, self.frequencies, self.simulated
        report = {**lin.to_dict(), "valves": [{**v.to_dict(), "units": _SI_COEFFICIENTS} for v in self.valves]}
        if f is not None:
            report["frequency_response"] = [
                {"input": i, "output": o, "frequencies_Hz": f.tolist(),
                 "real": (H := lin.transfer(f, i, o)).real.tolist(), "imag": H.imag.tolist()}
                for i in lin.inputs for o in lin.outputs
            ]
        if sim is not None:
            report["simulated_response"] = {
                "input": lin.inputs[0], "output": lin.outputs[0], "amplitudes": sim.amplitudes.tolist(),
                "frequencies_Hz": sim.frequencies.tolist(), "gain_dB": sim.gain_db.tolist(),
                "phase_deg": sim.phase_deg.tolist(),
                "linear_gain_dB": lin.bode(sim.frequencies, lin.inputs[0], lin.outputs[0]).gain_db[0].tolist(),
                **({"note": sim.info["not_run"]} if "not_run" in sim.info else {}),
            }
        if self.files:
            report["files"] = self.files
        return report

    def lines(self) -> list[str]:
        from hydroservo.io.text import text_table
        from hydroservo.units import si_unit

        lin = self.model
        out = [self.title() + (f", steady motion of {', '.join(lin.info['free'])}" if lin.info.get("free") else "")
               + (" through the run's state at t" if lin.info.get("states_from_run") and lin.info.get("free") else "")]
        out.append(f"  {len(lin.states)} states, {len(lin.inputs)} inputs ({', '.join(lin.inputs)}), "
                   f"{len(lin.outputs)} outputs")
        out.append("  operating point:")
        point = self._point()
        moving = any(abs(drift) > 1e-9 * max(1.0, abs(v)) for _, v, _, drift in point)
        out += text_table(
            [[s, v, si_unit(unit)] + ([drift] if moving else []) for s, v, unit, drift in point],
            ["state", "value", "unit"] + (["rate [unit/s]"] if moving else []), indent=4, digits=[5, 5, 5, 4],
        )
        out.append("  modes (slowest first):")
        rows = []
        for m in lin.modes():
            lam = m.eigenvalue
            pole = f"{lam.real + 0.0:.4g}" + (f" ± {abs(lam.imag):.4g}j" if m.oscillatory else "")
            rows.append([pole, m.frequency, None if m.damping != m.damping else f"{m.damping:.3f}",
                         m.time_constant if abs(m.time_constant) < 1e12 else "inf",
                         ", ".join(f"{s} {100 * m.participation[s]:.0f}%" for s in m.main_states(0.1))])
        out += text_table(rows, ["pole [1/s]", "f_n [Hz]", "damping", "tau [s]", "states taking part"], indent=4,
                          digits=[4, 4, 3, 3], align=["right", "decimal", "decimal", "decimal", "left"])
        for vc in self.valves:
            out.append(f"  valve {vc.valve} at {self._valve_point(vc)} ([Efe2014] eqs. 4.8-4.12):")
            rows = [[f"{key}_{side}", factor * vc.model[f"{key}_{side}"],
                     factor * vc.closed_form[f"{key}_{side}"] if vc.closed_form else None, unit]
                    for key, unit, factor in self._coefficients() for side in ("A", "B")]
            out += text_table(rows, ["coefficient", "model", "closed form", "unit"], indent=4, digits=4)
        for what, path in self.files.items():
            out.append(f"  {what}: {path}")
        sim = self.simulated
        if sim is not None:
            linear = lin.bode(sim.frequencies, lin.inputs[0], lin.outputs[0])
            out.append(f"  {lin.outputs[0]} / {lin.inputs[0]}, simulated sines against the linear model [dB]:")
            out += text_table(
                [[fk, linear.gain_db[0, j], *(sim.gain_db[i, j] for i in range(sim.amplitudes.size))]
                 for j, fk in enumerate(sim.frequencies)],
                ["f [Hz]", "linear", *(f"A={a:g}" for a in sim.amplitudes)], indent=4,
                digits=[3, *[".2f"] * (1 + sim.amplitudes.size)],
            )
            if "not_run" in sim.info:
                out.append(f"    note: {sim.info['not_run']}")
        return out

    def document(self) -> Page:
        """The operating point, the modes, the valve coefficients, and Bode plots of the first input."""
        import numpy as np

        from hydroservo.io.html import Figure, Section, Table
        from hydroservo.plotting.interactive import bode_figure
        from hydroservo.units import si_unit
        from hydroservo.workflows import pages

        lin = self.model
        point = Table(["state", "value", "unit", "rate [unit/s]"],
                      [[s, v, si_unit(unit), drift] for s, v, unit, drift in self._point()])
        modes = Table(["pole [1/s]", "f_n [Hz]", "damping", "tau [s]", "states taking part"], [
            [f"{m.eigenvalue.real:.4g}" + (f" ± {abs(m.eigenvalue.imag):.4g}j" if m.oscillatory else ""), m.frequency,
             None if m.damping != m.damping else m.damping, m.time_constant if abs(m.time_constant) < 1e12 else None,
             ", ".join(f"{s} {100 * m.participation[s]:.0f}%" for s in m.main_states(0.1))] for m in lin.modes()
        ], "slowest first")
        grid = self.frequencies if self.frequencies is not None else np.logspace(-1, 3, 200)
        figures = []
        for out in lin.outputs[:4]:
            response = lin.bode(grid, lin.inputs[0], out)
            response.label = "linear"
            others = [response]
            if self.simulated is not None and out == lin.outputs[0]:
                self.simulated.label = "simulated"
                others.append(self.simulated)
            figures.append(Figure(bode_figure(others, title=f"{out} / {lin.inputs[0]}",
                                              input_unit=si_unit(lin.units.get(lin.inputs[0], "")),
                                              output_unit=si_unit(lin.units.get(out, "")))))
        valves = [Table(["coefficient", "model", "closed form", "unit"], [
            [f"{key}_{side}", factor * vc.model[f"{key}_{side}"],
             factor * vc.closed_form[f"{key}_{side}"] if vc.closed_form else None, si_unit(unit)]
            for key, unit, factor in self._coefficients() for side in ("A", "B")
        ], f"valve {vc.valve} at {self._valve_point(vc)} ([Efe2014] eqs. 4.8-4.12)") for vc in self.valves]
        return pages.page(self.title(), f"{len(lin.states)} states, inputs {', '.join(lin.inputs)}", [
            pages.circuit_section(self.system),
            Section("Operating point", [point]),
            Section("Modes", [modes]),
            Section("Frequency response", figures),
            Section("Valve coefficients", valves) if valves else None,
            pages.references_section(self.system.references()),
            pages.files_section(self.files),
        ], self.warnings)


@dataclass
class Linearize(Workflow):
    """The linear model of ``model`` at an operating point.

    Parameters
    ----------
    model : str, Path or System
        A built-in model's name, a model file or a system.
    sets : list of "COMPONENT.PARAMETER=VALUE" or dict, optional
        Changes to its parameters first.
    at : str, mapping or Path
        ``"trim"`` (an equilibrium, default), ``"run"`` (the state a run from the initial state reaches at ``t``,
        every state as simulated), ``"initial"``, ``"STATE=VALUE,..."``, a mapping of states, or an
        operating-point file (:func:`hydroservo.analysis.linear.operating_point`).
    t : float or str
        Time of the operating point [s] (the signals' values then).
    free : list of str
        States the trim leaves free: a steady motion. They keep the system's values at ``t`` (a run's from the
        initial state; at ``t = 0`` the initial ones).
    inputs, outputs : list of str, optional
        Component inputs or parameters; states, outputs or aliases (default: the signal-block inputs; the states).
    frequencies : array, optional
        [Hz] of the Bode plot and of the JSON's frequency response.
    simulate : list of float, optional
        Amplitudes (the first input's unit) of sines run through the nonlinear system beside the linear model.
    write : bool
        Whether the report writes its files (the model as JSON, the poles and the Bode plots).
    units : str or dict, optional
        Units to show the operating point and the valve coefficients in, over the model's own (``"p=bar, mm"``;
        :class:`~hydroservo.units.UnitChoice`). The JSON keeps SI, as the matrices are.
    si : bool
        Show them in SI instead.
    """

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set"}

    model: str | Path | System
    sets: Sequence[str] | Mapping[str, Any] | None = None
    at: str | Mapping[str, Any] | Path = "trim"
    t: float | str = 0.0
    free: Sequence[str] = ()
    inputs: Sequence[str] | None = None
    outputs: Sequence[str] | None = None
    frequencies: Sequence[float] | np.ndarray | None = None
    simulate: Sequence[float] | None = None
    write: bool = True
    units: str | Mapping[str, str] | None = None
    si: bool = False
    point: Any = field(init=False, repr=False)

    def __post_init__(self) -> None:
        import numpy as np

        from hydroservo.units import to_si

        self.system = load_with_sets(self.model, self.sets, self.name("sets"))
        self.point = operating_point(self.at, self.name("at"))
        for what, names, kind in (("inputs", self.inputs, "input"), ("outputs", self.outputs, "signal"),
                                  ("free", self.free, "state"), ("at", self.point if isinstance(self.point, Mapping) else None, "state")):
            check_names(self.system, self.name(what), names, kind)
        from hydroservo.analysis.linear import operating_time

        self.time = operating_time(to_si(self.t, "s", what=self.name("t")), self.name("t"), self.t)
        self.grid = None if self.frequencies is None else np.asarray(self.frequencies, dtype=float)
        self.unit_choice = self.system.unit_choice(asked_units(self.system, self.units, self.si, self.name))

    def folder(self) -> str:
        return f"hydroservo-{safe_name(self.system.name)}-linear"

    def planned(self) -> list[str]:
        if not self.write:
            return []
        name = safe_name(self.system.name)
        names = [f"{name}-linear.json", f"{name}-poles.png", f"{name}-bode.png"]
        return names + ([f"{name}-bode-simulated.png"] if self.simulate else [])

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> LinearReport:
        import numpy as np

        from hydroservo.analysis.linear import linearize, simulated_response, valve_coefficients

        lin = linearize(
            self.system, self.point, inputs=None if self.inputs is None else list(self.inputs),
            outputs=None if self.outputs is None else list(self.outputs), t=self.time, free=list(self.free),
        )
        valves = valve_coefficients(self.system, lin.x0, t=self.time)
        simulated = None
        if self.simulate:
            grid_sim = self.grid if self.grid is not None else np.logspace(0, 2, 9)
            simulated = simulated_response(
                self.system, lin, grid_sim, list(self.simulate), input=lin.inputs[0], output=lin.outputs[0]
            )
        return LinearReport(self.system, lin, valves, self.grid, simulated, self.write, self.unit_choice)


def run(model: str | Path | System, **inputs: Any) -> LinearReport:
    """The linear model of ``model`` (:class:`Linearize`'s inputs as keywords)."""
    return Linearize(model, **inputs).run()
