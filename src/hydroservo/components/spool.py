r"""Four-way spool valve of seed 002 (Maré & Attar) as a component: geometry and fluid temperature in, flows out.

The Wheatstone bridge of four orifices (Fig. 1), each a staged slot (Fig. 5)
following the 9-parameter law of Table 1 with its own lap: see
:func:`hydroservo.spool_orifices.bridge_orifice_flow`. The fluid's density and
viscosity are evaluated at the fluid temperature ``T`` (a parameter, so it can
be swept) and at the mean of supply and return pressures, the same for the four
orifices (the paper does not say where; this choice keeps a symmetric valve
symmetric: useport pressures at exactly half supply at null). Static characteristics of
the same valve (flow gain, pressure gain, leakage, Table 2):
:mod:`hydroservo.analysis.bench`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo.components.base import Component, Option, Output, Param, Port, register
from hydroservo.errors import ParameterError
from hydroservo.fluid_library import FLUIDS, get_fluid
from hydroservo.parameters.mare_attar_002 import EXAMPLE_VALVE
from hydroservo.spool_orifices import BRIDGE, BRIDGE_PARAMETERS, bridge_orifice_flow
from hydroservo.units import to_si

__all__ = ["MareSpoolValve"]

#: Smoothing of |dp| in the component's orifice laws [Pa]: exact derivatives at
#: zero drop, the laminar slope unchanged (see :func:`hydroservo.spool_orifices.orifice_flow`).
DP_SMOOTH = 1.0

_LIMITS: dict[str, dict[str, Any]] = {
    "w_L": {"min": 0.0, "min_inclusive": False},
    "w_H": {"min": 0.0, "min_inclusive": False},
    "r": {"min": 0.0},
    "c": {"min": 0.0, "min_inclusive": False},
    "n": {"min": 1.0},
    "Cq_inf": {"min": 0.0, "max": 1.0, "min_inclusive": False},
    "lambda_tL": {"min": 0.0, "min_inclusive": False},
    "lambda_tH": {"min": 0.0, "min_inclusive": False},
    **{f"X_{i}0H": {"max": 0.0} for i in BRIDGE},
}


def _params() -> dict[str, Param]:
    out = {}
    for key, (unit, text) in BRIDGE_PARAMETERS.items():
        out[key] = Param(to_si(EXAMPLE_VALVE[key], unit, what=key), unit, text, **_LIMITS.get(key, {}))
    out["T"] = Param(-15.0, "degC", "fluid temperature", min=-273.15, min_inclusive=False)
    return out


@register
class MareSpoolValve(Component):
    """Four-way staged-slot spool valve, seed 002 Table 1 and Figs. 1 and 5, at fluid temperature ``T``.

    Orifices: a (supply to A), b (A to tank), c (supply to B), d (B to tank);
    ``X_i0`` > 0 is an underlap (open at null), < 0 an overlap. Defaults:
    hydroservo's example aerospace valve (:mod:`hydroservo.parameters.mare_attar_002`,
    not published) in Skydrol at -15 degC.
    """

    PARAMETERS = _params()
    INPUTS = {
        "xv": Port("m", "spool position from hydraulic null"),
        "pS": Port("Pa", "supply pressure"),
        "pT": Port("Pa", "tank pressure", default=0.0),
        "pA": Port("Pa", "pressure in line A (use port 1)"),
        "pB": Port("Pa", "pressure in line B (use port 2)"),
    }
    OUTPUTS = {
        "QA": Output("m^3/s", "flow out of port A into line A"),
        "QB": Output("m^3/s", "flow out of port B into line B"),
        "QS": Output("m^3/s", "flow drawn from supply"),
        "QT": Output("m^3/s", "flow returned to tank"),
    }
    OPTIONS = {"fluid": Option("skydrol", tuple(FLUIDS), "hydraulic fluid (hydroservo.fluid_library)")}

    def check(self) -> None:
        v = self.values
        if v["w_H"] < v["w_L"]:
            raise ParameterError(
                f"{self.name}.w_H = {v['w_H']:g} m < w_L = {v['w_L']:g} m: expected the high-gain width "
                ">= the low-gain width (equal: no staging)"
            )
        for i in BRIDGE:
            if v[f"X_{i}0H"] > v[f"X_{i}0"]:
                raise ParameterError(
                    f"{self.name}.X_{i}0H = {v[f'X_{i}0H']:g} m > X_{i}0 = {v[f'X_{i}0']:g} m: expected the "
                    "high-gain stage to open after the low-gain one (X_i0H <= X_i0)"
                )
        get_fluid(self.option("fluid")).check_range(0.0, v["T"])

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        fluid = get_fluid(self.option("fluid"))
        p_mean = 0.5 * (u["pS"] + u["pT"])
        rho, nu = fluid.density(p_mean, p["T"]), fluid.kinematic_viscosity(p_mean, p["T"])
        nodes = {"S": u["pS"], "R": u["pT"], "1": u["pA"], "2": u["pB"]}
        q = {
            i: bridge_orifice_flow(i, u["xv"], nodes[up], nodes[down], p, rho, nu, DP_SMOOTH)
            for i, (up, down, _) in BRIDGE.items()
        }
        return {"QA": q["a"] - q["b"], "QB": q["c"] - q["d"], "QS": q["a"] + q["c"], "QT": q["b"] + q["d"]}
