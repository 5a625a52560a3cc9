"""Rotational mechanics joined port to port: an inertia, a torsional spring, torque and angular-velocity sources.

The rotational counterparts of :mod:`hydroservo.components.mass` and :mod:`hydroservo.components.mechanics`:
their mechanical ports are of kind ``"rotational"`` (angle [rad], angular velocity [rad/s], torque [N*m]) and
join only rotational ports (:mod:`hydroservo.system.nodes`). The laws are the translational ones on an angle:
an inertia is :func:`~hydroservo.laws.rigid_body.rigid_body_acceleration` as a mass is, a torque source is a
force source, an angular-velocity source a velocity source. Hopsan's rotational components ([Hopsan2026]
Mechanic/Rotational/) join the same way, one C component (a torque source, a shaft) to one Q component (an
inertia, a motor, an angular-velocity source) at each node.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo import backend as bk
from hydroservo.components.base import Component, Mechanical, Option, Output, Param, Port, State, register
from hydroservo.components.mechanics import ForceSource, VelocitySource
from hydroservo.errors import ParameterError
from hydroservo.laws.friction import aerodynamic_drag, stribeck
from hydroservo.laws.rigid_body import rigid_body_acceleration
from hydroservo.laws.stops import end_stop_force

__all__ = ["RotationalInertia", "TorsionalSpring", "TorqueSource", "AngularVelocitySource", "Vehicle", "Crank"]


@register
class RotationalInertia(Component):
    r"""Rigid rotating inertia with viscous and Stribeck friction, a torsional spring to ground and end stops.

    .. math:: J\,\ddot\theta = T - n\,T_{P1} - T_f(\dot\theta) - k_{rot}\,\theta + T_{stop}

    (:func:`~hydroservo.laws.rigid_body.rigid_body_acceleration`, the law of
    :class:`~hydroservo.components.mass.Mass` on an angle), with the friction torque :math:`T_f` the Stribeck law
    of the mass (:func:`~hydroservo.laws.friction.stribeck`: viscous ``B_rot``, Coulomb ``T_c0``, static
    ``T_s0`` above it falling off over ``omega_s``, the sign smoothed over ``omega_reg``; with ``T_c0`` and
    ``T_s0`` at 0, the default, it is ``B_rot`` times the speed). Its two ends are the rotational ports ``P2`` (at
    :math:`\theta`, counted along +θ) and ``P1`` (at :math:`-\theta`, counted the other way), as Hopsan's
    MechanicRotationalInertia ([Hopsan2026] Mechanic/Rotational/MechanicRotationalInertia.hpp): the torques of
    what is connected at P2 add into ``T``, those at P1 into ``T_P1``. With a gear ratio ``n_gear`` =
    :math:`n` (1 by default) end 1 is behind an ideal gear, at :math:`-n\theta` (Hopsan's
    MechanicRotationalInertiaWithGearRatio). End stops
    (:func:`~hydroservo.laws.stops.end_stop_force` on the angle) act beyond ``theta_min`` and ``theta_max``
    when ``k_stop_rot`` or ``c_stop_rot`` is set.
    """

    PARAMETERS = {
        "J": Param(0.1, "kg*m^2", "moment of inertia", min=0.0, min_inclusive=False),
        "B_rot": Param(0.0, "N*m*s/rad", "rotational viscous friction coefficient", min=0.0),
        "T_c0": Param(0.0, "N*m", "Coulomb friction torque", min=0.0),
        "T_s0": Param(0.0, "N*m", "static friction torque above the Coulomb one", min=0.0),
        "omega_s": Param(0.01, "rad/s", "Stribeck angular velocity", min=0.0, min_inclusive=False),
        "omega_reg": Param(1e-4, "rad/s", "angular velocity over which the friction's sign is smoothed", min=0.0,
                           min_inclusive=False),
        "k_rot": Param(0.0, "N*m/rad", "stiffness of a torsional spring to ground, relaxed at theta = 0", min=0.0),
        "n_gear": Param(1.0, "", "gear ratio omega1/omega2 (negative: the gear reverses)"),
        "theta_min": Param(-1e30, "rad", "end stop, low side"),
        "theta_max": Param(1e30, "rad", "end stop, high side"),
        "k_stop_rot": Param(0.0, "N*m/rad", "end-stop stiffness (0 with c_stop_rot 0: no end stops)", min=0.0),
        "c_stop_rot": Param(0.0, "N*m*s/rad", "end-stop damping", min=0.0),
        "theta0": Param(0.0, "rad", "initial angle"),
        "omega0": Param(0.0, "rad/s", "initial angular velocity"),
    }
    STATES = {
        "theta": State("rad", "angle", initial="theta0", nominal=1.0),
        "omega": State("rad/s", "angular velocity", initial="omega0", nominal=10.0),
    }
    INPUTS = {
        "T": Port("N*m", "torque on end 2, along +θ", default=0.0),
        "T_P1": Port("N*m", "torque on end 1, counted along -θ: what port P1 sums", default=0.0),
    }
    MECHANICAL = {
        "P1": Mechanical("theta_P1", "omega_P1", "T_P1", "end 1 (counted along -θ)", kind="rotational"),
        "P2": Mechanical("theta", "omega", "T", "end 2 (counted along +θ)", kind="rotational"),
    }
    OUTPUTS = {
        "theta": Output("rad", "angle"),
        "omega": Output("rad/s", "angular velocity"),
        "theta_P1": Output("rad", "angle of end 1, counted along -θ: -n_gear theta"),
        "omega_P1": Output("rad/s", "angular velocity of end 1, counted along -θ: -n_gear omega"),
    }

    def check(self) -> None:
        super().check()
        if self.values["n_gear"] == 0.0:
            raise ParameterError(f"{self.name}.n_gear = 0: a gear ratio must not be zero")

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        n = p["n_gear"]
        return {"theta": x["theta"], "omega": x["omega"], "theta_P1": -n * x["theta"], "omega_P1": -n * x["omega"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        theta, omega = x["theta"], x["omega"]
        load = u["T"] - p["n_gear"] * u["T_P1"]
        load = load + end_stop_force(theta, omega, p["theta_min"], p["theta_max"], p["k_stop_rot"], p["c_stop_rot"])
        friction = stribeck(omega, p["B_rot"], p["T_c0"], p["T_s0"], p["omega_s"], p["omega_reg"])
        return {"theta": omega, "omega": rigid_body_acceleration(load, theta, p["J"], p["k_rot"], 0.0, friction)}


@register
class TorqueSource(ForceSource):
    """A torque from a signal: the rotational counterpart of a force source.

    Its rotational port ``P`` twists what it is joined to with the input ``u``, counted along the port's outward direction (Hopsan's MechanicTorqueTransformer, [Hopsan2026]
    Mechanic/Rotational/MechanicTorqueTransformer.hpp, whose signal is the torque it presses on its node: a
    load against the motion of the Q component there). The law of
    :class:`~hydroservo.components.mechanics.ForceSource` on an angle."""

    INPUTS = {
        "u": Port("N*m", "torque on what port P is joined to, outward", default=0.0),
        "x": Port("rad", "outward angle of port P", default=0.0),
        "v": Port("rad/s", "outward angular velocity of port P", default=0.0),
    }
    MECHANICAL = {"P": Mechanical("x", "v", "F", "where the torque acts (outward)", kind="rotational")}
    OUTPUTS = {"F": Output("N*m", "torque on what port P is joined to, outward")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"F": u["u"]}  # no damping behind it (ForceSource's input B)


@register
class AngularVelocitySource(VelocitySource):
    """An angular velocity from a signal: the rotational counterpart of a velocity source.

    Its rotational port ``P`` turns outward at the input ``u``, from ``theta0``, whatever torque it takes (Hopsan's MechanicAngularVelocityTransformer and MechanicThetaSource,
    [Hopsan2026] Mechanic/Rotational/MechanicAngularVelocityTransformer.hpp, MechanicThetaSource.hpp). The law of
    :class:`~hydroservo.components.mechanics.VelocitySource` on an angle: option ``position`` ``"integral"``
    integrates the angular velocity, ``"input"`` takes the angle from the input ``x_in`` (the theta source's
    ``thetain`` connected)."""

    PARAMETERS = {"theta0": Param(0.0, "rad", "initial angle (option position = 'integral')")}
    STATES = {"x": State("rad", "angle", initial="theta0", nominal=1.0)}
    INPUTS = {
        "u": Port("rad/s", "angular velocity imposed outward", default=0.0),
        "F": Port("N*m", "torque acting on port P, outward", default=0.0),
        "x_in": Port("rad", "angle imposed outward (option position = 'input')", default=0.0),
    }
    MECHANICAL = {"P": Mechanical("x", "v", "F", "the turning point (outward)", kind="rotational")}
    OUTPUTS = {
        "x": Output("rad", "angle"),
        "v": Output("rad/s", "angular velocity"),
    }


@register
class TorsionalSpring(Component):
    r"""Linear torsional spring between two ends, through a gear: the rotational counterpart of a spring.

    .. math:: T_2 = -k_{rot}\,(\theta_1/n + \theta_2 - e_{0,rot}), \qquad T_1 = T_2/n

    with :math:`\theta_1`, :math:`\theta_2` the outward angles of its ends, ``T1``, ``T2`` the torques it exerts
    outward on what they are joined to, and :math:`n` (``n_gear``) the gear ratio :math:`\omega_1/\omega_2` of an
    ideal gear at end 1, the spring at end 2 (:math:`T_1 \omega_1 = T_2 \omega_2`). With ``n_gear`` 1 it is the law
    of :class:`~hydroservo.components.mechanics.Spring` on an angle. Output ``F`` is the spring's torque (twisted
    open positive). Hopsan's MechanicTorsionalSpring, MechanicRotShaft, MechanicRotShaftG and MechanicGearShaft
    ([Hopsan2026] Mechanic/Rotational/) are this law as transmission-line elements.
    """

    PARAMETERS = {
        "k_rot": Param(100.0, "N*m/rad", "torsional stiffness (at end 2)", min=0.0),
        "e0_rot": Param(0.0, "rad", "twist (theta1/n_gear + theta2) at which the spring is relaxed"),
        "n_gear": Param(1.0, "", "gear ratio omega1/omega2 (negative: the gear reverses)"),
    }
    INPUTS = {
        "x1": Port("rad", "outward angle of end 1", default=0.0),
        "v1": Port("rad/s", "outward angular velocity of end 1", default=0.0),
        "x2": Port("rad", "outward angle of end 2", default=0.0),
        "v2": Port("rad/s", "outward angular velocity of end 2", default=0.0),
    }
    MECHANICAL = {
        "P1": Mechanical("x1", "v1", "F1", "end 1 of the spring (outward)", kind="rotational"),
        "P2": Mechanical("x2", "v2", "F2", "end 2 of the spring (outward)", kind="rotational"),
    }
    OUTPUTS = {
        "F1": Output("N*m", "torque on what end 1 is joined to, outward"),
        "F2": Output("N*m", "torque on what end 2 is joined to, outward"),
        "F": Output("N*m", "torque in the spring (twisted open positive)"),
    }

    def check(self) -> None:
        super().check()
        if self.values["n_gear"] == 0.0:
            raise ParameterError(f"{self.name}.n_gear = 0: a gear ratio must not be zero")

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        n = p["n_gear"]
        torque = p["k_rot"] * (u["x1"] / n + u["x2"] - p["e0_rot"])
        return {"F1": -torque / n, "F2": -torque, "F": torque}


@register
class Vehicle(Component):
    r"""A vehicle on a level road driven at its wheels: its two rotational ports are the wheels' shaft.

    .. math:: M\,\dot v = -\frac{T_1 + T_2}{r} - \tfrac{1}{2}\rho\,C_dA\,v|v| - F_r(v)

    with :math:`T_1`, :math:`T_2` the torques at its ports ``P1`` and ``P2`` (outward), both turning at
    :math:`-v/r` (a torque pressing on a port against that motion drives the vehicle forward), the aerodynamic
    drag :func:`~hydroservo.laws.friction.aerodynamic_drag` and the rolling resistance :math:`F_r` Coulomb's
    friction :math:`c_r M g` (:func:`~hydroservo.laws.friction.stribeck`, its sign smoothed over ``v_reg``: a
    vehicle at rest stays there until the wheels' torque overcomes it). Hopsan's MechanicVehicle1D ([Hopsan2026]
    Special/MechanicVehicle1D.hpp) is this law, its rolling resistance the force that would stop the vehicle
    within a step, limited to :math:`c_r M g`: Coulomb's law as the step vanishes.
    """

    PARAMETERS = {
        "M": Param(1000.0, "kg", "vehicle mass", min=0.0, min_inclusive=False),
        "r_wheel": Param(1.0, "m", "wheel radius", min=0.0, min_inclusive=False),
        "c_r": Param(0.02, "", "rolling resistance coefficient (force per weight)", min=0.0),
        "CdA": Param(0.5, "m^2", "drag coefficient times frontal area", min=0.0),
        "rho_air": Param(1.25, "kg/m^3", "density of the air", min=0.0),
        "g": Param(9.81, "m/s^2", "acceleration of gravity", min=0.0),
        "v_reg": Param(1e-4, "m/s", "velocity over which the friction sign is smoothed", min=0.0, min_inclusive=False),
        "x0": Param(0.0, "m", "initial position"),
        "v0": Param(0.0, "m/s", "initial velocity"),
    }
    STATES = {
        "x": State("m", "position of the vehicle", initial="x0", nominal=10.0),
        "v": State("m/s", "speed of the vehicle", initial="v0", nominal=1.0),
    }
    INPUTS = {
        "T1": Port("N*m", "torque on port P1, outward", default=0.0),
        "T2": Port("N*m", "torque on port P2, outward", default=0.0),
    }
    MECHANICAL = {
        "P1": Mechanical("theta", "omega", "T1", "the wheels' shaft, one end (outward)", kind="rotational"),
        "P2": Mechanical("theta", "omega", "T2", "the wheels' shaft, other end (outward)", kind="rotational"),
    }
    OUTPUTS = {
        "x": Output("m", "position"),
        "v": Output("m/s", "speed"),
        "theta": Output("rad", "angle of the wheels' shaft at either port, outward: -x/r_wheel"),
        "omega": Output("rad/s", "angular velocity of the shaft, outward: -v/r_wheel"),
        "F_d": Output("N", "aerodynamic drag"),
        "F_r": Output("N", "rolling resistance"),
    }

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        v = x["v"]
        return {
            "x": x["x"], "v": v, "theta": -x["x"] / p["r_wheel"], "omega": -v / p["r_wheel"],
            "F_d": aerodynamic_drag(v, p["rho_air"], p["CdA"]),
            "F_r": stribeck(v, 0.0, p["c_r"] * p["M"] * p["g"], 0.0, 1.0, p["v_reg"]),
        }

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        drive = -(u["T1"] + u["T2"]) / p["r_wheel"]
        return {"x": x["v"], "v": rigid_body_acceleration(drive, x["x"], p["M"], friction=y["F_d"] + y["F_r"])}


@register
class Crank(Component):
    r"""A crank: a link of length ``r_link`` on a rotating inertia, whose end moves a translational port along a line.

    .. math:: J\,\ddot\theta = T - (F_0 + F_1)\,r\cos\theta - B_{rot}\,\dot\theta + T_{stop},
              \qquad x = x_{link} - r\sin\theta

    The rotational port ``P2`` is the inertia (:math:`\theta`, outward), the translational ports ``P0`` and ``P1``
    the link's end, both at :math:`x` moving at :math:`-r\cos\theta\,\dot\theta` (outward): the forces there
    turn the inertia through the arm :math:`r\cos\theta` (:func:`~hydroservo.laws.rigid_body.rigid_body_acceleration`
    on the angle). Stiff end stops (:func:`~hydroservo.laws.stops.end_stop_force`) keep the angle within
    ``theta_min``, ``theta_max``. Hopsan's MechanicJLink (one translational port, Pm1) and MechanicJLink2 (two,
    Pm0 and Pm1) ([Hopsan2026] Mechanic/Rotational/MechanicJLink.hpp, MechanicJLink2.hpp) are this law.

    Option ``link``: ``"crank"`` (the default), the law above; ``"rack"``, a rack on a pinion of pitch radius
    ``r_link``: :math:`x = x_{link} - r\,\theta`, moving at :math:`-r\dot\theta`, the forces turning it through
    the constant arm :math:`r` (the crank's law for :math:`\sin\theta \to \theta`, :math:`\cos\theta \to 1`).
    Hopsan's MechanicRackAndPinion ([Hopsan2026] Mechanic/Rotational/MechanicRackAndPinion.hpp) is this law.
    """

    PARAMETERS = {
        "J": Param(1.0, "kg*m^2", "moment of inertia", min=0.0, min_inclusive=False),
        "B_rot": Param(0.0, "N*m*s/rad", "rotational viscous friction coefficient", min=0.0),
        "r_link": Param(0.1, "m", "link length (from the axis to the translational port)", min=0.0,
                        min_inclusive=False),
        "x_link": Param(0.0, "m", "position of the translational ports at zero angle"),
        "theta_min": Param(-1e30, "rad", "end stop, low side"),
        "theta_max": Param(1e30, "rad", "end stop, high side"),
        "k_stop_rot": Param(0.0, "N*m/rad", "end-stop stiffness (0 with c_stop_rot 0: no end stops)", min=0.0),
        "c_stop_rot": Param(0.0, "N*m*s/rad", "end-stop damping", min=0.0),
        "theta0": Param(0.0, "rad", "initial angle"),
        "omega0": Param(0.0, "rad/s", "initial angular velocity"),
    }
    OPTIONS = {"link": Option("crank", ("crank", "rack"), "the link's end on a circle (a crank) or a rack on a pinion")}
    STATES = {
        "theta": State("rad", "angle", initial="theta0", nominal=1.0),
        "omega": State("rad/s", "angular velocity", initial="omega0", nominal=1.0),
    }
    INPUTS = {
        "T": Port("N*m", "torque on the rotational port P2, outward", default=0.0),
        "F0": Port("N", "force on the translational port P0, outward", default=0.0),
        "F1": Port("N", "force on the translational port P1, outward", default=0.0),
    }
    MECHANICAL = {
        "P0": Mechanical("x", "v", "F0", "the link's end (outward)"),
        "P1": Mechanical("x", "v", "F1", "the link's end (outward)"),
        "P2": Mechanical("theta", "omega", "T", "the inertia (outward)", kind="rotational"),
    }
    OUTPUTS = {
        "theta": Output("rad", "angle"),
        "omega": Output("rad/s", "angular velocity"),
        "x": Output("m", "position of the link's end, outward"),
        "v": Output("m/s", "velocity of the link's end, outward"),
    }

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        theta, omega = x["theta"], x["omega"]
        rack = self.option("link") == "rack"
        travel, arm = (theta, 1.0) if rack else (bk.sin(theta), bk.cos(theta))
        return {
            "theta": theta, "omega": omega,
            "x": p["x_link"] - p["r_link"] * travel, "v": -p["r_link"] * arm * omega,
        }

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        theta, omega = x["theta"], x["omega"]
        arm = 1.0 if self.option("link") == "rack" else bk.cos(theta)
        load = u["T"] - (u["F0"] + u["F1"]) * p["r_link"] * arm
        load = load + end_stop_force(theta, omega, p["theta_min"], p["theta_max"], p["k_stop_rot"], p["c_stop_rot"])
        return {"theta": omega, "omega": rigid_body_acceleration(load, theta, p["J"], friction=p["B_rot"] * omega)}
