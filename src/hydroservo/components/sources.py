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
from hydroservo.units import VACUUM, to_si

__all__ = ["ConstantPressure", "Tank", "PressureTable", "PressureSource", "FlowSource"]


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
