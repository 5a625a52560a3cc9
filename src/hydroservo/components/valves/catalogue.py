"""A servovalve as a catalogue describes it: rated flow, and a transfer function of first, second or third order."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo.components.base import Component, Option, Output, Param, Port, State, register
from hydroservo.components.valves.ports import FLOW_OUTPUTS, HYDRAULIC_PORTS, PRESSURE_PORTS
from hydroservo.laws.four_way import four_way_valve_flows
from hydroservo.laws.spool_dynamics import first_order_spool_rate, second_order_spool_acceleration

__all__ = ["CatalogueServovalve"]


@register
class CatalogueServovalve(Component):
    r"""Servovalve from catalogue data: the normalised spool follows the current through a transfer function.

    The spool position :math:`s` (1 at rated current) follows :math:`u = i/i_N`, saturated at ±1 (the stroke), as

    * ``order`` 1: :math:`1/(\tau s + 1)` (:func:`~hydroservo.laws.spool_dynamics.first_order_spool_rate`);
    * ``order`` 2: :math:`\omega_n^2/(s^2 + 2\zeta\omega_n s + \omega_n^2)`
      (:func:`~hydroservo.laws.spool_dynamics.second_order_spool_acceleration`);
    * ``order`` 3: the two in series, the lag first;

    and the four edges pass :math:`c_v s \sqrt{\Delta p}`
    (:func:`~hydroservo.laws.four_way.four_way_valve_flows`, critical centre), with
    :math:`c_v = Q_N/\sqrt{\Delta p_N/2}`: ``Q_N`` at no load with ``dp_N`` across the valve (both edges),
    plus a laminar leakage ``G_leak`` per edge. These are the lower rungs of the servovalve fidelity ladder;
    :func:`hydroservo.identification.servovalve_catalogue.fit_catalogue` fits them to a measured or simulated
    frequency response (docs/servovalve.md).
    """

    PARAMETERS = {
        "Q_N": Param(12 / 6e4, "m^3/s", "rated flow at rated current, no load", min=0.0, min_inclusive=False),
        "dp_N": Param(70e5, "Pa", "pressure drop across the valve (both edges) at which Q_N is rated",
                      min=0.0, min_inclusive=False),
        "i_N": Param(0.01, "A", "rated current", min=0.0, min_inclusive=False),
        "tau": Param(2e-3, "s", "time constant (orders 1 and 3)", min=0.0, min_inclusive=False),
        "omega_n": Param(1000.0, "rad/s", "natural frequency (orders 2 and 3)", min=0.0, min_inclusive=False),
        "zeta": Param(0.7, "", "damping ratio (orders 2 and 3)", min=0.0, min_inclusive=False),
        "G_leak": Param(0.0, "m^3/s/Pa", "laminar leakage conductance of each edge", min=0.0),
        "p_tr": Param(1e3, "Pa", "pressure drop below which the orifice law is linearised", min=0.0, min_inclusive=False),
    }
    STATES = {
        "s": State("", "normalised spool position", nominal=1.0),
        "v": State("1/s", "normalised spool velocity (orders 2 and 3)", nominal=100.0),
        "c": State("", "lagged command (order 3)", nominal=1.0),
    }
    INPUTS = {"i": Port("A", "coil current"), **PRESSURE_PORTS}
    OUTPUTS = {**FLOW_OUTPUTS, "y": Output("", "normalised spool position (1 at rated current)")}
    OPTIONS = {"order": Option("2", ("1", "2", "3"), "order of the transfer function from current to spool")}
    HYDRAULIC = dict(HYDRAULIC_PORTS)

    def __init__(self, name: str, **values: Any) -> None:
        super().__init__(name, **values)
        self._declare()

    def set_option(self, key: str, value: Any) -> None:
        super().set_option(key, str(value))
        self._declare()

    def _declare(self) -> None:
        if not hasattr(self, "option_values"):
            return
        keep = {"1": ("s",), "2": ("s", "v"), "3": ("s", "v", "c")}[self.option("order")]
        self.STATES = {k: v for k, v in type(self).STATES.items() if k in keep}  # type: ignore[misc]

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        c_v = p["Q_N"] / (p["dp_N"] / 2) ** 0.5
        QA, QB, QS, QT = four_way_valve_flows(
            x["s"], u["pS"], u["pT"], u["pA"], u["pB"], c_v, p_tr=p["p_tr"], G_leak=p["G_leak"]
        )
        return {"QA": QA, "QB": QB, "QS": QS, "QT": QT, "y": x["s"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        command = u["i"] / p["i_N"]
        order = self.option("order")
        if order == "1":
            return {"s": first_order_spool_rate(command, x["s"], p["tau"])}
        rates: dict[str, Any] = {}
        if order == "3":
            rates["c"] = first_order_spool_rate(command, x["c"], p["tau"])
            command = x["c"]
        rates["s"] = x["v"]
        rates["v"] = second_order_spool_acceleration(command, x["s"], x["v"], p["omega_n"], p["zeta"])
        return rates
