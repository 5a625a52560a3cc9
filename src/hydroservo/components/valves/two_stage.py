"""The two-stage servovalve with mechanical spool-position feedback, from first principles ([GordicND]).

One component, current in and four port flows out, whose every parameter is
a dimension, a stiffness, a mass or a property of the oil (Table 1 of
[GordicND] by default: the PPT B.31.210.12.1000.U2V, 12 L/min at 10 mA and
210 bar). Its equations are the laws of :mod:`hydroservo.laws.torque_motor`,
:mod:`~hydroservo.laws.armature`, :mod:`~hydroservo.laws.flapper_nozzle`,
:mod:`~hydroservo.laws.servo_spool` and :mod:`~hydroservo.laws.friction`;
the component adds the states, the ports and two structural choices, which
make the upper rungs of the fidelity ladder (docs/servovalve.md):

``first_stage``
    ``"quasi-static"`` (default), the paper's simplified model: the nozzle
    pressures in closed form (eqs. 33-38, compressibility and end-land
    leakage of eqs. 20-21 neglected, flow coefficients at their null
    values), the drain compartment with its compressibility (eq. 22 whole).
    ``"compressible"``: eqs. 20-22 whole, the three pressures as states
    with the spool-end and drain volumes, the leakage past the end lands,
    and the constant and drain orifices' coefficients from Lichtarowicz's
    correlation at their instantaneous Reynolds numbers.
``flapper``
    ``"bent"`` (default): the flapper tip of eq. 14, bent by the flow force
    of eq. 13 that depends on the tip: an algebraic unknown the engine
    solves (:mod:`hydroservo.system.implicit`), with the inclination of
    eq. 18 in the feedback spring. ``"rigid"``: the usual assumption the
    paper corrects, :math:`x = \\theta l_a`, :math:`\\varphi = \\theta`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.components.base import Algebraic, Component, FromSet, Option, Output, Param, Port, State, register
from hydroservo.components.valves.ports import FLOW_OUTPUTS, HYDRAULIC_PORTS, PRESSURE_PORTS
from hydroservo.errors import ParameterError
from hydroservo.laws import armature as ar
from hydroservo.laws import flapper_nozzle as fn
from hydroservo.laws import orifice
from hydroservo.laws import servo_spool as sp
from hydroservo.laws import torque_motor as tm
from hydroservo.laws.friction import stribeck
from hydroservo.laws.leakage import annulus_conductance

__all__ = ["TwoStageServovalve"]


def _set(table: str, key: str) -> FromSet:
    return FromSet("GordicND", table, key)


@register
class TwoStageServovalve(Component):
    r"""Two-stage, spool-position-feedback servovalve from first principles, [GordicND] eqs. (3)-(58).

    Armature (eq. 10):
    :math:`J_a\ddot\theta = T_e - k_v\dot\theta - T_t - F_h l_a - F_f l_f - T_i`,
    with the torque of eq. 4, the flexure tube of eq. 12, the flow force on
    the flapper of eq. 13 at the tip of eq. 14, the feedback spring with the
    ball's clearance of eqs. 15-18 and the nozzle impact of eq. 19.

    Spool (eq. 39):
    :math:`m_s\ddot y = (p_l - p_r)A_s - k_n\dot y - F_c - F_a - F_f`, the dry
    friction of eq. 41 as :func:`~hydroservo.laws.friction.stribeck` friction
    (static ``F_c0``, sliding ``F_cn``) smoothed over ``v_reg`` so that the
    integrator survives, and the axial flow force of eq. 43 (steady with the
    real openings of eqs. 44-47, transient with Merritt's signs).

    Ports: the use-port flows of eqs. 49-51 with the real openings and the
    leakage of the overlapped lands (eqs. 52-56); ``QS`` adds the first
    stage's supply flow, ``QT`` its drain flow. The first stage drains to the
    tank port (its ``p_0`` is ``pT``). The coil current ``i`` is an input:
    the amplifier of eqs. 1-2 is an :class:`~hydroservo.components.Amplifier`
    in front (with a :class:`~hydroservo.components.Sum` and the spool
    position output for electrical feedback).

    Options ``first_stage`` and ``flapper``: see the module docstring.
    """

    PARAMETERS = {
        # torque motor, eq. 4
        "r": Param(_set("torque_motor", "r"), "m", "pivot to the centre of a pole face", min=0.0, min_inclusive=False),
        "A_p": Param(_set("torque_motor", "A_p"), "m^2", "pole face (air gap) area", min=0.0, min_inclusive=False),
        "x_p0": Param(_set("torque_motor", "x_p0"), "m", "air gap length at null", min=0.0, min_inclusive=False),
        "M_m": Param(_set("torque_motor", "M_m"), "A", "magnetomotive force of the magnet", min=0.0, min_inclusive=False),
        "N": Param(_set("torque_motor", "N"), "", "turns of each coil", min=0.0, min_inclusive=False),
        "k_c": Param(_set("torque_motor", "k_c"), "", "coil connection constant (1: parallel)", min=0.0, min_inclusive=False),
        "k_r": Param(_set("torque_motor", "k_r"), "", "magnetic reluctance constant (eqs. 7-9)", min=0.0),
        # armature assembly, eqs. 10-19
        "J_a": Param(_set("armature", "J_a"), "kg*m^2", "armature assembly inertia", min=0.0, min_inclusive=False),
        "k_v": Param(_set("armature", "k_v"), "N*m*s", "armature viscous friction", min=0.0),
        "B_t": Param(_set("armature", "B_t"), "N*m^2", "flexure tube rigidity", min=0.0, min_inclusive=False),
        "B_fl": Param(_set("armature", "B_fl"), "N*m^2", "flapper bending rigidity", min=0.0, min_inclusive=False),
        "l_t": Param(_set("armature", "l_t"), "m", "flexure tube length", min=0.0, min_inclusive=False),
        "l_fl": Param(_set("armature", "l_fl"), "m", "flapper length", min=0.0, min_inclusive=False),
        "l_a": Param(_set("armature", "l_a"), "m", "pivot to the nozzle axis (eq. 11)", min=0.0, min_inclusive=False),
        "l_f": Param(_set("armature", "l_s"), "m", "feedback spring length (Table 1's l_s)", min=0.0, min_inclusive=False),
        "K_f": Param(_set("armature", "K_f"), "N/m", "feedback spring stiffness", min=0.0, min_inclusive=False),
        "z": Param(_set("armature", "z"), "m", "half the feedback ball's clearance", min=0.0),
        "k_i": Param(_set("armature", "k_i"), "N/m", "impact stiffness of a nozzle", min=0.0, min_inclusive=False),
        # flapper-nozzle stage, eqs. 20-38
        "d_n": Param(_set("first_stage", "d_n"), "m", "nozzle diameter", min=0.0, min_inclusive=False),
        "d_o": Param(_set("first_stage", "d_o"), "m", "constant orifice diameter", min=0.0, min_inclusive=False),
        "l_o": Param(_set("first_stage", "l_o"), "m", "constant orifice length", min=0.0, min_inclusive=False),
        "d_od": Param(_set("first_stage", "d_od"), "m", "drain orifice diameter", min=0.0, min_inclusive=False),
        "l_od": Param(_set("first_stage", "l_od"), "m", "drain orifice length", min=0.0, min_inclusive=False),
        "x_0": Param(_set("first_stage", "x_0"), "m", "flapper-nozzle gap at null", min=0.0, min_inclusive=False),
        "V_1": Param(_set("first_stage", "V_1"), "m^3", "volume at each spool end", min=0.0, min_inclusive=False),
        "V_d": Param(_set("first_stage", "V_d"), "m^3", "drain compartment volume", min=0.0, min_inclusive=False),
        "K_n0": Param(
            orifice.DISCHARGE_COEFFICIENT, "", "flapper-nozzle flow coefficient (sharp-edged: docs/servovalve.md)",
            min=0.0, max=1.0, min_inclusive=False,
        ),
        "K_o0": Param(
            0.782, "", "constant orifices' flow coefficient at null (quasi-static; Lichtarowicz at 210 bar)",
            min=0.0, max=1.0, min_inclusive=False,
        ),
        "K_od0": Param(
            0.794, "", "drain orifice's flow coefficient at null (quasi-static; Lichtarowicz at 210 bar)",
            min=0.0, max=1.0, min_inclusive=False,
        ),
        # spool stage, eqs. 39-58
        "d_s": Param(_set("spool", "d_s"), "m", "spool diameter", min=0.0, min_inclusive=False),
        "m_s": Param(_set("spool", "m_s"), "kg", "spool mass", min=0.0, min_inclusive=False),
        "f_width": Param(_set("spool", "f_width"), "m", "width of each metering port", min=0.0, min_inclusive=False),
        "f_ports": Param(_set("spool", "f_ports"), "", "metering ports per edge (area gradient f = f_ports f_width)", min=1.0),
        "l_1": Param(_set("spool", "l_1"), "m", "damping length, supply port to use port", min=0.0),
        "l_2": Param(_set("spool", "l_2"), "m", "damping length, return port to use port", min=0.0),
        "l_l": Param(_set("spool", "l_l"), "m", "length of the spool end lands", min=0.0, min_inclusive=False),
        "delta": Param(_set("spool", "delta"), "m", "radial clearance of the spool", min=0.0, min_inclusive=False),
        "e": Param(_set("spool", "e"), "m", "spool eccentricity", min=0.0),
        "r_s": Param(_set("spool", "r_s"), "m", "radius of the spool's control edges", min=0.0),
        "r_b": Param(_set("spool", "r_b"), "m", "radius of the bushing's control edges", min=0.0),
        "y_0": Param(_set("spool", "y_0i"), "m", "null lap of every orifice (positive: underlap)"),
        "k_n": Param(_set("spool", "k_n"), "kg/s", "spool viscous friction", min=0.0),
        "F_c0": Param(_set("spool", "F_c0"), "N", "static dry friction of the spool", min=0.0),
        "F_cn": Param(_set("spool", "F_cn"), "N", "sliding dry friction of the spool", min=0.0),
        "v_reg": Param(1e-5, "m/s", "spool velocity over which dry friction is smoothed", min=0.0, min_inclusive=False),
        "c_s": Param(1e-4, "m/s", "velocity over which static friction falls to sliding", min=0.0, min_inclusive=False),
        "K_t": Param(0.611, "", "spool orifices' flow coefficient (Von Mises)", min=0.0, max=1.0, min_inclusive=False),
        "K_c": Param(0.673, "", "spool orifices' contraction coefficient (Von Mises)", min=0.0, max=1.0, min_inclusive=False),
        "jet_angle": Param(
            float(np.radians(69.0)), "rad", "jet angle alpha (Von Mises)", min=0.0, max=np.pi / 2, min_inclusive=False
        ),
        # oil
        "rho": Param(_set("fluid", "rho"), "kg/m^3", "oil density", min=0.0, min_inclusive=False, fluid="density"),
        "nu": Param(
            _set("fluid", "nu"), "m^2/s", "kinematic viscosity", min=0.0, min_inclusive=False, fluid="kinematic_viscosity"
        ),
        "beta_e": Param(_set("fluid", "beta"), "Pa", "bulk modulus", min=0.0, min_inclusive=False, fluid="bulk_modulus"),
        # initial pressures of the first stage (near their null values at 210 bar)
        "p_d0": Param(16e5, "Pa", "initial drain compartment pressure", min=0.0),
        "p_n0": Param(110e5, "Pa", "initial nozzle pressures (option compressible)", min=0.0),
    }
    STATES = {
        "theta": State("rad", "armature rotation", nominal=1e-3),
        "omega": State("rad/s", "armature angular velocity", nominal=1.0),
        "y": State("m", "spool displacement", nominal=1e-4),
        "v": State("m/s", "spool velocity", nominal=0.1),
        "p_d": State("Pa", "drain compartment pressure", initial="p_d0", nominal=1e6),
    }
    INPUTS = {"i": Port("A", "coil current"), **PRESSURE_PORTS}
    OUTPUTS = {
        **FLOW_OUTPUTS,
        "y": Output("m", "spool displacement"),
        "x": Output("m", "flapper-tip displacement"),
        "p_l": Output("Pa", "left nozzle pressure"),
        "p_r": Output("Pa", "right nozzle pressure"),
        "F_h": Output("N", "flow force on the flapper"),
        "F_f": Output("N", "feedback spring force"),
        "Q_first": Output("m^3/s", "flow drawn by the first stage from supply"),
    }
    OPTIONS = {
        "first_stage": Option(
            "quasi-static", ("quasi-static", "compressible"), "the flapper-nozzle stage: [GordicND]'s simplified or whole"
        ),
        "flapper": Option("bent", ("bent", "rigid"), "flapper tip from eqs. 13-14 (an algebraic loop) or theta l_a"),
    }
    HYDRAULIC = dict(HYDRAULIC_PORTS)

    def __init__(self, name: str, **values: Any) -> None:
        super().__init__(name, **values)
        self._declare()

    # -- structure ----------------------------------------------------------
    def set_option(self, key: str, value: Any) -> None:
        super().set_option(key, value)
        self._declare()

    def _declare(self) -> None:
        """The states and the algebraic unknown of the chosen options."""
        if not hasattr(self, "option_values"):  # options are set before the constructor's defaults exist
            return
        states = dict(type(self).STATES)
        if self.option("first_stage") == "compressible":
            states["p_l"] = State("Pa", "left spool end (nozzle) pressure", initial="p_n0", nominal=1e7)
            states["p_r"] = State("Pa", "right spool end (nozzle) pressure", initial="p_n0", nominal=1e7)
        self.STATES = states  # type: ignore[misc]
        bent = self.option("flapper") == "bent"
        self.ALGEBRAIC = {"x": Algebraic("m", "flapper-tip displacement (eq. 14)", nominal=1e-5)} if bent else {}  # type: ignore[misc]

    def check(self) -> None:
        v = self.values
        if v["l_a"] >= v["l_fl"]:
            raise ParameterError(
                f"{self.name}.l_a = {v['l_a']:g} m: the pivot must lie within the flapper (l_fl = {v['l_fl']:g} m)"
            )
        if abs(v["y_0"]) >= v["d_s"]:
            raise ParameterError(f"{self.name}.y_0 = {v['y_0']:g} m: a lap as large as the spool (d_s = {v['d_s']:g} m)")
        if v["F_cn"] > v["F_c0"]:
            raise ParameterError(
                f"{self.name}.F_cn = {v['F_cn']:g} N: sliding friction above the static F_c0 = {v['F_c0']:g} N"
            )

    # -- equations ------------------------------------------------------------
    def _tip(self, x: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        return x["x"] if self.ALGEBRAIC else x["theta"] * p["l_a"]

    def _stage(self, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], tip: Any) -> dict[str, Any]:
        """The first stage at flapper tip ``tip``: nozzle pressures, flows, flow force on the flapper."""
        rho, p_s, p_0, p_d = p["rho"], u["pS"], u["pT"], x["p_d"]
        A_s = np.pi * p["d_s"] ** 2 / 4.0
        gap_l = bk.fmax(p["x_0"] - tip, 0.0)
        gap_r = bk.fmax(p["x_0"] + tip, 0.0)
        b = fn.nozzle_conductance(p["K_n0"], p["d_n"], gap_l, rho)
        c = fn.nozzle_conductance(p["K_n0"], p["d_n"], gap_r, rho)
        if self.option("first_stage") == "compressible":
            p_l, p_r = x["p_l"], x["p_r"]
            K_o = [
                orifice.short_tube_discharge(orifice.flow_number(p["d_o"], dp, rho, p["nu"]) + 1e-9, p["l_o"] / p["d_o"])
                for dp in (p_s - p_l, p_s - p_r)
            ]
            a0 = fn.orifice_conductance(1.0, p["d_o"], rho)
            Q_ol = K_o[0] * a0 * orifice.signed_sqrt(p_s - p_l, _P_REG)
            Q_or = K_o[1] * a0 * orifice.signed_sqrt(p_s - p_r, _P_REG)
            K_od = orifice.short_tube_discharge(
                orifice.flow_number(p["d_od"], p_d - p_0, rho, p["nu"]) + 1e-9, p["l_od"] / p["d_od"]
            )
            a_d = fn.orifice_conductance(K_od, p["d_od"], rho)
            leak = annulus_conductance(p["d_s"], p["delta"], p["e"], rho * p["nu"], p["l_l"])
        else:
            a = fn.orifice_conductance(p["K_o0"], p["d_o"], rho)
            p_l, p_r = fn.nozzle_pressures(p_s, p_d, a, b, c, A_s * x["v"])
            Q_ol = a * bk.sqrt(bk.fmax(p_s - p_l, 0.0))
            Q_or = a * bk.sqrt(bk.fmax(p_s - p_r, 0.0))
            a_d = fn.orifice_conductance(p["K_od0"], p["d_od"], rho)
            leak = 0.0
        Q_nl = b * orifice.signed_sqrt(p_l - p_d, _P_REG)
        Q_nr = c * orifice.signed_sqrt(p_r - p_d, _P_REG)
        Q_od = a_d * orifice.signed_sqrt(p_d - p_0, _P_REG)
        F_h = ar.flapper_flow_force(p_l, p_r, p_d, tip, p["x_0"], p["d_n"], p["K_n0"], p["K_n0"])
        return {
            "p_l": p_l, "p_r": p_r, "Q_ol": Q_ol, "Q_or": Q_or, "Q_nl": Q_nl, "Q_nr": Q_nr, "Q_od": Q_od, "F_h": F_h,
            "Q_leak_l": leak * (p_s - p_l), "Q_leak_r": leak * (p_s - p_r),
            "Q_leak": leak * (2.0 * p_s - p_l - p_r),
        }

    def _feedback(self, x: Mapping[str, Any], p: Mapping[str, Any], tip: Any, F_h: Any) -> Any:
        phi = ar.flapper_inclination(x["theta"], F_h, p["l_fl"], p["B_fl"]) if self.ALGEBRAIC else x["theta"]
        return ar.feedback_spring_force(x["y"], tip, phi, p["l_f"], p["K_f"], p["z"])

    def _spool(self, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> dict[str, Any]:
        """The four orifices' flows (open: eqs. 44-51; overlapped: the leakage of eqs. 52-56) and the axial flow force.

        The flow force of eq. 43 is written with the real openings; an overlapped orifice counts with the
        opening that would pass its leakage (its "equivalent opening"), which meets the real opening at the
        edge: eq. 43 with the openings of eq. 44 alone would jump by the jet force of the edge's clearance
        opening as the spool crosses null (0.2 N for Table 1, a relay no integrator steps through).
        """
        f = p["f_ports"] * p["f_width"]
        rho, eta = p["rho"], p["rho"] * p["nu"]
        y = x["y"]
        drops = sp.orifice_drops(u["pS"], u["pT"], u["pA"], u["pB"])
        c = p["K_t"] * f * bk.sqrt(2.0 / rho)
        Q, equivalent = [], []
        for k in range(4):
            j = sp.SIGNS[k] * y + p["y_0"]
            root = bk.sqrt(bk.fmax(drops[k], 0.0))
            opened = c * sp.real_opening(y, k + 1, p["delta"], p["r_s"], p["r_b"], p["y_0"]) * root
            leak = sp.lapped_leakage(-j, drops[k], p["K_t"], f, rho, eta, p["delta"], p["r_s"], p["r_b"], p["d_s"])
            flow = bk.if_else(j < 0, leak, opened)
            Q.append(flow)
            equivalent.append(bk.fabs(flow) / (c * bk.fmax(root, 1.0)))
        F_a = sp.steady_flow_force(equivalent, drops, p["K_t"], p["K_c"], f, p["jet_angle"]) + sp.transient_flow_force(
            y, x["v"], drops, p["K_t"], f, rho, p["l_1"], p["l_2"]
        )
        return {"Q": Q, "F_a": F_a}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        tip = self._tip(x, p)
        stage = self._stage(x, u, p, tip)
        spool = self._spool(x, u, p)
        Q = spool["Q"]
        first = stage["Q_ol"] + stage["Q_or"] + stage["Q_leak"]
        return {
            "QA": Q[0] - Q[3],
            "QB": Q[1] - Q[2],
            "QS": Q[0] + Q[1] + first,
            "QT": Q[2] + Q[3] + stage["Q_od"],
            "y": x["y"],
            "x": tip,
            "p_l": stage["p_l"],
            "p_r": stage["p_r"],
            "F_h": stage["F_h"],
            "F_f": self._feedback(x, p, tip, stage["F_h"]),
            "Q_first": first,
        }

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        tip, F_h, F_f = y["x"], y["F_h"], y["F_f"]
        T_e = tm.electromagnetic_torque(x["theta"], u["i"], p["r"], p["A_p"], p["x_p0"], p["M_m"], p["N"], p["k_c"], p["k_r"])
        T_i = ar.impact_torque(tip, p["x_0"], p["k_i"], p["l_a"])
        torque = T_e - p["k_v"] * x["omega"] - ar.flexure_torque(x["theta"], p["B_t"], p["l_t"]) - F_h * p["l_a"]
        torque = torque - F_f * p["l_f"] - T_i
        A_s = np.pi * p["d_s"] ** 2 / 4.0
        spool = self._spool(x, u, p)
        F_c = stribeck(x["v"], p["k_n"], p["F_cn"], p["F_c0"] - p["F_cn"], p["c_s"], p["v_reg"])
        force = (y["p_l"] - y["p_r"]) * A_s - F_c - spool["F_a"] - F_f
        stage = self._stage(x, u, p, tip)
        rates = {
            "theta": x["omega"],
            "omega": torque / p["J_a"],
            "y": x["v"],
            "v": force / p["m_s"],
            "p_d": p["beta_e"] / p["V_d"] * (stage["Q_nl"] + stage["Q_nr"] - stage["Q_od"]),
        }
        if self.option("first_stage") == "compressible":
            k = p["beta_e"] / p["V_1"]
            rates["p_l"] = k * (stage["Q_ol"] - stage["Q_nl"] - A_s * x["v"] + stage["Q_leak_l"])
            rates["p_r"] = k * (stage["Q_or"] - stage["Q_nr"] + A_s * x["v"] + stage["Q_leak_r"])
        return rates

    def residual_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        F_h = self._stage(x, u, p, x["x"])["F_h"]
        return {"x": x["x"] - ar.flapper_tip(x["theta"], F_h, p["l_a"], p["l_fl"], p["B_fl"], p["l_t"], p["B_t"])}

    def guess_equations(self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> dict[str, Any]:
        """Eq. 14 linearised about the centred flapper: the tip's stiffness against the nozzle pressures' gradient."""
        rho, p_s = p["rho"], u["pS"]
        a = fn.orifice_conductance(p["K_o0"], p["d_o"], rho)
        b = fn.nozzle_conductance(p["K_n0"], p["d_n"], p["x_0"], rho)
        gradient = 4.0 * a**2 * b**2 * bk.fmax(p_s - x["p_d"], 0.0) / ((a**2 + b**2) ** 2 * p["x_0"])  # d(p_l - p_r)/dx
        compliance = p["l_fl"] ** 3 / (3.0 * p["B_fl"]) + p["l_t"] ** 3 / (12.0 * p["B_t"])
        return {"x": x["theta"] * p["l_a"] / (1.0 + compliance * np.pi * p["d_n"] ** 2 / 4.0 * gradient)}


#: Pressure drop below which the first stage's orifice laws are linearised [Pa] (keeps their derivatives finite).
_P_REG = 100.0
