"""First-order spool dynamics from a catalogue response time."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo.components.base import Component, Output, Param, Port, State, register
from hydroservo.laws.spool_dynamics import first_order_spool_rate

__all__ = ["SpoolFirstOrder"]


@register
class SpoolFirstOrder(Component):
    r"""First-order spool dynamics from a catalogue response time.

    :math:`\tau\,\dot s + s = \operatorname{sat}(u)`, :math:`x_v = x_{v,max} s`, with
    the command saturated to :math:`[-1, 1]` (the stroke limit):
    :func:`hydroservo.laws.spool_dynamics.first_order_spool_rate`, [Efe2014]
    eqs. (3.24)-(3.28). ``tau`` is the catalogue :math:`T_{63}`.
    """

    RENAMED = {"T": "tau", "x_max": "xv_max"}
    PARAMETERS = {
        "tau": Param(0.03, "s", "time constant (catalogue T63)", min=0.0, min_inclusive=False),
        "xv_max": Param(1e-3, "m", "spool stroke at |u| = 1", min=0.0, min_inclusive=False),
        "s0": Param(0.0, "", "initial relative spool position", min=-1.0, max=1.0),
    }
    STATES = {"s": State("", "relative spool position", initial="s0", nominal=1.0)}
    INPUTS = {"u": Port("", "relative command, -1 to 1")}
    OUTPUTS = {"xv": Output("m", "spool position"), "vv": Output("m/s", "spool velocity")}

    def _rate(self, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        return first_order_spool_rate(u["u"], x["s"], p["tau"])

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"xv": p["xv_max"] * x["s"], "vv": p["xv_max"] * self._rate(x, u, p)}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"s": self._rate(x, u, p)}
