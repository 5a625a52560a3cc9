"""Lumped volumes: a node where flows meet and pressure builds up."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo.components.base import Component, Hydraulic, Limit, Option, Output, Param, Port, State, register
from hydroservo.laws.chamber import cavity_pressure, cavity_volume, pressure_rate
from hydroservo.units import VACUUM

__all__ = ["Volume"]


@register
class Volume(Component):
    r"""Lumped volume node: :math:`\dot p = \frac{E}{V}\sum Q_{in}`.

    [Efe2014] eq. (3.17) (:func:`hydroservo.laws.chamber.pressure_rate`). Its
    hydraulic port ``P`` takes any number of connected ports (their flows
    summed into ``Q``); the signal inputs ``Q1`` to ``Q4`` (positive into the
    volume) remain for circuits wired signal by signal.

    Option ``pressure_floor``: ``none`` (default), the continuity equation
    alone; ``cavity``, cavitation as Hopsan models it ([Hopsan2026], as the
    cylinder's option of that name): the pressure state ``p_state`` may fall
    below ``p_floor``, where the volume holds a cavity (``V_cav``) to refill,
    and the port sees :math:`\max(p_{state}, p_{floor})`.
    """

    RENAMED = {"beta": "beta_e"}

    PARAMETERS = {
        "V": Param(1e-4, "m^3", "volume", min=0.0, min_inclusive=False),
        "beta_e": Param(1.4e9, "Pa", "effective bulk modulus", min=0.0, min_inclusive=False, fluid="bulk_modulus"),
        "p0": Param(0.0, "Pa", "initial pressure", min=VACUUM),
        "p_floor": Param(VACUUM, "Pa", "lowest pressure (option cavity)", min=VACUUM),
    }
    OPTIONS = {"pressure_floor": Option("none", ("none", "cavity"), "the continuity equation alone, or a cavity to refill")}
    STATES = {"p": State("Pa", "pressure", initial="p0", nominal=1e7)}
    LIMITS = {"p": Limit("pressure")}
    INPUTS = {
        "Q": Port("m^3/s", "net flow into the volume through port P", default=0.0),
        **{f"Q{i}": Port("m^3/s", f"flow {i} into the volume", default=0.0) for i in range(1, 5)},
    }
    HYDRAULIC = {"P": Hydraulic("p", "Q", "the volume's port")}
    OUTPUTS = {"p": Output("Pa", "pressure")}

    def options_changed(self) -> None:
        """The state of the chosen floor: the pressure, or (cavity) a pressure state below the port's pressure."""
        cls = type(self)
        if self.option("pressure_floor") != "cavity":
            self.STATES, self.OUTPUTS = dict(cls.STATES), dict(cls.OUTPUTS)  # type: ignore[misc]
            return
        self.STATES = {  # type: ignore[misc]
            "p_state": State("Pa", "pressure state: the pressure, or below p_floor a cavity to refill", initial="p0", nominal=1e7)
        }
        self.OUTPUTS = {**cls.OUTPUTS, "V_cav": Output("m^3", "cavity volume (option cavity)")}  # type: ignore[misc]

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        if self.option("pressure_floor") != "cavity":
            return {"p": x["p"]}
        return {
            "p": cavity_pressure(x["p_state"], p["p_floor"]),
            "V_cav": cavity_volume(x["p_state"], p["p_floor"], p["V"], p["beta_e"]),
        }

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """The pressure state reaching the floor (option cavity)."""
        if self.option("pressure_floor") != "cavity":
            return {}
        return {"floor": (x["p_state"] - p["p_floor"], 1e5)}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        q = u["Q"] + u["Q1"] + u["Q2"] + u["Q3"] + u["Q4"]
        name = "p_state" if self.option("pressure_floor") == "cavity" else "p"
        return {name: pressure_rate(p["beta_e"], p["V"], q)}
