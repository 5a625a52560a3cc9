"""The two-stage servovalve of [GordicND] written out for SciPy: a plain NumPy right-hand side.

The same equations as :class:`hydroservo.components.TwoStageServovalve` with its defaults (quasi-static first
stage, bent flapper), written by hand from the published laws of :mod:`hydroservo.laws` evaluated on floats:
the flapper tip of eqs. 13-14 is solved at every call by SciPy's Brent method, the rest is explicit. It is the
baseline of ``bench_servovalve.py`` and a cross-check of the component's assembly.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from scipy.optimize import brentq

from hydroservo.components import TwoStageServovalve
from hydroservo.laws import armature as ar
from hydroservo.laws import flapper_nozzle as fn
from hydroservo.laws import servo_spool as sp
from hydroservo.laws import torque_motor as tm
from hydroservo.laws.friction import stribeck
from hydroservo.laws.orifice import signed_sqrt

#: Table 1 in SI, as the component's defaults.
P: dict[str, float] = dict(TwoStageServovalve("sv").values)
P_REG = 100.0  # Pa, as the component's first-stage regularisation


def _stage(tip: float, theta: float, v: float, p_d: float, p_s: float, p_0: float, p: dict[str, float]) -> tuple:
    rho = p["rho"]
    A_s = math.pi * p["d_s"] ** 2 / 4
    b = fn.nozzle_conductance(p["K_n0"], p["d_n"], max(p["x_0"] - tip, 0.0), rho)
    c = fn.nozzle_conductance(p["K_n0"], p["d_n"], max(p["x_0"] + tip, 0.0), rho)
    a = fn.orifice_conductance(p["K_o0"], p["d_o"], rho)
    p_l, p_r = fn.nozzle_pressures(p_s, p_d, a, b, c, A_s * v)
    F_h = ar.flapper_flow_force(p_l, p_r, p_d, tip, p["x_0"], p["d_n"], p["K_n0"], p["K_n0"])
    return float(p_l), float(p_r), float(F_h), b, c


def _tip(theta: float, v: float, p_d: float, p_s: float, p_0: float, p: dict[str, float]) -> float:
    def residual(x: float) -> float:
        F_h = _stage(x, theta, v, p_d, p_s, p_0, p)[2]
        return x - float(ar.flapper_tip(theta, F_h, p["l_a"], p["l_fl"], p["B_fl"], p["l_t"], p["B_t"]))

    guess, width = theta * p["l_a"], 5e-5  # the bending is usually well within 50 um: widen until bracketed
    while residual(guess - width) * residual(guess + width) > 0 and width < 10.0:
        width *= 2
    return brentq(residual, guess - width, guess + width, xtol=1e-16, rtol=1e-14)


def _spool(y: float, v: float, p_s: float, p_0: float, p_A: float, p_B: float, p: dict[str, float]) -> tuple:
    f = p["f_ports"] * p["f_width"]
    rho, eta = p["rho"], p["rho"] * p["nu"]
    drops = sp.orifice_drops(p_s, p_0, p_A, p_B)
    c = p["K_t"] * f * math.sqrt(2 / rho)
    Q, eq = [], []
    for k in range(4):
        j = sp.SIGNS[k] * y + p["y_0"]
        root = math.sqrt(max(drops[k], 0.0))
        if j < 0:
            flow = float(sp.lapped_leakage(-j, drops[k], p["K_t"], f, rho, eta, p["delta"], p["r_s"], p["r_b"], p["d_s"]))
        else:
            flow = c * float(sp.real_opening(y, k + 1, p["delta"], p["r_s"], p["r_b"], p["y_0"])) * root
        Q.append(flow)
        eq.append(abs(flow) / (c * max(root, 1.0)))
    F_a = float(sp.steady_flow_force(eq, drops, p["K_t"], p["K_c"], f, p["jet_angle"])) + float(
        sp.transient_flow_force(y, v, drops, p["K_t"], f, rho, p["l_1"], p["l_2"])
    )
    return Q, F_a


def rhs(t: float, s: np.ndarray, current: Any, p_s: float, p_0: float, load: Any, p: dict[str, float] = P) -> np.ndarray:
    """States [theta, omega, y, v, p_d] (+ [p_A, p_B] with blocked ports); ``current(t)`` in A; ``load`` None (no
    load: both ports at half supply) or the volume [m^3] and bulk modulus [Pa] of each blocked port."""
    theta, omega, y, v, p_d = s[:5]
    p_A, p_B = (s[5], s[6]) if load is not None else ((p_s + p_0) / 2, (p_s + p_0) / 2)
    i = current(t)
    tip = _tip(theta, v, p_d, p_s, p_0, p)
    p_l, p_r, F_h, b, c = _stage(tip, theta, v, p_d, p_s, p_0, p)
    phi = float(ar.flapper_inclination(theta, F_h, p["l_fl"], p["B_fl"]))
    F_f = float(ar.feedback_spring_force(y, tip, phi, p["l_f"], p["K_f"], p["z"]))
    T_e = float(tm.electromagnetic_torque(theta, i, p["r"], p["A_p"], p["x_p0"], p["M_m"], p["N"], p["k_c"], p["k_r"]))
    T_i = float(ar.impact_torque(tip, p["x_0"], p["k_i"], p["l_a"]))
    torque = T_e - p["k_v"] * omega - float(ar.flexure_torque(theta, p["B_t"], p["l_t"])) - F_h * p["l_a"] - F_f * p["l_f"] - T_i
    Q, F_a = _spool(y, v, p_s, p_0, p_A, p_B, p)
    F_c = float(stribeck(v, p["k_n"], p["F_cn"], p["F_c0"] - p["F_cn"], p["c_s"], p["v_reg"]))
    A_s = math.pi * p["d_s"] ** 2 / 4
    a_d = fn.orifice_conductance(p["K_od0"], p["d_od"], p["rho"])
    Q_nl, Q_nr = b * signed_sqrt(p_l - p_d, P_REG), c * signed_sqrt(p_r - p_d, P_REG)
    Q_od = a_d * signed_sqrt(p_d - p_0, P_REG)
    out = [omega, torque / p["J_a"], v, ((p_l - p_r) * A_s - F_c - F_a - F_f) / p["m_s"],
           p["beta_e"] / p["V_d"] * float(Q_nl + Q_nr - Q_od)]
    if load is not None:
        volume, beta = load
        out += [beta / volume * (Q[0] - Q[3]), beta / volume * (Q[1] - Q[2])]
    return np.array(out)


def flows(s: np.ndarray, p_s: float, p_0: float, p: dict[str, float] = P) -> tuple[float, float]:
    """No-load flow (QA - QB)/2 and the flow from supply at state ``s`` (no load)."""
    theta, _, y, v, p_d = s[:5]
    half = (p_s + p_0) / 2
    Q, _ = _spool(y, v, p_s, p_0, half, half, p)
    tip = _tip(theta, v, p_d, p_s, p_0, p)
    p_l, p_r, *_ = _stage(tip, theta, v, p_d, p_s, p_0, p)
    a = fn.orifice_conductance(p["K_o0"], p["d_o"], p["rho"])
    first = a * (math.sqrt(max(p_s - p_l, 0.0)) + math.sqrt(max(p_s - p_r, 0.0)))
    return ((Q[0] - Q[3]) - (Q[1] - Q[2])) / 2, Q[0] + Q[1] + first
