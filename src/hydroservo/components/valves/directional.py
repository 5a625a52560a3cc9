"""Spool valves with fewer ports than the four-way valve: the three-way valve (P, T, A) and the two-way valve (A, B).

Both are made of the four-way valve's sharp metering edge
(:func:`hydroservo.laws.four_way.edge_flow`): the three-way valve is the A half
of the four-way bridge (:func:`hydroservo.laws.four_way.three_way_valve_flows`),
the two-way valve one edge between its two ports. The spool position comes
from a spool component (:class:`~hydroservo.components.spools.SpoolSecondOrder`),
as for :class:`~hydroservo.components.valves.FourWayValve`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo import backend as bk
from hydroservo.components.base import Component, Hydraulic, Output, Param, Port, State, register
from hydroservo.components.valves.ports import (
    FLOW_OUTPUTS,
    FLUID_PARAMETERS,
    HYDRAULIC_PORTS,
    PRESSURE_PORTS,
    TWO_PORT_HYDRAULIC,
    TWO_PORT_PRESSURES,
)
from hydroservo.errors import ParameterError
from hydroservo.laws.four_way import edge_flow, three_way_valve_flows
from hydroservo.laws.orifice import transition_pressure
from hydroservo.laws.pressure_valve import STOP_RELAXATION, flow_force_gradient, limited_rate

__all__ = ["ThreeWayValve", "ThreeWayPressureValve", "TwoWayValve"]

_D_H = Param(1e-3, "m", "hydraulic diameter at which the laminar transition is evaluated", min=0.0, min_inclusive=False)


@register
class ThreeWayValve(Component):
    r"""Three-way spool valve: supply P, tank T and one use port A, sharp edges with per-edge laps.

    .. math::
        Q_A = c_{PA} f(x_v - x_{PA})\,g(p_S - p_A) - c_{AT} f(-x_v - x_{AT})\,g(p_A - p_T)

    (:func:`hydroservo.laws.four_way.three_way_valve_flows`): positive ``xv``
    connects P to A, negative A to T; each edge has its own flow coefficient.
    The turbulent law is regularised below the transition pressure at which
    the flow number ([MareAttarND] eq. 4) with hydraulic diameter ``D_h``
    reaches ``lambda_crit``, as in :class:`~hydroservo.components.valves.FourWayValve`.
    Hopsan's Hydraulic33Valve, Hydraulic32DirectionalValve and HydraulicValve33
    ([Hopsan2026]) import as this valve (docs/hopsan.md).
    """

    PARAMETERS = {
        "c_PA": Param(3.56e-4, "m^2/s/Pa^0.5", "flow coefficient of edge P-A, Efe2014 eq. 3.9", min=0.0),
        "c_AT": Param(3.56e-4, "m^2/s/Pa^0.5", "flow coefficient of edge A-T", min=0.0),
        "x_PA": Param(0.0, "m", "overlap of edge P-A (negative: underlap)"),
        "x_AT": Param(0.0, "m", "overlap of edge A-T (negative: underlap)"),
        **FLUID_PARAMETERS,
        "D_h": _D_H,
    }
    INPUTS = {"xv": Port("m", "spool position"), **{k: PRESSURE_PORTS[k] for k in ("pS", "pT", "pA")}}
    OUTPUTS = {k: FLOW_OUTPUTS[k] for k in ("QA", "QS", "QT")}
    HYDRAULIC = {k: HYDRAULIC_PORTS[k] for k in ("P", "T", "A")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        p_tr = transition_pressure(p["D_h"], p["rho"], p["nu"], p["lambda_crit"])
        QA, QS, QT = three_way_valve_flows(
            u["xv"], u["pS"], u["pT"], u["pA"], p["c_PA"], p["c_AT"], p["x_PA"], p["x_AT"], p_tr
        )
        return {"QA": QA, "QS": QS, "QT": QT}


@register
class ThreeWayPressureValve(ThreeWayValve):
    r"""Three-way pressure-control valve: :class:`ThreeWayValve`'s edges on a spool set by a pilot pressure X.

    A damped, massless spool of pilot area ``A_v``, pushed by the pilot port X
    against the setting ``p_ref`` and held by its spring ``k_s`` and the steady
    flow forces of its open edges ([Hopsan2026]
    Hydraulic/Valves/HydraulicPressureControlValve33.hpp):

    .. math::
        B_v\dot x_v = A_v (p_X - p_{ref}) - (k_s + k_{f,PA} + k_{f,AT})\,x_v,
        \quad x_v \in [x_{min}, x_{max}]

    with :math:`k_f = 2 C_q w\cos\varphi\,|\Delta p|` of an edge
    (:func:`~hydroservo.laws.pressure_valve.flow_force_gradient`, jet angle
    ``phi``) while it is open: P-A's for :math:`x_v > x_{PA}`, A-T's once its
    opening :math:`-x_v - x_{AT}` passes ``x_ATf`` (0 by default; Hopsan's
    valve switches it on only at :math:`x_v < -X_{at0}`, an opening of
    :math:`X_{ap0} + X_{at0}`). Each flow force sets in over the spool's
    travel ``dx_f`` (0.1 µm) rather than at once: with the force
    :math:`k_f x_v` of Hopsan's law a sudden onset is a jump of the force, on
    which a spool that balances there would chatter. The spool stops at its
    bounds without wind-up (:func:`~hydroservo.laws.pressure_valve.limited_rate`).
    The pilot takes no flow. A pilot pressure above ``p_ref`` opens P-A: with
    X joined to A the valve holds A where the spool balances (a
    pressure-reducing valve that relieves to T); with X on another line it
    sets A from that line's pressure.
    """

    PARAMETERS = {
        **ThreeWayValve.PARAMETERS,
        "A_v": Param(7.85e-5, "m^2", "pilot area of the spool", min=0.0, min_inclusive=False),
        "p_ref": Param(1e7, "Pa", "pilot pressure at which the spool's force balance is at x_v = 0"),
        "k_s": Param(100.0, "N/m", "spring stiffness of the spool", min=0.0),
        "B_v": Param(100.0, "N*s/m", "damping of the spool", min=0.0, min_inclusive=False),
        "phi": Param(0.03, "rad", "jet angle of the flow forces", min=0.0, max=1.5707963267948966),
        "x_min": Param(-0.01, "m", "lower bound of the spool"),
        "x_max": Param(0.01, "m", "upper bound of the spool"),
        "x_ATf": Param(0.0, "m", "opening of A-T beyond which its flow force acts (0: once open)"),
        "dx_f": Param(1e-7, "m", "spool travel over which an edge's flow force sets in", min=0.0, min_inclusive=False),
    }
    STATES = {"x_v": State("m", "spool position", nominal=1e-3)}
    INPUTS = {**{k: PRESSURE_PORTS[k] for k in ("pS", "pT", "pA")}, "pX": Port("Pa", "pilot pressure")}
    OUTPUTS = {**ThreeWayValve.OUTPUTS, "xv": Output("m", "spool position"), "QX": Output("m^3/s", "pilot flow (none)")}
    HYDRAULIC = {**ThreeWayValve.HYDRAULIC, "X": Hydraulic("pX", "QX", "pilot port", into=True)}

    def check(self) -> None:
        v = self.values
        if v["x_min"] >= v["x_max"]:
            raise ParameterError(f"{self.name}.x_min = {v['x_min']:g} m: expected below x_max = {v['x_max']:g} m")

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        xv = bk.fmin(bk.fmax(x["x_v"], p["x_min"]), p["x_max"])
        return {**super().output_equations(t, x, {**u, "xv": xv}, p), "xv": xv, "QX": 0.0}

    def _x_atf(self, p: Mapping[str, Any]) -> Any:
        """The spool position below which A-T's flow force acts: its opening -x_v - x_AT past ``x_ATf``."""
        return -p["x_AT"] - p["x_ATf"]

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        xv = y["xv"]
        pa_open = bk.fmin(bk.fmax((xv - p["x_PA"]) / p["dx_f"], 0.0), 1.0)
        at_open = bk.fmin(bk.fmax((self._x_atf(p) - xv) / p["dx_f"], 0.0), 1.0)
        k_f = (pa_open * flow_force_gradient(p["c_PA"], u["pS"] - u["pA"], p["rho"], p["phi"])
               + at_open * flow_force_gradient(p["c_AT"], u["pA"] - u["pT"], p["rho"], p["phi"]))
        stiffness = p["k_s"] + k_f
        rate = (p["A_v"] * (u["pX"] - p["p_ref"]) - stiffness * xv) / p["B_v"]
        delta = STOP_RELAXATION * p["B_v"] / bk.fmax(stiffness, 1.0)  # the spool's own time constant
        return {"x_v": limited_rate(x["x_v"] - p["x_min"], rate, p["x_max"] - p["x_min"], delta)}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """Where an edge's flow force starts to act."""
        return {"pa_force": (y["xv"] - p["x_PA"], 1e-4), "at_force": (y["xv"] - self._x_atf(p), 1e-4)}


@register
class TwoWayValve(Component):
    r"""Two-way spool valve: one sharp edge from A to B that opens as the spool travels past its overlap.

    .. math:: Q = c_v f(x_v - x_{AB})\,g(p_A - p_B)

    (:func:`hydroservo.laws.four_way.edge_flow`), closed for
    :math:`x_v \le x_{AB}`; flow in either direction once open. The turbulent
    law is regularised as in :class:`ThreeWayValve`. Hopsan's Hydraulic22Valve
    and Hydraulic22DirectionalValve ([Hopsan2026]) import as this valve
    (docs/hopsan.md).
    """

    PARAMETERS = {
        "c_v": Param(3.56e-4, "m^2/s/Pa^0.5", "flow coefficient of the edge, Efe2014 eq. 3.9", min=0.0),
        "x_AB": Param(0.0, "m", "overlap of edge A-B: the spool position at which it opens (negative: underlap)"),
        **FLUID_PARAMETERS,
        "D_h": _D_H,
    }
    INPUTS = {"xv": Port("m", "spool position"), **TWO_PORT_PRESSURES}
    OUTPUTS = {"Q": Output("m^3/s", "flow from A to B")}
    HYDRAULIC = dict(TWO_PORT_HYDRAULIC)

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        p_tr = transition_pressure(p["D_h"], p["rho"], p["nu"], p["lambda_crit"])
        return {"Q": edge_flow(p["c_v"], u["xv"] - p["x_AB"], u["pA"] - u["pB"], p_tr)}
