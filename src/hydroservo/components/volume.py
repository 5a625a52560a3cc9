"""Lumped volumes: a node where flows meet and pressure builds up."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo.components.base import Component, Hydraulic, Limit, Output, Param, Port, State, register
from hydroservo.laws.chamber import pressure_rate
from hydroservo.units import VACUUM

__all__ = ["Volume"]


@register
class Volume(Component):
    r"""Lumped volume node: :math:`\dot p = \frac{E}{V}\sum Q_{in}`.

    [Efe2014] eq. (3.17) (:func:`hydroservo.laws.chamber.pressure_rate`). Its
    hydraulic port ``P`` takes any number of connected ports (their flows
    summed into ``Q``); the signal inputs ``Q1`` to ``Q4`` (positive into the
    volume) remain for circuits wired signal by signal.
    """

    RENAMED = {"beta": "beta_e"}

    PARAMETERS = {
        "V": Param(1e-4, "m^3", "volume", min=0.0, min_inclusive=False),
        "beta_e": Param(1.4e9, "Pa", "effective bulk modulus", min=0.0, min_inclusive=False, fluid="bulk_modulus"),
        "p0": Param(0.0, "Pa", "initial pressure", min=VACUUM),
    }
    STATES = {"p": State("Pa", "pressure", initial="p0", nominal=1e7)}
    LIMITS = {"p": Limit("pressure")}
    INPUTS = {
        "Q": Port("m^3/s", "net flow into the volume through port P", default=0.0),
        **{f"Q{i}": Port("m^3/s", f"flow {i} into the volume", default=0.0) for i in range(1, 5)},
    }
    HYDRAULIC = {"P": Hydraulic("p", "Q", "the volume's port")}
    OUTPUTS = {"p": Output("Pa", "pressure")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"p": x["p"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        q = u["Q"] + u["Q1"] + u["Q2"] + u["Q3"] + u["Q4"]
        return {"p": pressure_rate(p["beta_e"], p["V"], q)}
