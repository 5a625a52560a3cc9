"""The shuttle valve: an outlet joined to whichever of its two inlets has the higher pressure (load sensing's
"OR" of load pressures)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo import backend as bk
from hydroservo.components.base import Component, Hydraulic, Output, Param, Port, register
from hydroservo.laws.orifice import laminar_flow

__all__ = ["ShuttleValve"]


@register
class ShuttleValve(Component):
    r"""Shuttle valve: the outlet ``P3`` joined to the inlet of higher pressure, ``P1`` or ``P2``; the other is shut.

    .. math:: Q_3 = G_{open}\,(\max(p_1, p_2) - p_3),\qquad
              Q_1 = Q_3 \text{ if } p_1 > p_2 \text{ else } 0,\qquad Q_2 = Q_3 - Q_1

    (:func:`hydroservo.laws.orifice.laminar_flow` through the open seat). The ball (or shuttle) is taken as
    massless: it sits on the seat of the lower inlet at every instant, as in a load-sensing circuit's chain of
    shuttle valves, which passes the highest load pressure on to the pump's regulator. The flow may go either
    way through the open inlet (the outlet line drains back into it when its pressure falls).

    Hopsan's HydraulicShuttleValve ([Hopsan2026] Hydraulic/Valves/HydraulicShuttleValve.hpp) joins the outlet to
    the higher inlet without resistance: its TLM step writes the outlet's flow as
    :math:`(c_{in} - c_3)/(Z_{c,in} + Z_{c,3})`, the flow of an ideal connection between the two nodes' wave
    variables, whose limit for a vanishing step is :math:`p_3 = \max(p_1, p_2)`. An ODE model cannot hold a
    volume's pressure equal to another's without a path between them; ``G_open`` is that path, large enough
    that the outlet follows within :math:`Q_3/G_{open}` (17 Pa per L/min at the default) and with a time
    constant :math:`V/(\beta_e G_{open})` (1e-8 s on a 1e-5 m³ line) far below anything the circuit does.
    The output ``out`` is Hopsan's: -1 while P1 is the open inlet, 1 while P2 is.

    At :math:`p_1 = p_2` the flow :math:`Q_3` is continuous; only the inlet it is drawn from changes (a switch
    event).
    """

    PARAMETERS = {
        "G_open": Param(1e-6, "m^3/s/Pa", "conductance of the open seat (Hopsan's: ideal)", min=0.0, min_inclusive=False),
    }
    INPUTS = {
        "p1": Port("Pa", "pressure at inlet P1"),
        "p2": Port("Pa", "pressure at inlet P2"),
        "p3": Port("Pa", "pressure at the outlet P3"),
    }
    OUTPUTS = {
        "Q1": Output("m^3/s", "flow into the valve at P1"),
        "Q2": Output("m^3/s", "flow into the valve at P2"),
        "Q3": Output("m^3/s", "flow out of the valve at P3 into its line"),
        "out": Output("", "the open inlet: -1 for P1, 1 for P2 (Hopsan's output)"),
    }
    HYDRAULIC = {
        "P1": Hydraulic("p1", "Q1", "inlet 1", into=True),
        "P2": Hydraulic("p2", "Q2", "inlet 2", into=True),
        "P3": Hydraulic("p3", "Q3", "outlet (the higher of the inlets' pressures)", into=False),
    }

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        first = u["p1"] > u["p2"]
        q3 = laminar_flow(p["G_open"], bk.fmax(u["p1"], u["p2"]) - u["p3"])
        return {
            "Q1": bk.if_else(first, q3, 0.0),
            "Q2": bk.if_else(first, 0.0, q3),
            "Q3": q3,
            "out": bk.if_else(first, -1.0, 1.0),
        }

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """The shuttle crossing over: the inlets' pressures equal."""
        return {"shuttle": (u["p1"] - u["p2"], 1e5)}
