"""Moving masses and their loads: weight, damping, spring, Stribeck friction."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.components.base import Component, Mechanical, Output, Param, Port, State, register
from hydroservo.laws.friction import stribeck
from hydroservo.laws.rigid_body import rigid_body_acceleration
from hydroservo.laws.stops import end_stop_force

__all__ = ["Mass", "MassPair"]

G = 9.80665


@register
class Mass(Component):
    r"""Rigid mass on a line with weight, damping, spring and Stribeck friction.

    .. math:: (m + m_{add})\ddot x = F - n F_{P1} + F_{ext} - W\sin\theta - F_f(\dot x) - k_{spring}(x - x_{spring})
              + F_{stop}

    with the Stribeck friction :math:`F_f` of [Efe2014] eq. (3.47) (viscous
    coefficient ``B`` = :math:`\sigma`, ``F_c0``, ``F_s0``, ``c_s``; the sign is
    smoothed as :math:`\tanh(\dot x/v_{reg})`), the weight ``W`` acting
    downwards and :math:`\theta` (``incline``) the angle of the +x axis above
    the horizontal (90 deg: +x points up). [Efe2014] eq. (3.43); [FlightSimulatorND] eq.
    (3-26), where the weight-per-mass term "g" is :math:`W/M`.
    ``m_add`` (input) is added mass such as a cylinder's oil ([Efe2014] eqs.
    3.44-3.46).

    Its two ends are the mechanical ports ``P2`` (at ``x``, outward along +x)
    and ``P1`` (at ``x_P1 = length - x`` along its own outward direction, -x),
    as Hopsan's MechanicTranslationalMass ([Hopsan2026]), whose ``length`` is
    the sum of its ends' start positions: the forces of what is connected at
    P2 add into ``F``, those at P1 into ``F_P1`` (counted outward at end 1). With a lever ratio ``n_lever`` =
    :math:`n` (1 by default), end 1 is on a lever: at :math:`length - n x`, moving n times as fast as the mass, its
    force entering as :math:`n F_{P1}` (Hopsan's MechanicTranslationalMassWithLever, [Hopsan2026]
    Mechanic/Linear/MechanicTranslationalMassWithLever.hpp).
    End stops (:func:`~hydroservo.laws.stops.end_stop_force`) act beyond ``x_min`` and ``x_max`` when ``k_stop`` or ``c_stop`` is set.
    """

    RENAMED = {"k": "k_spring", "x_s": "x_spring"}

    PARAMETERS = {
        "m": Param(100.0, "kg", "moving mass", min=0.0, min_inclusive=False),
        "W": Param(0.0, "N", "weight carried (acts downwards)", min=0.0),
        "incline": Param(np.pi / 2, "rad", "angle of the +x axis above horizontal", min=-np.pi, max=np.pi),
        "B": Param(0.0, "N*s/m", "viscous friction coefficient (sigma)", min=0.0),
        "F_c0": Param(0.0, "N", "Coulomb friction", min=0.0),
        "F_s0": Param(0.0, "N", "static friction above Coulomb", min=0.0),
        "c_s": Param(0.01, "m/s", "Stribeck velocity", min=0.0, min_inclusive=False),
        "v_reg": Param(1e-4, "m/s", "velocity over which the friction sign is smoothed", min=0.0, min_inclusive=False),
        "k_spring": Param(0.0, "N/m", "spring stiffness", min=0.0),
        "x_spring": Param(0.0, "m", "spring free position"),
        "x_min": Param(-1e30, "m", "end stop, low side"),
        "x_max": Param(1e30, "m", "end stop, high side"),
        "k_stop": Param(0.0, "N/m", "end-stop stiffness (0 with c_stop 0: no end stops)", min=0.0),
        "c_stop": Param(0.0, "N*s/m", "end-stop damping", min=0.0),
        "length": Param(0.0, "m", "position of end 1 plus that of end 2, each along its outward direction"),
        "n_lever": Param(1.0, "", "lever ratio: how many times as fast as the mass end 1 moves", min=0.0,
                         min_inclusive=False),
        "x0": Param(0.0, "m", "initial position"),
        "v0": Param(0.0, "m/s", "initial velocity"),
    }
    STATES = {
        "x": State("m", "position", initial="x0", nominal=0.1),
        "v": State("m/s", "velocity", initial="v0", nominal=0.1),
    }
    INPUTS = {
        "F": Port("N", "driving force in +x (e.g. a cylinder's F)", default=0.0),
        "F_P1": Port("N", "force on end 1, outward (along -x): what port P1 sums", default=0.0),
        "F_ext": Port("N", "external force in +x", default=0.0),
        "m_add": Port("kg", "added moving mass", default=0.0),
    }
    MECHANICAL = {
        "P1": Mechanical("x_P1", "v_P1", "F_P1", "end 1 (outward is -x)"),
        "P2": Mechanical("x", "v", "F", "end 2 (outward is +x)"),
    }
    OUTPUTS = {
        "x": Output("m", "position"),
        "v": Output("m/s", "velocity"),
        "F_f": Output("N", "friction force (opposing motion)"),
        "x_P1": Output("m", "position of end 1 along its outward direction (-x): length - n_lever x"),
        "v_P1": Output("m/s", "velocity of end 1, outward (-n_lever v)"),
    }

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        v = x["v"]
        Ff = stribeck(v, p["B"], p["F_c0"], p["F_s0"], p["c_s"], p["v_reg"])
        return {"x": x["x"], "v": v, "F_f": Ff, "x_P1": p["length"] - p["n_lever"] * x["x"], "v_P1": -p["n_lever"] * v}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        weight = p["W"] * bk.sin(p["incline"])
        load = u["F"] - p["n_lever"] * u["F_P1"] + u["F_ext"] - weight
        load = load + end_stop_force(x["x"], x["v"], p["x_min"], p["x_max"], p["k_stop"], p["c_stop"])
        a = rigid_body_acceleration(load, x["x"], p["m"] + u["m_add"], p["k_spring"], p["x_spring"], y["F_f"])
        return {"x": x["v"], "v": a}


@register
class MassPair(Component):
    r"""Two masses on one line that slide on each other: their centre of gravity moves under the forces at their
    outer ends, and their relative displacement under a force between them (a cylinder's rod joining them),
    against dry friction between them and within a stroke.

    .. math:: (m_1 + m_2)\,\ddot x_t = F_2 - F_1, \qquad
              \mu\,\ddot x_3 = F_3 - \frac{m_2 F_1 + m_1 F_2}{m_1 + m_2} - F_f(\dot x_3) + F_{stop}

    with :math:`\mu = m_1 m_2/(m_1 + m_2)` and :math:`x_3 = X_1 - X_2` the position of mass 1 less that of
    mass 2 (``P1``'s outward direction is -x, ``P2``'s +x, so :math:`-x_3` is the stroke between them); each
    mass's own equation is :func:`~hydroservo.laws.rigid_body.rigid_body_acceleration`, written for the centre of
    gravity and the relative displacement. ``F1``, ``F2`` are the forces at the outer ends (outward), ``F3`` the
    force on the relative displacement (outward at ``P3``: pushing mass 1 along +x and mass 2 along -x). The
    friction :math:`F_f` is the Stribeck law of :class:`Mass` (:func:`~hydroservo.laws.friction.stribeck`) on the
    relative velocity, and stiff end stops (:func:`~hydroservo.laws.stops.end_stop_force`) keep the stroke
    :math:`-x_3` within [``x_p_min``, ``x_p_max``]. Hopsan's MechanicM2load1D ([Hopsan2026]
    Mechanic/Linear/MechanicM2load1D.hpp) is this load: P1 at :math:`-X_1`, P2 at :math:`X_2`, P3 at :math:`x_3`.
    """

    PARAMETERS = {
        "m1": Param(1000.0, "kg", "mass 1 (at end P1)", min=0.0, min_inclusive=False),
        "m2": Param(1000.0, "kg", "mass 2 (at end P2)", min=0.0, min_inclusive=False),
        "B": Param(0.0, "N*s/m", "viscous friction coefficient (sigma)", min=0.0),
        "F_c0": Param(0.0, "N", "Coulomb friction", min=0.0),
        "F_s0": Param(0.0, "N", "static friction above Coulomb", min=0.0),
        "c_s": Param(0.01, "m/s", "Stribeck velocity", min=0.0, min_inclusive=False),
        "v_reg": Param(1e-4, "m/s", "velocity over which the friction sign is smoothed", min=0.0, min_inclusive=False),
        "x_p_min": Param(-1e30, "m", "shortest stroke between the masses (-x3)"),
        "x_p_max": Param(1e30, "m", "longest stroke between the masses (-x3)"),
        "k_stop": Param(0.0, "N/m", "end-stop stiffness (0 with c_stop 0: no end stops)", min=0.0),
        "c_stop": Param(0.0, "N*s/m", "end-stop damping", min=0.0),
        "xt0": Param(0.0, "m", "initial position of the centre of gravity"),
        "vt0": Param(0.0, "m/s", "initial velocity of the centre of gravity"),
        "x30": Param(0.0, "m", "initial relative displacement x3 (mass 1 less mass 2)"),
        "v30": Param(0.0, "m/s", "initial relative velocity"),
    }
    STATES = {
        "xt": State("m", "position of the centre of gravity", initial="xt0", nominal=0.1),
        "vt": State("m/s", "velocity of the centre of gravity", initial="vt0", nominal=0.1),
        "x3": State("m", "relative displacement (mass 1 less mass 2)", initial="x30", nominal=0.1),
        "v3": State("m/s", "relative velocity", initial="v30", nominal=0.1),
    }
    INPUTS = {
        "F1": Port("N", "force on end 1, outward (along -x)", default=0.0),
        "F2": Port("N", "force on end 2, outward (along +x)", default=0.0),
        "F3": Port("N", "force on the relative displacement, outward at P3 (along +x3)", default=0.0),
    }
    MECHANICAL = {
        "P1": Mechanical("x1", "v1", "F1", "end 1, on mass 1 (outward is -x)"),
        "P2": Mechanical("x2", "v2", "F2", "end 2, on mass 2 (outward is +x)"),
        "P3": Mechanical("x3", "v3", "F3", "the relative displacement x3 (mass 1 less mass 2)"),
    }
    OUTPUTS = {
        "x1": Output("m", "position of end 1 along its outward direction (-X1)"),
        "v1": Output("m/s", "velocity of end 1, outward"),
        "x2": Output("m", "position of end 2 (X2)"),
        "v2": Output("m/s", "velocity of end 2, outward"),
        "x3": Output("m", "relative displacement"),
        "v3": Output("m/s", "relative velocity"),
        "xt": Output("m", "position of the centre of gravity"),
        "vt": Output("m/s", "velocity of the centre of gravity"),
        "F_f": Output("N", "friction between the masses (opposing the relative motion)"),
    }

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        share1 = p["m2"] / (p["m1"] + p["m2"])  # X1 = xt + share1 x3, X2 = xt - share2 x3
        share2 = p["m1"] / (p["m1"] + p["m2"])
        Ff = stribeck(x["v3"], p["B"], p["F_c0"], p["F_s0"], p["c_s"], p["v_reg"])
        return {
            "x1": -(x["xt"] + share1 * x["x3"]), "v1": -(x["vt"] + share1 * x["v3"]),
            "x2": x["xt"] - share2 * x["x3"], "v2": x["vt"] - share2 * x["v3"],
            "x3": x["x3"], "v3": x["v3"], "xt": x["xt"], "vt": x["vt"], "F_f": Ff,
        }

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        total = p["m1"] + p["m2"]
        reduced = p["m1"] * p["m2"] / total
        relative = u["F3"] - (p["m2"] * u["F1"] + p["m1"] * u["F2"]) / total
        relative = relative + end_stop_force(x["x3"], x["v3"], -p["x_p_max"], -p["x_p_min"], p["k_stop"], p["c_stop"])
        return {
            "xt": x["vt"],
            "vt": rigid_body_acceleration(u["F2"] - u["F1"], x["xt"], total),
            "x3": x["v3"],
            "v3": rigid_body_acceleration(relative, x["x3"], reduced, friction=y["F_f"]),
        }

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """The stroke's ends reached."""
        return {"stop_min": (-x["x3"] - p["x_p_min"], 1e-3), "stop_max": (-x["x3"] - p["x_p_max"], 1e-3)}
