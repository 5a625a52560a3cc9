"""Static characteristic of the first-principles two-stage servovalve of [GordicND], from its laws.

At rest (no spool velocity, no armature motion) the servovalve's equations
are algebraic: the torque balance on the armature (eq. 10 without its
dynamic terms), the flapper tip bent by the jets (eq. 14), the force balance
on the spool (eq. 39 at rest: the nozzle pressure difference against the
steady flow force and the feedback spring) and the drain compartment's
continuity (eq. 22). Solved for the armature rotation, the flapper tip, the
spool position and the drain pressure at each current, they give the flow of
the no-load valve (eqs. 49-51, 57-58): the flow-current characteristic a
manufacturer measures, and the rated flow.

Dry friction is left out (the paper finds it negligible against the spool's
pressure force), and with it the hysteresis of a slow cycle; the dynamic
model (issue 12, in progress) will have it. The flow coefficients of the
first stage are taken at null, as the paper's simplified model does
(its Fig. 5): the constant and drain orifices from Lichtarowicz's
correlation at their Reynolds numbers, the flapper-nozzle restrictions as
sharp-edged orifices (docs/servovalve.md); the spool orifices use Von
Mises' constants (0.611, 0.673, 69 degrees).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from hydroservo.data import parameter_set
from hydroservo.errors import SolverError
from hydroservo.laws import armature as ar
from hydroservo.laws import flapper_nozzle as fn
from hydroservo.laws import orifice
from hydroservo.laws import servo_spool as sp
from hydroservo.laws import torque_motor as tm

__all__ = ["TABLE_1", "table1", "first_stage_null", "StaticPoint", "static_point", "flow_characteristic"]

#: Parameter set of the published valve, and the SI unit of each entry used: (table, key, unit).
TABLE_1 = {
    "r": ("torque_motor", "r", "m"),
    "A_p": ("torque_motor", "A_p", "m^2"),
    "x_p0": ("torque_motor", "x_p0", "m"),
    "M_m": ("torque_motor", "M_m", "A"),
    "N": ("torque_motor", "N", ""),
    "k_c": ("torque_motor", "k_c", ""),
    "k_r": ("torque_motor", "k_r", ""),
    "B_t": ("armature", "B_t", "N*m^2"),
    "B_fl": ("armature", "B_fl", "N*m^2"),
    "l_t": ("armature", "l_t", "m"),
    "l_fl": ("armature", "l_fl", "m"),
    "l_a": ("armature", "l_a", "m"),
    "l_f": ("armature", "l_s", "m"),
    "K_f": ("armature", "K_f", "N/m"),
    "z": ("armature", "z", "m"),
    "d_n": ("first_stage", "d_n", "m"),
    "d_o": ("first_stage", "d_o", "m"),
    "l_o": ("first_stage", "l_o", "m"),
    "d_od": ("first_stage", "d_od", "m"),
    "l_od": ("first_stage", "l_od", "m"),
    "x_0": ("first_stage", "x_0", "m"),
    "p_0": ("first_stage", "p_0", "Pa"),
    "d_s": ("spool", "d_s", "m"),
    "f_width": ("spool", "f_width", "m"),
    "f_ports": ("spool", "f_ports", ""),
    "delta": ("spool", "delta", "m"),
    "r_s": ("spool", "r_s", "m"),
    "r_b": ("spool", "r_b", "m"),
    "y_0": ("spool", "y_0i", "m"),
    "rho": ("fluid", "rho", "kg/m^3"),
    "nu": ("fluid", "nu", "m^2/s"),
}

#: Von Mises' spool-orifice constants ([GordicND] section 2.5): flow and contraction coefficients, jet angle.
VON_MISES = {"K_t": 0.611, "K_c": 0.673, "alpha": float(np.radians(69.0))}


def table1(**overrides: float) -> dict[str, float]:
    """The published valve's parameters in SI (parameter set ``GordicND``), with ``overrides`` (SI) applied."""
    ps = parameter_set("GordicND")
    values = {key: ps.si(table, name, unit) for key, (table, name, unit) in TABLE_1.items()}
    values["f"] = values.pop("f_width") * values.pop("f_ports")
    values.update(VON_MISES)
    values["K_n"] = orifice.DISCHARGE_COEFFICIENT
    unknown = set(overrides) - set(values)
    if unknown:
        raise KeyError(f"unknown servovalve parameter(s) {', '.join(sorted(unknown))}; known: {', '.join(values)}")
    values.update(overrides)
    return values


def first_stage_null(p_s: float, v: dict[str, float]) -> dict[str, float]:
    """The flapper-nozzle stage with the flapper centred at supply ``p_s``: nozzle and drain pressures, and the
    constant and drain orifices' coefficients at their Reynolds numbers (Lichtarowicz), solved together."""
    rho, nu, p_0 = v["rho"], v["nu"], v["p_0"]
    b = fn.nozzle_conductance(v["K_n"], v["d_n"], v["x_0"], rho)
    K_o = K_od = 0.8
    p_n, p_d = 0.5 * (p_s + p_0), p_0
    for _ in range(200):
        a = fn.orifice_conductance(K_o, v["d_o"], rho)
        a_d = fn.orifice_conductance(K_od, v["d_od"], rho)
        # a sqrt(p_s - p_n) = b sqrt(p_n - p_d) and 2 a sqrt(p_s - p_n) = a_d sqrt(p_d - p_0), in p_n
        lo, hi = p_0, p_s
        for _ in range(100):
            p_n = 0.5 * (lo + hi)
            p_d = float(fn.null_drain_pressure(p_s, p_n, p_0, a, a_d))
            if p_d >= p_n or a * np.sqrt(p_s - p_n) < b * np.sqrt(p_n - p_d):
                hi = p_n
            else:
                lo = p_n
        K_o_new = float(orifice.short_tube_discharge(orifice.flow_number(v["d_o"], p_s - p_n, rho, nu), v["l_o"] / v["d_o"]))
        K_od_new = float(
            orifice.short_tube_discharge(orifice.flow_number(v["d_od"], p_d - p_0, rho, nu), v["l_od"] / v["d_od"])
        )
        if abs(K_o_new - K_o) + abs(K_od_new - K_od) < 1e-13:
            break
        K_o, K_od = K_o_new, K_od_new
    return {"p_n": p_n, "p_d": p_d, "K_o": K_o, "K_od": K_od, "a": float(a), "a_d": float(a_d)}


@dataclass(frozen=True)
class StaticPoint:
    """The servovalve at rest at one current (SI)."""

    i: float
    theta: float  #: armature rotation [rad]
    x: float  #: flapper-tip displacement [m]
    y: float  #: spool displacement [m]
    p_l: float  #: left nozzle pressure [Pa]
    p_r: float  #: right nozzle pressure [Pa]
    p_d: float  #: drain compartment pressure [Pa]
    F_h: float  #: flow force on the flapper [N]
    F_f: float  #: feedback spring force [N]
    Q_SV: float  #: valve flow, eq. 58 [m^3/s]
    extra: dict[str, float] = field(default_factory=dict)


def _equations(u: np.ndarray, i: float, p_s: float, v: dict[str, float], null: dict[str, float]) -> tuple[np.ndarray, dict[str, Any]]:
    theta, x, y, p_d = u
    rho, x0 = v["rho"], v["x_0"]
    b = fn.nozzle_conductance(v["K_n"], v["d_n"], x0 - x, rho)
    c = fn.nozzle_conductance(v["K_n"], v["d_n"], x0 + x, rho)
    p_l, p_r = fn.nozzle_pressures(p_s, p_d, null["a"], b, c, 0.0)
    F_h = ar.flapper_flow_force(p_l, p_r, p_d, x, x0, v["d_n"], v["K_n"], v["K_n"])
    phi = ar.flapper_inclination(theta, F_h, v["l_fl"], v["B_fl"])
    F_f = ar.feedback_spring_force(y, x, phi, v["l_f"], v["K_f"], v["z"])
    T_e = tm.electromagnetic_torque(theta, i, v["r"], v["A_p"], v["x_p0"], v["M_m"], v["N"], v["k_c"], v["k_r"])
    torque = T_e - ar.flexure_torque(theta, v["B_t"], v["l_t"]) - F_h * v["l_a"] - F_f * v["l_f"]
    tip = x - ar.flapper_tip(theta, F_h, v["l_a"], v["l_fl"], v["B_fl"], v["l_t"], v["B_t"])
    p_L = 0.5 * (p_s + v["p_0"])  # no load, eq. 57
    openings = [sp.real_opening(y, k, v["delta"], v["r_s"], v["r_b"], v["y_0"]) for k in (1, 2, 3, 4)]
    drops = sp.orifice_drops(p_s, v["p_0"], p_L, p_L)
    A_s = np.pi * v["d_s"] ** 2 / 4.0
    spool = (p_l - p_r) * A_s - sp.steady_flow_force(openings, drops, v["K_t"], v["K_c"], v["f"], v["alpha"]) - F_f
    drain = (
        b * np.sqrt(max(p_l - p_d, 0.0)) + c * np.sqrt(max(p_r - p_d, 0.0)) - null["a_d"] * np.sqrt(max(p_d - v["p_0"], 0.0))
    )
    Q_L1, Q_L2 = sp.port_flows(openings, drops, v["K_t"], v["f"], rho)
    scaled = np.array([float(torque) * 1e3, float(tip) * 1e6, float(spool), float(drain) * 1e6])
    state = {"p_l": p_l, "p_r": p_r, "F_h": F_h, "F_f": F_f, "Q_SV": 0.5 * (Q_L1 + Q_L2)}
    return scaled, state


def static_point(i: float, p_s: float = 210e5, params: dict[str, float] | None = None, start: Any = None) -> StaticPoint:
    """The servovalve at rest at current ``i`` [A] and supply ``p_s`` [Pa] (no load).

    Raises
    ------
    SolverError
        When the equilibrium is not found, with the residuals.
    """
    from scipy.optimize import root

    v = params or table1()
    null = first_stage_null(p_s, v)
    u0 = np.array(start) if start is not None else np.array([0.0, 0.0, 0.0, null["p_d"]])
    sol = root(lambda u: _equations(u, i, p_s, v, null)[0], u0, method="hybr", options={"xtol": 1e-13})
    res, state = _equations(sol.x, i, p_s, v, null)
    if np.max(np.abs(res)) > 1e-6:
        raise SolverError(
            f"servovalve static equilibrium at i = {i * 1e3:g} mA, p_s = {p_s / 1e5:g} bar not found: residuals "
            f"(torque [mN m], tip [um], spool [N], drain [mm^3/s]) = {', '.join(f'{r:.3g}' for r in res)}"
        )
    theta, x, y, p_d = (float(t) for t in sol.x)
    return StaticPoint(
        i, theta, x, y, float(state["p_l"]), float(state["p_r"]), p_d, float(state["F_h"]), float(state["F_f"]),
        float(state["Q_SV"]), {"p_n_null": null["p_n"], "K_o": null["K_o"], "K_od": null["K_od"]},
    )


def flow_characteristic(currents: Any, p_s: float = 210e5, params: dict[str, float] | None = None) -> list[StaticPoint]:
    """Static points along ``currents`` [A] (continuation from each to the next; start away from zero current,
    where the feedback spring's clearance makes the equilibrium a plateau)."""
    v = params or table1()
    points: list[StaticPoint] = []
    start = None
    for i in currents:
        point = static_point(float(i), p_s, v, start)
        start = [point.theta, point.x, point.y, point.p_d]
        points.append(point)
    return points
