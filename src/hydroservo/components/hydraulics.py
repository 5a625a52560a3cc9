"""Supplies, tanks and lumped volumes: the components that set pressures."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import _math as m
from hydroservo.components.base import Component, Output, Param, Port, State, register
from hydroservo.errors import ParameterError

__all__ = ["ConstantPressure", "Tank", "PressureTable", "Volume"]


@register
class ConstantPressure(Component):
    """Ideal pressure source (pump with accumulators and pressure control).

    Seed 003 assumption (3): "a constant supply pressure is used".
    """

    PARAMETERS = {"p": Param(100e5, "Pa", "supply pressure (gauge)", min=0.0)}
    OUTPUTS = {"p": Output("Pa", "supply pressure")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"p": p["p"]}


@register
class Tank(Component):
    """Return line at constant pressure; seed 003 assumption (6): atmospheric (0 gauge)."""

    PARAMETERS = {"p": Param(0.0, "Pa", "tank pressure (gauge)", min=-1e5)}
    OUTPUTS = {"p": Output("Pa", "tank pressure")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"p": p["p"]}


@register
class PressureTable(Component):
    """Supply pressure that follows a time table, linear between points, held outside.

    Seed 001 (section 4.1, V) measured the supply of the robot arm varying
    between 25 and 35 bar and found that it matters; feed such a record here.
    Set ``times`` [s] and ``pressures`` [Pa] as equally long lists.
    """

    PARAMETERS = {"scale": Param(1.0, "", "factor applied to the table", min=0.0)}
    OUTPUTS = {"p": Output("Pa", "supply pressure")}

    def __init__(self, name: str, times: Any = (0.0,), pressures: Any = (100e5,), **values: Any) -> None:
        super().__init__(name, **values)
        self.set_table(times, pressures)

    def set_table(self, times: Any, pressures: Any) -> None:
        t = np.asarray(times, dtype=float).ravel()
        pr = np.asarray(pressures, dtype=float).ravel()
        if t.size == 0 or t.size != pr.size:
            raise ParameterError(
                f"{self.name}: times and pressures must be equally long and non-empty; got {t.size} and {pr.size}"
            )
        if np.any(np.diff(t) <= 0):
            raise ParameterError(f"{self.name}.times: expected strictly increasing times [s]")
        if np.any(pr < 0):
            raise ParameterError(f"{self.name}.pressures: expected gauge pressures ≥ 0 Pa, got min {pr.min():g} Pa")
        self.times, self.pressures = t, pr

    def config(self) -> dict[str, Any]:
        return {"times": self.times.tolist(), "pressures": self.pressures.tolist()}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"p": p["scale"] * m.interp(t, self.times, self.pressures)}


@register
class Volume(Component):
    r"""Lumped volume node: :math:`\dot p = \frac{E}{V}\sum Q_{in}`.

    Seed 001 eq. (3.17). Up to four flows may be connected; each is positive
    into the volume.
    """

    PARAMETERS = {
        "V": Param(1e-4, "m^3", "volume", min=0.0, min_inclusive=False),
        "beta": Param(1.4e9, "Pa", "bulk modulus", min=0.0, min_inclusive=False),
        "p0": Param(0.0, "Pa", "initial pressure"),
    }
    STATES = {"p": State("Pa", "pressure", initial="p0", nominal=1e7)}
    INPUTS = {f"Q{i}": Port("m^3/s", f"flow {i} into the volume", default=0.0) for i in range(1, 5)}
    OUTPUTS = {"p": Output("Pa", "pressure")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"p": x["p"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        q = u["Q1"] + u["Q2"] + u["Q3"] + u["Q4"]
        return {"p": p["beta"] / p["V"] * q}
