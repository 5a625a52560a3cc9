"""The [FlightSimulatorND] actuator loop written out by hand: a plain-Python right-hand side for SciPy.

An independent implementation of the same equations as the built-in
``flight-simulator`` system ([FlightSimulatorND] eqs. 3-7, 3-16 re-derived, 3-26,
3-27/3-28 in the sign-correct form 3-18a/3-23a, 3-29/3-30, 3-31, 3-32, 3-35
in the dissertation's form, 3-37), in SI, with the same orifice regularisation. It
serves as the baseline of the speed benchmark and as a cross-check of the
engine's assembly of components (tests/integration/test_builtin_models.py).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

IN = 0.0254
LBF = 4.4482216152605
PSI = LBF / IN**2

P = {
    "A1": 3.40 * IN**2,
    "A2": 8.29 * IN**2,
    "Bm": 10 * LBF / IN,
    "Cl": 0.6e-3 * IN**5 / LBF,
    "cv": 104.5 * IN**2 / math.sqrt(LBF) * 2.36 * IN,
    "Ga": 6.0,
    "Gf": 0.278 / IN,
    "K1": 0.031 * LBF * IN / 1e-3,
    "K2": 187.0 * IN**2,
    "Kf": 90.0 * LBF,
    "Kw": 2.4 * LBF,
    "M": 16.6 * LBF / IN,
    "Ps": 1500 * PSI,
    "Rv": 668.1,
    "RC": 0.34,
    "Vt1": 106.7 * IN**3,
    "Vt2": 245.0 * IN**3,
    "W": 6400 * LBF,
    "wn": 4580.0,
    "zn": 0.4,
    "wh": 1940.0,
    "dh": 1.0,
    "Av": 0.1104 * IN**2,
    "beta": 1e5 * PSI,
}
# transition pressure of the regularised orifice law: flow number 1000, D_h = 0.2 in, nu = 14 cSt
_RHO = 2.0 * (0.61 / (104.5 * IN**2 / math.sqrt(LBF))) ** 2
P["p_tr"] = 0.5 * _RHO * (1000 * 14e-6 / (0.2 * IN)) ** 2


def _g(dp: float, p_tr: float) -> float:
    return dp / (dp * dp + p_tr * p_tr) ** 0.25


def rhs(t: float, s: np.ndarray, p: dict[str, float], vi: float) -> np.ndarray:
    """State s = [y, ydot, P1, P2, xf, xf', xv, xv', xv'', Eo], the dissertation's variables in SI."""
    y, yd, P1, P2, xf, vf, xv, vv, av, Eo = s
    Ei = vi - p["Gf"] * y
    dEo = Ei - Eo / p["RC"]
    Is = p["Ga"] * Eo / p["Rv"]
    wn2 = p["wn"] ** 2
    af = -2 * p["wn"] * p["zn"] * vf - wn2 * xf + p["K1"] * wn2 / p["Kf"] * Is - p["Kw"] / p["Kf"] * wn2 * xv
    jv = p["K2"] / p["Av"] * p["wh"] ** 2 * xf - 2 * p["dh"] * p["wh"] * av - p["wh"] ** 2 * vv
    cv, ptr, Ps = p["cv"], p["p_tr"], p["Ps"]
    pos, neg = max(xv, 0.0), max(-xv, 0.0)
    Q1 = cv * pos * _g(Ps - P1, ptr) - cv * neg * _g(P1, ptr)  # into the rod end
    Q2 = cv * pos * _g(P2, ptr) - cv * neg * _g(Ps - P2, ptr)  # out of the full end
    leak = p["Cl"] * (P1 - P2)
    dP1 = p["beta"] / p["Vt1"] * (Q1 - p["A1"] * yd - leak)
    dP2 = p["beta"] / p["Vt2"] * (-Q2 + p["A2"] * yd + leak)
    if P1 <= 0.0:
        dP1 = max(dP1, 0.0)
    if P2 <= 0.0:
        dP2 = max(dP2, 0.0)
    ydd = (p["A1"] * P1 - p["A2"] * P2 - p["Bm"] * yd + p["W"]) / p["M"]
    return np.array([yd, ydd, dP1, dP2, vf, af, vv, av, jv, dEo])


def simulate(
    t_end: float = 2.0, vi: float = 2.0, n_points: int = 1001, rtol: float = 1e-6, p: dict[str, float] | None = None
):
    """Step response from the Appendix D initial state with LSODA; returns (t, states)."""
    p = P if p is None else p
    s0 = np.zeros(10)
    s0[3] = p["W"] / p["A2"]
    t_eval = np.linspace(0.0, t_end, n_points)
    atol = np.array([1e-7, 1e-7, 1e-1, 1e-1, 1e-11, 1e-8, 1e-10, 1e-7, 1e-4, 1e-9])
    sol = solve_ivp(rhs, (0.0, t_end), s0, method="LSODA", t_eval=t_eval, rtol=rtol, atol=atol, args=(p, vi))
    if not sol.success:
        raise RuntimeError(sol.message)
    return sol.t, sol.y
