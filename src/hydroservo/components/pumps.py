"""Pumps and motors: displacement machines with leakage; a pressure-compensated pump; a motor driving an inertia; a
machine whose shaft what it is joined to turns; centrifugal pumps, at a speed or turned through their shaft."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo import backend as bk
from hydroservo.components.base import (
    Algebraic,
    Component,
    Hydraulic,
    Limit,
    Mechanical,
    Option,
    Output,
    Param,
    Port,
    State,
    register,
)
from hydroservo.laws.centrifugal import (
    hydraulic_power,
    impeller_flow,
    loss_transition_pressure,
    shaft_torque,
    theoretical_pressure,
)
from hydroservo.laws.displacement import (
    compensator_displacement,
    displaced_flow,
    floored_port_flow,
    leakage_flow,
    motor_torque,
    regulator_rates,
)
from hydroservo.laws.orifice import smooth_abs
from hydroservo.laws.pressure_valve import STOP_RELAXATION, limited_rate
from hydroservo.units import VACUUM

#: The lags by which LoadSensingPump's ``regulator = "g"`` takes the rates of its error and of the lead, as a
#: fraction of ``tau_v``: 1e-2 delays its regulator by about 1.5 ms against Hopsan's
#: (tests/unit/io/hopsan_circuits/pressure_controlled_pump_g.hmf: 1.1 % of the displacement flow's range); 1e-3
#: stalls the solver once the displacement reaches its minimum.
G_LAG = 1e-2

__all__ = ["Pump", "VariablePump", "LoadSensingPump", "Motor", "Machine", "CentrifugalPump", "CentrifugalPumpInertia"]

_PUMP_INPUTS = {
    "pS": Port("Pa", "pressure at the suction port S", default=0.0),
    "pP": Port("Pa", "pressure at the pressure port P"),
    "omega_in": Port("rad/s", "shaft speed (option speed = input; negative turns it backwards)", default=0.0),
}
_PUMP_HYDRAULIC = {
    "S": Hydraulic("pS", "QS", "suction port", into=True),
    "P": Hydraulic("pP", "QP", "pressure port", into=False),
}


@register
class Pump(Component):
    r"""Fixed-displacement pump at constant speed, with internal leakage.

    .. math:: Q_P = \varepsilon D\,\omega - C_{leak}\,(p_P - p_S), \qquad Q_S = Q_P

    (:mod:`hydroservo.laws.displacement`, [Merritt1967]). ``D`` is per radian;
    give a catalogue's displacement with its unit (``"25 cm^3/rev"``) and the
    speed as ``"1500 rpm"``. The drive holds its speed whatever the load (an
    electric motor far from stall). The input ``eps`` (default 1) scales the
    displacement: a variable pump driven by a signal, without a controller
    (Hopsan's HydraulicVariableDisplacementPump, [Hopsan2026]). Outputs: the
    delivered flow ``QP`` and the shaft torque the pump takes.

    Option ``inlet``: ``free`` (default) delivers the flow above whatever the
    pressure at the inlet, so a pump drawing from a closed volume empties it
    (a volume or cylinder with a cavity floor then holds a cavity); ``floor``
    draws no port below ``p_floor``: the flow falls to what flows into the
    inlet, the inlet held within ``p_reg`` of the floor
    (:func:`~hydroservo.laws.displacement.floored_port_flow`), as Hopsan's pumps
    clamp their flow ([Hopsan2026]).

    Option ``speed``: ``constant`` (default), the drive turns the shaft at
    ``omega``; ``input``, at the input ``omega_in`` (a drive whose speed a
    signal sets, as Hopsan's HydraulicFixedDisplacementPump takes its ``n_p``,
    [Hopsan2026] Hydraulic/Pumps&Motors/HydraulicFixedDisplacementPump.hpp;
    a negative speed turns the pump backwards, P to S).
    """

    OPTIONS = {
        "inlet": Option("free", ("free", "floor"),
                        "the displacement flow whatever the inlet pressure, or no port drawn below p_floor (Hopsan)"),
        "speed": Option("constant", ("constant", "input"), "the shaft speed: the parameter omega, or the input omega_in"),
    }

    PARAMETERS = {
        "D": Param(25e-6 / 6.283185307179586, "m^3/rad", "displacement per radian (write '25 cm^3/rev')", min=0.0),
        "omega": Param(157.07963267948966, "rad/s", "shaft speed (write '1500 rpm')", min=0.0),
        "C_leak": Param(0.0, "m^3/s/Pa", "internal leakage coefficient, P to S", min=0.0),
        "p_rated": Param(
            350e5, "Pa", "rated pressure: the highest it is built to deliver against", min=0.0, min_inclusive=False
        ),
        "p_floor": Param(VACUUM, "Pa", "lowest pressure a port is drawn to (option floor)", min=VACUUM),
        "p_reg": Param(100.0, "Pa", "pressure over which the flow falls to nothing at the floor (option floor)",
                       min=0.0, min_inclusive=False),
    }
    INPUTS = {
        **_PUMP_INPUTS,
        "eps": Port("", "displacement setting (1: full; a variable pump without a controller)", default=1.0),
    }
    OUTPUTS = {
        "QP": Output("m^3/s", "flow delivered at P"),
        "QS": Output("m^3/s", "flow drawn at S"),
        "T": Output("N*m", "shaft torque taken from the drive"),
        "p_rated": Output("Pa", "rated pressure"),
    }
    HYDRAULIC = dict(_PUMP_HYDRAULIC)
    #: the rated pressure is the highest a pump makes: the circuit's pressure ceiling (plausibility); a pump
    #: dead-headed far beyond it is flagged
    LIMITS = {"p_rated": Limit("source")}

    def _delivery(self, u: Mapping[str, Any], p: Mapping[str, Any], eps: Any = 1.0) -> dict[str, Any]:
        dp = u["pP"] - u["pS"]
        omega = u["omega_in"] if self.option("speed") == "input" else p["omega"]
        q = displaced_flow(p["D"], omega, eps) - leakage_flow(p["C_leak"], dp)
        if self.option("inlet") == "floor":
            q = floored_port_flow(q, u["pS"], u["pP"], p["p_floor"], p["p_reg"])
        return {"QP": q, "QS": q, "T": motor_torque(eps * p["D"], dp), "p_rated": p["p_rated"]}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return self._delivery(u, p, u["eps"])


@register
class VariablePump(Pump):
    r"""Pressure-compensated variable-displacement pump: full displacement up to ``p_c``, none ``dp_band`` above.

    The displacement setting :math:`\varepsilon` follows the compensator's
    static characteristic (:func:`hydroservo.laws.displacement.compensator_displacement`)
    with the time constant ``tau`` of the swash-plate actuator, and the input
    ``eps_cmd`` (0 to 1, default 1) limits it:

    .. math:: \tau\,\dot\varepsilon = \varepsilon_{cmd}\,c(p_P) - \varepsilon, \qquad
              Q_P = \varepsilon D\,\omega - C_{leak}\,(p_P - p_S)

    ([JelaliKroll2004], pressure-compensated pumps; [Merritt1967] for the
    displacement and leakage flows).
    """

    PARAMETERS = {
        **Pump.PARAMETERS,
        "p_c": Param(200e5, "Pa", "compensator setting (destroking begins)", min=0.0),
        "dp_band": Param(5e5, "Pa", "pressure rise from full to zero displacement", min=0.0, min_inclusive=False),
        "tau": Param(0.02, "s", "time constant of the displacement actuator", min=0.0, min_inclusive=False),
        "eps0": Param(1.0, "", "initial displacement setting", min=0.0, max=1.0),
    }
    STATES = {"eps": State("", "displacement setting (0 to 1)", initial="eps0", nominal=1.0)}
    INPUTS = {**_PUMP_INPUTS, "eps_cmd": Port("", "displacement command, 0 to 1", default=1.0)}
    OUTPUTS = {**Pump.OUTPUTS, "eps": Output("", "displacement setting (0 to 1)")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {**self._delivery(u, p, x["eps"]), "eps": x["eps"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        target = u["eps_cmd"] * compensator_displacement(u["pP"], p["p_c"], p["dp_band"])
        return {"eps": (target - x["eps"]) / p["tau"]}


@register
class LoadSensingPump(Pump):
    r"""Variable pump whose regulator holds its outlet ``p_dif`` above the pressure at its port X (load sensing).

    The regulator of Hopsan's HydraulicPressureControlledPump ([Hopsan2026] Hydraulic/Pumps&Motors/
    HydraulicPressureControlledPump.hpp) in the limit of a vanishing step: the pressure error
    :math:`u = p_{dif} - (p_P - p_X)` drives the displacement flow :math:`Q_r = \varepsilon D\omega` through

    .. math:: Q_r = \frac{y}{L}, \qquad
              \frac{\ell\,\tau_v}{L}\,\ddot y + \dot y + \frac{R_p}{L}\,y = u + \frac{\dot u}{\omega_{p1}},
              \qquad L = \ell + R_p\tau_v,\quad
              \ell = l_p \sqrt{p_{nom}/p_P}\;\frac{\omega_{nom}}{\omega + 0.001}

    (at constant :math:`L`, :math:`(\ell s + R_p)(\tau_v s + 1)\,Q_r = (1 + s/\omega_{p1})\,u`: a control
    valve of time constant ``tau_v`` with a lead at ``omega_p1``, acting on a regulator of inductance :math:`\ell`
    that falls with the pressure and the speed, and static gain :math:`1/R_p`), :math:`Q_r` held in
    :math:`[\varepsilon_{min}, 1] D\omega` and its rate within :math:`D\omega L\sqrt{|p_P - p_0|/(p_{nom} t_p)}`
    upwards and :math:`D\omega L\sqrt{|p_P - p_0|/(p_{nom} t_m)}` downwards (``t_p``, ``t_m``: from minimum to
    full displacement and back at ``p_nom``), without wind-up
    (:func:`hydroservo.laws.displacement.regulator_rates`, whose states are :math:`y`, its rate :math:`v`
    and :math:`w`, the error lagged by ``tau_v``/100 for its rate). Hopsan's TLM terms (:math:`Z_c` of the outlet in :math:`L` and
    its pressures :math:`c_e`) vanish with the step; its pressures are absolute (:math:`p_P` in :math:`\ell` at
    least 1 Pa absolute, :math:`p_X` at least 0), ``p_0`` is its 1e5 Pa absolute.

    The flows are the :class:`Pump`'s at :math:`\varepsilon = Q_r/(D\omega)`: :math:`Q_P = Q_r - C_{leak}(p_P -
    p_S)`. Port X only reads its pressure (no flow). The states start at 0 (no displacement, at rest); at rest
    with a displacement flow :math:`Q_0` and an error :math:`u_0` they are :math:`y = L Q_0`, :math:`v = 0`,
    :math:`w = u_0` (a :math:`w` off :math:`u` at the start is a step of the error: the lead kicks).

    Option ``regulator``: ``standard`` (default), the law above; ``g``, Hopsan's HydraulicPressureControlledPumpG
    ([Hopsan2026] Hydraulic/Special/HydraulicPressureControlledPumpG.hpp), whose regulator filters the error into
    the *rate* of the displacement flow, :math:`\dot Q_r = s\,(1 + s/\omega_{p1e})/((\ell s + R)(\tau_v s + 1))\,u`
    with :math:`\ell = l_p f`, :math:`R = R_p f`, :math:`f = \sqrt{p_{nom}/p_P}\,\omega_{nom}/\max(\omega, 0.1)`,
    :math:`\omega_{p1e} = \omega_{p1}\max(\omega, 0.1)/\omega_{nom}`: only changes of the error move it. Its
    bilinear transform divides each step's terms by that step's :math:`f`, so that in the limit of a vanishing
    step the filter acts on :math:`U = u/f`:
    :math:`l_p\tau_v\ddot e + (l_p + R_p\tau_v)\dot e + R_p e = \dot h` with :math:`e = \dot Q_r` and
    :math:`h = U + \dot U/\omega_{p1e}` (the lead); :math:`e` is held within
    :math:`\pm(1 - \varepsilon_{min}) D\omega\sqrt{p_P/p_{nom}}/t_{p|m}`
    (:func:`hydroservo.laws.displacement.regulator_rates` on :math:`y = (l_p + R_p\tau_v) e`, no bound on its
    rate) and :math:`Q_r` (state ``q``) within :math:`[\varepsilon_{min}, 1] D\omega`, each with its memory as
    Hopsan clamps them; :math:`\dot U` and :math:`\dot h` from lags ``wu`` and ``wh`` of them by ``tau_v``/100.
    It starts at rest at its displacement flow ``q`` (an initial state) with :math:`e = 0`.
    """

    OPTIONS = {
        **Pump.OPTIONS,
        "regulator": Option("standard", ("standard", "g"),
                            "Hopsan's HydraulicPressureControlledPump's regulator, or HydraulicPressureControlledPumpG's"),
    }
    PARAMETERS = {
        **Pump.PARAMETERS,
        "p_dif": Param(1e6, "Pa", "pressure difference held from X to P", min=0.0),
        "l_p": Param(7e7, "Pa*s^2/m^3", "regulator inductance at p_nom and omega_nom", min=0.0, min_inclusive=False),
        "R_p": Param(1e9, "Pa*s/m^3", "static characteristic: pressure error per displacement flow", min=0.0),
        "omega_p1": Param(200.0, "rad/s", "lead frequency of the regulator", min=0.0, min_inclusive=False),
        "tau_v": Param(1e-3, "s", "time constant of the control valve", min=0.0, min_inclusive=False),
        "t_p": Param(0.15, "s", "time from minimum to full displacement at p_nom", min=0.0, min_inclusive=False),
        "t_m": Param(0.12, "s", "time from full to minimum displacement at p_nom", min=0.0, min_inclusive=False),
        "eps_min": Param(0.0, "", "lowest displacement setting", min=0.0, max=1.0),
        "p_nom": Param(7e6, "Pa", "nominal pressure of the regulator's data (Hopsan's 7 MPa)", min=0.0,
                       min_inclusive=False),
        "omega_nom": Param(125.0, "rad/s", "nominal speed of the regulator's data (Hopsan's 125 rad/s)", min=0.0,
                           min_inclusive=False),
        "p_0": Param(-1325.0, "Pa", "outlet pressure at which the rate limits vanish (Hopsan's 1e5 Pa absolute)"),
    }
    STATES = {
        "y": State("Pa*s", "regulator filter output: L times the displacement flow", nominal=1e4),
        "v": State("Pa", "rate of y", nominal=1e5),
        "w": State("Pa", "the pressure error u lagged by tau_v/100 (its rate is the lead's)", nominal=1e6),
    }
    INPUTS = {**_PUMP_INPUTS, "pX": Port("Pa", "pressure at the reference port X")}
    OUTPUTS = {
        **Pump.OUTPUTS,
        "eps": Output("", "displacement setting"),
        "QX": Output("m^3/s", "flow at X (none)"),
    }
    HYDRAULIC = {**_PUMP_HYDRAULIC, "X": Hydraulic("pX", "QX", "reference port: its pressure only", into=True)}

    def options_changed(self) -> None:
        """Option ``regulator = "g"``: its states, the displacement flow ``q`` and the lags ``wu``, ``wh`` beside the
        filter's."""
        super().options_changed()
        cls = type(self)
        self.STATES = dict(cls.STATES)  # type: ignore[misc]
        if self.option("regulator") == "g":
            self.STATES = {  # type: ignore[misc]
                "y": State("Pa", "regulator filter output: (l_p + R_p tau_v) times the displacement flow's rate",
                           nominal=1e5),
                "v": State("Pa/s", "rate of y", nominal=1e7),
                "w": State("Pa/s", "the filter's input lagged by tau_v/100 (unused: its lead is in h)", nominal=1e6),
                "q": State("m^3/s", "displacement flow", nominal=1e-3),
                "wu": State("Pa", "U, the pressure error over f, lagged by tau_v/100 (for its rate)", nominal=1e6),
                "wh": State("Pa", "U with its lead, h, lagged by tau_v/100 (for its rate)", nominal=1e6),
            }

    def _regulator_g(self, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> dict[str, Any]:
        """Option regulator = g: the filter of the displacement flow's rate (class notes)."""
        q_max = p["D"] * p["omega"]
        speed = bk.fmax(p["omega"], 0.1)
        inv_f = bk.sqrt(smooth_abs(u["pP"] - VACUUM, 1.0) / p["p_nom"]) * speed / p["omega_nom"]
        a1 = p["l_p"] + p["R_p"] * p["tau_v"]
        slew = (1.0 - p["eps_min"]) * q_max * inv_f * p["omega_nom"] / speed
        big_u = inv_f * (p["p_dif"] - u["pP"] + bk.fmax(u["pX"], VACUUM))
        tau_d = G_LAG * p["tau_v"]
        h = big_u + (big_u - x["wu"]) / tau_d / (p["omega_p1"] * speed / p["omega_nom"])
        return {
            "q_max": q_max, "a1": a1, "g1": p["l_p"] * p["tau_v"] / a1, "g2": p["R_p"] / a1, "U": big_u, "h": h,
            "r": (h - x["wh"]) / tau_d, "e_max": slew / p["t_p"], "e_min": -slew / p["t_m"],
        }

    def _regulator(self, u: Mapping[str, Any], p: Mapping[str, Any]) -> dict[str, Any]:
        q_max = p["D"] * p["omega"]
        ell = p["l_p"] * bk.sqrt(p["p_nom"] / bk.fmax(u["pP"] - VACUUM, 1.0)) * p["omega_nom"] / (p["omega"] + 0.001)
        big_l = ell + p["R_p"] * p["tau_v"]
        slew = q_max * big_l * bk.sqrt(smooth_abs(u["pP"] - p["p_0"], 1.0) / p["p_nom"])
        return {
            "q_max": q_max, "L": big_l, "g1": ell * p["tau_v"] / big_l, "g2": p["R_p"] / big_l,
            "u": p["p_dif"] - u["pP"] + bk.fmax(u["pX"], VACUUM),
            "v_max": slew / bk.sqrt(p["t_p"]), "v_min": -slew / bk.sqrt(p["t_m"]),
        }

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        if self.option("regulator") == "g":
            eps = bk.clip(x["q"] / (p["D"] * p["omega"]), p["eps_min"], 1.0)
            return {**self._delivery(u, p, eps), "eps": eps, "QX": 0.0}
        r = self._regulator(u, p)
        eps = bk.clip(x["y"] / (r["L"] * r["q_max"]), p["eps_min"], 1.0)
        return {**self._delivery(u, p, eps), "eps": eps, "QX": 0.0}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        if self.option("regulator") == "g":
            g = self._regulator_g(x, u, p)
            big = 1e30  # the filter's rate is not bounded, its output (the flow's rate) is; its lead is in h
            tau_d = G_LAG * p["tau_v"]
            ydot, vdot, wdot = regulator_rates(
                x["y"], x["v"], x["w"], g["r"], g["g1"], g["g2"], big, g["a1"] * g["e_min"], g["a1"] * g["e_max"],
                -big, big, 0.01 * p["tau_v"], STOP_RELAXATION * p["tau_v"],
            )
            q_min = p["eps_min"] * g["q_max"]
            e = bk.fmin(bk.fmax(x["y"] / g["a1"], g["e_min"]), g["e_max"])
            qdot = limited_rate(x["q"] - q_min, e, g["q_max"] - q_min, STOP_RELAXATION * p["tau_v"])
            return {"y": ydot, "v": vdot, "w": wdot, "q": qdot, "wu": (g["U"] - x["wu"]) / tau_d,
                    "wh": (g["h"] - x["wh"]) / tau_d}
        r = self._regulator(u, p)
        ydot, vdot, wdot = regulator_rates(
            x["y"], x["v"], x["w"], r["u"], r["g1"], r["g2"], p["omega_p1"], p["eps_min"] * r["q_max"] * r["L"],
            r["q_max"] * r["L"], r["v_min"], r["v_max"], 0.01 * p["tau_v"], STOP_RELAXATION * p["tau_v"],
        )
        return {"y": ydot, "v": vdot, "w": wdot}


@register
class Motor(Component):
    r"""Fixed-displacement hydraulic motor driving an inertia, with leakage and viscous friction.

    .. math::
        Q_A &= D\,\omega + C_{im}(p_A - p_B) + C_{em}\,p_A, \qquad
        Q_B = D\,\omega + C_{im}(p_A - p_B) - C_{em}\,p_B\\
        J\,\dot\omega &= \eta_{hm} D\,(p_A - p_B) - B_m\,\omega - T_{load}, \qquad \dot\theta = \omega

    ([Merritt1967], hydraulic motors: flow continuity with internal and
    external leakage coefficients, torque :math:`D_m P_L`). Flow entering at A
    turns the shaft in +θ. ``J`` is the motor's and its load's inertia;
    external leakage goes to the case drain (tank).

    The input ``eps`` (default 1) scales the displacement, :math:`D\,\varepsilon`
    in flow and torque: a variable motor driven by a signal. The shaft is also
    the rotational port ``shaft`` (:class:`~hydroservo.components.base.Mechanical`,
    kind ``"rotational"``, counted along +θ): the motor gives its angle and
    speed, and what is joined there (a torque source, a shaft) twists it with
    ``T_shaft`` (along +θ), beside ``T_load``. Hopsan's Q-type motors
    ([Hopsan2026] Hydraulic/Pumps&Motors/HydraulicFixedDisplacementMotorQ.hpp,
    HydraulicVariableDisplacementMotorQ.hpp) are this law with ``C_em`` 0 and
    ``eta_hm`` 1: their damped double integrator of :math:`(c_1 - c_2)\,D\varepsilon - c_3`
    over ``J`` with the damping :math:`B + (Z_{c1} + Z_{c2}) (D\varepsilon)^2 + Z_{x3}` is
    the implicit step of :math:`J\dot\omega = D\varepsilon\,(p_1 - p_2) - B\omega - T_3`.

    Option ``inlet``: ``free`` (default) passes the displaced flow whatever the
    pressures; ``floor`` draws no port below ``p_floor``
    (:func:`~hydroservo.laws.displacement.floored_port_flow` on :math:`D\varepsilon\omega`),
    as Hopsan's motors clamp their flow so that neither port's pressure falls
    below zero.
    """

    OPTIONS = {
        "inlet": Option("free", ("free", "floor"),
                        "the displaced flow whatever the port pressures, or no port drawn below p_floor (Hopsan)"),
    }

    PARAMETERS = {
        "D": Param(50e-6 / 6.283185307179586, "m^3/rad", "displacement per radian (write '50 cm^3/rev')", min=0.0, min_inclusive=False),
        "C_im": Param(0.0, "m^3/s/Pa", "internal leakage coefficient, A to B", min=0.0),
        "C_em": Param(0.0, "m^3/s/Pa", "external leakage coefficient of each port", min=0.0),
        "eta_hm": Param(1.0, "", "hydromechanical efficiency", min=0.0, max=1.0, min_inclusive=False),
        "J": Param(0.01, "kg*m^2", "inertia of motor and load", min=0.0, min_inclusive=False),
        "B_m": Param(0.0, "N*m*s/rad", "viscous friction coefficient of the shaft", min=0.0),
        "omega0": Param(0.0, "rad/s", "initial speed"),
        "theta0": Param(0.0, "rad", "initial angle"),
        "p_floor": Param(VACUUM, "Pa", "lowest pressure a port is drawn to (option inlet = floor)", min=VACUUM),
        "p_reg": Param(100.0, "Pa", "pressure over which the flow falls to nothing at the floor (option floor)",
                       min=0.0, min_inclusive=False),
    }
    STATES = {
        "theta": State("rad", "shaft angle", initial="theta0", nominal=1.0),
        "omega": State("rad/s", "shaft speed", initial="omega0", nominal=100.0),
    }
    INPUTS = {
        "pA": Port("Pa", "pressure at port A"),
        "pB": Port("Pa", "pressure at port B"),
        "T_load": Port("N*m", "load torque against +θ", default=0.0),
        "T_shaft": Port("N*m", "torque of what the port shaft is joined to, along +θ", default=0.0),
        "eps": Port("", "displacement setting (1: full; -1: full, reversed)", default=1.0),
    }
    OUTPUTS = {
        "QA": Output("m^3/s", "flow into the motor at A"),
        "QB": Output("m^3/s", "flow out of the motor at B"),
        "T": Output("N*m", "hydraulic torque on the shaft"),
        "theta": Output("rad", "shaft angle"),
        "omega": Output("rad/s", "shaft speed"),
    }
    HYDRAULIC = {
        "A": Hydraulic("pA", "QA", "port A (inlet for +θ)", into=True),
        "B": Hydraulic("pB", "QB", "port B (outlet for +θ)", into=False),
    }
    MECHANICAL = {"shaft": Mechanical("theta", "omega", "T_shaft", "the shaft (counted along +θ)", kind="rotational")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        dp = u["pA"] - u["pB"]
        q = displaced_flow(p["D"], x["omega"], u["eps"])
        if self.option("inlet") == "floor":
            q = floored_port_flow(q, u["pA"], u["pB"], p["p_floor"], p["p_reg"])
        q = q + leakage_flow(p["C_im"], dp)
        return {
            "QA": q + leakage_flow(p["C_em"], u["pA"]),
            "QB": q - leakage_flow(p["C_em"], u["pB"]),
            "T": motor_torque(u["eps"] * p["D"], dp, p["eta_hm"]),
            "theta": x["theta"],
            "omega": x["omega"],
        }

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"theta": x["omega"], "omega": (y["T"] - p["B_m"] * x["omega"] - u["T_load"] + u["T_shaft"]) / p["J"]}


@register
class Machine(Component):
    r"""Displacement machine, pump or motor, whose shaft what it is joined to turns (no inertia of its own).

    .. math::
        Q_A = Q_B = \varepsilon D\,\omega + C_{im}\,(p_A - p_B), \qquad
        T = \varepsilon D\,(p_A - p_B) - B_m\,\omega

    ([Merritt1967], hydraulic motors: flow continuity with internal leakage, torque :math:`D_m P_L`;
    :mod:`hydroservo.laws.displacement`). Flow entering at A turns the shaft in +θ; turned the other way by its
    load, it pumps from B to A. Its shaft is the rotational port ``shaft`` (counted outward, along +θ), a torque
    port: it reads the speed ``omega`` of what it is joined to (an inertia, a motor, an angular-velocity source)
    and twists it with ``T``. The input ``eps`` (default 1) scales the displacement. Hopsan's
    HydraulicMachineC ([Hopsan2026] Hydraulic/Pumps&Motors/HydraulicMachineC.hpp) is this machine between two
    volumes (its transmission-line port volumes ``V_1``, ``V_2``), its torque characteristic
    :math:`c_3 = (p_1 - p_2)\,\varepsilon D` with the impedance :math:`B_m + (\varepsilon D)^2 (Z_{c1} + Z_{c2})`, the
    pressures at least 0 absolute (the volumes' cavity law).
    """

    PARAMETERS = {
        "D": Param(50e-6 / 6.283185307179586, "m^3/rad", "displacement per radian (write '50 cm^3/rev')", min=0.0,
                   min_inclusive=False),
        "C_im": Param(0.0, "m^3/s/Pa", "internal leakage coefficient, A to B", min=0.0),
        "B_m": Param(0.0, "N*m*s/rad", "viscous friction coefficient of the shaft", min=0.0),
    }
    INPUTS = {
        "pA": Port("Pa", "pressure at port A"),
        "pB": Port("Pa", "pressure at port B"),
        "theta": Port("rad", "angle of the shaft, along +θ", default=0.0),
        "omega": Port("rad/s", "speed of the shaft, along +θ", default=0.0),
        "eps": Port("", "displacement setting (1: full; -1: full, reversed)", default=1.0),
    }
    OUTPUTS = {
        "QA": Output("m^3/s", "flow into the machine at A"),
        "QB": Output("m^3/s", "flow out of the machine at B"),
        "T": Output("N*m", "torque on what the shaft is joined to, along +θ"),
    }
    HYDRAULIC = {
        "A": Hydraulic("pA", "QA", "port A (inlet for +θ as a motor)", into=True),
        "B": Hydraulic("pB", "QB", "port B (outlet for +θ as a motor)", into=False),
    }
    MECHANICAL = {"shaft": Mechanical("theta", "omega", "T", "the shaft (counted along +θ)", kind="rotational")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        dp = u["pA"] - u["pB"]
        q = displaced_flow(p["D"], u["omega"], u["eps"]) + leakage_flow(p["C_im"], dp)
        return {"QA": q, "QB": q, "T": motor_torque(u["eps"] * p["D"], dp) - p["B_m"] * u["omega"]}


@register
class CentrifugalPump(Component):
    r"""Centrifugal pump at a speed: Euler's impeller pressure driving the flow through the pump's losses.

    The flow :math:`Q` from P1 (inlet) to P2 (outlet) solves

    .. math::
        Q = A_p\sqrt{\frac{2}{k_l\rho}}\,\operatorname{sign}(\Delta p_{th} - \Delta p)\sqrt{|\Delta p_{th} -
        \Delta p|} + K_{cp}\,(p_1 - p_2), \qquad
        \Delta p_{th} = \rho U_2^2 - \rho_s U_2\,\frac{Q\cot\beta_2}{\pi d b}, \quad U_2 = \frac{\omega d}{2}

    with :math:`\Delta p = p_2 - p_1` (:mod:`hydroservo.laws.centrifugal`: Euler's pump equation for the impeller,
    a loss of ``kl`` dynamic heads at the outlet area ``Ap``, laminar leakage ``Kcp`` back through the pump). As
    :math:`\Delta p_{th}` falls with :math:`Q`, the flow is an algebraic unknown (``q2e``) solved by Newton's method
    inside the model (:mod:`hydroservo.system.implicit`). The shaft takes

    .. math:: T = B_p\,\omega + \frac{(\Delta p + k_l\rho Q^2/(2A_p^2))\,(Q - K_{cp}(p_1 - p_2))}{|\omega| + 0.001}

    (the power given to the fluid over the speed, :func:`~hydroservo.laws.centrifugal.shaft_torque`); outputs
    ``torp`` (that torque), ``Pin`` = :math:`T\omega` and ``Pout`` = :math:`\Delta p\,Q`.

    This is Hopsan's HydraulicCentrifugalPump ([Hopsan2026] HydroDynamicComponents/HydraulicCentrifugalPump.hpp)
    with its parameters' names: its Newton iterations of that implicit law at each step, and its pressures at the
    ports from their wave variables, are the law at a vanishing step. Option ``slip = "hopsan"`` writes the slip
    term as Hopsan does, with :math:`\rho_s = \rho^2\cdot 1\,\mathrm{m^3/kg}` (a density too many in its
    notebook); ``"euler"`` (default), :math:`\rho_s = \rho`. Its loss is laminar below a loss velocity of
    :math:`\sqrt{10}` m/s (its signedSquareL: :func:`~hydroservo.laws.centrifugal.loss_transition_pressure`).

    Option ``inlet``: ``free`` (default) delivers the flow whatever the inlet pressure; ``floor`` draws no port
    below ``p_floor`` (:func:`~hydroservo.laws.displacement.floored_port_flow`), the continuous form of Hopsan's
    pump, whose flow stops where its inlet's pressure reaches 0 (absolute).

    Option ``speed``: ``constant`` (default), the parameter ``omegap``; ``input``, the input ``omega_in`` (Hopsan's
    ``omegap`` driven by a signal).
    """

    OPTIONS = {
        "speed": Option("constant", ("constant", "input"), "the speed: the parameter omegap, or the input omega_in"),
        "slip": Option("euler", ("euler", "hopsan"),
                       "the slip term of Euler's equation with the density (euler) or its square (Hopsan's law)"),
        "inlet": Option("free", ("free", "floor"),
                        "the flow whatever the inlet pressure, or no port drawn below p_floor (Hopsan)"),
    }
    PARAMETERS = {
        "kl": Param(0.1, "", "loss coefficient: dynamic heads lost at the outlet area", min=0.0, min_inclusive=False),
        "b": Param(0.03, "m", "impeller outlet width", min=0.0, min_inclusive=False),
        "d": Param(0.3, "m", "diameter: the impeller's, at its outlet", min=0.0, min_inclusive=False),
        "beta2": Param(1.57, "rad", "blade angle at the outlet (pi/2: radial)", min=0.0, max=3.141592653589793,
                       min_inclusive=False, max_inclusive=False),
        "Ap": Param(0.001, "m^2", "outlet flow area", min=0.0, min_inclusive=False),
        "rho": Param(870.0, "kg/m^3", "oil density", min=0.0, min_inclusive=False, fluid="density"),
        "Kcp": Param(1e-11, "m^3/s/Pa", "leakage coefficient, P2 back to P1", min=0.0),
        "Bp": Param(0.1, "N*m*s/rad", "viscous friction coefficient of the shaft", min=0.0),
        "omegap": Param(157.0, "rad/s", "speed (option speed = constant)"),
        "p_floor": Param(VACUUM, "Pa", "lowest pressure a port is drawn to (option inlet = floor)", min=VACUUM),
        "p_reg": Param(100.0, "Pa", "pressure over which the flow falls to nothing at the floor (option floor)",
                       min=0.0, min_inclusive=False),
    }
    ALGEBRAIC = {"q2e": Algebraic("m^3/s", "flow of the impeller law, before the inlet's floor", nominal=1e-3)}
    INPUTS = {
        "p1": Port("Pa", "pressure at the inlet P1"),
        "p2": Port("Pa", "pressure at the outlet P2"),
        "omega_in": Port("rad/s", "speed (option speed = input)", default=0.0),
    }
    OUTPUTS = {
        "Q1": Output("m^3/s", "flow drawn at P1"),
        "Q2": Output("m^3/s", "flow delivered at P2"),
        "q2e": Output("m^3/s", "flow of the impeller law, before the inlet's floor"),
        "torp": Output("N*m", "torque the shaft takes"),
        "Pin": Output("W", "power into the shaft"),
        "Pout": Output("W", "hydraulic power delivered, (p2 - p1) Q"),
    }
    HYDRAULIC = {
        "P1": Hydraulic("p1", "Q1", "inlet", into=True),
        "P2": Hydraulic("p2", "Q2", "outlet", into=False),
    }

    def _speed(self, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        return u["omega_in"] if self.option("speed") == "input" else p["omegap"]

    def _slip_density(self, p: Mapping[str, Any]) -> Any:
        return p["rho"] * p["rho"] if self.option("slip") == "hopsan" else p["rho"]

    def _pump(self, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], omega: Any) -> dict[str, Any]:
        """The flows, the torque the shaft takes and the powers at speed ``omega``."""
        dp = u["p2"] - u["p1"]
        q = x["q2e"]
        if self.option("inlet") == "floor":
            q = floored_port_flow(q, u["p1"], u["p2"], p["p_floor"], p["p_reg"])
        power = hydraulic_power(dp, q, q + leakage_flow(p["Kcp"], dp), p["Ap"], p["kl"], p["rho"])
        torque = shaft_torque(power, omega, p["Bp"])
        return {"Q1": q, "Q2": q, "q2e": x["q2e"], "torp": torque, "Pin": torque * omega, "Pout": dp * q}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return self._pump(x, u, p, self._speed(x, u, p))

    def residual_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        dp = u["p2"] - u["p1"]
        omega = self._speed(x, u, p)
        dp_th = theoretical_pressure(omega, x["q2e"], p["d"], p["b"], p["beta2"], p["rho"], self._slip_density(p))
        q = impeller_flow(dp_th, dp, p["Ap"], p["kl"], p["rho"], loss_transition_pressure(p["kl"], p["rho"]))
        return {"q2e": x["q2e"] - q + leakage_flow(p["Kcp"], dp)}

    def guess_equations(self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> dict[str, Any]:
        """The flow of the law without the laminar part: :math:`k Q_i|Q_i| + c Q_i = a`, a quadratic."""
        dp = u["p2"] - u["p1"]
        omega = self._speed(x, u, p)
        leak = -leakage_flow(p["Kcp"], dp)
        head = theoretical_pressure(omega, 0.0, p["d"], p["b"], p["beta2"], p["rho"])
        c = head - theoretical_pressure(omega, 1.0, p["d"], p["b"], p["beta2"], p["rho"], self._slip_density(p))
        k = 0.5 * p["kl"] * p["rho"] / (p["Ap"] * p["Ap"])
        a = head - dp - c * leak
        return {"q2e": leak + 2.0 * a / (bk.fabs(c) + bk.sqrt(c * c + 4.0 * k * (bk.fabs(a) + 1.0)))}


@register
class CentrifugalPumpInertia(CentrifugalPump):
    r"""Centrifugal pump turned through its shaft: :class:`CentrifugalPump`'s law, its impeller an inertia.

    .. math:: J_p\,\dot\omega = T_{shaft} - T, \qquad \dot\theta = \omega

    with :math:`T` the torque the pump takes (:class:`CentrifugalPump`: viscous friction ``Bp`` and the power given
    to the fluid over :math:`|\omega| + 0.001`) and :math:`T_{shaft}` that of what turns it. The shaft is the
    rotational port ``Pmr1``, counted along the drive's turning, into the pump (a drive and the pump joined turn the
    same way; Hopsan's port counts outward, so its speed there is :math:`-\omega`). Outputs: ``Pout``, ``q2e``, the
    angle and the speed (the power into the shaft, :math:`T_{shaft}\,\omega`, is no output: an output that read the
    torque of what turns the shaft would close an algebraic loop through it).

    Hopsan's HydraulicCentrifugalPumpJ ([Hopsan2026] HydroDynamicComponents/HydraulicCentrifugalPumpJ.hpp):
    its notebook's :math:`(t + B_p w + J_p \dot w)(|w| + 0.001) = P` at its port's speed :math:`w = -\omega`,
    integrated by its implicit steps, is the law above. Hopsan's component never writes its port's angle (it stays
    at its start value); here :math:`\theta` is the speed's integral, which a spring joined to it needs.
    """

    OPTIONS = {k: v for k, v in CentrifugalPump.OPTIONS.items() if k != "speed"}
    PARAMETERS = {
        **{k: v for k, v in CentrifugalPump.PARAMETERS.items() if k != "omegap"},
        "Jp": Param(0.1, "kg*m^2", "inertia of the impeller and shaft", min=0.0, min_inclusive=False),
        "omega0": Param(0.0, "rad/s", "initial angular velocity"),
        "theta0": Param(0.0, "rad", "initial angle"),
    }
    STATES = {
        "theta": State("rad", "shaft angle", initial="theta0", nominal=1.0),
        "omega": State("rad/s", "shaft speed", initial="omega0", nominal=100.0),
    }
    INPUTS = {
        "p1": CentrifugalPump.INPUTS["p1"],
        "p2": CentrifugalPump.INPUTS["p2"],
        "T_shaft": Port("N*m", "torque of what turns the shaft Pmr1, along its turning", default=0.0),
    }
    OUTPUTS = {
        **{k: v for k, v in CentrifugalPump.OUTPUTS.items() if k not in ("torp", "Pin")},
        "theta": Output("rad", "shaft angle"),
        "omega": Output("rad/s", "shaft speed"),
    }
    MECHANICAL = {
        "Pmr1": Mechanical("theta", "omega", "T_shaft", "the shaft, counted along the drive's turning (into the pump)",
                           outward=False, kind="rotational"),
    }

    def _speed(self, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        return x["omega"]

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        out = {k: v for k, v in self._pump(x, u, p, x["omega"]).items() if k not in ("torp", "Pin")}
        return {**out, "theta": x["theta"], "omega": x["omega"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        torque = self._pump(x, u, p, x["omega"])["torp"]
        return {"theta": x["omega"], "omega": (u["T_shaft"] - torque) / p["Jp"]}
