"""Pressure sources: supplies and tanks (pumps, relief and check valves follow in this module's kind)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.components.base import (
    Algebraic,
    Component,
    Hydraulic,
    Limit,
    Option,
    Output,
    Param,
    Port,
    State,
    register,
)
from hydroservo.errors import ParameterError
from hydroservo.laws.pressure_valve import limited_rate
from hydroservo.units import VACUUM, to_si

__all__ = ["ConstantPressure", "Tank", "HeadTank", "PressureTable", "PressureSource", "FlowSource"]


@register
class ConstantPressure(Component):
    """Ideal pressure source (pump with accumulators and pressure control).

    [FlightSimulatorND] assumption (3): "a constant supply pressure is used".
    """

    PARAMETERS = {"p": Param(100e5, "Pa", "supply pressure (gauge)", min=0.0)}
    INPUTS = {"Q": Port("m^3/s", "flow delivered into the circuit through port P", default=0.0)}
    OUTPUTS = {"p": Output("Pa", "supply pressure")}
    LIMITS = {"p": Limit("source")}
    HYDRAULIC = {"P": Hydraulic("p", "Q", "pressure port", into=False)}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"p": p["p"]}


@register
class Tank(ConstantPressure):
    """Return line at constant pressure; [FlightSimulatorND] assumption (6): atmospheric (0 gauge)."""

    PARAMETERS = {"p": Param(0.0, "Pa", "tank pressure (gauge)", min=VACUUM)}
    INPUTS = {"Q": Port("m^3/s", "flow returned into the tank through port P", default=0.0)}
    OUTPUTS = {"p": Output("Pa", "tank pressure")}
    HYDRAULIC = {"P": Hydraulic("p", "Q", "return port")}



@register
class HeadTank(Component):
    r"""A tank whose outlet pressure is the pressure above its liquid plus the liquid's head, which falls as it empties.

    .. math:: p = p_0 + \rho\,g\,h_{full}\,\frac{m}{m_{full}} \;\; (m > 0), \qquad
              p = p_{vac} \;\; (m \le 0), \qquad \dot m = \rho\,Q

    the hydrostatic pressure at the bottom of a tank of constant section, its liquid's mass ``m`` (a state, from
    ``m0``) changed by the flow ``Q`` into it through port P, held within [``m_min``, ``m_max``] without wind-up
    (:func:`hydroservo.laws.pressure_valve.limited_rate`, relaxed over ``t_stop``); an empty tank (``m`` at or
    below 0) gives vacuum at its outlet. Hopsan's HydraulicFuelTankG ([Hopsan2026]
    Hydraulic/Special/FuelComponents/HydraulicFuelTankG.hpp): its consumed mass, the trapezoidal integral of
    -ρ q_T limited to [0, m0 + 1e-4 kg], is ``m0 - m`` (output ``m_used``), its wave variable
    (p0 + g h ρ)·[m > 0] with no impedance this pressure. Pressures gauge; vacuum is ``p_vac``.
    """

    PARAMETERS = {
        "p0": Param(0.0, "Pa", "pressure above the liquid (gauge)", min=VACUUM),
        "rho": Param(870.0, "kg/m^3", "density of the liquid", min=0.0, min_inclusive=False, fluid="density"),
        "g": Param(9.81, "m/s^2", "acceleration of gravity", min=0.0),
        "h_full": Param(1.0, "m", "height of the liquid in the full tank", min=0.0),
        "m_full": Param(1000.0, "kg", "mass of the liquid in the full tank", min=0.0, min_inclusive=False),
        "m0": Param(1000.0, "kg", "initial mass of the liquid"),
        "m_min": Param(-1e-4, "kg", "lowest mass, a little below empty (Hopsan's: 1e-4 kg below)", max=0.0,
                       max_inclusive=False),
        "m_max": Param(1000.0, "kg", "highest mass", min=0.0, min_inclusive=False),
        "p_vac": Param(VACUUM, "Pa", "outlet pressure of the empty tank (gauge)", min=VACUUM),
        "t_stop": Param(1e-6, "s", "time over which the mass's approach to a bound is relaxed", min=0.0,
                        min_inclusive=False),
    }
    STATES = {"m": State("kg", "mass of the liquid", initial="m0", nominal=1.0)}
    INPUTS = {"Q": Port("m^3/s", "flow into the tank through port P", default=0.0)}
    OUTPUTS = {
        "p": Output("Pa", "outlet pressure"),
        "mass": Output("kg", "mass of the liquid (the state m)"),
        "m_used": Output("kg", "mass drawn since the start, m0 - m"),
    }
    HYDRAULIC = {"P": Hydraulic("p", "Q", "outlet port", into=True)}

    def check(self) -> None:
        v = self.values
        if not v["m_min"] <= v["m0"] <= v["m_max"]:
            raise ParameterError(
                f"{self.name}.m0 = {v['m0']:g} kg: expected within m_min = {v['m_min']:g} and m_max = {v['m_max']:g} kg"
            )

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        head = p["p0"] + p["rho"] * p["g"] * p["h_full"] * x["m"] / p["m_full"]
        return {"p": bk.if_else(x["m"] > 0.0, head, p["p_vac"]), "mass": x["m"], "m_used": p["m0"] - x["m"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        rate = p["rho"] * u["Q"]
        return {"m": limited_rate(x["m"] - p["m_min"], rate, p["m_max"] - p["m_min"], p["t_stop"])}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """The tank running empty, where its outlet pressure drops to vacuum."""
        return {"empty": (x["m"], 1.0)}

@register
class PressureTable(Component):
    """Supply pressure that follows a time table, linear between points, held outside.

    [Efe2014] (section 4.1, V) measured the supply of the robot arm varying
    between 25 and 35 bar and found that it matters; feed such a record here.
    Set ``times`` [s] and ``pressures`` [Pa] as equally long lists.
    """

    PARAMETERS = {"scale": Param(1.0, "", "factor applied to the table", min=0.0)}
    INPUTS = {"Q": Port("m^3/s", "flow delivered into the circuit through port P", default=0.0)}
    OUTPUTS = {"p": Output("Pa", "supply pressure")}
    LIMITS = {"p": Limit("source")}
    HYDRAULIC = {"P": Hydraulic("p", "Q", "pressure port", into=False)}

    def __init__(self, name: str, times: Any = (0.0,), pressures: Any = (100e5,), **values: Any) -> None:
        super().__init__(name, **values)
        self.set_table(times, pressures)

    def set_table(self, times: Any, pressures: Any) -> None:
        """Set the table: numbers in SI, or quantities with units (``"30 bar"``, as a model file keeps them)."""
        t = np.asarray(_si_list(times, "s", f"{self.name}.times"), dtype=float).ravel()
        pr = np.asarray(_si_list(pressures, "Pa", f"{self.name}.pressures"), dtype=float).ravel()
        if t.size == 0 or t.size != pr.size:
            raise ParameterError(
                f"{self.name}: times and pressures must be equally long and non-empty; got {t.size} and {pr.size}"
            )
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(pr))):
            raise ParameterError(f"{self.name}: times and pressures must be finite numbers")
        if np.any(np.diff(t) <= 0):
            raise ParameterError(f"{self.name}.times: expected strictly increasing times [s]")
        if np.any(pr < 0):
            raise ParameterError(f"{self.name}.pressures: expected gauge pressures ≥ 0 Pa, got min {pr.min():g} Pa")
        self.times, self.pressures = t, pr
        given = [*np.atleast_1d(np.asarray(times, dtype=object)).ravel(), *np.atleast_1d(np.asarray(pressures, dtype=object)).ravel()]
        #: The table as given with its units, so that a model file is written back as its author wrote it.
        self.table_given: dict[str, list[Any]] | None = (
            {"times": list(times), "pressures": list(pressures)} if any(isinstance(v, str) for v in given) else None
        )

    def config(self) -> dict[str, Any]:
        if self.table_given is not None:
            return dict(self.table_given)
        return {"times": self.times.tolist(), "pressures": self.pressures.tolist()}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"p": p["scale"] * bk.interp(t, self.times, self.pressures)}


def _si_list(values: Any, unit: str, what: str) -> list[float]:
    """A list of numbers (SI) or of quantities with units, in SI."""
    items = np.atleast_1d(np.asarray(values, dtype=object)).ravel().tolist()
    return [to_si(v, unit, what=what) if isinstance(v, str) else float(v) for v in items]


@register
class FlowSource(Component):
    """Ideal flow source: delivers the flow ``q + u`` into the circuit through its port ``P``, whatever the
    pressure there (Hopsan's HydraulicFlowSourceQ, [Hopsan2026])."""

    PARAMETERS = {"q": Param(1e-3, "m^3/s", "constant flow delivered")}
    INPUTS = {
        "u": Port("m^3/s", "flow delivered on top of q (a signal)", default=0.0),
        "p": Port("Pa", "pressure at port P", default=0.0),
    }
    OUTPUTS = {"Q": Output("m^3/s", "flow delivered into the circuit at P")}
    HYDRAULIC = {"P": Hydraulic("p", "Q", "flow port", into=False)}
    #: a flow whatever the pressure: the circuit's relief valves bound it (plausibility)
    LIMITS = {"Q": Limit("flow-source")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"Q": p["q"] + u["u"]}


#: the time constant [s] with which a PressureSource behind a resistance follows its pressure (its solver's guess)
_GUESS_TAU = 1e-6


@register
class PressureSource(Component):
    """A pressure set by a signal: its port ``P`` holds ``p0 + u`` whatever flow it takes (Hopsan's
    HydraulicPressureSourceC with its pressure driven, [Hopsan2026]; a signal of absolute pressure takes
    ``p0 = "0 Pa_abs"``).

    Option ``impedance``: ``"none"`` (the default), an ideal source; ``"input"``, the source behind a linear
    resistance given by the input ``Z``: p = p0 + u - Z Q, Q the flow it delivers (Hopsan's HydraulicCSource,
    [Hopsan2026] Hydraulic/Sources&Sinks/HydraulicCSource.hpp, whose wave variable and impedance are its
    inputs). The flow depends on the pressure it meets, so the pressure is then an algebraic unknown, solved
    with the flows of the node each time the model is evaluated (:mod:`hydroservo.system.implicit`)."""

    PARAMETERS = {"p0": Param(0.0, "Pa", "pressure added to the signal (gauge)", min=VACUUM)}
    INPUTS = {
        "u": Port("Pa", "pressure signal"),
        "Q": Port("m^3/s", "flow delivered into the circuit through port P", default=0.0),
    }
    OUTPUTS = {"p": Output("Pa", "pressure")}
    LIMITS = {"p": Limit("source")}
    HYDRAULIC = {"P": Hydraulic("p", "Q", "pressure port", into=False)}
    OPTIONS = {"impedance": Option("none", ("none", "input"), "an ideal source, or one behind the resistance Z")}

    def options_changed(self) -> None:
        """Behind a resistance, an input ``Z`` and the pressure an algebraic unknown."""
        behind = self.option("impedance") == "input"
        inputs = dict(type(self).INPUTS)
        if behind:
            inputs["Z"] = Port("Pa*s/m^3", "resistance the source stands behind (option impedance = input)",
                               default=0.0)
        self.INPUTS = inputs  # type: ignore[misc]
        self.ALGEBRAIC = (  # type: ignore[misc]
            {"p": Algebraic("Pa", "pressure at port P (option impedance = input)", nominal=1e7)} if behind else {}
        )
        self.STATES = (  # type: ignore[misc]
            {"p_f": State("Pa", "the pressure followed within 1 µs: the first guess of its solution", nominal=1e7)}
            if behind else {}
        )

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        if self.option("impedance") == "input":  # reads no input: the node's flow enters through the residual
            return {"p": x["p"]}
        return {"p": p["p0"] + u["u"]}

    def residual_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        if self.option("impedance") == "input":
            return {"p": x["p"] - (p["p0"] + u["u"] - u["Z"] * u["Q"])}
        return {}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"p_f": (x["p"] - x["p_f"]) / _GUESS_TAU} if self.option("impedance") == "input" else {}

    def guess_equations(self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> dict[str, Any]:
        # where the pressure was a microsecond ago: Newton's steps start next to the solution
        return {"p": x["p_f"]} if self.option("impedance") == "input" else {}
