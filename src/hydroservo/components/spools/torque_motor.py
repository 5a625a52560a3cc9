"""Torque motor of a two-stage, force-feedback servovalve (MOOG 72 series, [FlightSimulatorND]).

With :class:`~hydroservo.components.FlapperNozzleSpool` it forms the first
stage: the two are connected in a loop through the feedback wire (the spool
position ``xv`` feeds back into the torque motor).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo.components.base import Component, Output, Param, Port, State, register
from hydroservo.laws.torque_motor import armature_acceleration

__all__ = ["TorqueMotor"]


@register
class TorqueMotor(Component):
    r"""Torque motor with armature/flapper and feedback wire, [FlightSimulatorND] eq. (3-7).

    .. math:: \ddot x_f = -2\omega_n\zeta_n\dot x_f - \omega_n^2 x_f
              + \frac{K_1\omega_n^2}{K_f} I_s - \frac{K_w}{K_f}\omega_n^2 x_v

    (:func:`hydroservo.laws.torque_motor.armature_acceleration`). :math:`x_f`
    is the flapper displacement at the nozzles; :math:`K_1` the torque-motor
    gain per unit current, :math:`K_f` the net stiffness of the
    armature/flapper and :math:`K_w` the feedback-wire stiffness, all referred
    to the flapper tip as in eq. (3-6).
    """

    PARAMETERS = {
        "omega_n": Param(4580.0, "rad/s", "natural frequency of the first stage", min=0.0, min_inclusive=False),
        "zeta_n": Param(0.4, "", "damping ratio of the first stage", min=0.0),
        "K1": Param(3.5025, "N*m/A", "torque-motor gain", min=0.0),
        "Kf": Param(
            400.34,
            "N",
            "net stiffness of armature/flapper (torque per flapper displacement)",
            min=0.0,
            min_inclusive=False,
        ),
        "Kw": Param(10.676, "N", "feedback-wire stiffness (torque per spool displacement)", min=0.0),
    }
    STATES = {
        "xf": State("m", "flapper displacement", nominal=2.54e-4),
        "vf": State("m/s", "flapper velocity", nominal=0.254),
    }
    INPUTS = {"i": Port("A", "coil current"), "xv": Port("m", "spool position (feedback wire)")}
    OUTPUTS = {"xf": Output("m", "flapper displacement")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"xf": x["xf"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        acc = armature_acceleration(
            x["xf"], x["vf"], u["i"], u["xv"], p["omega_n"], p["zeta_n"], p["K1"], p["Kf"], p["Kw"]
        )
        return {"xf": x["vf"], "vf": acc}
