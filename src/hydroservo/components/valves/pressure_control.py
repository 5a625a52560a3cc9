"""Pressure-control valves: relief, pressure-reducing and counterbalance valves, each a spring-loaded spool with a lag."""

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
    spool_mass_acceleration,
    valve_hysteresis,
)

__all__ = ["ReliefValve", "PressureReducingValve", "CounterbalanceValve", "PressureCompensatorValve"]

#: The time constant with which a spool with mass (option ``spool = "mass"``) settles on a bound, as a fraction of
#: its ``tau_m``: its velocity is relaxed to the held rate within it. Hopsan's stop is inelastic (its clamped
#: transfer function); with STOP_RELAXATION's 1e-3 the spool left its stop some 1e-5 s late on
#: tests/unit/io/hopsan_circuits/relief2_valve_g.hmf (0.34 % of its position's range), with 1e-5 within Hopsan's
#: own uncertainty (0.1 %).
MASS_STOP_RELAXATION = 1e-5

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
    "tau_m": Param(1e-4, "s", "mechanical time constant of the spool, mass over damping (spool = mass)", min=0.0,
                   min_inclusive=False),
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
    HydraulicPressureReducingValveG.hpp; there ``tau`` is :math:`B_v/k_s`); ``mass``, that spool with mass
    :math:`M_v`: its velocity relaxes to the massless spool's rate with the time constant ``tau_m``
    :math:`= M_v/B_v`, :math:`\tau_m\ddot K = \dot K_{balance} - \dot K`
    (:func:`~hydroservo.laws.pressure_valve.spool_mass_acceleration`; [Hopsan2026]
    Hydraulic/Special/HydraulicPressureRelief2ValveG.hpp), a second state ``dK``; at a bound the spool stops
    (inelastic, as Hopsan's clamped transfer function): its position is held there (``limited_rate``) and its
    velocity relaxed to the held rate within ``MASS_STOP_RELAXATION`` ``tau_m``; output ``ds`` the opening's rate.
    """

    OPTIONS = {
        "spool": Option(
            "lag", ("lag", "balance", "mass"),
            "the spool: a lag of constant tau, or the force balance of a damped spool, without or with mass",
        )
    }
    STATES = {"K": State("m^3/s/Pa^0.5", "flow coefficient of the spool", nominal=1e-6)}
    INPUTS = dict(TWO_PORT_PRESSURES)
    OUTPUTS = {
        "Q": Output("m^3/s", "flow from A to B"),
        "s": Output("", "opening (0 closed, 1 fully open)"),
    }
    HYDRAULIC = dict(TWO_PORT_HYDRAULIC)

    #: the pilot ports a value of option ``pilot`` adds (they take no flow), if the valve has that option
    PILOT_PORTS: dict[str, tuple[str, ...]] = {}

    def over(self, u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        raise NotImplementedError

    def _pilot_ports(self) -> tuple[str, ...]:
        return self.PILOT_PORTS.get(self.option("pilot"), ()) if "pilot" in self.OPTIONS else ()

    def options_changed(self) -> None:
        """Option ``pilot`` from ports: their pressures inputs, their flows (none) outputs; option ``spool = "mass"``:
        the rate of K a state, the opening's rate an output."""
        cls = type(self)
        self.INPUTS, self.OUTPUTS = dict(cls.INPUTS), dict(cls.OUTPUTS)  # type: ignore[misc]
        self.HYDRAULIC, self.STATES = dict(cls.HYDRAULIC), dict(cls.STATES)  # type: ignore[misc]
        if self.option("spool") == "mass":
            self.STATES["dK"] = State("m^3/s/Pa^0.5/s", "rate of the spool's flow coefficient", nominal=1e-4)
            self.OUTPUTS["ds"] = Output("1/s", "rate of the opening (0 at a bound)")
        for port in self._pilot_ports():
            self.INPUTS[f"p{port}"] = Port("Pa", f"pilot pressure at {port}")
            self.OUTPUTS[f"Q{port}"] = Output("m^3/s", f"pilot flow at {port} (none)")
            self.HYDRAULIC[port] = Hydraulic(f"p{port}", f"Q{port}", f"pilot port {port}", into=True)

    def check(self) -> None:
        super().check()
        if self.option("spool") != "lag" and self.values["p_h"] > 0.0:
            raise ParameterError(
                f"{self.name}.p_h = {self.values['p_h']:g} Pa: a hysteresis needs spool = \"lag\"; "
                f"expected 0 with spool = \"{self.option('spool')}\""
            )

    def _K(self, x: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        return bk.fmin(bk.fmax(x["K"], 0.0), p["q_nom"] / bk.sqrt(p["p_nom"]))

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        K = self._K(x, p)
        out = {
            "Q": turbulent_flow(K, u["pA"] - u["pB"], p["p_tr"]),
            "s": K * bk.sqrt(p["p_nom"]) / p["q_nom"],
            **{f"Q{port}": 0.0 for port in self._pilot_ports()},
        }
        if self.option("spool") == "mass":
            out["ds"] = self._mass_rate(x, p) * bk.sqrt(p["p_nom"]) / p["q_nom"]
        return out

    def _mass_rate(self, x: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        """Option spool = mass: the rate of K, its velocity state held at a bound."""
        return limited_rate(x["K"], x["dK"], p["q_nom"] / bk.sqrt(p["p_nom"]), MASS_STOP_RELAXATION * p["tau_m"])

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        dp, K_max = u["pA"] - u["pB"], p["q_nom"] / bk.sqrt(p["p_nom"])
        if self.option("spool") == "mass":
            rate = spool_balance_rate(self.over(u, p), dp, x["K"], p["k_cs"], p["k_cf"], p["p_nom"], p["tau"])
            held = self._mass_rate(x, p)
            relax = MASS_STOP_RELAXATION * p["tau_m"]
            return {"K": held, "dK": spool_mass_acceleration(rate, x["dK"], p["tau_m"]) - (x["dK"] - held) / relax}
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
    (Hopsan's HydraulicPressureReliefValveG, with ``spool = "balance"``);
    ``ports``, piloted from elsewhere: the pilot port X against the spring
    chamber's port Y, :math:`\Delta p_{over} = p_X - p_Y - p_{crack}` (a
    sequence or unloading valve; Hopsan's HydraulicPressureControlValveG, with
    ``spool = "balance"``). The pilot ports take no flow.
    """

    OPTIONS = {
        **_PressureControl.OPTIONS,
        "pilot": Option(
            "inlet", ("inlet", "drop", "ports"),
            "the setting against the inlet's pressure, the drop A-B, or the drop from pilot port X to port Y",
        ),
    }
    PILOT_PORTS = {"ports": ("X", "Y")}

    PARAMETERS = {
        "p_crack": Param(200e5, "Pa", "cracking pressure (setting)"),
        **SPOOL_PARAMETERS,
    }
    OUTPUTS = {**_PressureControl.OUTPUTS, "p_crack": Output("Pa", "cracking pressure (setting)")}
    #: the setting bounds a circuit fed by a flow source (plausibility: a flow source's line is not flagged at the
    #: valve's override); with pumps and pressure sources their ratings are the ceiling, whatever the setting
    LIMITS = {"p_crack": Limit("relief")}

    def options_changed(self) -> None:
        """Its setting bounds the circuit only against its inlet's pressure: set on a drop (``drop``, ``ports``) it
        bounds no pressure of the circuit."""
        super().options_changed()
        self.LIMITS = dict(type(self).LIMITS) if self.option("pilot") == "inlet" else {}  # type: ignore[misc]

    def over(self, u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        if self.option("pilot") == "drop":
            return u["pA"] - u["pB"] - p["p_crack"]
        if self.option("pilot") == "ports":
            return u["pX"] - u["pY"] - p["p_crack"]
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

    Option ``pilot``: ``outlet`` (default), the spring chamber at the
    atmosphere; ``port``, the spring chamber at the pilot port X, which takes
    no flow: :math:`\Delta p_{over} = p_{set} + p_X - p_B`, the valve holds B
    at ``p_set`` above X (a pressure compensator keeping the drop across a
    metering orifice from B to X; Hopsan's HydraulicPressureCompensatingValveG,
    with ``spool = "balance"``).
    """

    OPTIONS = {
        **_PressureControl.OPTIONS,
        "pilot": Option(
            "outlet", ("outlet", "port"), "the outlet against the setting, or against the setting above pilot port X"
        ),
    }
    PARAMETERS = {
        "p_set": Param(50e5, "Pa", "reduced pressure setting (option pilot = port: above the pressure at X)"),
        **SPOOL_PARAMETERS,
    }
    PILOT_PORTS = {"port": ("X",)}

    def over(self, u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        if self.option("pilot") == "port":
            return p["p_set"] + u["pX"] - u["pB"]
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
class PressureCompensatorValve(_PressureControl):
    r"""Pressure compensator from A to B: open at rest, closing as the pilot X passes the pilot Y by ``p_ref``.

    The spring-loaded spool of :class:`_PressureControl`, normally open: the
    pilot X pushes it closed against its spring and the pilot Y,
    :math:`\Delta p_{over} = p_X - p_Y - p_{ref}`, and its state :math:`K_c`
    is how far that has closed it, following
    :func:`~hydroservo.laws.pressure_valve.pressure_valve_coefficient` of
    :math:`\Delta p_{over}` as a relief valve's opening does (its lag ``tau``,
    its hysteresis ``p_h``, its bounds :math:`[0, K_{max}]`); the valve passes
    :math:`Q = (K_{max} - K_c)\sqrt{\Delta p}`, :math:`K_{max} = q_{nom}/\sqrt{p_{nom}}`.
    It holds :math:`p_X - p_Y` near ``p_ref`` by throttling (X upstream of
    the metering orifice it guards, Y downstream: a load-sensing compensator).
    The pilots take no flow. Hopsan's HydraulicPressureCompensatingValve
    ([Hopsan2026] Hydraulic/Valves/PressureControlValves/HydraulicPressureCompensatingValve.hpp:
    x_s = X_0max − (p_open − p_ref − p_close)/b_1, filtered and with its
    hysteresis) imports as this valve, its P_OPEN the pilot X, its P_CLOSE Y.
    """

    PARAMETERS = {
        "p_ref": Param(20e5, "Pa", "pilot difference p_X - p_Y at which the valve starts to close"),
        **SPOOL_PARAMETERS,
    }
    STATES = {"K": State("m^3/s/Pa^0.5", "flow coefficient by which the pilot has closed the valve", nominal=1e-6)}
    INPUTS = {
        **TWO_PORT_PRESSURES,
        "pX": Port("Pa", "pilot pressure that closes the valve"),
        "pY": Port("Pa", "pilot pressure that holds it open, with the spring"),
    }
    OUTPUTS = {
        **_PressureControl.OUTPUTS,
        "QX": Output("m^3/s", "pilot flow at X (none)"),
        "QY": Output("m^3/s", "pilot flow at Y (none)"),
    }
    HYDRAULIC = {
        **TWO_PORT_HYDRAULIC,
        "X": Hydraulic("pX", "QX", "closing pilot port", into=True),
        "Y": Hydraulic("pY", "QY", "opening pilot port (the spring's side)", into=True),
    }

    def over(self, u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        return u["pX"] - u["pY"] - p["p_ref"]

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        K_max = p["q_nom"] / bk.sqrt(p["p_nom"])
        K = K_max - self._K(x, p)
        return {"Q": turbulent_flow(K, u["pA"] - u["pB"], p["p_tr"]), "s": K / K_max, "QX": 0.0, "QY": 0.0}
