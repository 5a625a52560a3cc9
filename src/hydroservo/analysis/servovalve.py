"""The first stage of the two-stage servovalve of [GordicND] at null, from Table 1.

With the flapper centred the flapper-nozzle stage is algebraic: both
constant orifices feed their nozzles, both nozzles drain through the drain
orifice, and the flow coefficients of the constant and drain orifices follow
their Reynolds numbers (Lichtarowicz's correlation, the paper's Fig. 4-a).
:func:`first_stage_null` solves them together; it gives the assembly rule's
null gap (section 3: nozzles at 70 bar with 140 bar supply) and the null
coefficients ``K_o0``, ``K_od0`` of the quasi-static first stage of
:class:`~hydroservo.components.TwoStageServovalve`. :func:`table1` gives
Table 1 as the laws' arguments (SI). The valve itself, at rest and in
motion, is the component; its bench is :mod:`hydroservo.analysis.servovalve_bench`.
"""

from __future__ import annotations

import numpy as np

from hydroservo.data import parameter_set
from hydroservo.laws import flapper_nozzle as fn
from hydroservo.laws import orifice

__all__ = ["TABLE_1", "table1", "first_stage_null"]

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


def first_stage_null(p_s: float, v: dict[str, float], p_n: float | None = None) -> dict[str, float]:
    """The flapper-nozzle stage with the flapper centred at supply ``p_s``: nozzle and drain pressures, and the
    constant and drain orifices' coefficients at their Reynolds numbers (Lichtarowicz), solved together.

    With ``p_n`` the nozzle pressure is given instead (the assembly rule of [GordicND] section 3: 70 bar at
    140 bar supply), and the gap ``x_0`` of ``v`` is not used.
    """
    rho, nu, p_0 = v["rho"], v["nu"], v["p_0"]
    b = fn.nozzle_conductance(v["K_n"], v["d_n"], v["x_0"], rho)
    K_o = K_od = 0.8
    fixed = p_n is not None
    p_n, p_d = (0.5 * (p_s + p_0) if p_n is None else p_n), p_0
    for _ in range(200):
        a = fn.orifice_conductance(K_o, v["d_o"], rho)
        a_d = fn.orifice_conductance(K_od, v["d_od"], rho)
        # a sqrt(p_s - p_n) = b sqrt(p_n - p_d) and 2 a sqrt(p_s - p_n) = a_d sqrt(p_d - p_0), in p_n
        p_d = float(fn.null_drain_pressure(p_s, p_n, p_0, a, a_d))
        lo, hi = p_0, p_s
        for _ in range(0 if fixed else 100):
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
