"""The shuttle valve: an outlet joined to whichever of its two inlets has the higher pressure (load sensing's
"OR" of load pressures)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo.components.base import Component, Hydraulic, Output, Param, Port, register
from hydroservo.laws.orifice import laminar_flow
from hydroservo.laws.pressure_valve import opening_fraction

__all__ = ["ShuttleValve"]


@register
class ShuttleValve(Component):
    r"""Shuttle valve: the outlet ``P3`` joined to the inlet of higher pressure, ``P1`` or ``P2``; the other is shut.

    .. math:: Q_1 = s\,G_{open}\,(p_1 - p_3),\qquad Q_2 = (1 - s)\,G_{open}\,(p_2 - p_3),\qquad
              Q_3 = Q_1 + Q_2

    (:func:`hydroservo.laws.orifice.laminar_flow` through the open seat) with :math:`s` the opening of inlet 1:
    1 once :math:`p_1 - p_2 \ge` ``dp_shift``/2, 0 once it is :math:`\le -` ``dp_shift``/2, between them the
    rounded ramp of :func:`hydroservo.laws.pressure_valve.opening_fraction`. The ball (or shuttle) is taken as
    massless: it sits on the seat of the lower inlet at every instant, as in a load-sensing circuit's chain of
    shuttle valves, which passes the highest load pressure on to the pump's regulator; within ``dp_shift`` of
    balance it floats between its seats. The flow may go either way through the open inlet (the outlet line
    drains back into it when its pressure falls).

    Hopsan's HydraulicShuttleValve ([Hopsan2026] Hydraulic/Valves/HydraulicShuttleValve.hpp) joins the outlet to
    the higher inlet without resistance: its TLM step writes the outlet's flow as
    :math:`(c_{in} - c_3)/(Z_{c,in} + Z_{c,3})`, the flow of an ideal connection between the two nodes' wave
    variables, whose limit for a vanishing step is :math:`p_3 = \max(p_1, p_2)`. An ODE model cannot hold a
    volume's pressure equal to another's without a path between them; ``G_open`` is that path, large enough
    that the outlet follows within :math:`Q_3/G_{open}` (17 Pa per L/min at the default) and with a time
    constant :math:`V/(\beta_e G_{open})` (1e-8 s on a 1e-5 m³ line) far below anything the circuit does.
    The output ``out`` is Hopsan's: -1 while P1 is the open inlet, 1 while P2 is.

    Hopsan's shuttle switches at :math:`p_1 = p_2` (P1 while :math:`p_1 > p_2`), where :math:`Q_3` is continuous
    but the inlet it is drawn from changes; ``dp_shift`` (100 Pa by default) rounds that switch, so that two lines
    at one pressure (idle valves of a load-sensing circuit) do not toggle it at every step: the outlet is within
    :math:`G_{open}\,` ``dp_shift``/4 of following the higher inlet there, and exactly on it elsewhere.
    """

    PARAMETERS = {
        "G_open": Param(1e-6, "m^3/s/Pa", "conductance of the open seat (Hopsan's: ideal)", min=0.0, min_inclusive=False),
        "dp_shift": Param(100.0, "Pa", "inlet pressure difference over which the ball shifts", min=0.0,
                          min_inclusive=False),
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
        "out": Output("", "the open inlet: -1 for P1, 1 for P2 (Hopsan's output; between them while the ball shifts)"),
    }
    HYDRAULIC = {
        "P1": Hydraulic("p1", "Q1", "inlet 1", into=True),
        "P2": Hydraulic("p2", "Q2", "inlet 2", into=True),
        "P3": Hydraulic("p3", "Q3", "outlet (the higher of the inlets' pressures)", into=False),
    }

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        s = opening_fraction(u["p1"] - u["p2"], -0.5 * p["dp_shift"], p["dp_shift"])
        q1 = s * laminar_flow(p["G_open"], u["p1"] - u["p3"])
        q2 = (1.0 - s) * laminar_flow(p["G_open"], u["p2"] - u["p3"])
        return {"Q1": q1, "Q2": q2, "Q3": q1 + q2, "out": 1.0 - 2.0 * s}
