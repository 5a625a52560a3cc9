"""Hydraulic lines and hoses: lumped segments of capacitance, inertance and laminar friction."""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from typing import Any, ClassVar

from hydroservo import backend as bk
from hydroservo.components.base import Component, Hydraulic, Limit, Option, Output, Param, Port, State, register
from hydroservo.errors import ParameterError
from hydroservo.laws.fluid import wave_speed
from hydroservo.laws.line import (
    critical_flow,
    friction_drop,
    segment_capacitance,
    segment_inertance,
    segment_resistance,
    segments_needed,
    wall_bypass_inertance,
    wave_line_elements,
)
from hydroservo.units import VACUUM

__all__ = ["Line", "Hose", "LosslessLine", "LineResolutionWarning"]

#: The ends a line may have: (end A, end B), each "pressure" (a half volume) or "flow" (a half oil column).
ENDS = {
    "pressure": ("pressure", "pressure"),
    "flow": ("flow", "flow"),
    "pressure-flow": ("pressure", "flow"),
    "flow-pressure": ("flow", "pressure"),
}


class LineResolutionWarning(UserWarning):
    """A line has too few segments to resolve its waves up to its ``f_max``."""


@register
class Line(Component):
    r"""Line or hose of length ``l`` and bore ``d``: ``segments`` lumped segments, each a volume, an oil column and laminar friction.

    Per segment of length :math:`l/n` (:mod:`hydroservo.laws.line`): a volume
    :math:`\pi d^2 l/(4n)` whose pressure builds up with the bulk modulus
    ``beta_e`` ([Efe2014] eq. 3.17), an oil column of inertance
    :math:`\rho (l/n)/A` and a Hagen-Poiseuille resistance
    :math:`128\mu (l/n)/(\pi d^4)`:

    .. math::
        C\,\dot p_k = q_{k} - q_{k+1}, \qquad
        L\,\dot q_k = p_{k-1} - p_k - R\,q_k

    A short line is one segment; a long one needs enough segments to carry
    its pressure waves: [Efe2014]'s criterion :math:`l < c/(10 f_{max})`
    (eq. 3.30), with :math:`c = \sqrt{\beta_e/\rho}`, applied to each segment
    (``segments="auto"`` picks the fewest that meet it for the parameter
    ``f_max``; a set number that does not meet it warns). The segments then
    reproduce the line's wave dynamics (quarter-wave resonance
    :math:`c/(4l)` of a line closed at one end) up to ``f_max``. Wall friction is
    the steady laminar one; frequency-dependent friction is not modelled, so
    resonances are less damped than in a real line. Option ``friction``:
    ``"laminar"`` (default) at any flow, or ``"laminar-blasius"``, laminar
    below a Reynolds number of 2300 and Blasius' turbulent friction above
    (:func:`hydroservo.laws.line.friction_drop`, [Hopsan2026]
    Hydraulic/Volumes&Lines/HydraulicHose.hpp's law), each oil column's at its
    own flow; the jump at the transition is a switch event.

    ``ends`` chooses what each end is, so that the line fits the ports it joins
    (a node needs exactly one pressure port, :mod:`hydroservo.system.nodes`):

    * ``"pressure"`` (default): both ends hold half a segment's volume (a π
      ladder); connect them to flow ports (valves, orifices, pumps);
    * ``"flow"``: both ends are half an oil column (a T ladder); connect them
      to pressure ports (cylinder chambers, volumes, sources);
    * ``"pressure-flow"``, ``"flow-pressure"``: one of each (end A first).

    The ladders are the staggered grids of the wave equation: pressures at the
    segment ends, flows at their middles (π), or the reverse (T). At a flow end
    half a segment's volume is not in the line: it is the volume of the
    pressure port there (a chamber's dead volume already counts its line).

    Option ``wall``: ``"rigid"`` (default), the wall adds nothing but its
    compliance (:class:`Hose`); ``"viscous"``, a wall whose damping attenuates
    the waves without a steady pressure drop, [Hopsan2026]
    Hydraulic/Volumes&Lines/HydraulicHose.hpp's law: its equivalent wall
    viscosity ``eta_w`` gives the resistance :math:`R_w = 128\eta_w l/(\pi d^4)`,
    which Hopsan applies as the filter :math:`(1 + s/W_4)/(1 + s/W_3)` on each
    transmitted wave, :math:`W_3 = R_w/(2 Z_c T)`, :math:`W_4 = W_3 e^{R_w/(2Z_c)}`
    (:math:`Z_c` the line's impedance, :math:`T` its delay). To first order in
    :math:`R_w/Z_c` that filter is :math:`e^{-Z_w/(2Z_c)}`, the attenuation of
    a line whose series impedance is :math:`Z_w = R_w s\tau/(1 + s\tau)`,
    :math:`\tau = 1/W_3`: the resistance :math:`R_w` in parallel with the
    inertance :math:`R_w\tau = 2 L_{line}`, distributed along the line. Each
    oil column of a fraction :math:`f` of the line carries it as
    :math:`f R_w (q_k - w_k)`, the bypass flow :math:`w_k` obeying
    :math:`2L\,\dot w_k = R_w (q_k - w_k)` (:func:`hydroservo.laws.line.wall_bypass_inertance`):

    .. math::
        f L\,\dot q_k = p_{k-1} - p_k - f R\,q_k - f R_w (q_k - w_k)

    States: the pressures ``p0``, ``p1``, … of the volumes and the flows
    ``q0``, ``q1``, … of the oil columns, from end A to end B (with a viscous
    wall, the bypass flows ``w0``, ``w1``, … of the columns).
    """

    OPTIONS = {
        "wall": Option("rigid", ("rigid", "viscous"), "a wall without damping, or with the damping of eta_w"),
        "friction": Option(
            "laminar", ("laminar", "laminar-blasius"), "laminar friction, or Blasius' turbulent above Re = 2300"
        ),
    }

    PARAMETERS = {
        "l": Param(1.0, "m", "length", min=0.0, min_inclusive=False),
        "d": Param(0.01, "m", "inner diameter (bore)", min=0.0, min_inclusive=False),
        "beta_e": Param(
            1.0e9, "Pa", "effective bulk modulus of oil and wall", min=0.0, min_inclusive=False, fluid="bulk_modulus"
        ),
        "rho": Param(870.0, "kg/m^3", "oil density", min=0.0, min_inclusive=False, fluid="density"),
        "nu": Param(
            32e-6, "m^2/s", "kinematic viscosity", min=0.0, min_inclusive=False, fluid="kinematic_viscosity"
        ),
        "f_max": Param(100.0, "Hz", "highest frequency of interest (sets segments='auto')", min=0.0, min_inclusive=False),
        "p_init": Param(0.0, "Pa", "initial pressure along the line", min=VACUUM),
        "eta_w": Param(0.0, "Pa*s", "equivalent wall viscosity (wall = 'viscous')", min=0.0),
    }
    #: ``p0`` is also the first volume's pressure state: the parameter is ``p_init``
    RENAMED = {"p0": "p_init"}

    #: Most segments a line may have (a stiff, dense model beyond).
    MAX_SEGMENTS = 200

    def __init__(self, name: str, segments: int | str = "auto", ends: str = "pressure", **values: Any) -> None:
        self.auto = False
        super().__init__(name, **values)
        if ends not in ENDS:
            raise ParameterError(f"{name}.ends = {ends!r}: expected one of {', '.join(ENDS)}")
        self._ends = ends
        if segments == "auto":
            self.auto = True
            segments = self.segments_needed()
        else:
            if isinstance(segments, float) and float(segments).is_integer():
                segments = int(segments)
            if isinstance(segments, bool) or not isinstance(segments, int) or not 1 <= segments <= self.MAX_SEGMENTS:
                raise ParameterError(
                    f"{name}.segments = {segments!r}: expected a whole number from 1 to {self.MAX_SEGMENTS}, or 'auto'"
                )
        self._segments = int(segments)
        self._declare()

    @property
    def viscous_wall(self) -> bool:
        """Whether the wall damps the waves (option ``wall = "viscous"``)."""
        return self.option_values.get("wall") == "viscous"

    @property
    def turbulent(self) -> bool:
        """Whether the friction turns turbulent above a Reynolds number of 2300 (option ``friction``)."""
        return self.option_values.get("friction") == "laminar-blasius"

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """An oil column's flow crossing the laminar-turbulent transition (option friction = laminar-blasius)."""
        if not self.turbulent:
            return {}
        q_c = critical_flow(p["d"], p["rho"], p["rho"] * p["nu"])
        return {f"turbulent_{q}": (bk.fabs(x[q]) - q_c, 1e-3) for q in self._names if q.startswith("q")}

    def options_changed(self) -> None:
        if hasattr(self, "_segments"):  # the constructor declares the states once it knows the segments
            self._declare()

    @property
    def segments(self) -> int:
        """Number of lumped segments (set in the constructor; 'auto' follows the length and the oil)."""
        return self._segments

    @property
    def ends(self) -> str:
        """What each end is: 'pressure', 'flow', 'pressure-flow' or 'flow-pressure' (set in the constructor)."""
        return self._ends

    def segments_needed(self) -> int:
        """The fewest segments that carry waves up to ``f_max`` ([Efe2014] eq. 3.30 per segment)."""
        v = self.values
        n = self._segments_for(v)
        if n > self.MAX_SEGMENTS:
            raise ParameterError(
                f"{self.name}: {self._described()} needs {n} segments to carry waves up to f_max = {v['f_max']:g} Hz "
                f"([Efe2014] eq. 3.30 per segment); expected at most {self.MAX_SEGMENTS}: lower f_max or split the line"
            )
        return n

    def _segments_for(self, v: Mapping[str, Any]) -> int:
        return segments_needed(v["l"], float(wave_speed(self.bulk_modulus(v), v["rho"])), v["f_max"])

    def _described(self) -> str:
        return f"a {self.values['l']:g} m line"

    def elements(self, p: Mapping[str, Any]) -> tuple[Any, Any, Any]:
        """The whole line's capacitance [m^3/Pa], inertance [Pa s^2/m^3] and laminar resistance [Pa s/m^3]."""
        return (
            segment_capacitance(p["l"], p["d"], self.bulk_modulus(p)),
            segment_inertance(p["l"], p["d"], p["rho"]),
            segment_resistance(p["l"], p["d"], p["rho"] * p["nu"]),
        )

    def wall_resistance(self, p: Mapping[str, Any]) -> Any:
        """The viscous wall's resistance R_w = 128 eta_w l/(pi d^4) [Pa s/m^3] (Hopsan's HydraulicHose)."""
        return segment_resistance(p["l"], p["d"], p["eta_w"])

    def bulk_modulus(self, p: Mapping[str, Any]) -> Any:
        """The bulk modulus of the oil in the line, its wall's compliance included (a hose's)."""
        return p["beta_e"]

    def changed(self) -> None:
        if self.auto:  # "auto" follows the length and the oil
            self._segments = self.segments_needed()
            self._declare()

    def structure_key(self) -> tuple[Any, ...]:
        return (self.segments, self.ends)

    def config(self) -> dict[str, Any]:
        return {"segments": "auto" if self.auto else self.segments, "ends": self.ends}

    def _elements(self) -> list[tuple[str, float]]:
        """The ladder from A to B: ("C", fraction of the line's volume) and ("L", fraction of its length)."""
        n = self.segments
        a, b = ENDS[self.ends]
        if (a, b) == ("pressure", "pressure"):
            return [("C", 0.5 / n)] + [("L", 1.0 / n), ("C", 1.0 / n)] * (n - 1) + [("L", 1.0 / n), ("C", 0.5 / n)]
        if (a, b) == ("flow", "flow"):
            return [("L", 0.5 / n)] + [("C", 1.0 / n), ("L", 1.0 / n)] * (n - 1) + [("C", 1.0 / n), ("L", 0.5 / n)]
        # one pressure end: the grid of a closed end (pressures every l/n, the last one holding half a
        # segment); the other half segment's volume is that of the pressure port the flow end joins
        if a == "pressure":
            return [("C", 0.5 / n), ("L", 1.0 / n)] + [("C", 1.0 / n), ("L", 1.0 / n)] * (n - 1)
        return [("L", 1.0 / n), ("C", 1.0 / n)] * (n - 1) + [("L", 1.0 / n), ("C", 0.5 / n)]

    def _declare(self) -> None:
        states: dict[str, State] = {}
        self._names: list[str] = []
        nc = nl = 0
        for kind, _ in self._elements():
            if kind == "C":
                name = f"p{nc}"
                nc += 1
                states[name] = State("Pa", f"pressure of volume {nc} from end A", initial="p_init", nominal=1e7)
            else:
                name = f"q{nl}"
                nl += 1
                states[name] = State("m^3/s", f"flow in oil column {nl} from end A, towards B", nominal=1e-3)
                if self.viscous_wall:
                    states[f"w{nl - 1}"] = State("m^3/s", f"flow past the wall's damping in oil column {nl}", nominal=1e-3)
            self._names.append(name)
        inputs: dict[str, Port] = {}
        outputs: dict[str, Output] = {}
        hydraulic: dict[str, Hydraulic] = {}
        for end, state in (("A", self._names[0]), ("B", self._names[-1])):
            if state.startswith("p"):  # a pressure end: gives its pressure, takes the flow into the line
                outputs[f"p{end}"] = Output("Pa", f"pressure at end {end}")
                inputs[f"Q{end}"] = Port("m^3/s", f"flow into the line at end {end}", default=0.0)
            else:  # a flow end: takes the pressure, gives the flow into the line
                inputs[f"p{end}"] = Port("Pa", f"pressure at end {end}")
                outputs[f"Q{end}"] = Output("m^3/s", f"flow into the line at end {end}")
            hydraulic[end] = Hydraulic(f"p{end}", f"Q{end}", f"end {end}")
        self.STATES = states  # type: ignore[misc]
        self.INPUTS = inputs  # type: ignore[misc]
        self.OUTPUTS = outputs  # type: ignore[misc]
        self.HYDRAULIC = hydraulic  # type: ignore[misc]
        self.LIMITS = {n: Limit("pressure") for n in states if n.startswith("p")}  # type: ignore[misc]

    def check(self) -> None:
        needed = self.segments_needed()
        if self.segments < needed:
            warnings.warn(
                f"{self.name}: {self.segments} segment(s) of {self._described()} carry waves up to "
                f"{self.values['f_max'] * self.segments / needed:.3g} Hz at most, below f_max = "
                f"{self.values['f_max']:g} Hz ([Efe2014] eq. 3.30 per segment); use segments={needed} or 'auto'",
                LineResolutionWarning,
                stacklevel=2,
            )

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for end, state, sign in (("A", self._names[0], 1.0), ("B", self._names[-1], -1.0)):
            if state.startswith("p"):
                out[f"p{end}"] = x[state]
            else:  # the column's flow runs from A to B: into the line at A, out of it at B
                out[f"Q{end}"] = sign * x[state]
        return out

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        elements = self._elements()
        capacitance, inertance, resistance = self.elements(p)
        viscous = self.viscous_wall
        if viscous:
            wall = self.wall_resistance(p)
            bypass = wall_bypass_inertance(inertance)
        last = len(elements) - 1
        der: dict[str, Any] = {}
        for k, ((kind, frac), name) in enumerate(zip(elements, self._names, strict=True)):
            if kind == "C":
                q_in = u["QA"] if k == 0 else x[self._names[k - 1]]
                q_out = -u["QB"] if k == last else x[self._names[k + 1]]
                der[name] = (q_in - q_out) / (frac * capacitance)  # C_k dp_k/dt = q_in - q_out
            else:
                p_up = u["pA"] if k == 0 else x[self._names[k - 1]]
                p_down = u["pB"] if k == last else x[self._names[k + 1]]
                if self.turbulent:
                    drop = p_up - p_down - frac * friction_drop(x[name], p["l"], p["d"], p["rho"], p["rho"] * p["nu"])
                else:
                    drop = p_up - p_down - frac * resistance * x[name]
                if viscous:  # the wall's resistance, bypassed by its inertance (the class's docstring)
                    w = f"w{name[1:]}"
                    drop = drop - frac * wall * (x[name] - x[w])
                    der[w] = wall * (x[name] - x[w]) / bypass
                der[name] = drop / (frac * inertance)
        return der


@register
class Hose(Line):
    r"""Hose: a :class:`Line` whose wall stretches with the pressure, softening the oil it holds.

    The wall's compliance ``k_wall`` (relative volume increase per pressure,
    :math:`\Delta V/(V\,\Delta p)`, from a catalogue's volumetric expansion)
    adds to the oil's, [Merritt1967] (effective bulk modulus with a compliant
    container):

    .. math:: \frac{1}{\beta_{eff}} = \frac{1}{\beta_e} + k_{wall}

    which slows the waves (:math:`c = \sqrt{\beta_{eff}/\rho}`) and lowers the
    hose's resonances; everything else is the line's. A 1/2-inch two-wire hose
    expands by about 1 % of its volume per 100 bar (``k_wall`` = 1e-9 1/Pa):
    :math:`\beta_{eff}` about 0.6 GPa with a mineral oil of 1.6 GPa.
    """

    PARAMETERS = {
        **Line.PARAMETERS,
        "k_wall": Param(1e-9, "1/Pa", "wall compliance: relative volume increase per pressure", min=0.0),
    }

    def bulk_modulus(self, p: Mapping[str, Any]) -> Any:
        return 1.0 / (1.0 / p["beta_e"] + p["k_wall"])


@register
class LosslessLine(Line):
    r"""Lossless line given by its characteristic impedance ``Z_c`` and the time ``deltat`` a wave takes along it.

    The wave equation of a line without friction, whose characteristics
    [Hopsan2026] Hydraulic/Volumes&Lines/HydraulicTLMlossless.hpp solves
    exactly (the wave :math:`p + Z_c q` arriving at one end is the one that
    left the other end ``deltat`` earlier). hydroservo integrates ODEs, which
    hold no delay: the line is the :class:`Line`'s ladder of ``segments``
    lumped segments, whose totals are the telegrapher's
    :math:`Z_c = \sqrt{L/C}`, :math:`T = \sqrt{L C}`
    (:func:`hydroservo.laws.line.wave_line_elements`), with no friction. The
    ladder carries the waves without loss up to its cut-off
    :math:`\omega = 2n/T` and with little dispersion well below it
    (``segments="auto"``: :math:`n \ge 10 f_{max} T`, [Efe2014] eq. 3.30
    per segment); a step's wavefront arrives spread over some
    :math:`T/n^{2/3}` and rings behind it, as a truncated series does at a
    jump: more segments sharpen it, none removes the ringing.

    States: those of :class:`Line` (``ends`` chooses the ladder).
    """

    OPTIONS: ClassVar[dict[str, Option]] = {}  # no wall option: a lossless line has none

    PARAMETERS = {
        "Z_c": Param(1.0e9, "Pa*s/m^3", "characteristic impedance", min=0.0, min_inclusive=False),
        "deltat": Param(0.01, "s", "time a wave takes from one end to the other", min=0.0, min_inclusive=False),
        "f_max": Param(100.0, "Hz", "highest frequency of interest (sets segments='auto')", min=0.0, min_inclusive=False),
        "p_init": Param(0.0, "Pa", "initial pressure along the line", min=VACUUM),
    }

    def _segments_for(self, v: Mapping[str, Any]) -> int:
        # [Efe2014]'s criterion per segment, l/n < c/(10 f_max), is n >= 10 f_max T for a line of delay T = l/c:
        # a line of that delay at any wave speed (1 m/s here) needs the same segments
        return segments_needed(v["deltat"] * 1.0, 1.0, v["f_max"])

    def _described(self) -> str:
        return f"a line of delay {self.values['deltat']:g} s"

    def elements(self, p: Mapping[str, Any]) -> tuple[Any, Any, Any]:
        capacitance, inertance = wave_line_elements(p["Z_c"], p["deltat"])
        return capacitance, inertance, 0.0
