"""Four-way spool valve with sharp edges: per-edge laps, clearance leakage, flow-gain and hysteresis tables ([Efe2014])."""

from __future__ import annotations

import copy
from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.components.base import Component, Hydraulic, Option, Output, Param, Port, register
from hydroservo.components.valves.ports import FLOW_OUTPUTS, FLUID_PARAMETERS, HYDRAULIC_PORTS, PRESSURE_PORTS
from hydroservo.errors import ParameterError
from hydroservo.laws.four_way import four_way_valve_flows
from hydroservo.laws.orifice import laminar_flow, transition_pressure
from hydroservo.laws.pressure_valve import opening_fraction

__all__ = ["FourWayValve", "LOAD_SENSING_CONDUCTANCE"]

#: Conductance of the passage from the loaded use port to the load-sensing port L [m^3/s/Pa] (option
#: load_sensing = port): stiff, so that a load-sensing line of 1e-5 m^3 follows within 1e-8 s and 17 Pa per L/min
#: (Hopsan's connection is ideal); not a parameter, so that a valve without the port carries none.
LOAD_SENSING_CONDUCTANCE = 1e-6
#: The spool travel over which port L passes from B's pressure to A's, a fraction of ``xv_max`` [-]: Hopsan's
#: switch at x_v = 0 rounded (:func:`hydroservo.laws.pressure_valve.opening_fraction`), so that a spool resting at
#: its centre does not toggle the line between two pressures at every step.
LOAD_SENSING_BAND = 1e-4


@register
class FourWayValve(Component):
    """Four-way spool valve: flows from spool position and port pressures.

    Per-edge overlap (negative: underlap), optional clearance leakage, and the
    flow-coefficient compensation :math:`K(x_v)` and hysteresis
    :math:`H(x_v, d_f)` of [Efe2014] eqs. (3.22)-(3.23) as tables over the
    relative spool position :math:`x_v/x_{v,max}`. With all overlaps zero and no
    leakage it is the critical-centre valve of [FlightSimulatorND] (eqs. 3-18,
    3-20, 3-22, 3-23, in their sign-correct form 3-18a and 3-23a). The flows
    are :func:`hydroservo.laws.four_way.four_way_valve_flows`.

    The turbulent law is regularised below the transition pressure at which
    the flow number ([MareAttarND] eq. 4) with hydraulic diameter ``D_h``
    reaches ``lambda_crit``; see :mod:`hydroservo.laws.orifice`.

    Tables (lists, set in the constructor or model file): ``K_x``/``K`` and
    ``H_x``/``H_opening``/``H_closing`` (``H_opening`` applies while
    :math:`x_v \\dot x_v \\ge 0`). Defaults: 1 everywhere.

    Option ``load_sensing``: ``none`` (default), or ``port``, a load-sensing port ``L`` that passes on the
    pressure of the loaded use port, A while :math:`x_v \\ge 0` and B otherwise, to a load-sensing line (to a
    shuttle valve, a pump's regulator): :math:`Q_L = G_L\\,(p_{A|B} - p_L)` out of L, a stiff passage
    (:math:`G_L` = :data:`LOAD_SENSING_CONDUCTANCE`, 1e-6 m³/s/Pa) that keeps
    the line within :math:`Q_L/G_L` of the loaded port's pressure. As Hopsan's Hydraulic43LoadSensingValve
    ([Hopsan2026] Hydraulic/Valves/FlowControlValves/Hydraulic43LoadSensingValve.hpp), which writes that
    pressure to its PL node (an ideal connection: its flow :math:`(p_{load} - c_L)/Z_{c,L}`), the line's flow is
    not taken from A or B. Hopsan switches from B to A at :math:`x_v = 0`; here over
    :data:`LOAD_SENSING_BAND` of the stroke about it (the pressures blended by a rounded ramp), so that a spool
    resting at its centre does not toggle the line between two pressures at every step.
    """

    RENAMED = {"x_max": "xv_max"}
    OPTIONS = {
        "load_sensing": Option("none", ("none", "port"), "no load-sensing port, or port L at the loaded use port's pressure"),
    }
    PARAMETERS = {
        "c_v": Param(3.56e-4, "m^2/s/Pa^0.5", "flow coefficient per edge, Efe2014 eq. 3.9", min=0.0),
        "xv_max": Param(
            1e-3, "m", "spool stroke (normalises the K and H tables; the driving spool's)", min=0.0, min_inclusive=False
        ),
        "x_PA": Param(0.0, "m", "overlap of edge P-A (negative: underlap)"),
        "x_AT": Param(0.0, "m", "overlap of edge A-T"),
        "x_PB": Param(0.0, "m", "overlap of edge P-B"),
        "x_BT": Param(0.0, "m", "overlap of edge B-T"),
        "G_leak": Param(0.0, "m^3/s/Pa", "laminar clearance leakage conductance of each edge", min=0.0),
        **FLUID_PARAMETERS,
        "D_h": Param(
            1e-3, "m", "hydraulic diameter at which the laminar transition is evaluated", min=0.0, min_inclusive=False
        ),
    }
    INPUTS = {
        "xv": Port("m", "spool position"),
        "vv": Port("m/s", "spool velocity (only for the hysteresis table)", default=0.0),
        **PRESSURE_PORTS,
    }
    OUTPUTS = dict(FLOW_OUTPUTS)
    HYDRAULIC = dict(HYDRAULIC_PORTS)

    def __init__(self, name: str, tables: Mapping[str, Any] | None = None, **values: Any) -> None:
        super().__init__(name, **values)
        self.tables: dict[str, np.ndarray] = {
            "K_x": np.array([-1.0, 1.0]),
            "K": np.array([1.0, 1.0]),
            "H_x": np.array([-1.0, 1.0]),
            "H_opening": np.array([1.0, 1.0]),
            "H_closing": np.array([1.0, 1.0]),
        }
        for key, val in (tables or {}).items():
            if key not in self.tables:
                raise ParameterError(f"{name}.tables.{key}: unknown table; known: {', '.join(self.tables)}")
            self.tables[key] = np.asarray(val, dtype=float).ravel()
        for xs, ys in (("K_x", ("K",)), ("H_x", ("H_opening", "H_closing"))):
            grid = self.tables[xs]
            if np.any(np.diff(grid) <= 0):
                raise ParameterError(f"{name}.tables.{xs}: expected strictly increasing relative positions")
            for y in ys:
                if self.tables[y].size != grid.size:
                    raise ParameterError(
                        f"{name}.tables.{y}: {self.tables[y].size} values for {grid.size} points of {xs}"
                    )
                if np.any(self.tables[y] < 0) or np.any(self.tables[y] > 1.5):
                    raise ParameterError(f"{name}.tables.{y}: expected factors between 0 and 1.5")

    def options_changed(self) -> None:
        """Option load_sensing = port adds the port L (its pressure input and flow output)."""
        cls = type(self)
        self.INPUTS, self.OUTPUTS, self.HYDRAULIC = dict(cls.INPUTS), dict(cls.OUTPUTS), dict(cls.HYDRAULIC)  # type: ignore[misc]
        if self.option("load_sensing") == "port":
            self.INPUTS["pL"] = Port("Pa", "pressure in the load-sensing line (port L)")
            self.OUTPUTS["QL"] = Output("m^3/s", "flow out of port L into the load-sensing line")
            self.HYDRAULIC["L"] = Hydraulic("pL", "QL", "load-sensing port: the loaded use port's pressure", into=False)

    def config(self) -> dict[str, Any]:
        return {"tables": {k: v.tolist() for k, v in self.tables.items()}} if self.has_tables() else {}

    def with_tables(self, tables: Mapping[str, Any] | None = None) -> FourWayValve:
        """A copy of this valve with other compensation tables (none: K = H = 1, the plain law of eq. 3.18)."""
        new = copy.copy(self)
        new.values, new.given, new.explicit = dict(self.values), dict(self.given), set(self.explicit)
        new.option_values = dict(self.option_values)
        new.tables = type(self)(self.name, tables=tables).tables
        return new

    def has_tables(self) -> bool:
        return any(np.any(self.tables[k] != 1.0) for k in ("K", "H_opening", "H_closing"))

    def compensation(self, xv: Any, vv: Any, xv_max: Any) -> Any:
        """The factor :math:`K(x_v)H(x_v, d_f)` on the flow coefficient ([Efe2014] eqs. 3.22-3.23); 1 without tables."""
        if not self.has_tables():
            return 1.0
        rel = xv / xv_max
        h_open = bk.interp(rel, self.tables["H_x"], self.tables["H_opening"])
        h_close = bk.interp(rel, self.tables["H_x"], self.tables["H_closing"])
        return bk.interp(rel, self.tables["K_x"], self.tables["K"]) * bk.if_else(xv * vv >= 0, h_open, h_close)

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        xv = u["xv"]
        K = self.compensation(xv, u["vv"], p["xv_max"])
        p_tr = transition_pressure(p["D_h"], p["rho"], p["nu"], p["lambda_crit"])
        QA, QB, QS, QT = four_way_valve_flows(
            xv,
            u["pS"],
            u["pT"],
            u["pA"],
            u["pB"],
            p["c_v"],
            p["x_PA"],
            p["x_AT"],
            p["x_PB"],
            p["x_BT"],
            p_tr,
            p["G_leak"],
            K,
        )
        out = {"QA": QA, "QB": QB, "QS": QS, "QT": QT}
        if self.option("load_sensing") == "port":
            band = LOAD_SENSING_BAND * p["xv_max"]
            s = opening_fraction(xv, -0.5 * band, band)
            out["QL"] = laminar_flow(LOAD_SENSING_CONDUCTANCE, s * u["pA"] + (1.0 - s) * u["pB"] - u["pL"])
        return out


