"""Fixed restrictions: the sharp-edged orifice, turbulent with its laminar transition, and the laminar one."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.components.base import Component, Option, Output, Param, Port, register
from hydroservo.components.valves.ports import FLUID_PARAMETERS, TWO_PORT_HYDRAULIC, TWO_PORT_PRESSURES
from hydroservo.laws.orifice import DISCHARGE_COEFFICIENT, laminar_flow, orifice_flow, transition_pressure

__all__ = ["Orifice", "LaminarOrifice"]


@register
class Orifice(Component):
    r"""Sharp-edged orifice of diameter ``d``: turbulent flow with a laminar transition at small pressure drops.

    .. math:: Q = C_d A \sqrt{2/\rho}\;\frac{\Delta p}{(\Delta p^2 + p_{tr}^2)^{1/4}},
              \qquad A = \pi d^2/4,\quad \Delta p = p_A - p_B

    the turbulent law of [Efe2014] eqs. (3.5), (3.6) with the package's one
    regularisation at null (:func:`hydroservo.laws.orifice.orifice_flow`):
    :math:`p_{tr}` is the drop at which the flow number of [MareAttarND] eq. (4),
    with the bore as hydraulic diameter, reaches ``lambda_crit``
    (:func:`hydroservo.laws.orifice.transition_pressure`). Below it the flow is
    proportional to the drop, as laminar flow is.

    Option ``area``: ``bore`` (default), :math:`A = \pi d^2/4`; ``input``,
    :math:`A = |A_{in}|`, the input ``A_in`` (a signal that opens and closes
    the orifice, as Hopsan's HydraulicTurbulentOrifice takes its area
    ([Hopsan2026] Hydraulic/Restrictors/HydraulicTurbulentOrifice.hpp); ``d``
    then sets only the laminar transition).
    """

    OPTIONS = {"area": Option("bore", ("bore", "input"), "the bore's area, or the input A_in's")}
    PARAMETERS = {
        "d": Param(1e-3, "m", "bore diameter", min=0.0, min_inclusive=False),
        "Cd": Param(DISCHARGE_COEFFICIENT, "", "discharge coefficient", min=0.0, max=1.0, min_inclusive=False),
        **FLUID_PARAMETERS,
    }
    INPUTS = {**TWO_PORT_PRESSURES, "A_in": Port("m^2", "the orifice's area (option area = input)", default=0.0)}
    OUTPUTS = {"Q": Output("m^3/s", "flow from A to B")}
    HYDRAULIC = dict(TWO_PORT_HYDRAULIC)

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        p_tr = transition_pressure(p["d"], p["rho"], p["nu"], p["lambda_crit"])
        area = bk.fabs(u["A_in"]) if self.option("area") == "input" else np.pi * p["d"] ** 2 / 4.0
        return {"Q": orifice_flow(area, u["pA"] - u["pB"], p["rho"], p["Cd"], p_tr)}


@register
class LaminarOrifice(Component):
    r"""Laminar restriction: :math:`Q = (G_{lam} + u)\,(p_A - p_B)` (:func:`hydroservo.laws.orifice.laminar_flow`), a
    capillary, a long narrow passage, or Hopsan's HydraulicLaminarOrifice ([Hopsan2026]); the input ``u`` is a
    signal that varies the coefficient (a load of Hopsan's examples)."""

    PARAMETERS = {"G_lam": Param(1e-11, "m^3/s/Pa", "laminar conductance (pressure-flow coefficient)", min=0.0)}
    INPUTS = {**TWO_PORT_PRESSURES, "u": Port("m^3/s/Pa", "conductance added to G_lam (a signal)", default=0.0)}
    OUTPUTS = {"Q": Output("m^3/s", "flow from A to B")}
    HYDRAULIC = dict(TWO_PORT_HYDRAULIC)

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"Q": laminar_flow(bk.fabs(p["G_lam"] + u["u"]), u["pA"] - u["pB"])}
