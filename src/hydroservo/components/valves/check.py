"""Check valves: flow from A to B once the pressure difference passes the cracking pressure."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo.components.base import Component, Option, Output, Param, register
from hydroservo.components.valves.ports import FLUID_PARAMETERS, TWO_PORT_HYDRAULIC, TWO_PORT_PRESSURES
from hydroservo.laws.orifice import DISCHARGE_COEFFICIENT, orifice_flow, transition_pressure
from hydroservo.laws.pressure_valve import opening_fraction, seat_opening

__all__ = ["CheckValve"]


@register
class CheckValve(Component):
    r"""Check valve: closed until :math:`p_A - p_B` reaches the cracking pressure, fully open ``dp_open`` above it.

    .. math:: Q = C_d\, s(p_A - p_B)\, A \sqrt{2/\rho}\;
              \frac{\Delta p}{(\Delta p^2 + p_{tr}^2)^{1/4}} + G_{leak}\,\Delta p,
              \qquad A = \pi d^2/4

    with the opening fraction :math:`s` rising from 0 at ``p_crack`` to 1 at
    ``p_crack + dp_open`` (:func:`hydroservo.laws.pressure_valve.opening_fraction`,
    corners rounded) and the orifice law of the package
    (:func:`hydroservo.laws.orifice.orifice_flow`). The poppet is taken as
    fast against the circuit (no dynamics). ``G_leak`` is the leakage of the
    closed seat, in both directions (0: tight).

    Option ``opening``: ``"ramp"`` (the default, above) or ``"seat"``, a seat that opens fully once
    :math:`p_A - p_B` exceeds ``p_crack`` (:func:`hydroservo.laws.pressure_valve.seat_opening`, ``dp_open``
    unused): Hopsan's HydraulicCheckValve ([Hopsan2026] Hydraulic/Restrictors/HydraulicCheckValve.hpp), whose
    flow is :math:`K_s\sqrt{p_A - p_B}` while :math:`p_A > p_B`.
    """

    PARAMETERS = {
        "d": Param(5e-3, "m", "equivalent bore when fully open", min=0.0, min_inclusive=False),
        "Cd": Param(DISCHARGE_COEFFICIENT, "", "discharge coefficient", min=0.0, max=1.0, min_inclusive=False),
        "p_crack": Param(1e5, "Pa", "cracking pressure (A over B)", min=0.0),
        "dp_open": Param(2e5, "Pa", "pressure rise over cracking to full opening", min=0.0, min_inclusive=False),
        "G_leak": Param(0.0, "m^3/s/Pa", "leakage conductance of the closed seat", min=0.0),
        **FLUID_PARAMETERS,
    }
    OPTIONS = {
        "opening": Option("ramp", ("ramp", "seat"), "opening from p_crack over dp_open, or fully at p_crack (Hopsan)"),
    }
    INPUTS = dict(TWO_PORT_PRESSURES)
    OUTPUTS = {
        "Q": Output("m^3/s", "flow from A to B"),
        "s": Output("", "opening fraction (0 closed, 1 fully open)"),
    }
    HYDRAULIC = dict(TWO_PORT_HYDRAULIC)

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        dp = u["pA"] - u["pB"]
        if self.option("opening") == "seat":
            s = seat_opening(dp, p["p_crack"])
        else:
            s = opening_fraction(dp, p["p_crack"], p["dp_open"])
        p_tr = transition_pressure(p["d"], p["rho"], p["nu"], p["lambda_crit"])
        area = s * np.pi * p["d"] ** 2 / 4.0
        return {"Q": orifice_flow(area, dp, p["rho"], p["Cd"], p_tr) + p["G_leak"] * dp, "s": s}
