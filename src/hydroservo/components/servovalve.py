"""First stage of a two-stage, force-feedback servovalve (seed 003, MOOG 72 series).

Two components, connected in a loop through the feedback wire:

* :class:`TorqueMotor`: armature and flapper driven by the coil current and
  pulled back by the feedback wire, seed 003 eq. (3-7);
* :class:`FlapperNozzleSpool`: the flapper-nozzle pressure difference drives
  the main spool, seed 003 eqs. (3-14) to (3-16).

Re-derivation of eq. (3-16)
---------------------------
The extraction dropped the derivative dots. From eqs. (3-9) to (3-12) without
flow forces, :math:`A_v P_{Lv} = M_v s^2 x_v` and
:math:`P_{Lv}(K_{ce} + V_v s/4\\beta) = K_2 x_f - A_v s x_v`, hence

.. math:: x_v\\left(\\frac{s^3}{\\omega_h^2} + \\frac{2\\delta_h}{\\omega_h}s^2 + s\\right)
          = \\frac{K_2}{A_v} x_f,
          \\quad \\omega_h^2 = \\frac{4\\beta A_v^2}{M_v V_v},
          \\quad \\delta_h = \\frac{\\omega_h K_{ce} M_v}{2A_v^2}

(eq. 3-14 with D = E = 0), i.e.
:math:`\\dddot x_v = \\frac{K_2}{A_v}\\omega_h^2 x_f - 2\\delta_h\\omega_h\\ddot x_v - \\omega_h^2\\dot x_v`.
The analog pot values of Appendix D confirm each coefficient: P101 =
:math:`K_2\\omega_h^2/(10^{10}A_v)` = 0.6375, P38 = :math:`2\\delta_h\\omega_h/10^4` = 0.388,
P15 = :math:`\\omega_h^2/10^7` = 0.376. The spool is an integrator of flapper
displacement: it stops only when :math:`x_f = 0`, which the torque motor
reaches when :math:`K_1 I_s = K_w x_v` (section 5.2.1).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo.components.base import Component, Output, Param, Port, State, register

__all__ = ["TorqueMotor", "FlapperNozzleSpool"]


@register
class TorqueMotor(Component):
    r"""Torque motor with armature/flapper and feedback wire, seed 003 eq. (3-7).

    .. math:: \ddot x_f = -2\omega_n\zeta_n\dot x_f - \omega_n^2 x_f
              + \frac{K_1\omega_n^2}{K_f} I_s - \frac{K_w}{K_f}\omega_n^2 x_v

    :math:`x_f` is the flapper displacement at the nozzles; :math:`K_1` the
    torque-motor gain per unit current, :math:`K_f` the net stiffness of the
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
        wn2 = p["omega_n"] ** 2
        acc = (
            -2 * p["omega_n"] * p["zeta_n"] * x["vf"]
            - wn2 * x["xf"]
            + p["K1"] * wn2 / p["Kf"] * u["i"]
            - p["Kw"] / p["Kf"] * wn2 * u["xv"]
        )
        return {"xf": x["vf"], "vf": acc}


@register
class FlapperNozzleSpool(Component):
    r"""Main spool driven by the flapper-nozzle stage, seed 003 eq. (3-16) re-derived.

    .. math:: \dddot x_v = \frac{K_2}{A_v}\omega_h^2 x_f - 2\delta_h\omega_h\ddot x_v - \omega_h^2\dot x_v

    Flow forces (terms D and E of eq. 3-15) are left out, as in the seed's
    final model (Appendix A found them negligible).
    """

    PARAMETERS = {
        "K2": Param(0.12065, "m^2/s", "flapper-nozzle flow gain", min=0.0),
        "Av": Param(7.1226e-5, "m^2", "spool end area", min=0.0, min_inclusive=False),
        "omega_h": Param(1940.0, "rad/s", "natural frequency of the spool stage", min=0.0, min_inclusive=False),
        "delta_h": Param(1.0, "", "damping ratio of the spool stage", min=0.0),
        "xv0": Param(0.0, "m", "initial spool position"),
    }
    STATES = {
        "xv": State("m", "spool position", initial="xv0", nominal=2.54e-3),
        "vv": State("m/s", "spool velocity", nominal=0.254),
        "av": State("m/s^2", "spool acceleration", nominal=254.0),
    }
    INPUTS = {"xf": Port("m", "flapper displacement")}
    OUTPUTS = {"xv": Output("m", "spool position"), "vv": Output("m/s", "spool velocity")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"xv": x["xv"], "vv": x["vv"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        wh = p["omega_h"]
        jerk = p["K2"] / p["Av"] * wh**2 * u["xf"] - 2 * p["delta_h"] * wh * x["av"] - wh**2 * x["vv"]
        return {"xv": x["vv"], "vv": x["av"], "av": jerk}
