"""Gas-loaded accumulators: oil stored against a pre-charged, polytropically compressed gas."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo import backend as bk
from hydroservo.components.base import Component, Hydraulic, Limit, Option, Output, Param, Port, State, register
from hydroservo.laws.accumulator import gas_capacitance, gas_pressure, gas_volume
from hydroservo.laws.chamber import pressure_rate
from hydroservo.laws.pressure_valve import limited_rate, opening_fraction
from hydroservo.laws.stops import end_stop_force
from hydroservo.units import VACUUM

__all__ = ["Accumulator"]

#: Width of the rounded corner at the pre-charge, as a fraction of the absolute pre-charge pressure.
CORNER = 0.01
#: With ``inlet = "laminar"``, the time over which the oil stored settles on a bound (empty, full) [s]: the
#: oil that passes in it, the flow times 1 µs, is far below what a pressure in the circuit responds to.
STOP_TIME = 1e-6


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

    Option ``inlet``: ``open`` (default), the above; ``laminar``, the oil
    enters through a laminar inlet of conductance ``K_ca`` and the oil stored
    is the state:

    .. math:: \dot V_{oil} = Q = K_{ca}\,(p_P - p_g), \qquad
              p_g = p_0 \Big(\frac{V_0}{\max(V_0 - V_{oil},\, V_{g,min})}\Big)^{\kappa}\ \text{(absolute)}

    with :math:`V_{oil}` held in :math:`[0, V_0]` (empty: no flow out; full:
    none in; :func:`~hydroservo.laws.pressure_valve.limited_rate`, settling
    on a bound within 1 µs). Its port then takes the node's pressure and
    gives the flow; output ``p`` is the gas pressure, ``V_gas`` the gas
    volume. This is [Hopsan2026] Hydraulic/Volumes&Lines/HydraulicAckumulator.hpp
    (its state of charge :math:`x = V_{oil}/V_0`, integrated there by the
    trapezoidal rule and limited to [0, 1], the gas volume to at least
    0.1 :math:`V_0`). The gas law is the same in both; the laminar inlet
    makes a Q-type accumulator of it, which is empty below the pre-charge
    rather than compressing its port's oil.

    ``inlet = "piston"``: a piston of area ``A_p`` and mass ``m_p`` separates
    the oil from the gas; the accumulator's stroke is :math:`V_0/A_p`:

    .. math:: m_p\ddot x_p = A_p (p_P - p_g) - B_p\dot x_p + F_{stop}, \qquad Q = A_p\dot x_p,
              \qquad V_{oil} = A_p x_p

    with the gas law above and end stops at 0 and the stroke
    (:func:`~hydroservo.laws.stops.end_stop_force`, ``k_stop``, ``c_stop``).
    This is [Hopsan2026] Hydraulic/Volumes&Lines/HydraulicPistonAckumulator.hpp
    (its bilinear transform of the piston's motion, its position clamped to the
    stroke and its velocity zeroed there: inelastic stops, which the stiff
    spring-damper approaches; its gas volume at least 0.001 :math:`V_0`).
    """

    OPTIONS = {
        "inlet": Option(
            "open", ("open", "laminar", "piston"),
            "oil straight into the gas spring, through a laminar inlet, or against a piston with mass",
        ),
    }

    PARAMETERS = {
        "V0": Param(1e-3, "m^3", "gas volume at pre-charge (nominal size)", min=0.0, min_inclusive=False),
        "p0": Param(50e5, "Pa", "gas pre-charge pressure (gauge)", min=VACUUM, min_inclusive=False),
        "kappa": Param(1.4, "", "polytropic exponent: 1 isothermal (slow), 1.4 adiabatic (fast)", min=1.0, max=1.67),
        "V_dead": Param(1e-5, "m^3", "oil volume in the port and connection", min=0.0, min_inclusive=False),
        "beta_e": Param(1.4e9, "Pa", "bulk modulus of the oil in the port", min=0.0, min_inclusive=False, fluid="bulk_modulus"),
        "p_init": Param(0.0, "Pa", "initial oil pressure (gauge)", min=VACUUM),
        "K_ca": Param(1e-8, "m^3/s/Pa", "conductance of the laminar inlet (option inlet = laminar)", min=0.0,
                      min_inclusive=False),
        "V_gmin": Param(1e-4, "m^3", "smallest gas volume (options inlet = laminar, piston; Hopsan's 0.1 V0, 0.001 V0)",
                        min=0.0, min_inclusive=False),
        "A_p": Param(1e-3, "m^2", "piston area (option inlet = piston)", min=0.0, min_inclusive=False),
        "m_p": Param(1.0, "kg", "piston mass (option inlet = piston)", min=0.0, min_inclusive=False),
        "B_p": Param(10.0, "N*s/m", "piston's viscous friction (option inlet = piston)", min=0.0),
        "k_stop": Param(1e9, "N/m", "stiffness of the piston's end stops (option inlet = piston)", min=0.0),
        "c_stop": Param(1e6, "N*s/m", "damping of the piston's end stops (option inlet = piston)", min=0.0),
    }
    STATES = {"p": State("Pa", "oil pressure", initial="p_init", nominal=1e7)}
    INPUTS = {"Q": Port("m^3/s", "flow into the accumulator through port P", default=0.0)}
    OUTPUTS = {
        "p": Output("Pa", "oil pressure"),
        "V_oil": Output("m^3", "oil stored (V0 minus the gas volume)"),
    }
    HYDRAULIC = {"P": Hydraulic("p", "Q", "oil port")}
    LIMITS = {"p": Limit("pressure")}

    def options_changed(self) -> None:
        cls = type(self)
        if self.option("inlet") != "open":
            if self.option("inlet") == "laminar":
                self.STATES = {  # type: ignore[misc]
                    "V_oil": State("m^3", "oil stored (V0 minus the gas volume)", nominal=1e-3)
                }
            else:
                self.STATES = {  # type: ignore[misc]
                    "x_p": State("m", "piston position from empty", nominal=0.1),
                    "v_p": State("m/s", "piston velocity (filling)", nominal=0.1),
                }
            self.INPUTS = {"pP": Port("Pa", "pressure at port P")}  # type: ignore[misc]
            self.OUTPUTS = {  # type: ignore[misc]
                "Q": Output("m^3/s", "flow into the accumulator through port P"),
                "p": Output("Pa", "gas pressure"),
                "V_oil": Output("m^3", "oil stored (V0 minus the gas volume)"),
                "V_gas": Output("m^3", "gas volume"),
            }
            self.HYDRAULIC = {"P": Hydraulic("pP", "Q", "oil port")}  # type: ignore[misc]
            self.LIMITS = {}  # type: ignore[misc]
        else:
            for key in ("STATES", "INPUTS", "OUTPUTS", "HYDRAULIC", "LIMITS"):
                setattr(self, key, getattr(cls, key))

    def _oil(self, x: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        return x["V_oil"] if self.option("inlet") == "laminar" else p["A_p"] * x["x_p"]

    def _gas(self, x: Mapping[str, Any], p: Mapping[str, Any]) -> tuple[Any, Any]:
        """The gas volume and pressure of the laminar inlet's or the piston's accumulator."""
        V_g = bk.fmax(p["V0"] - self._oil(x, p), p["V_gmin"])
        return V_g, gas_pressure(V_g, p["p0"], p["V0"], p["kappa"])

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        if self.option("inlet") != "open":
            V_g, p_g = self._gas(x, p)
            if self.option("inlet") == "laminar":
                Q = limited_rate(x["V_oil"], p["K_ca"] * (u["pP"] - p_g), p["V0"], STOP_TIME)
            else:
                Q = p["A_p"] * x["v_p"]
            V_oil = self._oil(x, p)
            return {"Q": Q, "p": p_g, "V_oil": V_oil, "V_gas": p["V0"] - V_oil}
        return {"p": x["p"], "V_oil": p["V0"] - gas_volume(x["p"], p["p0"], p["V0"], p["kappa"])}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        if self.option("inlet") == "laminar":
            return {"V_oil": y["Q"]}
        if self.option("inlet") == "piston":
            force = p["A_p"] * (u["pP"] - y["p"]) - p["B_p"] * x["v_p"] + end_stop_force(
                x["x_p"], x["v_p"], 0.0, p["V0"] / p["A_p"], p["k_stop"], p["c_stop"]
            )
            return {"x_p": x["v_p"], "v_p": force / p["m_p"]}
        band = CORNER * (p["p0"] - VACUUM)
        w = opening_fraction(x["p"], p["p0"] - band / 2, band)
        C = p["V_dead"] / p["beta_e"] + w * gas_capacitance(x["p"], p["p0"], p["V0"], p["kappa"])
        return {"p": pressure_rate(1.0, C, u["Q"])}
