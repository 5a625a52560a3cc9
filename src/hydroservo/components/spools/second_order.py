"""Second-order spool dynamics with stroke limit."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.components.base import Component, Output, Param, Port, State, register
from hydroservo.laws.spool_dynamics import second_order_spool_acceleration

__all__ = ["SpoolSecondOrder"]


@register
class SpoolSecondOrder(Component):
    r"""Second-order spool dynamics with stroke limit.

    :math:`\ddot s = \omega_n^2(\operatorname{sat}(u) - s) - 2\zeta\omega_n \dot s`,
    :math:`x_v = x_{v,max}\,\operatorname{clip}(s, -1, 1)`: the command is
    saturated to the stroke and the delivered position clipped to it
    (:func:`hydroservo.laws.spool_dynamics.second_order_spool_acceleration`).
    """

    RENAMED = {"x_max": "xv_max"}
    PARAMETERS = {
        "omega_n": Param(2 * np.pi * 80, "rad/s", "natural frequency", min=0.0, min_inclusive=False),
        "zeta": Param(0.7, "", "damping ratio", min=0.0),
        "xv_max": Param(1e-3, "m", "spool stroke at |u| = 1", min=0.0, min_inclusive=False),
    }
    STATES = {
        "s": State("", "relative spool position", nominal=1.0),
        "sdot": State("1/s", "relative spool velocity", nominal=1e3),
    }
    INPUTS = {"u": Port("", "relative command, -1 to 1")}
    OUTPUTS = {"xv": Output("m", "spool position"), "vv": Output("m/s", "spool velocity")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"xv": p["xv_max"] * bk.clip(x["s"], -1.0, 1.0), "vv": p["xv_max"] * x["sdot"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        acc = second_order_spool_acceleration(u["u"], x["s"], x["sdot"], p["omega_n"], p["zeta"])
        return {"s": x["sdot"], "sdot": acc}
