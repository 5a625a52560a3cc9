"""Hydraulic cylinders: two chambers whose pressures build up, a piston, end stops; a piston of four chambers."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo.components.base import (
    Component,
    Hydraulic,
    Limit,
    Mechanical,
    Option,
    Output,
    Param,
    Port,
    State,
    register,
)
from hydroservo.errors import ParameterError
from hydroservo.laws.chamber import (
    cavity_pressure,
    cavity_volume,
    check_valve_floor,
    cylinder_volumes,
    pressure_rate,
)
from hydroservo.laws.fluid import bulk_modulus_eggerth, bulk_modulus_lee
from hydroservo.laws.stops import end_stop_force
from hydroservo.units import VACUUM

__all__ = ["Cylinder", "FourChamberCylinder"]


#: The pressure floors with a cavity to refill (pressure states below the ports' pressures).
_CAVITY = ("cavity", "cavity-ports")


@register
class Cylinder(Component):
    r"""Double-acting cylinder, differential (``A_B < A_A``) or symmetric (``A_B = A_A``).

    Chamber A is the piston (full-bore) side, B the rod side; positive ``x``
    extends the rod, enlarging A. Chamber pressure dynamics, [Efe2014]
    eqs. (3.32)-(3.41) and [FlightSimulatorND] eqs. (3-17), (3-19)
    (:mod:`hydroservo.laws.chamber`):

    .. math::
        \dot p_A &= \frac{E'(p_A)}{V_A}\left(Q_A - A_A\dot x - Q_{Li} - Q_{LeA}\right),
        \quad V_A = V_{A0} + k_V A_A x\\
        \dot p_B &= \frac{E'(p_B)}{V_B}\left(Q_B + A_B\dot x + Q_{Li} - Q_{LeB}\right),
        \quad V_B = V_{B0} - k_V A_B x

    with internal leakage :math:`Q_{Li} = C_{Li}(p_A - p_B)` ([Efe2014] eq. 3.42) and
    external leakage :math:`Q_{Le} = C_{Le} p`. ``V_A0``, ``V_B0`` are the
    volumes at ``x = 0`` including dead volumes and the lines to the valve.
    ``k_V`` = 1 makes the volumes follow the piston; 0 freezes them at
    ``V_A0``, ``V_B0`` in the capacitance terms :math:`V/E'` (the displacement
    flows :math:`A\dot x` stay), as [FlightSimulatorND] does in its final model
    (section 3.2.2, eqs. 3-31, 3-32).

    Effective bulk modulus (option ``bulk_modulus``): ``constant`` (``beta_e``),
    ``lee`` ([Efe2014] eq. 3.2 with ``E_max``) or ``eggerth`` (eq. 3.3, Table
    3.1 interpolated at ``temperature``).

    Pressure floor (option ``pressure_floor``):

    * ``check-valve`` (default) models replenishing check valves of
      instantaneous response, [FlightSimulatorND] eqs. (3-29)-(3-30): a chamber
      at or below ``p_floor`` cannot lose pressure;
    * ``cavity`` models cavitation as Hopsan does ([Hopsan2026],
      HydraulicCylinderC with its valves): the chamber's pressure state
      ``pA_state`` integrates the continuity equation without a floor, and
      where it falls below ``p_floor`` the chamber holds a cavity of volume
      :math:`V (p_{floor} - p_{state})/\beta_e` (output ``V_cavA``) that the
      inflow must refill before the pressure rises again; the pressure the
      ports and the piston see, ``pA``, is :math:`\max(p_{state}, p_{floor})`.
      The internal leakage follows the pressure states, as Hopsan's does
      (its leakage flow is driven by the chambers' wave variables, which
      stand for the pressure states and are not floored: [Hopsan2026]
      Hydraulic/LinearActuators/HydraulicCylinderC.hpp, ``qLeak``), so a
      cavitating chamber draws leakage from the other as if its pressure
      were below the floor. Set ``p_floor`` to the pressure at which the oil
      releases gas or vapour, near vacuum (``"0 Pa_abs"``);
    * ``cavity-ports``: ``cavity`` with the floor at the ports only: the ports see
      :math:`\max(p_{state}, p_{floor})`, the piston the pressure states themselves, so that a cavitating
      chamber pulls on it (Hopsan's HydraulicPiston, [Hopsan2026] Hydraulic/Special/HydraulicPiston.hpp, whose
      force wave :math:`A_1 c_1 - A_2 c_2` is of its chambers' unfloored waves, where HydraulicCylinderC floors
      them);
    * ``none``: the continuity equation alone (a chamber may go below vacuum,
      which the plausibility check flags).

    Output ``F`` is the hydraulic force on the piston in +x (the chambers' gauge
    pressures on their areas, and ``p_amb``, the gauge pressure around the rod,
    on the rod's section: 0 for a rod in the atmosphere; Hopsan's cylinder, whose
    force is that of absolute pressures, has none, ``"0 Pa_abs"``), less a
    constant spring force ``F_s`` (a spring-loaded piston's: Hopsan's
    HydraulicSpringLoadedPistonC, [Hopsan2026]) and the
    piston's viscous friction ``B_p`` v, plus the end-stop force
    (:func:`~hydroservo.laws.stops.end_stop_force`): a spring-damper (``k_stop``, ``c_stop``) acting beyond ``x_min``/``x_max``,
    stiff by default (1e9 N/m, 1e6 N s/m: 0.1 mm under 100 kN, a hard stop for any
    practical load, as Hopsan's stroke limit tends to one); with both 0 there
    are no end stops. Output ``m_oil`` is the oil mass in both chambers
    ([Efe2014] eqs. 3.44-3.46); connect it to a mass's ``m_add`` to count it
    in the moving mass. The rod's end is the mechanical port ``R``
    (``connect("cyl.R", "load.P1")`` feeds ``x``, ``v`` and ``F``). Outputs ``VA``, ``VB`` are the volumes of the
    pressure equations.

    Option ``chambers``: ``volumes`` (default), the chambers' pressures build up in the cylinder as above (its
    ports ``A`` and ``B`` are pressure ports); ``ports``, the chambers' oil is outside it, in the volumes joined to
    ``A`` and ``B``, whose pressures the piston reads (flow ports: the flow into A is
    :math:`A_A\dot x + Q_{Li} + C_{LeA} p_A`, into B :math:`-A_B\dot x - Q_{Li} + C_{LeB} p_B`, with no pressure
    states, volumes or oil mass). That is the same piston with the other causality, Hopsan's
    HydraulicCylinderQ ([Hopsan2026] Hydraulic/LinearActuators/HydraulicCylinderQ.hpp, whose chambers are the
    C components joined to it); the pressure floor options do not apply.

    Every run is checked against the cylinder's physical bounds (``LIMITS``,
    :mod:`hydroservo.system.plausibility`): chamber pressures between vacuum and
    the supply (with margins), the piston within its stops, positive volumes.
    """

    RENAMED = {"beta": "beta_e"}

    PARAMETERS = {
        "A_A": Param(2e-3, "m^2", "piston area, side A", min=0.0, min_inclusive=False),
        "A_B": Param(1e-3, "m^2", "annulus area, side B (rod side)", min=0.0, min_inclusive=False),
        "V_A0": Param(
            5e-4, "m^3", "volume of side A at x = 0, with dead volume and line", min=0.0, min_inclusive=False
        ),
        "V_B0": Param(
            5e-4, "m^3", "volume of side B at x = 0, with dead volume and line", min=0.0, min_inclusive=False
        ),
        "k_V": Param(1.0, "", "1: volumes follow the piston; 0: frozen at V_A0, V_B0", min=0.0, max=1.0),
        "C_Li": Param(0.0, "m^3/s/Pa", "internal leakage coefficient A to B", min=0.0),
        "C_LeA": Param(0.0, "m^3/s/Pa", "external leakage coefficient of side A", min=0.0),
        "C_LeB": Param(0.0, "m^3/s/Pa", "external leakage coefficient of side B", min=0.0),
        "beta_e": Param(
            1.4e9, "Pa", "effective bulk modulus (option constant)", min=0.0, min_inclusive=False, fluid="bulk_modulus"
        ),
        "E_max": Param(1.8e9, "Pa", "pure-oil bulk modulus (option lee)", min=0.0, min_inclusive=False),
        "p_max": Param(280e5, "Pa", "maximum pressure (option lee)", min=0.0, min_inclusive=False),
        "temperature": Param(50.0, "degC", "oil temperature (option eggerth)", min=20.0, max=90.0),
        "rho": Param(870.0, "kg/m^3", "oil density (for m_oil)", min=0.0, fluid="density"),
        "p_floor": Param(
            0.0, "Pa", "lowest chamber pressure (options check-valve and cavity)", min=VACUUM
        ),
        "x_min": Param(-0.1, "m", "end stop, retracted"),
        "x_max": Param(0.1, "m", "end stop, extended"),
        "k_stop": Param(1e9, "N/m", "end-stop stiffness (0 with c_stop 0: no end stops)", min=0.0),
        "B_p": Param(0.0, "N*s/m", "viscous friction of the piston", min=0.0),
        "p_amb": Param(
            0.0, "Pa", "pressure around the rod, acting on its section A_A - A_B (gauge; '0 Pa_abs' for none)", min=VACUUM
        ),
        "c_stop": Param(1e6, "N*s/m", "end-stop damping", min=0.0),
        "F_s": Param(0.0, "N", "constant spring force on the piston, in -x (a spring-loaded piston's)"),
        "pA0": Param(0.0, "Pa", "initial pressure, side A", min=VACUUM),
        "pB0": Param(0.0, "Pa", "initial pressure, side B", min=VACUUM),
    }
    OPTIONS = {
        "bulk_modulus": Option("constant", ("constant", "lee", "eggerth"), "effective bulk modulus law"),
        "pressure_floor": Option(
            "check-valve",
            ("check-valve", "cavity", "cavity-ports", "none"),
            "replenishing check valves, a cavity to refill (Hopsan), the same floored at the ports only, or none",
        ),
        "chambers": Option(
            "volumes",
            ("volumes", "ports"),
            "the chambers' pressures built up in the cylinder, or read from the volumes joined to A and B",
        ),
    }
    STATES = {
        "pA": State("Pa", "pressure, side A", initial="pA0", nominal=1e7),
        "pB": State("Pa", "pressure, side B", initial="pB0", nominal=1e7),
    }
    INPUTS = {
        "QA": Port("m^3/s", "flow into side A"),
        "QB": Port("m^3/s", "flow into side B"),
        "x": Port("m", "piston position"),
        "v": Port("m/s", "piston velocity"),
    }
    HYDRAULIC = {
        "A": Hydraulic("pA", "QA", "chamber A (piston side)"),
        "B": Hydraulic("pB", "QB", "chamber B (rod side)"),
    }
    MECHANICAL = {"R": Mechanical("x", "v", "F", "the rod's end (outward is +x, extending)")}
    OUTPUTS = {
        "pA": Output("Pa", "pressure, side A"),
        "pB": Output("Pa", "pressure, side B"),
        "F": Output("N", "force on the piston in +x (hydraulic and end stops)"),
        "m_oil": Output("kg", "oil mass in both chambers"),
        "QLi": Output("m^3/s", "internal leakage A to B"),
        "VA": Output("m^3", "volume of side A in the pressure equation"),
        "VB": Output("m^3", "volume of side B in the pressure equation"),
    }
    LIMITS = {
        "pA": Limit("pressure", hint="option pressure_floor = check-valve holds the chamber at p_floor"),
        "pB": Limit("pressure", hint="option pressure_floor = check-valve holds the chamber at p_floor"),
        "x": Limit(
            "travel", "x_min", "x_max", hint="no end stops when k_stop and c_stop are 0, soft ones when k_stop is small"
        ),
        "VA": Limit("volume"),
        "VB": Limit("volume"),
    }

    def options_changed(self) -> None:
        """The states of the chosen pressure floor: the pressures, or (cavity) pressure states below the ports' pressures;
        with the chambers outside (option ``chambers = "ports"``), none: the ports read the pressures and give the
        flows."""
        cls = type(self)
        if self.option("chambers") == "ports":
            self.STATES = {}  # type: ignore[misc]
            self.INPUTS = {  # type: ignore[misc]
                "pA": Port("Pa", "pressure at port A (of the volume joined to it)"),
                "pB": Port("Pa", "pressure at port B (of the volume joined to it)"),
                "x": cls.INPUTS["x"],
                "v": cls.INPUTS["v"],
            }
            self.OUTPUTS = {  # type: ignore[misc]
                "QA": Output("m^3/s", "flow into the cylinder at A"),
                "QB": Output("m^3/s", "flow into the cylinder at B"),
                "F": cls.OUTPUTS["F"],
                "QLi": cls.OUTPUTS["QLi"],
            }
            self.LIMITS = {"x": cls.LIMITS["x"]}  # type: ignore[misc]
            return
        self.INPUTS, self.LIMITS = dict(cls.INPUTS), dict(cls.LIMITS)  # type: ignore[misc]
        if self.option("pressure_floor") not in _CAVITY:
            self.STATES, self.OUTPUTS = dict(cls.STATES), dict(cls.OUTPUTS)  # type: ignore[misc]
            return
        self.STATES = {  # type: ignore[misc]
            f"p{side}_state": State(
                "Pa",
                f"pressure state of side {side}: the pressure, or below p_floor a cavity to refill",
                initial=f"p{side}0",
                nominal=1e7,
            )
            for side in "AB"
        }
        self.OUTPUTS = {  # type: ignore[misc]
            **cls.OUTPUTS,
            "V_cavA": Output("m^3", "cavity volume in side A (option cavity)"),
            "V_cavB": Output("m^3", "cavity volume in side B (option cavity)"),
        }

    def _pressures(self, x: Mapping[str, Any], p: Mapping[str, Any], u: Mapping[str, Any]) -> tuple[Any, Any]:
        """The chamber pressures the ports and the piston see."""
        if self.option("chambers") == "ports":
            return u["pA"], u["pB"]
        if self.option("pressure_floor") in _CAVITY:
            return cavity_pressure(x["pA_state"], p["p_floor"]), cavity_pressure(x["pB_state"], p["p_floor"])
        return x["pA"], x["pB"]

    def check(self) -> None:
        v = self.values
        if v["x_min"] >= v["x_max"]:
            raise ParameterError(f"{self.name}.x_min = {v['x_min']:g} m: expected below x_max = {v['x_max']:g} m")
        if self.option("chambers") == "ports":
            return  # no chamber volumes
        for side, area in (("A", "A_A"), ("B", "A_B")):
            for end in ("x_min", "x_max"):
                sign = 1.0 if side == "A" else -1.0
                vol = v[f"V_{side}0"] + sign * v["k_V"] * v[area] * v[end]
                if vol <= 0:
                    raise ParameterError(
                        f"{self.name}.V_{side}0 = {v[f'V_{side}0']:g} m³: chamber {side} would have volume {vol:g} m³ "
                        f"at {end} = {v[end]:g} m; expected a positive volume over the stroke"
                    )

    def _bulk(self, pr: Any, p: Mapping[str, Any]) -> Any:
        law = self.option("bulk_modulus")
        if law == "constant":
            return p["beta_e"]
        if law == "lee":
            return bulk_modulus_lee(pr, E_max=p["E_max"], p_max=p["p_max"])
        return bulk_modulus_eggerth(pr, temperature=p["temperature"])

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        pA, pB = self._pressures(x, p, u)
        ports = self.option("chambers") == "ports"
        cavity = not ports and self.option("pressure_floor") in _CAVITY  # Hopsan's leakage: between the states
        drop = x["pA_state"] - x["pB_state"] if cavity else pA - pB
        out = {"QLi": p["C_Li"] * drop}
        fA, fB = (x["pA_state"], x["pB_state"]) if self.option("pressure_floor") == "cavity-ports" else (pA, pB)
        pos = u["x"]
        stop = end_stop_force(pos, u["v"], p["x_min"], p["x_max"], p["k_stop"], p["c_stop"])
        out["F"] = (
            fA * p["A_A"] - fB * p["A_B"] - p["p_amb"] * (p["A_A"] - p["A_B"]) - p["F_s"] - p["B_p"] * u["v"] + stop
        )
        if ports:  # the chambers' continuity is the volumes' outside: the flows the piston displaces
            out["QA"] = p["A_A"] * u["v"] + out["QLi"] + p["C_LeA"] * pA
            out["QB"] = -p["A_B"] * u["v"] - out["QLi"] + p["C_LeB"] * pB
            return out
        out["pA"], out["pB"] = pA, pB
        VA, VB = cylinder_volumes(p["V_A0"], p["V_B0"], p["A_A"], p["A_B"], pos, p["k_V"])
        out["m_oil"] = p["rho"] * (VA + VB)
        out["VA"], out["VB"] = VA, VB
        if self.option("pressure_floor") in _CAVITY:
            for side, V in (("A", VA), ("B", VB)):
                out[f"V_cav{side}"] = cavity_volume(x[f"p{side}_state"], p["p_floor"], V, self._bulk(out[f"p{side}"], p))
        return out

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """The end stops reached, and a chamber at its pressure floor (options cavity and check-valve)."""
        found = {"stop_min": (u["x"] - p["x_min"], 1e-3), "stop_max": (u["x"] - p["x_max"], 1e-3)}
        if self.option("chambers") == "ports":
            return found
        floor = self.option("pressure_floor")
        if floor in _CAVITY:
            found.update({f"floor_{s}": (x[f"p{s}_state"] - p["p_floor"], 1e5) for s in ("A", "B")})
        elif floor == "check-valve":
            found.update({f"floor_{s}": (x[f"p{s}"] - p["p_floor"], 1e5) for s in ("A", "B")})
        return found

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        if self.option("chambers") == "ports":
            return {}
        pA, pB = y["pA"], y["pB"]
        vel = u["v"]
        VA, VB = y["VA"], y["VB"]
        QLi = y["QLi"]
        dpA = pressure_rate(self._bulk(pA, p), VA, u["QA"] - p["A_A"] * vel - QLi - p["C_LeA"] * pA)
        dpB = pressure_rate(self._bulk(pB, p), VB, u["QB"] + p["A_B"] * vel + QLi - p["C_LeB"] * pB)
        floor = self.option("pressure_floor")
        if floor in _CAVITY:
            return {"pA_state": dpA, "pB_state": dpB}
        if floor == "check-valve":
            dpA = check_valve_floor(pA, dpA, p["p_floor"])
            dpB = check_valve_floor(pB, dpB, p["p_floor"])
        return {"pA": dpA, "pB": dpB}


#: the chambers of :class:`FourChamberCylinder`: each one's number and whether it grows as the piston extends
_FOUR_CHAMBERS = ((1, True), (2, False), (3, True), (4, False))
#: its six leakage paths (from, to)
_FOUR_LEAKS = ((1, 2), (1, 3), (1, 4), (2, 3), (2, 4), (3, 4))


@register
class FourChamberCylinder(Component):
    r"""Cylinder of four chambers on one piston (a digital cylinder): chambers 1 and 3 on the extending side, 2 and 4
    on the retracting side, with leakage between every pair.

    The piston's position :math:`x` runs from 0 (retracted) to the stroke ``s_l``; each chamber is a volume whose
    pressure builds up as :class:`Cylinder`'s do (:func:`~hydroservo.laws.chamber.pressure_rate`), and cannot fall
    below ``p_floor`` (:func:`~hydroservo.laws.chamber.check_valve_floor`: a chamber at the floor holds there, as
    with :class:`Cylinder`'s ``pressure_floor = "check-valve"``, with no cavity to refill):

    .. math::
        V_i = V_{i0} + A_i x \;(i = 1, 3), \qquad V_i = V_{i0} + A_i (s_l - x) \;(i = 2, 4), \\
        \dot p_i = \frac{\beta_e}{V_i}\Big(Q_i \mp A_i\dot x - \sum_j q_{ij}\Big), \qquad
        q_{ij} = c_{leak,ij}\,(p_i - p_j)

    (:math:`-A_i\dot x` for 1 and 3, :math:`+A_i\dot x` for 2 and 4; :math:`q_{ij}` the leakage out of chamber
    :math:`i` into :math:`j`), and the force on the piston in +x

    .. math:: F = A_1 p_1 - A_2 p_2 + A_3 p_3 - A_4 p_4 - p_{amb}(A_1 - A_2 + A_3 - A_4) - B_p \dot x + F_{stop}

    with the end stops at 0 and ``s_l`` (:func:`~hydroservo.laws.stops.end_stop_force`, ``k_stop``, ``c_stop``;
    both 0: none) and ``p_amb`` the gauge pressure around the rod (``"0 Pa_abs"`` for the force of absolute
    pressures, as Hopsan's). ``V_1`` to ``V_4`` are the dead volumes: each chamber's volume where it is smallest.

    This is Hopsan's HydraulicFourChamberPiston ([Hopsan2026] Hydraulic/LinearActuators/HydraulicFourChamberPiston.hpp)
    with its parameters' names: each chamber a transmission-line volume (its impedance (n + 2)/2 β_e Ts/(V (1 − α))
    over its n external and two internal ports, the piston's and the leakage's, its waves filtered by α = 0.1 and
    floored at 0), and the piston's force A_1 c_1 − A_2 c_2 + A_3 c_3 − A_4 c_4 of the internal waves: as the step
    vanishes, the impedances and the filter's lag vanish with it and the chambers are the volumes above. Every
    wave of a chamber is floored at 0 Pa absolute at every step, so a chamber drawn below 0 holds at 0 and keeps no
    memory of it: the floor above, not the cavity of HydraulicCylinderC (whose waves are not floored: Cylinder's
    ``pressure_floor = "cavity"``). On HydraulicFourChamberPistonTest, whose chamber 1 sits at 0 Pa absolute
    while the piston draws it out and pushes it back, a cavity to refill made the flow out of it 14 % of range
    off Hopsan's, the floor 7.2 %: there Hopsan's chamber passes twice the oil it displaces, at any step (its
    floored waves do not conserve the oil of a chamber held at the floor; docs/validation.md). Its stroke limit,
    a spring of stiffness 0.1 m_e/Ts², tends to a hard stop: stiff stops here. Hopsan's smallest
    volume β_e Ts² A²/(0.1 m_e) vanishes with the step. Four chambers rather than an option of :class:`Cylinder`:
    four areas, four dead volumes and six leakage paths, which a two-chamber cylinder would carry unused.

    The rod is the mechanical port ``P5`` (a force port: it reads the position and velocity of what it is joined to,
    outward +x, extending).
    """

    PARAMETERS = {
        **{f"A_{i}": Param(0.001, "m^2", f"piston area of chamber {i}", min=0.0, min_inclusive=False)
           for i in (1, 2, 3, 4)},
        "s_l": Param(1.0, "m", "stroke", min=0.0, min_inclusive=False),
        **{f"V_{i}": Param(0.0003, "m^3", f"dead volume of chamber {i}", min=0.0, min_inclusive=False)
           for i in (1, 2, 3, 4)},
        "B_p": Param(1000.0, "N*s/m", "viscous friction of the piston", min=0.0),
        "Beta_e": Param(1e9, "Pa", "bulk modulus of the oil", min=0.0, min_inclusive=False, fluid="bulk_modulus"),
        **{f"c_leak{i}{j}": Param(1e-11 if (i, j) in ((1, 2), (1, 4), (3, 4)) else 0.0, "m^3/s/Pa",
                                  f"leakage coefficient between chambers {i} and {j}", min=0.0)
           for i, j in _FOUR_LEAKS},
        "p_floor": Param(VACUUM, "Pa", "lowest pressure of a chamber", min=VACUUM),
        "p_amb": Param(0.0, "Pa", "pressure around the rod (gauge; '0 Pa_abs' for none)", min=VACUUM),
        "k_stop": Param(1e9, "N/m", "end-stop stiffness (0 with c_stop 0: no end stops)", min=0.0),
        "c_stop": Param(1e6, "N*s/m", "end-stop damping", min=0.0),
        **{f"p{i}_0": Param(0.0, "Pa", f"initial pressure of chamber {i}", min=VACUUM) for i in (1, 2, 3, 4)},
    }
    STATES = {f"p{i}": State("Pa", f"pressure of chamber {i}", initial=f"p{i}_0", nominal=1e7) for i in (1, 2, 3, 4)}
    INPUTS = {
        **{f"Q{i}": Port("m^3/s", f"flow into chamber {i}") for i in (1, 2, 3, 4)},
        "x": Port("m", "piston position, from the retracted end"),
        "v": Port("m/s", "piston velocity"),
    }
    HYDRAULIC = {f"P{i}": Hydraulic(f"p{i}", f"Q{i}", f"chamber {i}") for i in (1, 2, 3, 4)}
    MECHANICAL = {"P5": Mechanical("x", "v", "F", "the rod's end (outward is +x, extending)")}
    OUTPUTS = {
        **{f"p{i}": Output("Pa", f"pressure of chamber {i}") for i in (1, 2, 3, 4)},
        "F": Output("N", "force on the piston in +x (hydraulic, friction and end stops)"),
        **{f"V{i}": Output("m^3", f"volume of chamber {i}") for i in (1, 2, 3, 4)},
    }
    LIMITS = {
        **{f"p{i}": Limit("pressure") for i in (1, 2, 3, 4)},
        **{f"V{i}": Limit("volume") for i in (1, 2, 3, 4)},
    }

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        out: dict[str, Any] = {}
        force = -p["B_p"] * u["v"] + end_stop_force(u["x"], u["v"], 0.0, p["s_l"], p["k_stop"], p["c_stop"])
        for i, extends in _FOUR_CHAMBERS:
            pressure = x[f"p{i}"]
            sign = 1.0 if extends else -1.0
            out[f"p{i}"] = pressure
            out[f"V{i}"] = p[f"V_{i}"] + p[f"A_{i}"] * (u["x"] if extends else p["s_l"] - u["x"])
            force = force + sign * p[f"A_{i}"] * (pressure - p["p_amb"])
        out["F"] = force
        return out

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """The end stops reached, and a chamber at its pressure floor."""
        found = {"stop_min": (u["x"], 1e-3), "stop_max": (u["x"] - p["s_l"], 1e-3)}
        found.update({f"floor_{i}": (x[f"p{i}"] - p["p_floor"], 1e5) for i in (1, 2, 3, 4)})
        return found

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        net = {i: u[f"Q{i}"] + (-1.0 if extends else 1.0) * p[f"A_{i}"] * u["v"] for i, extends in _FOUR_CHAMBERS}
        for i, j in _FOUR_LEAKS:
            leak = p[f"c_leak{i}{j}"] * (y[f"p{i}"] - y[f"p{j}"])
            net[i] = net[i] - leak
            net[j] = net[j] + leak
        return {
            f"p{i}": check_valve_floor(x[f"p{i}"], pressure_rate(p["Beta_e"], y[f"V{i}"], net[i]), p["p_floor"])
            for i in (1, 2, 3, 4)
        }
