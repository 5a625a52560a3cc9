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
from hydroservo.errors import ParameterError, SolverError
from hydroservo.laws import armature as ar
from hydroservo.laws import flapper_nozzle as fn
from hydroservo.laws import orifice
from hydroservo.laws import servo_spool as sp
from hydroservo.laws import torque_motor as tm

__all__ = [
    "TABLE_1",
    "PARAMETER_UNITS",
    "table1",
    "check_geometry",
    "first_stage_null",
    "StaticPoint",
    "static_point",
    "flow_characteristic",
    "StaticBench",
    "static_bench",
    "DESIGN_FIGURES",
    "design_figures",
    "Sensitivity",
    "sensitivity",
]

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

#: The SI unit of every parameter of :func:`table1` (for values given with units).
PARAMETER_UNITS = {
    **{key: unit for key, (_, _, unit) in TABLE_1.items() if key not in ("f_width", "f_ports")},
    "f": "m",
    "K_t": "",
    "K_c": "",
    "alpha": "rad",
    "K_n": "",
}


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


#: Parameters that must be positive: dimensions, stiffnesses, the magnet, the oil.
_POSITIVE = (
    "r", "A_p", "x_p0", "M_m", "N", "k_c", "B_t", "B_fl", "l_t", "l_fl", "l_a", "l_f", "K_f", "d_n", "d_o", "l_o",
    "d_od", "l_od", "x_0", "d_s", "f", "delta", "rho", "nu", "K_n", "K_t", "K_c",
)


def check_geometry(v: dict[str, float], p_s: float | None = None) -> None:
    """Refuse a servovalve no one could build, naming the parameter, its value and what was expected."""
    for key in _POSITIVE:
        if not (np.isfinite(v[key]) and v[key] > 0):
            raise ParameterError(f"servovalve {key} = {v[key]!r} (SI): expected a positive value")
    for key in ("z", "r_s", "r_b", "k_r"):
        if not (np.isfinite(v[key]) and v[key] >= 0):
            raise ParameterError(f"servovalve {key} = {v[key]!r} (SI): expected zero or more")
    for key in ("K_n", "K_t", "K_c"):
        if v[key] > 1:
            raise ParameterError(f"servovalve {key} = {v[key]!r}: expected a flow coefficient of at most 1")
    if not 0 < v["alpha"] < np.pi / 2:
        raise ParameterError(f"servovalve alpha = {v['alpha']!r} rad: expected a jet angle between 0 and 90 degrees")
    if v["l_a"] >= v["l_fl"]:
        raise ParameterError(
            f"servovalve l_a = {v['l_a']:g} m: the pivot must lie within the flapper (l_fl = {v['l_fl']:g} m)"
        )
    if abs(v["y_0"]) >= v["d_s"]:
        raise ParameterError(f"servovalve y_0 = {v['y_0']:g} m: a spool lap as large as the spool")
    if p_s is not None and not p_s > v["p_0"]:
        raise ParameterError(
            f"servovalve supply p_s = {p_s:g} Pa: expected above the return pressure p_0 = {v['p_0']:g} Pa"
        )


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
    c_t = v["K_t"] * v["f"] * np.sqrt(2.0 / rho)
    second = c_t * (openings[0] * np.sqrt(drops[0]) + openings[1] * np.sqrt(drops[1]))  # from supply, orifices 1, 2
    first = null["a"] * (np.sqrt(max(p_s - p_l, 0.0)) + np.sqrt(max(p_s - p_r, 0.0)))
    state = {
        "p_l": p_l, "p_r": p_r, "F_h": F_h, "F_f": F_f, "Q_SV": 0.5 * (Q_L1 + Q_L2),
        "Q_supply": float(first + second), "Q_first_stage": float(first),
    }
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
    check_geometry(v, p_s)
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
        float(state["Q_SV"]),
        {
            "p_n_null": null["p_n"], "K_o": null["K_o"], "K_od": null["K_od"],
            "Q_supply": state["Q_supply"], "Q_first_stage": state["Q_first_stage"],
        },
    )


def flow_characteristic(currents: Any, p_s: float = 210e5, params: dict[str, float] | None = None) -> list[StaticPoint]:
    """Static points at ``currents`` [A], in their order.

    Each side of null is solved from its largest current down (continuation: each point starts from the
    last); the largest starts from rest. Zero current is the centred valve.
    """
    v = params or table1()
    check_geometry(v, p_s)
    values = [float(i) for i in currents]
    found: dict[int, StaticPoint] = {}
    for side in (1.0, -1.0):
        order = sorted((k for k, i in enumerate(values) if i * side > 0), key=lambda k: -abs(values[k]))
        start = None
        for k in order:
            found[k] = static_point(values[k], p_s, v, start)
            start = [found[k].theta, found[k].x, found[k].y, found[k].p_d]
    for k, i in enumerate(values):
        if i == 0.0:
            found[k] = static_point(0.0, p_s, v, [0.0, 0.0, 0.0, first_stage_null(p_s, v)["p_d"]])
    return [found[k] for k in range(len(values))]


@dataclass(frozen=True)
class StaticBench:
    """The static tests of a servovalve at one supply pressure, no load (ISO 10770-1 / SAE ARP490 style), SI."""

    p_s: float  #: supply pressure [Pa]
    i_rated: float  #: rated current [A]
    currents: np.ndarray  #: the characteristic's currents [A]
    flows: np.ndarray  #: and flows [m^3/s]
    supply_flows: np.ndarray  #: flow drawn from supply at each current (leakage included) [m^3/s]
    rated_flow: float  #: flow at +rated current [m^3/s]
    rated_flow_negative: float  #: flow at -rated current [m^3/s]
    symmetry: float  #: (|Q+| - |Q-|) / max, [-]
    linearity: float  #: largest deviation from the line through 0 and the rated point, over the rated flow [-]
    flow_gain_null: float  #: dQ/di between -5 and +5 % of rated current [m^3/s/A]
    internal_leakage_null: float  #: flow from supply at zero current, both stages [m^3/s]
    first_stage_flow_null: float  #: its first-stage part [m^3/s]

    def table(self) -> list[tuple[str, float, str]]:
        """The figures: name, value, unit (engineering units)."""
        return [
            ("rated flow at +rated current", self.rated_flow * 6e4, "L/min"),
            ("rated flow at -rated current", self.rated_flow_negative * 6e4, "L/min"),
            ("symmetry", self.symmetry * 100, "%"),
            ("linearity (deviation from the rated line)", self.linearity * 100, "% of rated flow"),
            ("flow gain at null (+-5 % of rated current)", self.flow_gain_null * 6e4 / 1e3, "L/min/mA"),
            ("internal leakage at null", self.internal_leakage_null * 6e4, "L/min"),
            ("  of which the first stage", self.first_stage_flow_null * 6e4, "L/min"),
        ]


def static_bench(
    p_s: float = 210e5, i_rated: float = 0.01, params: dict[str, float] | None = None, points: int = 41
) -> StaticBench:
    """Rated flow, symmetry, linearity, flow gain at null and internal leakage from the static characteristic.

    The characteristic is solved from each side of null outwards (continuation); at null the feedback
    spring's clearance makes the equilibrium flat, so the null point is solved on its own.
    """
    v = params or table1()
    check_geometry(v, p_s)
    if not (np.isfinite(i_rated) and i_rated > 0):
        raise ParameterError(f"rated current {i_rated!r} A: expected a positive current")
    half = np.linspace(i_rated / (points // 2), i_rated, points // 2)
    small = 0.05 * i_rated
    currents = np.concatenate([-half[::-1], [0.0], half])
    probe = [small, -small]
    points_ = flow_characteristic([*currents, *probe], p_s, v)
    flows = np.array([p.Q_SV for p in points_[: currents.size]])
    supply = np.array([p.extra["Q_supply"] for p in points_[: currents.size]])
    zero = points_[half.size]
    q_plus, q_minus = flows[-1], flows[0]
    k_line = q_plus / i_rated
    q_small = [points_[-1].Q_SV, points_[-2].Q_SV]
    return StaticBench(
        p_s=p_s,
        i_rated=i_rated,
        currents=currents,
        flows=flows,
        supply_flows=supply,
        rated_flow=q_plus,
        rated_flow_negative=q_minus,
        symmetry=(abs(q_plus) - abs(q_minus)) / max(abs(q_plus), abs(q_minus)),
        linearity=float(np.max(np.abs(flows - k_line * currents)) / abs(q_plus)),
        flow_gain_null=(q_small[1] - q_small[0]) / (2 * small),
        internal_leakage_null=zero.extra["Q_supply"],
        first_stage_flow_null=zero.extra["Q_first_stage"],
    )


#: The figures of the design study: name -> (what it is, unit shown, scale from SI).
DESIGN_FIGURES = {
    "rated_flow": ("rated flow", "L/min", 6e4),
    "spool_travel": ("spool travel at rated current", "mm", 1e3),
    "flapper_tip": ("flapper tip at rated current", "um", 1e6),
    "leakage_null": ("internal leakage at null", "L/min", 6e4),
    "first_stage_null": ("first-stage flow at null", "L/min", 6e4),
    "nozzle_pressure_null": ("nozzle pressure at null", "bar", 1e-5),
}


def design_figures(p_s: float = 210e5, i_rated: float = 0.01, params: dict[str, float] | None = None) -> dict[str, float]:
    """The static figures a designer watches (SI): rated flow, spool travel and flapper tip at rated current,
    internal leakage, first-stage flow and nozzle pressure at null."""
    v = params or table1()
    rated = static_point(i_rated, p_s, v)
    null = static_point(0.0, p_s, v, [0.0, 0.0, 0.0, first_stage_null(p_s, v)["p_d"]])
    return {
        "rated_flow": rated.Q_SV,
        "spool_travel": rated.y,
        "flapper_tip": rated.x,
        "leakage_null": null.extra["Q_supply"],
        "first_stage_null": null.extra["Q_first_stage"],
        "nozzle_pressure_null": null.p_l,
    }


@dataclass(frozen=True)
class Sensitivity:
    """How much each figure moves per relative change of each physical parameter (elasticities)."""

    figures: dict[str, float]  #: the figures at the design point (SI)
    elasticity: dict[str, dict[str, float]]  #: figure -> parameter -> d ln(figure) / d ln(parameter)

    def ranked(self, figure: str, top: int | None = None) -> list[tuple[str, float]]:
        """The parameters by the size of their effect on ``figure``, largest first."""
        rows = sorted(self.elasticity[figure].items(), key=lambda kv: -abs(kv[1]))
        return rows[:top] if top else rows


def sensitivity(
    p_s: float = 210e5, i_rated: float = 0.01, params: dict[str, float] | None = None, step: float = 0.01
) -> Sensitivity:
    """Elasticities of the design figures to every physical parameter, by central differences of ``step``
    (relative): the figures are solutions of nonlinear equilibria, smooth away from the feedback spring's
    clearance, and a 1 % step is well inside that."""
    v = params or table1()
    base = design_figures(p_s, i_rated, v)
    names = [k for k in v if k not in ("alpha",) and v[k] != 0.0]
    out: dict[str, dict[str, float]] = {f: {} for f in base}
    for name in names:
        up = design_figures(p_s, i_rated, {**v, name: v[name] * (1 + step)})
        down = design_figures(p_s, i_rated, {**v, name: v[name] * (1 - step)})
        for f in base:
            out[f][name] = (up[f] - down[f]) / (2 * step * base[f]) if base[f] != 0 else float("nan")
    return Sensitivity(base, out)
