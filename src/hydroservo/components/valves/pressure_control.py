"""Pressure-control valves: relief, pressure-reducing, counterbalance and piloted valves, each a spring-loaded spool with a lag."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo import backend as bk
from hydroservo.components.base import Component, Hydraulic, Limit, Option, Output, Param, Port, State, register
from hydroservo.components.valves.ports import TWO_PORT_HYDRAULIC, TWO_PORT_PRESSURES
from hydroservo.errors import ParameterError
from hydroservo.laws.orifice import turbulent_flow
from hydroservo.laws.pressure_valve import (
    STOP_RELAXATION,
    hysteresis_half_width,
    limited_lag_rate,
    limited_rate,
    opening_fraction,
    pressure_valve_coefficient,
    spool_balance_rate,
    valve_hysteresis,
)

__all__ = ["ReliefValve", "PressureReducingValve", "CounterbalanceValve", "PilotedValve"]

#: The spool's characteristics, shared by every pressure-control valve ([Hopsan2026] defaults).
SPOOL_PARAMETERS = {
    "k_cs": Param(
        1e-8, "m^3/s/Pa", "pressure-flow gradient of the spring at the nominal drop (catalogue p-Q slope)",
        min=0.0, min_inclusive=False,
    ),
    "k_cf": Param(
        1e-8, "m^3/s/Pa", "steady-state characteristic of the flow forces", min=0.0, min_inclusive=False
    ),
    "q_nom": Param(1e-3, "m^3/s", "flow when fully open at the nominal drop", min=0.0, min_inclusive=False),
    "p_nom": Param(7e6, "Pa", "nominal pressure drop of the characteristics", min=0.0, min_inclusive=False),
    "tau": Param(0.01, "s", "time constant of the spool", min=0.0, min_inclusive=False),
    "p_tr": Param(
        1e4, "Pa", "drop below which the flow is taken as laminar (regularisation at null)", min=0.0, min_inclusive=False
    ),
    "p_h": Param(0.0, "Pa", "width of the spool's hysteresis in the pilot pressure (0: none)", min=0.0),
}


class _PressureControl(Component):
    r"""A spring-loaded spool whose flow coefficient :math:`K` lags its static value with time constant ``tau``:

    .. math:: \tau\dot K = K_s - K, \quad K \in [0, q_{nom}/\sqrt{p_{nom}}], \qquad Q = K\sqrt{\Delta p}

    (:func:`hydroservo.laws.pressure_valve.pressure_valve_coefficient`; the state
    stops at its bounds, no wind-up: :func:`~hydroservo.laws.pressure_valve.limited_lag_rate`). Subclasses give the pressure by which the
    pilot exceeds the setting.

    Option ``spool``: ``lag`` (default), the lag above with a constant
    ``tau`` (Hopsan's HydraulicPressureReliefValve and
    HydraulicPressureReducingValve); ``balance``, the force balance of a
    damped, massless spool, :math:`C_s\tau\dot K = \Delta p_{over} - (C_s + C_f\Delta p)K`
    (:func:`~hydroservo.laws.pressure_valve.spool_balance_rate`): the same
    static opening, reached with the time constant
    :math:`\tau C_s/(C_s + C_f\Delta p)` that the flow forces shorten
    ([Hopsan2026] Hydraulic/Special/HydraulicPressureReliefValveG.hpp,
    HydraulicPressureReducingValveG.hpp; there ``tau`` is :math:`B_v/k_s`).
    """

    OPTIONS = {
        "spool": Option(
            "lag", ("lag", "balance"), "the spool: a lag of constant tau, or the force balance of a damped spool"
        )
    }
    STATES = {"K": State("m^3/s/Pa^0.5", "flow coefficient of the spool", nominal=1e-6)}
    INPUTS = dict(TWO_PORT_PRESSURES)
    OUTPUTS = {
        "Q": Output("m^3/s", "flow from A to B"),
        "s": Output("", "opening (0 closed, 1 fully open)"),
    }
    HYDRAULIC = dict(TWO_PORT_HYDRAULIC)

    def over(self, u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        raise NotImplementedError

    def check(self) -> None:
        super().check()
        if self.option("spool") == "balance" and self.values["p_h"] > 0.0:
            raise ParameterError(
                f"{self.name}.p_h = {self.values['p_h']:g} Pa: a hysteresis needs spool = \"lag\"; "
                "expected 0 with spool = \"balance\""
            )

    def _K(self, x: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        return bk.fmin(bk.fmax(x["K"], 0.0), p["q_nom"] / bk.sqrt(p["p_nom"]))

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        K = self._K(x, p)
        return {"Q": turbulent_flow(K, u["pA"] - u["pB"], p["p_tr"]), "s": K * bk.sqrt(p["p_nom"]) / p["q_nom"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        dp, K_max = u["pA"] - u["pB"], p["q_nom"] / bk.sqrt(p["p_nom"])
        if self.option("spool") == "balance":
            rate = spool_balance_rate(self.over(u, p), dp, x["K"], p["k_cs"], p["k_cf"], p["p_nom"], p["tau"])
            # the spool's own time constant, tau C_s/(C_s + C_f dp), sets the approach to a bound
            tau = p["tau"] / (1.0 + bk.fmax(dp, 0.0) * p["k_cs"] / (p["k_cf"] * p["p_nom"]))
            return {"K": limited_rate(x["K"], rate, K_max, STOP_RELAXATION * tau)}
        target = pressure_valve_coefficient(self.over(u, p), dp, p["k_cs"], p["k_cf"], p["p_nom"])
        if self.values["p_h"] > 0.0:
            w = hysteresis_half_width(p["p_h"], dp, p["k_cs"], p["k_cf"], p["p_nom"])
            target = valve_hysteresis(target, x["K"], w)
        return {"K": limited_lag_rate(x["K"], target, p["tau"], K_max)}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """Cracking: the pilot pressure passing the setting, where the static opening leaves zero; with a
        hysteresis, the static opening leaving the band around the spool (where the spool starts or stops)."""
        events = {"cracking": (self.over(u, p), 1e5)}
        if self.values["p_h"] > 0.0 and self.option("spool") == "lag":
            dp = u["pA"] - u["pB"]
            target = pressure_valve_coefficient(self.over(u, p), dp, p["k_cs"], p["k_cf"], p["p_nom"])
            w = hysteresis_half_width(p["p_h"], dp, p["k_cs"], p["k_cf"], p["p_nom"])
            K_max = float(self.values["q_nom"]) / float(self.values["p_nom"]) ** 0.5
            events["band_up"] = (target - x["K"] - w, K_max)
            events["band_down"] = (target - x["K"] + w, K_max)
        return events


@register
class ReliefValve(_PressureControl):
    r"""Pressure-relief valve from A (the protected line) to B (tank): opens as :math:`p_A` passes ``p_crack``.

    The spring-loaded spool of :class:`_PressureControl` piloted by the inlet,
    :math:`\Delta p_{over} = p_A - p_{crack}`: closed below the cracking
    pressure, then passing :math:`Q \approx k_{cs}(p_A - p_{crack})\sqrt{\Delta p/p_{nom}}`,
    fully open at ``q_nom`` (at ``p_nom``); the spool follows with time
    constant ``tau``. This is the law of Hopsan's HydraulicPressureReliefValve
    ([Hopsan2026]) in the limit of a small time step, its pressure
    hysteresis ``p_h`` included (0 by default, Hopsan's is 5 bar); the turbulent law is regularised below ``p_tr`` as
    every orifice of the package is (:mod:`hydroservo.laws.orifice`).

    Option ``pilot``: ``inlet`` (default), the spring chamber at the
    atmosphere, :math:`\Delta p_{over} = p_A - p_{crack}`; ``drop``, the
    spring chamber drained to the outlet, :math:`\Delta p_{over} = p_A - p_B - p_{crack}`
    (Hopsan's HydraulicPressureReliefValveG, with ``spool = "balance"``).
    """

    OPTIONS = {
        **_PressureControl.OPTIONS,
        "pilot": Option("inlet", ("inlet", "drop"), "the setting against the inlet's pressure, or against the drop A-B"),
    }

    PARAMETERS = {
        "p_crack": Param(200e5, "Pa", "cracking pressure (setting)"),
        **SPOOL_PARAMETERS,
    }
    OUTPUTS = {**_PressureControl.OUTPUTS, "p_crack": Output("Pa", "cracking pressure (setting)")}
    #: the setting bounds a circuit fed by a flow source (plausibility: a flow source's line is not flagged at the
    #: valve's override); with pumps and pressure sources their ratings are the ceiling, whatever the setting
    LIMITS = {"p_crack": Limit("relief")}

    def over(self, u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        if self.option("pilot") == "drop":
            return u["pA"] - u["pB"] - p["p_crack"]
        return u["pA"] - p["p_crack"]

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {**super().output_equations(t, x, u, p), "p_crack": p["p_crack"]}


@register
class PressureReducingValve(_PressureControl):
    r"""Pressure-reducing valve from A (supply) to B (the reduced line): closes as :math:`p_B` reaches ``p_set``.

    The spool of :class:`_PressureControl` piloted by the outlet,
    :math:`\Delta p_{over} = p_{set} - p_B`: fully open while the outlet is well
    below the setting, throttling as it approaches it, closed above it. The
    law of Hopsan's HydraulicPressureReducingValve ([Hopsan2026]) in the limit
    of a small time step, hysteresis ``p_h`` included; with ``spool = "balance"``,
    that of its HydraulicPressureReducingValveG.
    """

    PARAMETERS = {
        "p_set": Param(50e5, "Pa", "reduced pressure setting"),
        **SPOOL_PARAMETERS,
    }
    def over(self, u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        return p["p_set"] - u["pB"]


@register
class CounterbalanceValve(_PressureControl):
    r"""Counterbalance (over-centre) valve: holds a load at A until :math:`p_A + r_p\,p_X` passes ``p_crack``; free flow B to A.

    Metered flow A to B is the spool of :class:`_PressureControl` piloted by
    the load pressure and, through the pilot ratio ``r_p``, by the pilot port
    X (the opposite line of the actuator):
    :math:`\Delta p_{over} = p_A + r_p p_X - p_{crack}`. An integral check
    valve lets oil flow freely from B to A (cracking pressure
    ``p_check``, the opening ramp of :class:`~hydroservo.components.CheckValve`,
    full bore ``K_check`` as a turbulent coefficient). The pilot takes no flow.
    The pilot-assisted opening is the usual counterbalance characteristic
    (pilot ratios 3:1 to 10:1 in catalogues); the metering law is
    :class:`ReliefValve`'s.

    Option ``pilot``: ``inlet`` (default), the spring chamber at the
    atmosphere, as above; ``drop``, drained to B:
    :math:`\Delta p_{over} = p_A - p_B + r_p p_X - p_{crack}` (Hopsan's
    HydraulicCounterBalanceValveG, [Hopsan2026] Hydraulic/Special/
    HydraulicCounterBalanceValveG.hpp, with ``spool = "balance"``). Option
    ``check``: ``integral`` (default), the check valve above; ``none``, the
    spool alone, which meters either way once open and holds both ways
    closed (Hopsan's HydraulicOverCenterValve, [Hopsan2026] Hydraulic/Valves/
    PressureControlValves/HydraulicOverCenterValve.hpp, and its
    HydraulicCounterBalanceValveG have none).
    """

    OPTIONS = {
        **_PressureControl.OPTIONS,
        "pilot": Option("inlet", ("inlet", "drop"), "the setting against the load's pressure, or against the drop A-B"),
        "check": Option("integral", ("integral", "none"), "an integral check valve B to A, or none"),
    }

    PARAMETERS = {
        "p_crack": Param(250e5, "Pa", "setting: load pressure that opens the valve without pilot"),
        "r_p": Param(4.0, "", "pilot ratio (pilot area over seat area)", min=0.0),
        "p_check": Param(2e5, "Pa", "cracking pressure of the integral check valve (B to A)", min=0.0),
        "dp_check": Param(2e5, "Pa", "pressure rise to open the check valve fully", min=0.0, min_inclusive=False),
        "K_check": Param(
            1e-6, "m^3/s/Pa^0.5", "turbulent coefficient of the open check valve", min=0.0, min_inclusive=False
        ),
        **SPOOL_PARAMETERS,
    }
    INPUTS = {**TWO_PORT_PRESSURES, "pX": Port("Pa", "pilot pressure", default=0.0)}
    OUTPUTS = {
        **_PressureControl.OUTPUTS,
        "Q": Output("m^3/s", "flow from A to B (metered A to B, free B to A)"),
        "QX": Output("m^3/s", "pilot flow (none)"),
    }
    HYDRAULIC = {**TWO_PORT_HYDRAULIC, "X": Hydraulic("pX", "QX", "pilot port", into=True)}

    def over(self, u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        load = u["pA"] - u["pB"] if self.option("pilot") == "drop" else u["pA"]
        return load + p["r_p"] * u["pX"] - p["p_crack"]

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        out = super().output_equations(t, x, u, p)
        out["QX"] = 0.0
        if self.option("check") == "none":
            return out
        dp = u["pB"] - u["pA"]
        check = opening_fraction(dp, p["p_check"], p["dp_check"]) * p["K_check"]
        out["Q"] = out["Q"] - turbulent_flow(check, dp, p["p_tr"])
        return out


@register
class PilotedValve(_PressureControl):
    r"""A valve from A to B opened by a pilot pressure at X against its setting and the pressure at Y.

    The spring-loaded spool of :class:`_PressureControl` piloted by two
    external lines: X pushes it open, Y (the spring chamber) and the spring's
    setting ``p_ref`` push it closed,
    :math:`\Delta p_{over} = p_X - p_Y - p_{ref}`; neither pilot takes flow.
    A sequence or unloading valve with external pilot and drain; with X on A
    and Y on B it is a relief valve set on the drop. The law of Hopsan's
    HydraulicPressureControlledValve ([Hopsan2026]
    Hydraulic/Valves/PressureControlValves/HydraulicPressureControlledValve.hpp,
    ports P_OPEN and P_CLOSE) in the limit of a small time step, its
    hysteresis ``p_h`` included. Hopsan's spring-and-flow-force term
    :math:`C_s + C_f(p_1 - p_2)` is not floored at a reverse drop there (it
    vanishes at :math:`p_2 - p_1 = C_s/C_f`, 7 MPa with its defaults); here it
    is, as for every pressure-control valve of the package.
    """

    PARAMETERS = {
        "p_ref": Param(20e5, "Pa", "pilot pressure over the spring chamber's that opens the valve (setting)"),
        **SPOOL_PARAMETERS,
    }
    INPUTS = {
        **TWO_PORT_PRESSURES,
        "pX": Port("Pa", "opening pilot pressure", default=0.0),
        "pY": Port("Pa", "closing pilot pressure (spring chamber)", default=0.0),
    }
    OUTPUTS = {
        **_PressureControl.OUTPUTS,
        "QX": Output("m^3/s", "flow into the opening pilot (none)"),
        "QY": Output("m^3/s", "flow into the closing pilot (none)"),
    }
    HYDRAULIC = {
        **TWO_PORT_HYDRAULIC,
        "X": Hydraulic("pX", "QX", "opening pilot port", into=True),
        "Y": Hydraulic("pY", "QY", "closing pilot port (spring chamber)", into=True),
    }

    def over(self, u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        return u["pX"] - u["pY"] - p["p_ref"]

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {**super().output_equations(t, x, u, p), "QX": 0.0, "QY": 0.0}
