"""Gas-loaded accumulators: oil stored against a pre-charged, polytropically compressed gas."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo.components.base import Component, Hydraulic, Limit, Output, Param, Port, State, register
from hydroservo.laws.accumulator import gas_capacitance, gas_volume
from hydroservo.laws.chamber import pressure_rate
from hydroservo.laws.pressure_valve import opening_fraction
from hydroservo.units import VACUUM

__all__ = ["Accumulator"]

#: Width of the rounded corner at the pre-charge, as a fraction of the absolute pre-charge pressure.
CORNER = 0.01


@register
class Accumulator(Component):
    r"""Gas-loaded (bladder or piston) accumulator of size ``V0`` pre-charged to ``p0``.

    Its pressure port gives the oil pressure :math:`p` and takes the flow in:

    .. math:: \dot p = \frac{Q}{C(p)}, \qquad
              C(p) = \frac{V_{dead}}{\beta_e} + w(p)\,\frac{V_g(p)}{\kappa\,p_{abs}}

    with the polytropic gas volume :math:`V_g` of
    :mod:`hydroservo.laws.accumulator`: above the pre-charge the gas spring
    takes the oil; below it the accumulator is empty and only the oil in its
    port (``V_dead``) is compressed. :math:`w` rounds the corner at
    the pre-charge over 1 % of its absolute pressure (the gas does not act
    until the pressure exceeds it). Output ``V_oil`` is the oil stored,
    :math:`V_0 - V_g`.
    """

    PARAMETERS = {
        "V0": Param(1e-3, "m^3", "gas volume at pre-charge (nominal size)", min=0.0, min_inclusive=False),
        "p0": Param(50e5, "Pa", "gas pre-charge pressure (gauge)", min=VACUUM, min_inclusive=False),
        "kappa": Param(1.4, "", "polytropic exponent: 1 isothermal (slow), 1.4 adiabatic (fast)", min=1.0, max=1.67),
        "V_dead": Param(1e-5, "m^3", "oil volume in the port and connection", min=0.0, min_inclusive=False),
        "beta_e": Param(1.4e9, "Pa", "bulk modulus of the oil in the port", min=0.0, min_inclusive=False, fluid="bulk_modulus"),
        "p_init": Param(0.0, "Pa", "initial oil pressure (gauge)", min=VACUUM),
    }
    STATES = {"p": State("Pa", "oil pressure", initial="p_init", nominal=1e7)}
    INPUTS = {"Q": Port("m^3/s", "flow into the accumulator through port P", default=0.0)}
    OUTPUTS = {
        "p": Output("Pa", "oil pressure"),
        "V_oil": Output("m^3", "oil stored (V0 minus the gas volume)"),
    }
    HYDRAULIC = {"P": Hydraulic("p", "Q", "oil port")}
    LIMITS = {"p": Limit("pressure")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"p": x["p"], "V_oil": p["V0"] - gas_volume(x["p"], p["p0"], p["V0"], p["kappa"])}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        band = CORNER * (p["p0"] - VACUUM)
        w = opening_fraction(x["p"], p["p0"] - band / 2, band)
        C = p["V_dead"] / p["beta_e"] + w * gas_capacitance(x["p"], p["p0"], p["V0"], p["kappa"])
        return {"p": pressure_rate(1.0, C, u["Q"])}
