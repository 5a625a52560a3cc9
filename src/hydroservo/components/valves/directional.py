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

from hydroservo.components.base import Component, Output, Param, Port, register
from hydroservo.components.valves.ports import (
    FLOW_OUTPUTS,
    FLUID_PARAMETERS,
    HYDRAULIC_PORTS,
    PRESSURE_PORTS,
    TWO_PORT_HYDRAULIC,
    TWO_PORT_PRESSURES,
)
from hydroservo.laws.four_way import edge_flow, three_way_valve_flows
from hydroservo.laws.orifice import transition_pressure

__all__ = ["ThreeWayValve", "TwoWayValve"]

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
