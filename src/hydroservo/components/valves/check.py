"""Check valves: flow from A to B once the pressure difference (or a pilot) passes the cracking pressure."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.components.base import Component, Hydraulic, Option, Output, Param, Port, register
from hydroservo.components.valves.ports import FLUID_PARAMETERS, TWO_PORT_HYDRAULIC, TWO_PORT_PRESSURES
from hydroservo.laws.orifice import DISCHARGE_COEFFICIENT, orifice_flow, transition_pressure
from hydroservo.laws.pressure_valve import opening_fraction, seat_opening

__all__ = ["CheckValve", "PilotCheckValve"]


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

    def opening_pressure(self, u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        """The pressure that opens the valve against ``p_crack``: the drop A to B."""
        return u["pA"] - u["pB"]

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        dp = u["pA"] - u["pB"]
        if self.option("opening") == "seat":
            s = seat_opening(self.opening_pressure(u, p), p["p_crack"])
        else:
            s = opening_fraction(self.opening_pressure(u, p), p["p_crack"], p["dp_open"])
        p_tr = transition_pressure(p["d"], p["rho"], p["nu"], p["lambda_crit"])
        area = s * np.pi * p["d"] ** 2 / 4.0
        if self.option("pilot") == "open":  # piloted open: the bore d_open both ways
            opened = u["open"] > 0.5
            s = bk.if_else(opened, 1.0, s)
            area = bk.if_else(opened, np.pi * p["d_open"] ** 2 / 4.0, area)
            p_tr = bk.if_else(opened, transition_pressure(p["d_open"], p["rho"], p["nu"], p["lambda_crit"]), p_tr)
        return {"Q": orifice_flow(area, dp, p["rho"], p["Cd"], p_tr) + p["G_leak"] * dp, "s": s}

    def jumps(self) -> bool:
        """Whether the flow jumps where the valve cracks: a seat that opens fully at a cracking pressure not 0
        (at 0 the flow vanishes as the square root of the drop there)."""
        return self.option("opening") == "seat" and float(self.values["p_crack"]) != 0.0

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """Cracking, where the flow of a seat jumps (:meth:`jumps`); the pilot crossing 0.5 (option pilot =
        open), where the valve switches between checking and open."""
        events: dict[str, tuple[Any, float]] = {}
        if self.jumps():
            events["cracking"] = (self.opening_pressure(u, p) - p["p_crack"], 1e5)
        if self.option("pilot") == "open":
            events["pilot"] = (u["open"] - 0.5, 1.0)
        return events


@register
class PilotCheckValve(CheckValve):
    r"""Pilot-operated check valve: a :class:`CheckValve` that a pilot pressure at X also opens, then both ways.

    The poppet opens once :math:`p_A - p_B + r_p\,p_X` passes ``p_crack``
    (the pilot piston, ``r_p`` times the seat's area, pushing it off its seat):
    oil flows freely from A to B, and from B to A while the pilot holds it
    open (the valve that holds a load at B until the pilot releases it). The
    pilot takes no flow; the flow law is :class:`CheckValve`'s, signed with
    the drop. ``p_crack`` may be negative: a valve held open at rest until B
    exceeds A by :math:`-p_{crack}`. A negative ``r_p`` is a pilot that holds
    the seat closed (Hopsan's HydraulicPilotClosableCheckValve, open while
    :math:`p_1 > p_2 + p_{pilot}` in absolute pressures: ``r_p`` = -1,
    ``p_crack`` = :math:`p_{atm}` in gauge). With option ``opening = "seat"`` this is
    Hopsan's HydraulicPilotControlledCheckValve ([Hopsan2026]
    Hydraulic/Restrictors/HydraulicPilotControlledCheckValve.hpp), whose
    condition :math:`p_1 + \varphi p_{pilot} - p_2 > p_f` reads absolute
    pressures: in gauge pressures its cracking pressure is
    :math:`p_f - \varphi\,p_{atm}`.
    """

    PARAMETERS = {
        **CheckValve.PARAMETERS,
        "p_crack": Param(1e5, "Pa", "cracking pressure (A over B plus r_p times the pilot)"),
        "r_p": Param(3.5, "", "pilot ratio (pilot piston area over seat area; negative: a pilot that closes it)"),
    }
    INPUTS = {**CheckValve.INPUTS, "pX": Port("Pa", "pilot pressure", default=0.0)}
    OUTPUTS = {**CheckValve.OUTPUTS, "QX": Output("m^3/s", "pilot flow (none)")}
    HYDRAULIC = {**TWO_PORT_HYDRAULIC, "X": Hydraulic("pX", "QX", "pilot port", into=True)}

    def opening_pressure(self, u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        """The drop A to B plus the pilot's push, ``r_p`` times its pressure."""
        return u["pA"] - u["pB"] + p["r_p"] * u["pX"]

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {**super().output_equations(t, x, u, p), "QX": 0.0}

    def jumps(self) -> bool:
        """A seat's flow jumps where a pilot opens it, whatever the cracking pressure (the drop is not 0 there)."""
        return self.option("opening") == "seat"
