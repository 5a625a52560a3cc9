"""The two-stage servovalve of [GordicND] (PPT B.31.210.12.1000.U2V): its laws against Table 1.

The first figures of the first-principles servovalve: the torque motor's
constants (eqs. 5-9), the armature's pivot (eq. 11) and the flapper-nozzle
gap at null that the assembly rule of section 3 sets. The parameter set is
``GordicND`` (Table 1, as printed); how each entry was read:
docs/servovalve.md. The rated flow (12 L/min at 10 mA, 210 bar) is the
static equilibrium of the whole valve (:mod:`hydroservo.analysis.servovalve`).
"""

from __future__ import annotations

from hydroservo.analysis.servovalve import first_stage_null, static_point, table1
from hydroservo.data import parameter_set
from hydroservo.laws import armature, flapper_nozzle, torque_motor
from hydroservo.validation import Row

__all__ = ["rows", "compute"]

_T1 = "GordicND Table 1"


def rows() -> list[Row]:
    """The servovalve's constants against Table 1."""
    return [
        Row(
            "K_i",
            "torque-motor gain K_i at null (eq. 5, Table 1, coils in parallel)",
            "GordicND eq. (5)",
            None,
            "N*m/A",
            None,
            "information: the paper prints the law, not the value",
            "eq. 5 with Table 1 (k_r = 0.465)",
            "info",
        ),
        Row(
            "K_m",
            "magnetic spring K_m at null (eq. 6, Table 1)",
            "GordicND eq. (6)",
            None,
            "N*m/rad",
            None,
            "information; it exceeds the flexure tube's B_t/l_t = 3.55 N*m/rad: the armature is held by the "
            "feedback spring and the nozzle jets",
            "eq. 6 with Table 1",
            "info",
        ),
        Row(
            "k_r",
            "magnetic reluctance constant k_r from the magnet (eqs. 7-9)",
            _T1,
            0.465,
            "-",
            0.05,
            "Table 1 prints mu_m = '5 H/m', a permeability no magnet has: read as the relative permeability 5 "
            "(5 mu_0), printed to one digit; 4.5 to 5.5 mu_0 gives k_r from 0.39 to 0.48",
            "eqs. 7-9 with l_m, A_m, k_m, k_l, x_p0, A_p of Table 1 and mu_m = 5 mu_0",
            "reproduced",
        ),
        Row(
            "l_a",
            "pivot distance l_a (eq. 11)",
            _T1,
            8.75,
            "mm",
            0.005,
            "printed to 0.01 mm",
            "l_fl - l_t/2 with Table 1's l_fl = 13 mm, l_t = 8.5 mm",
            "reproduced",
        ),
        Row(
            "x_0",
            "flapper-nozzle gap at null from the assembly rule (section 3)",
            _T1,
            38.5,
            "um",
            3.0,
            "the flow coefficients come from diagrams the text does not contain (Figs. 4-5): the constant and "
            "drain orifices are read from Lichtarowicz's correlation at their null Reynolds numbers, the "
            "flapper-nozzle restriction taken as a sharp-edged orifice (0.611); its coefficient between 0.6 "
            "and 0.7 moves the gap from 41 to 35 um",
            "nozzles at 70 bar with 140 bar supply and the flapper centred: a sqrt(p_s - p_n) = "
            "K_n pi d_n x_0 sqrt(2/rho) sqrt(p_n - p_d), the drain pressure from both nozzles' flow through "
            "the drain orifice (eqs. 22-27)",
            "reproduced",
        ),
        Row(
            "Q_rated",
            "rated flow at 10 mA, 210 bar supply, no load",
            "GordicND section 3",
            12.0,
            "L/min",
            0.5,
            "printed to two figures ('12 l/min'); no parameter is tuned to it. It hangs on the readings of "
            "f (two ports of 2.4 mm: one port would give 6.1 L/min) and l_f = l_s, and on k_r (0.431 from "
            "eqs. 7-9 would give 12.4); the first stage's coefficients move it by 0.002 L/min",
            "static equilibrium of eqs. 10, 14, 22, 39 at rest with Table 1, eqs. 43-51, 57-58 for the flow "
            "(analysis.servovalve.static_point)",
            "reproduced",
        ),
    ]


def compute() -> dict[str, float]:
    """The constants from Table 1."""
    ps = parameter_set("GordicND")

    def tm(key: str, unit: str) -> float:
        return ps.si("torque_motor", key, unit)

    r, A_p, x_p0, M_m = tm("r", "m"), tm("A_p", "m^2"), tm("x_p0", "m"), tm("M_m", "A")
    k_r = tm("k_r", "")
    mu_m = tm("mu_m", "") * torque_motor.MU_0
    p_s = ps.si("rating", "p_assembly_supply", "Pa")
    p_n = ps.si("rating", "p_assembly_nozzle", "Pa")
    valve = table1()  # the nozzle restriction's coefficient: a sharp-edged orifice's (Fig. 4-b is not in the text)
    null = first_stage_null(p_s, valve, p_n)
    x_0 = flapper_nozzle.null_gap(p_s, p_n, null["p_d"], null["a"], valve["K_n"], valve["d_n"], valve["rho"])
    return {
        "K_i": float(torque_motor.torque_gain(r, A_p, x_p0, M_m, tm("N", ""), tm("k_c", ""), k_r)),
        "K_m": float(torque_motor.magnetic_spring(r, A_p, x_p0, M_m, k_r)),
        "k_r": float(
            torque_motor.reluctance_constant(tm("l_m", "m"), tm("A_m", "m^2"), mu_m, tm("k_m", ""), tm("k_l", ""), x_p0, A_p)
        ),
        "l_a": float(armature.pivot_distance(ps.si("armature", "l_fl", "m"), ps.si("armature", "l_t", "m"))) * 1e3,
        "x_0": float(x_0) * 1e6,
        "Q_rated": _rated_flow() * 6e4,
    }


def _rated_flow() -> float:
    ps = parameter_set("GordicND")
    return static_point(ps.si("rating", "i_rated", "A"), ps.si("rating", "p_s", "Pa")).Q_SV
