r"""Four-way staged-slot spool valve of [MareAttarND]: geometry and fluid temperature in, flows out.

The Wheatstone bridge of four orifices (Fig. 1), each a staged slot (Fig. 5)
following the 9-parameter law of Table 1 with its own lap: see
:func:`hydroservo.laws.staged_slot.staged_slot_orifice_flow`. The fluid's density and
viscosity are evaluated at the fluid temperature ``temperature`` (a parameter,
so it can be swept) and at the mean of supply and return pressures, the same
for the four orifices (the paper does not say where; this choice keeps a
symmetric valve symmetric: useport pressures at exactly half supply at null).

The same component is what the static test bench measures
(:mod:`hydroservo.analysis.static_bench`) and what identification fits
(:mod:`hydroservo.identification.staged_slot`): both call
:meth:`StagedSlotValve.orifice_flow`, the law with the component's values.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo.components.base import REGISTRY, Component, FromSet, Option, Param, Port, register
from hydroservo.components.valves.ports import FLOW_OUTPUTS, HYDRAULIC_PORTS, PRESSURE_PORTS
from hydroservo.errors import ParameterError
from hydroservo.fluids import FLUIDS, Fluid, get_fluid
from hydroservo.laws.staged_slot import BRIDGE, BRIDGE_PARAMETERS, staged_slot_orifice_flow, staged_slot_valve_flows

__all__ = ["StagedSlotValve"]

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


def _parameters() -> dict[str, Param]:
    out = {
        key: Param(FromSet("MareAttarND_example", "valve", key), unit, text, **_LIMITS.get(key, {}))
        for key, (unit, text) in BRIDGE_PARAMETERS.items()
    }
    out["temperature"] = Param(-15.0, "degC", "fluid temperature", min=-273.15, min_inclusive=False)
    out["p_tr"] = Param(
        1.0, "Pa", "regularisation of |dp| at zero drop (numerical: leaves the laminar slope unchanged)", min=0.0
    )
    return out


@register
class StagedSlotValve(Component):
    """Four-way staged-slot spool valve, [MareAttarND] Table 1 and Figs. 1 and 5, at fluid temperature ``temperature``.

    Orifices: a (supply to A), b (A to tank), c (supply to B), d (B to tank);
    ``X_i0`` > 0 is an underlap (open at null), < 0 an overlap. Defaults:
    hydroservo's example aerospace valve (parameter set ``MareAttarND_example``,
    not published) in Skydrol at -15 degC. Formerly ``MareSpoolValve``.
    """

    RENAMED = {"T": "temperature"}
    PARAMETERS = _parameters()
    INPUTS = {
        "xv": Port("m", "spool position from hydraulic null"),
        **PRESSURE_PORTS,
    }
    OUTPUTS = dict(FLOW_OUTPUTS)
    HYDRAULIC = dict(HYDRAULIC_PORTS)
    OPTIONS = {"fluid": Option("skydrol", tuple(FLUIDS), "hydraulic fluid (hydroservo.fluids)")}

    @property
    def fluid(self) -> Fluid:
        """The hydraulic fluid (option ``fluid``)."""
        return get_fluid(self.option("fluid"))

    def bridge_parameters(self) -> dict[str, float]:
        """The geometry and flow parameters of the bridge (SI), :data:`~hydroservo.laws.staged_slot.BRIDGE_PARAMETERS`."""
        return {k: self.values[k] for k in BRIDGE_PARAMETERS}

    def fluid_properties(self, p_S: Any, p_T: Any, temperature: Any) -> tuple[Any, Any]:
        """Density [kg/m^3] and kinematic viscosity [m^2/s] at the mean of supply and return pressures [Pa]."""
        p_mean = 0.5 * (p_S + p_T)
        fluid = self.fluid
        return fluid.density(p_mean, temperature), fluid.kinematic_viscosity(p_mean, temperature)

    def orifice_flow(self, i: str, X: Any, p_up: Any, p_down: Any, props: tuple[Any, Any], p_tr: Any = 0.0) -> Any:
        """Flow through orifice ``i`` at openings ``X`` [m] with this valve's values (NumPy), fluid ``props`` (rho, nu)."""
        return staged_slot_orifice_flow(i, X, p_up, p_down, self.values, *props, p_tr)

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
        self.fluid.check_range(0.0, v["temperature"])

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        rho, nu = self.fluid_properties(u["pS"], u["pT"], p["temperature"])
        QA, QB, QS, QT = staged_slot_valve_flows(u["xv"], u["pS"], u["pT"], u["pA"], u["pB"], p, rho, nu, p["p_tr"])
        return {"QA": QA, "QB": QB, "QS": QS, "QT": QT}


REGISTRY.renamed["MareSpoolValve"] = "StagedSlotValve"
