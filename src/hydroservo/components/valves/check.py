"""Check valves: flow from A to B once the pressure difference passes the cracking pressure."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.components.base import Component, Option, Output, Param, Port, register
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

    Option ``pilot``: ``"none"`` (the default), a check valve; ``"open"``, a check valve that a pilot (a solenoid, a
    spool) opens both ways: while the input ``open`` exceeds 0.5 the flow is the orifice law through the bore
    ``d_open`` in either direction, otherwise the valve checks as above (Hopsan's
    Hydraulic22DirectionalCheckValve, [Hopsan2026] Hydraulic/Valves/DirectionalValves/
    Hydraulic22DirectionalCheckValve.hpp, whose filtered spool position is ``open``). The switch is an event.
    """

    PARAMETERS = {
        "d": Param(5e-3, "m", "equivalent bore when fully open", min=0.0, min_inclusive=False),
        "Cd": Param(DISCHARGE_COEFFICIENT, "", "discharge coefficient", min=0.0, max=1.0, min_inclusive=False),
        "p_crack": Param(1e5, "Pa", "cracking pressure (A over B)", min=0.0),
        "dp_open": Param(2e5, "Pa", "pressure rise over cracking to full opening", min=0.0, min_inclusive=False),
        "G_leak": Param(0.0, "m^3/s/Pa", "leakage conductance of the closed seat", min=0.0),
        "d_open": Param(5e-3, "m", "equivalent bore when piloted open (option pilot = open)", min=0.0,
                        min_inclusive=False),
        **FLUID_PARAMETERS,
    }
    OPTIONS = {
        "opening": Option("ramp", ("ramp", "seat"), "opening from p_crack over dp_open, or fully at p_crack (Hopsan)"),
        "pilot": Option("none", ("none", "open"), "a check valve, or one a pilot opens both ways while open > 0.5"),
    }
    INPUTS = {
        **TWO_PORT_PRESSURES,
        "open": Port("", "pilot: the valve open both ways above 0.5 (option pilot = open)", default=0.0),
    }
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
        if self.option("pilot") == "open":  # piloted open: the bore d_open both ways
            opened = u["open"] > 0.5
            s = bk.if_else(opened, 1.0, s)
            area = bk.if_else(opened, np.pi * p["d_open"] ** 2 / 4.0, area)
            p_tr = bk.if_else(opened, transition_pressure(p["d_open"], p["rho"], p["nu"], p["lambda_crit"]), p_tr)
        return {"Q": orifice_flow(area, dp, p["rho"], p["Cd"], p_tr) + p["G_leak"] * dp, "s": s}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """The pilot crossing 0.5 (option pilot = open): the valve switches between checking and open."""
        return {"pilot": (u["open"] - 0.5, 1.0)} if self.option("pilot") == "open" else {}
