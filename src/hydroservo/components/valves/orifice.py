"""Fixed restrictions: the sharp-edged orifice, turbulent with its laminar transition, and the laminar one."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.components.base import Component, Option, Output, Param, Port, register
from hydroservo.components.valves.ports import FLUID_PARAMETERS, TWO_PORT_HYDRAULIC, TWO_PORT_PRESSURES
from hydroservo.laws.orifice import (
    DISCHARGE_COEFFICIENT,
    blended_flow,
    laminar_flow,
    orifice_flow,
    transition_pressure,
)

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

    Option ``law``: ``transition`` (default), the law above; ``blend``, the laminar and turbulent resistances
    added as an ``n_blend``-norm (:func:`hydroservo.laws.orifice.blended_flow`):

    .. math:: Q = \frac{A\,\Delta p}{\big(k_{lam}^{-n} + (\rho|\Delta p|/2)^{n/2} C_d^{-n}\big)^{1/n}}

    laminar (:math:`Q = k_{lam} A \Delta p`) at small drops, turbulent at large ones: Hopsan's orifices with
    geometric parameters ([Hopsan2026] Hydraulic/Restrictors/HydraulicOrificeG.hpp and
    Hydraulic/Special/HydraulicOrificeCheckValveG.hpp with n = 2, Hydraulic/Special/HydraulicSlitOrifice.hpp with
    n = 4). ``lambda_crit`` and ``nu`` then do not enter.

    ``d_back`` > 0 is the bore for flow from B to A (a check valve whose back flow passes a different bore,
    Hopsan's HydraulicOrificeCheckValveG); 0, the default, is ``d`` both ways. The area switches at
    :math:`\Delta p = 0`, where the flow is 0 either way, so the flow stays continuous.
    """

    OPTIONS = {
        "area": Option("bore", ("bore", "input"), "the bore's area, or the input A_in's"),
        "law": Option("transition", ("transition", "blend"), "turbulent with its laminar transition, or the "
                      "laminar and turbulent resistances blended"),
    }
    PARAMETERS = {
        "d": Param(1e-3, "m", "bore diameter", min=0.0, min_inclusive=False),
        "Cd": Param(DISCHARGE_COEFFICIENT, "", "discharge coefficient", min=0.0, max=1.0, min_inclusive=False),
        **FLUID_PARAMETERS,
        "d_back": Param(0.0, "m", "bore diameter for flow from B to A (0: d)", min=0.0),
        "k_lam": Param(5e-4, "m/s/Pa", "laminar flow per unit of area and of pressure drop (law = blend)", min=0.0,
                       min_inclusive=False),
        "n_blend": Param(2.0, "", "exponent of the resistances' sum (law = blend)", min=1.0),
    }
    INPUTS = {**TWO_PORT_PRESSURES, "A_in": Port("m^2", "the orifice's area (option area = input)", default=0.0)}
    OUTPUTS = {"Q": Output("m^3/s", "flow from A to B")}
    HYDRAULIC = dict(TWO_PORT_HYDRAULIC)

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        dp = u["pA"] - u["pB"]
        if self.option("area") == "input":
            area = bk.fabs(u["A_in"])
        else:
            d_back = bk.if_else(p["d_back"] > 0.0, p["d_back"], p["d"])
            area = np.pi * bk.if_else(dp >= 0.0, p["d"], d_back) ** 2 / 4.0
        if self.option("law") == "blend":
            return {"Q": blended_flow(area, dp, p["rho"], p["Cd"], p["k_lam"], p["n_blend"])}
        p_tr = transition_pressure(p["d"], p["rho"], p["nu"], p["lambda_crit"])
        return {"Q": orifice_flow(area, dp, p["rho"], p["Cd"], p_tr)}


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
