"""A massless spool or poppet whose speed is the flow through its damping orifice."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo import backend as bk
from hydroservo.components.base import Component, Hydraulic, Option, Output, Param, Port, State, register
from hydroservo.errors import ParameterError
from hydroservo.laws.pressure_valve import limited_rate
from hydroservo.laws.spool_dynamics import damping_orifice_flow

__all__ = ["SpoolOrificeDamped"]


@register
class SpoolOrificeDamped(Component):
    r"""A massless spool or poppet held by its pilot pressures and spring, its speed the flow through a damping orifice.

    The pressures at ports 1 and 2 push the spool open on the areas ``A_1`` and ``A_2``; its spring (pre-load
    ``F_0``, stiffness ``k_s``) holds it back. Without mass it is in force balance at every instant, so its end
    chamber (area ``A_c``) is at :math:`p_c = (A_1 p_1 + A_2 p_2 - F_0 - k_s x)/A_c`, and it moves as fast as the
    chamber's oil passes the damping orifice to port C
    (:func:`hydroservo.laws.spool_dynamics.damping_orifice_flow`):

    .. math:: A_c \dot x = Q_C = K_d\,\frac{p_c - p_C}{((p_c - p_C)^2 + p_{tr}^2)^{1/4}},
              \qquad x \in [x_{min}, x_{max}]

    stopped at its bounds without wind-up over ``t_stop``
    (:func:`hydroservo.laws.pressure_valve.limited_rate`). The turbulent orifice is regularised below ``p_tr``
    (the spool rests where :math:`p_c = p_C`, at the null of the orifice's law). Hopsan's Hydraulic22PoppetValve
    (its spring chamber drained through the orifice d_d to PC) and Hydraulic33ShuttleValve (the spool between
    two damping orifices, from P and to T: in series one orifice of
    :math:`K_1 K_2/\sqrt{K_1^2 + K_2^2}`) import as this spool ([Hopsan2026]
    Hydraulic/Valves/Hydraulic22PoppetValve.hpp, Hydraulic/Valves/Hydraulic33ShuttleValve.hpp; docs/hopsan.md).

    Ports 1 and 2 take no flow. ``Q_C``, the orifice's flow out of the chamber into port C, is Hopsan's: it flows
    also while the spool rests at a bound (Hopsan's poppet writes the orifice's flow to PC whether or not its
    limited integrator moves). Option ``damping_flow``: ``port`` (default), ``Q_C`` is taken from port C;
    ``none``, port C only reads its pressure (Hopsan's Hydraulic33ShuttleValve, whose end chambers' oil it counts
    at no port). Pressures are gauge here: a spool whose areas ``A_1 + A_2`` differ from ``A_c`` sees the
    atmosphere's force on the difference, to be added to ``F_0``.
    """

    OPTIONS = {"damping_flow": Option("port", ("port", "none"), "the damping orifice's oil taken from port C, or not")}
    PARAMETERS = {
        "A_1": Param(7.85e-5, "m^2", "area on which port 1's pressure opens the spool"),
        "A_2": Param(0.0, "m^2", "area on which port 2's pressure opens the spool"),
        "A_c": Param(7.85e-5, "m^2", "area of the end chamber", min=0.0, min_inclusive=False),
        "F_0": Param(0.0, "N", "spring pre-load"),
        "k_s": Param(0.0, "N/m", "spring stiffness", min=0.0),
        "K_d": Param(2.5e-10, "m^3/s/Pa^0.5", "flow coefficient of the damping orifice", min=0.0, min_inclusive=False),
        "p_tr": Param(100.0, "Pa", "transition pressure of the damping orifice's law", min=0.0, min_inclusive=False),
        "x_min": Param(0.0, "m", "lower bound of the spool"),
        "x_max": Param(0.01, "m", "upper bound of the spool"),
        "x0": Param(0.0, "m", "initial position"),
        "t_stop": Param(1e-5, "s", "time over which the spool's approach to a bound is relaxed", min=0.0,
                        min_inclusive=False),
    }
    STATES = {"x": State("m", "spool position", initial="x0", nominal=1e-3)}
    INPUTS = {
        "p1": Port("Pa", "pressure at port 1"),
        "p2": Port("Pa", "pressure at port 2", default=0.0),
        "pC": Port("Pa", "pressure at port C, beyond the damping orifice"),
    }
    OUTPUTS = {
        "xv": Output("m", "spool position"),
        "QC": Output("m^3/s", "flow out of the chamber into port C"),
        "Q1": Output("m^3/s", "flow at port 1 (none)"),
        "Q2": Output("m^3/s", "flow at port 2 (none)"),
    }
    HYDRAULIC = {
        "P1": Hydraulic("p1", "Q1", "pilot port 1", into=True),
        "P2": Hydraulic("p2", "Q2", "pilot port 2", into=True),
        "C": Hydraulic("pC", "QC", "port C, beyond the damping orifice", into=False),
    }

    def check(self) -> None:
        v = self.values
        if v["x_min"] >= v["x_max"]:
            raise ParameterError(f"{self.name}.x_min = {v['x_min']:g} m: expected below x_max = {v['x_max']:g} m")

    def _flow(self, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> tuple[Any, Any]:
        xv = bk.fmin(bk.fmax(x["x"], p["x_min"]), p["x_max"])
        force = p["A_1"] * u["p1"] + p["A_2"] * u["p2"] - p["F_0"] - p["k_s"] * xv
        return xv, damping_orifice_flow(force, p["A_c"], u["pC"], p["K_d"], p["p_tr"])

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        xv, q = self._flow(x, u, p)
        q_c = q if self.option("damping_flow") == "port" else 0.0
        return {"xv": xv, "QC": q_c, "Q1": 0.0, "Q2": 0.0}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        _, q = self._flow(x, u, p)
        rate = q / p["A_c"]
        return {"x": limited_rate(x["x"] - p["x_min"], rate, p["x_max"] - p["x_min"], p["t_stop"])}
