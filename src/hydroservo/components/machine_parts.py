r"""The parts of an axial piston machine: the cylinder block on its swash plate, a pump piston, the valve plate.

A machine built of its parts rather than one displacement law (:class:`~hydroservo.components.pumps.Pump`): the
block (:class:`SwashPlate`) turns and strokes its N pistons, each piston (:class:`PumpPiston`) holds the oil of its
bore, and the valve plate (:class:`ValvePlate`) joins each bore to the suction or the delivery port as the block
passes them, so that the flow's ripple, the pre-compression in the notches and the pistons' torque on the shaft
come out of the model. Hopsan's In-Line Axial Piston Machine ([Hopsan2026] Hydraulic/MachineParts/) is built so.
The laws are :mod:`hydroservo.laws.axial_piston`.
"""

from __future__ import annotations

import math
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
from hydroservo.laws.axial_piston import swash_plate_piston, valve_plate_opening
from hydroservo.laws.chamber import check_valve_floor, pressure_rate
from hydroservo.laws.orifice import orifice_flow
from hydroservo.laws.rigid_body import rigid_body_acceleration
from hydroservo.units import VACUUM

__all__ = ["SwashPlate", "SwashPlateDrive", "PumpPiston", "ValvePlate"]

#: most pistons a block or a valve plate may have
MAX_PISTONS = 64


def _count(name: str, pistons: Any) -> int:
    if isinstance(pistons, float) and pistons.is_integer():
        pistons = int(pistons)
    if isinstance(pistons, bool) or not isinstance(pistons, int) or not 1 <= pistons <= MAX_PISTONS:
        raise ParameterError(f"{name}.pistons = {pistons!r}: expected a whole number from 1 to {MAX_PISTONS}")
    return pistons


def _swash_plate_declarations(n: int) -> dict[str, Any]:
    return {
        "INPUTS": {
            "T": Port("N*m", "torque on the shaft P2, outward (along +θ)", default=0.0),
            **{f"F{k}": Port("N", f"force on piston port C{k}, outward", default=0.0) for k in range(1, n + 1)},
        },
        "MECHANICAL": {
            "P2": Mechanical("theta", "omega", "T", "the shaft (outward: along +θ)", kind="rotational"),
            **{f"C{k}": Mechanical(f"x{k}", f"v{k}", f"F{k}", f"piston {k}'s foot (outward)") for k in range(1, n + 1)},
        },
        "OUTPUTS": {
            "theta": Output("rad", "angle of the block"),
            "omega": Output("rad/s", "angular velocity of the block"),
            "movement": Output("rad/s", "minus the angular velocity (Hopsan's output movement)"),
            **{f"x{k}": Output("m", f"position of piston {k}'s foot, outward") for k in range(1, n + 1)},
            **{f"v{k}": Output("m/s", f"velocity of piston {k}'s foot, outward") for k in range(1, n + 1)},
        },
    }


class _PerPiston(Component):
    """A machine part with a port per piston: its declarations made for their count, ``pistons``, in the
    constructor (a structural choice, as a line's segments are)."""

    @staticmethod
    def _declarations(n: int) -> dict[str, Any]:
        raise NotImplementedError

    def __init__(self, name: str, pistons: int = 9, **values: Any) -> None:
        self._pistons = _count(name, pistons)
        for key, value in self._declarations(self._pistons).items():
            setattr(self, key, value)
        super().__init__(name, **values)

    @property
    def pistons(self) -> int:
        """Number of pistons (set in the constructor)."""
        return self._pistons

    def structure_key(self) -> tuple[Any, ...]:
        return (self._pistons,)

    def config(self) -> dict[str, Any]:
        return {"pistons": self._pistons}


class _OnSwashPlate(_PerPiston):
    """A part whose pistons' feet a swash plate strokes (parameters ``r``, ``angle``, ``theta_offset``, ``x0``)."""

    def _phase(self, k: int, p: Mapping[str, Any]) -> Any:
        """Piston k's phase on the plate: its offset plus 2π (k - 1)/N."""
        return p["theta_offset"] + 2.0 * math.pi * (k - 1) / self._pistons

    def _feet(self, theta: Any, omega: Any, p: Mapping[str, Any]) -> tuple[dict[str, Any], list[Any]]:
        """The pistons' feet on a swash plate (:func:`~hydroservo.laws.axial_piston.swash_plate_piston`): their
        positions and velocities as outputs ``x{k}``, ``v{k}``, and their arms ∂x_k/∂θ."""
        feet: dict[str, Any] = {}
        arms = []
        for k in range(1, self._pistons + 1):
            stroke, velocity, arm = swash_plate_piston(theta, omega, p["r"], p["angle"], self._phase(k, p))
            feet[f"x{k}"], feet[f"v{k}"] = p["x0"] + stroke, velocity
            arms.append(arm)
        return feet, arms


@register
class SwashPlate(_OnSwashPlate):
    r"""A cylinder block turning on its shaft, its ``pistons`` N pistons' feet stroked by a swash plate.

    .. math:: J\,\dot\omega = T - B_{rot}\,\omega + \sum_{k=1}^{N} F_k\,\frac{\partial x_k}{\partial\theta},
              \qquad x_k = x_0 + r\tan\gamma\,\sin a_k,\quad a_k = -\theta - \theta_{offset} - 2\pi\frac{k-1}{N}

    (:func:`~hydroservo.laws.axial_piston.swash_plate_piston`, the torque of each piston's force through its arm
    :math:`\partial x_k/\partial\theta = -r\tan\gamma\cos a_k`; Newton's law on the angle,
    :func:`~hydroservo.laws.rigid_body.rigid_body_acceleration`). The shaft is the rotational port ``P2``
    (:math:`\theta`, outward), piston k's foot the translational port ``C{k}`` at :math:`x_k`, moving at
    :math:`-r\tan\gamma\cos a_k\,\omega` (outward: the block pushes a piston in where :math:`x_k` grows, and the
    piston's force :math:`F_k` on that port, outward, is minus the force it presses the plate with). Output
    ``movement``, :math:`-\omega`, is Hopsan's.

    Hopsan's MechanicCylinderBlockWithSwashPlate ([Hopsan2026]
    Hydraulic/MachineParts/MechanicCylinderBlockWithSwashPlate.hpp) is this law: its filters
    :math:`(J s^2 + (B + Z_p + Z_{x2}) s)\,a_2 = c_p - c_2` are, with its pistons' forces
    :math:`f_k = c_k + Z_k v_k` and its shaft's torque :math:`t_2 = c_2 + Z_{x2}\omega`, the law above as its step
    vanishes (:math:`T = -t_2`, :math:`F_k = -f_k`); it adds the pistons' :math:`m_p(r_p^2/2 + r^2)` to J after
    its filters have taken J, so that they turn with J alone, as here.
    """

    PARAMETERS = {
        "J": Param(0.1, "kg*m^2", "moment of inertia of the block", min=0.0, min_inclusive=False),
        "B_rot": Param(10.0, "N*m*s/rad", "rotational viscous friction coefficient", min=0.0),
        "r": Param(0.05, "m", "pitch radius of the pistons on the swash plate", min=0.0, min_inclusive=False),
        "angle": Param(0.0, "rad", "swash plate angle", min=-1.5, max=1.5),
        "theta_offset": Param(0.0, "rad", "phase of the first piston (the plate's offset)"),
        "x0": Param(0.0, "m", "mean position of the pistons' feet, outward"),
        "theta0": Param(0.0, "rad", "initial angle"),
        "omega0": Param(0.0, "rad/s", "initial angular velocity"),
    }
    STATES = {
        "theta": State("rad", "angle of the block", initial="theta0", nominal=1.0),
        "omega": State("rad/s", "angular velocity of the block", initial="omega0", nominal=100.0),
    }
    INPUTS = _swash_plate_declarations(9)["INPUTS"]
    MECHANICAL = _swash_plate_declarations(9)["MECHANICAL"]
    OUTPUTS = _swash_plate_declarations(9)["OUTPUTS"]

    _declarations = staticmethod(_swash_plate_declarations)

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        theta, omega = x["theta"], x["omega"]
        return {"theta": theta, "omega": omega, "movement": -omega, **self._feet(theta, omega, p)[0]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        theta, omega = x["theta"], x["omega"]
        load = u["T"]
        for k, arm in enumerate(self._feet(theta, omega, p)[1], start=1):
            load = load + u[f"F{k}"] * arm
        return {"theta": omega, "omega": rigid_body_acceleration(load, theta, p["J"], friction=p["B_rot"] * omega)}


def _swash_plate_drive_declarations(n: int) -> dict[str, Any]:
    return {
        "INPUTS": {
            "movement": Port("rad/s", "minus the block's angular velocity (Hopsan's movement; SwashPlate's output)",
                             default=0.0),
            **{f"F{k}": Port("N", f"force on piston port C{k}, outward", default=0.0) for k in range(1, n + 1)},
        },
        "MECHANICAL": {f"C{k}": Mechanical(f"x{k}", f"v{k}", f"F{k}", f"piston {k}'s foot (outward)")
                       for k in range(1, n + 1)},
        "OUTPUTS": {
            "theta": Output("rad", "angle of the block"),
            **{f"x{k}": Output("m", f"position of piston {k}'s foot, outward") for k in range(1, n + 1)},
            **{f"v{k}": Output("m/s", f"velocity of piston {k}'s foot, outward") for k in range(1, n + 1)},
        },
    }


@register
class SwashPlateDrive(_OnSwashPlate):
    r"""A swash plate whose cylinder block is turned at a given speed: its ``pistons`` N pistons' feet stroked as
    :class:`SwashPlate`'s.

    The block's angle :math:`\theta` turns at :math:`-u_{movement}` (the input ``movement``, Hopsan's sign, as
    :class:`SwashPlate`'s output of that name); piston k's foot, the translational port ``C{k}``, is at
    :math:`x_0 + r\tan\gamma\,\sin a_k`, :math:`a_k = -\theta - \theta_{offset} - 2\pi (k-1)/N`, and moves at
    :math:`-r\tan\gamma\cos a_k\,\dot\theta` (:func:`~hydroservo.laws.axial_piston.swash_plate_piston`). No
    inertia: the speed is imposed. The torque the pistons' forces take from the drive, :math:`\sum_k F_k\,\partial
    x_k/\partial\theta`, is no output: read from the forces at its ports (which follow the feet's velocities), it
    would close an algebraic loop through the pistons; :class:`SwashPlate` turns under it.

    Hopsan's MechanicSwashPlate ([Hopsan2026] Hydraulic/MachineParts/MechanicSwashPlate.hpp) is this law: its
    angle the integral of ``movement`` from 0, its pistons at :math:`x_0 + r\tan\gamma\sin(a_1 - \theta_{offset}
    - 2\pi i/N)`, :math:`a_1 = -\theta`, its output torque (not mapped) :math:`\sum f_i r\tan\gamma\cos(\cdot)`
    with the forces :math:`f_i = -F_i` at its ports.
    """

    PARAMETERS = {
        "r": Param(0.05, "m", "pitch radius of the pistons on the swash plate", min=0.0, min_inclusive=False),
        "angle": Param(0.0, "rad", "swash plate angle", min=-1.5, max=1.5),
        "theta_offset": Param(0.0, "rad", "phase of the first piston (the plate's offset)"),
        "x0": Param(0.0, "m", "mean position of the pistons' feet, outward"),
        "theta0": Param(0.0, "rad", "initial angle"),
    }
    STATES = {"theta": State("rad", "angle of the block", initial="theta0", nominal=1.0)}
    INPUTS = _swash_plate_drive_declarations(9)["INPUTS"]
    MECHANICAL = _swash_plate_drive_declarations(9)["MECHANICAL"]
    OUTPUTS = _swash_plate_drive_declarations(9)["OUTPUTS"]

    _declarations = staticmethod(_swash_plate_drive_declarations)

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"theta": x["theta"], **self._feet(x["theta"], -u["movement"], p)[0]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"theta": -u["movement"]}


@register
class PumpPiston(Component):
    r"""A pump's piston in its bore: one chamber whose oil it compresses, pressed out against its foot.

    The chamber's volume :math:`V = V_1 + A_1 (s_l/2 + x)` grows as the piston comes out of its bore
    (``x`` outward at its foot, the port ``P3``), so that

    .. math:: \dot p = \frac{\beta_e}{V}\bigl(Q - A_1\dot x - c_{leak}(p - p_{case})\bigr)

    (:func:`~hydroservo.laws.chamber.pressure_rate`), the oil entering at the port ``P1`` (``Q``) and leaking to the
    case at ``p_case``; a chamber at ``p_floor`` loses no more pressure
    (:func:`~hydroservo.laws.chamber.check_valve_floor`: the oil releases gas there rather than stretch). The
    piston presses its foot out with :math:`F = A_1 (p - p_{amb}) + F_0 - B_p\dot x` (output ``F``, outward on what
    ``P3`` is joined to: the swash plate), ``F_0`` the spring that holds it on the plate, ``p_amb`` the pressure on
    its other side.

    Hopsan's HydraulicPumpPiston ([Hopsan2026] Hydraulic/MachineParts/HydraulicPumpPiston.hpp) is this law: a
    C-type chamber whose pressure, the mean of its wave variables, integrates the flows of its port, of the piston
    (:math:`q_i = A_1 v_3`, its :math:`x_3` counted into the bore, :math:`V = V_1 + A_1(s_l/2 - x_3)`) and of the
    leakage :math:`c_{leak} p` to 0 Pa absolute, as its step vanishes; its piston's force
    :math:`c_3 + Z_{x3} v_3 = A_1 p + F_0 + B_p v_3` on the absolute pressure. Its internal wave variables are
    floored at 0 Pa absolute (the port's is not, so that its pressure dips below 0 by some :math:`Z_c q`, which
    vanishes with the step): a chamber at 0 Pa absolute loses no more pressure, ``p_floor`` there. Its minimum
    volume :math:`\beta_e T_s^2 A_1^2/(0.1 m_e)` vanishes with the step and its damping ``alpha`` is numerical.
    """

    PARAMETERS = {
        "A_1": Param(1e-3, "m^2", "piston area", min=0.0, min_inclusive=False),
        "s_l": Param(1.0, "m", "stroke (the chamber holds A_1 s_l/2 besides V_1 at x = 0)", min=0.0),
        "V_1": Param(3e-4, "m^3", "dead volume of the chamber", min=0.0),
        "B_p": Param(1000.0, "N*s/m", "viscous friction of the piston", min=0.0),
        "beta_e": Param(1e9, "Pa", "effective bulk modulus", min=0.0, min_inclusive=False, fluid="bulk_modulus"),
        "c_leak": Param(1e-11, "m^3/s/Pa", "leakage coefficient, to the case", min=0.0),
        "F_0": Param(1000.0, "N", "spring force pressing the piston out"),
        "p_case": Param(0.0, "Pa", "pressure the leakage flows to (gauge)", min=VACUUM),
        "p_amb": Param(0.0, "Pa", "pressure on the piston's other side (gauge; '0 Pa_abs' for none)", min=VACUUM),
        "p_floor": Param(0.0, "Pa", "lowest chamber pressure: below it the chamber loses no more", min=VACUUM),
        "p0": Param(0.0, "Pa", "initial pressure", min=VACUUM),
    }
    STATES = {"p": State("Pa", "chamber pressure", initial="p0", nominal=1e7)}
    INPUTS = {
        "Q": Port("m^3/s", "flow into the chamber at P1", default=0.0),
        "x": Port("m", "position of the foot, outward (out of the bore)", default=0.0),
        "v": Port("m/s", "velocity of the foot, outward", default=0.0),
    }
    HYDRAULIC = {"P1": Hydraulic("p", "Q", "the chamber's port")}
    MECHANICAL = {"P3": Mechanical("x", "v", "F", "the piston's foot (outward: out of the bore)")}
    OUTPUTS = {
        "p": Output("Pa", "chamber pressure"),
        "F": Output("N", "force on what P3 is joined to, outward"),
        "V": Output("m^3", "chamber volume"),
    }
    LIMITS = {"p": Limit("pressure", hint="p_floor holds the chamber"), "V": Limit("volume")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {
            "p": x["p"],
            "F": p["A_1"] * (x["p"] - p["p_amb"]) + p["F_0"] - p["B_p"] * u["v"],
            "V": p["V_1"] + p["A_1"] * (p["s_l"] / 2.0 + u["x"]),
        }

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """The chamber reaching its floor."""
        return {"floor": (x["p"] - p["p_floor"], 1e5)}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        q = u["Q"] - p["A_1"] * u["v"] - p["c_leak"] * (x["p"] - p["p_case"])
        return {"p": check_valve_floor(x["p"], pressure_rate(p["beta_e"], y["V"], q), p["p_floor"])}


def _valve_plate_declarations(n: int) -> dict[str, Any]:
    return {
        "INPUTS": {
            "movement": Port("rad/s", "angular velocity of the block relative to the plate"),
            "pA": Port("Pa", "pressure at port A"),
            "pB": Port("Pa", "pressure at port B"),
            **{f"p{k}": Port("Pa", f"pressure in bore {k} (port C{k})") for k in range(1, n + 1)},
        },
        "HYDRAULIC": {
            "A": Hydraulic("pA", "QA", "kidney port A", into=False),
            "B": Hydraulic("pB", "QB", "kidney port B (half a turn from A)", into=False),
            **{f"C{k}": Hydraulic(f"p{k}", f"Q{k}", f"bore {k}", into=False) for k in range(1, n + 1)},
        },
        "OUTPUTS": {
            "QA": Output("m^3/s", "flow out of the plate at A"),
            "QB": Output("m^3/s", "flow out of the plate at B"),
            **{f"Q{k}": Output("m^3/s", f"flow out of the plate at C{k}, into bore {k}") for k in range(1, n + 1)},
            **{f"A_A{k}": Output("m^2", f"opening from bore {k} to A") for k in range(1, n + 1)},
            **{f"A_B{k}": Output("m^2", f"opening from bore {k} to B") for k in range(1, n + 1)},
            "theta": Output("rad", "angle of the block relative to the plate"),
        },
    }


@register
class ValvePlate(_PerPiston):
    r"""The valve plate of an axial piston machine: its two kidney ports, and the ``pistons`` N bores passing them.

    The block's angle relative to the plate, :math:`\theta` (state ``theta``), is the integral of its angular
    velocity, the input ``movement``. Bore k (port ``C{k}``) reaches port A through the area
    :math:`A_{A,k}(\theta)` (:func:`~hydroservo.laws.axial_piston.valve_plate_opening` with its start at
    :math:`2\pi (k-1)/N`) and port B through :math:`A_{B,k}`, the same half a turn later; the oil flows through
    each as through a sharp-edged orifice (:func:`~hydroservo.laws.orifice.orifice_flow`,
    :math:`C_d A \sqrt{2/\rho}\,\Delta p/(\Delta p^2 + p_{tr}^2)^{1/4}`: turbulent down to about ``p_tr``, laminar
    below). All its ports are flow ports (the bores' oil is in the pistons, the ports' in the volumes joined to
    them); outputs ``Q{k}``, ``QA``, ``QB`` count out of the plate.

    Hopsan's HydraulicValvePlate ([Hopsan2026] Hydraulic/MachineParts/HydraulicValvePlate.hpp) is this law: its
    Q-type orifices of coefficient :math:`0.67 A \sqrt{2/\rho}` turbulent to the null (``p_tr`` rounds the null
    off, as hydroservo's orifices do), its angle the trapezoidal integral of ``movement`` from 0, the bores in
    the order of its multiport's connections, and its measure of the angle, which is not a rotation (option
    ``angle = "hopsan"``; :func:`~hydroservo.laws.axial_piston.valve_plate_opening`). Its outputs DEBUG1, DEBUG2 and DEBUG3 are ``theta``, ``A_B1`` and
    ``A_A3``. Hopsan declares the plate's ``alpha_f`` "length of each port" and ``phi_P`` "length of grooves":
    the law (:func:`~hydroservo.laws.axial_piston.valve_plate_opening`) tells how each enters.
    """

    OPTIONS = {
        "angle": Option("periodic", ("periodic", "hopsan"),
                        "the same plate every turn, or the angle as Hopsan's plate measures it (not a rotation: "
                        "some bores stay shut in the first turn)"),
    }
    PARAMETERS = {
        "phi_P": Param(160.0 * math.pi / 180.0, "rad", "length of the kidney (groove)", min=0.0, min_inclusive=False),
        "phi_1": Param(6.0 * math.pi / 180.0, "rad", "length of the first notch (pre-compression)", min=0.0,
                       min_inclusive=False),
        "phi_2": Param(6.0 * math.pi / 180.0, "rad", "length of the second notch", min=0.0),
        "Delta_alpha": Param(5.0 * math.pi / 180.0, "rad", "length of the kidney's rounded ends", min=0.0,
                             min_inclusive=False),
        "alpha_f": Param(30.0 * math.pi / 180.0, "rad", "length of each bore's port", min=0.0),
        "R_f": Param(0.03, "m", "radius of the groove's centre line", min=0.0, min_inclusive=False),
        "theta_1": Param(6.0 * math.pi / 180.0, "rad", "slope of the notches", min=0.0, max=math.pi / 2),
        "theta_2": Param(90.0 * math.pi / 180.0, "rad", "opening angle of the notches' V", min=0.0, max=math.pi),
        "rho": Param(870.0, "kg/m^3", "oil density", min=0.0, min_inclusive=False, fluid="density"),
        "Cd": Param(0.67, "", "discharge coefficient", min=0.0, min_inclusive=False),
        "p_tr": Param(50.0, "Pa", "pressure drop below which the flow turns laminar", min=0.0, min_inclusive=False),
        "theta0": Param(0.0, "rad", "initial angle"),
    }
    STATES = {"theta": State("rad", "angle of the block relative to the plate", initial="theta0", nominal=1.0)}
    INPUTS = _valve_plate_declarations(9)["INPUTS"]
    HYDRAULIC = _valve_plate_declarations(9)["HYDRAULIC"]
    OUTPUTS = _valve_plate_declarations(9)["OUTPUTS"]

    _declarations = staticmethod(_valve_plate_declarations)

    def _openings(self, theta: Any, p: Mapping[str, Any]) -> dict[str, Any]:
        geometry = (p["phi_P"], p["Delta_alpha"], p["alpha_f"], p["phi_1"], p["phi_2"], p["theta_1"], p["theta_2"],
                    p["R_f"])
        out = {}
        periodic = self.option("angle") == "periodic"
        for k in range(1, self._pistons + 1):
            start = 2.0 * math.pi * (k - 1) / self._pistons
            out[f"A_A{k}"] = valve_plate_opening(theta, start, *geometry, periodic=periodic)
            out[f"A_B{k}"] = valve_plate_opening(theta, start + math.pi, *geometry, periodic=periodic)
        return out

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        out = self._openings(x["theta"], p)
        out["theta"] = x["theta"]
        qa: Any = 0.0
        qb: Any = 0.0
        for k in range(1, self._pistons + 1):
            to_a = orifice_flow(out[f"A_A{k}"], u[f"p{k}"] - u["pA"], p["rho"], p["Cd"], p["p_tr"])
            to_b = orifice_flow(out[f"A_B{k}"], u[f"p{k}"] - u["pB"], p["rho"], p["Cd"], p["p_tr"])
            out[f"Q{k}"] = -(to_a + to_b)
            qa, qb = qa + to_a, qb + to_b
        out["QA"], out["QB"] = qa, qb
        return out

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"theta": u["movement"]}
