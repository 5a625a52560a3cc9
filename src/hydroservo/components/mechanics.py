"""One-dimensional mechanics joined port to port: springs, dampers, fixed points, force and velocity sources.

Each has mechanical ports (:class:`~hydroservo.components.base.Mechanical`) counted outward: a port's position,
velocity and force point out of the component. A :class:`~hydroservo.components.mass.Mass` or a fixed point
gives a node its motion; springs, dampers, cylinders' rods and force sources push on it
(:mod:`hydroservo.system.nodes`). Hopsan ([Hopsan2026]) joins its mechanical components the same way, one C
component (spring, force source) to one Q component (mass, fixed point) at each node.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo import backend as bk
from hydroservo.components.base import (
    Algebraic,
    Component,
    Mechanical,
    Option,
    Output,
    Param,
    Port,
    State,
    register,
)
from hydroservo.laws.stops import contact_residual

__all__ = ["Spring", "Damper", "FixedPosition", "Wall", "ForceSource", "VelocitySource"]


def _ends(what: str) -> dict[str, Mechanical]:
    return {
        "P1": Mechanical("x1", "v1", "F1", f"end 1 of the {what} (outward)"),
        "P2": Mechanical("x2", "v2", "F2", f"end 2 of the {what} (outward)"),
    }


_END_INPUTS = {
    "x1": Port("m", "outward displacement of end 1", default=0.0),
    "v1": Port("m/s", "outward velocity of end 1", default=0.0),
    "x2": Port("m", "outward displacement of end 2", default=0.0),
    "v2": Port("m/s", "outward velocity of end 2", default=0.0),
}

_END_OUTPUTS = {
    "F1": Output("N", "force on what end 1 is joined to, outward"),
    "F2": Output("N", "force on what end 2 is joined to, outward"),
    "F": Output("N", "tension"),
}


@register
class Spring(Component):
    r"""Linear spring between two ends: :math:`F_1 = F_2 = -k_{spring}\,(x_1 + x_2 - e_0)`.

    ``x1``, ``x2`` are the outward displacements of its ends, so :math:`x_1 + x_2` is its extension;
    ``F1``, ``F2`` the forces it exerts outward on what its ends are joined to (a stretched spring pulls them
    in). ``e0`` is the extension at which it is relaxed. Hopsan's MechanicTranslationalSpring ([Hopsan2026]) is
    the same law as a transmission-line element, relaxed at its start positions. Output ``F`` is the spring's
    tension (compression negative, Hopsan's node force with the opposite sign).

    Option ``slack``: ``"none"`` (the default), the law above; ``"slack"``, a rope or a chain that pulls but
    cannot push, :math:`F_1 = F_2 = -k_{spring}\max(x_1 + x_2 - e_0, 0)`: no force while it is shorter than
    where it is relaxed (Hopsan's MechanicTranslationalSpringWithSlack, [Hopsan2026]
    Mechanic/Linear/MechanicTranslationalSpringWithSlack.hpp).
    """

    PARAMETERS = {
        "k_spring": Param(100.0, "N/m", "spring stiffness", min=0.0),
        "e0": Param(0.0, "m", "extension (x1 + x2) at which the spring is relaxed"),
    }
    INPUTS = _END_INPUTS
    MECHANICAL = _ends("spring")
    OUTPUTS = _END_OUTPUTS
    OPTIONS = {"slack": Option("none", ("none", "slack"), "whether it only pulls (a rope: no force while slack)")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        stretch = u["x1"] + u["x2"] - p["e0"]
        if self.option("slack") == "slack":
            stretch = bk.fmax(stretch, 0.0)
        tension = p["k_spring"] * stretch
        return {"F1": -tension, "F2": -tension, "F": tension}


@register
class Damper(Component):
    r"""Linear damper between two ends: :math:`F_1 = F_2 = -B\,(v_1 + v_2)`, with ``v1``, ``v2`` the outward
    velocities of its ends (Hopsan's MechanicTranslationalDamper, [Hopsan2026])."""

    PARAMETERS = {"B": Param(100.0, "N*s/m", "damping coefficient", min=0.0)}
    INPUTS = _END_INPUTS
    MECHANICAL = _ends("damper")
    OUTPUTS = _END_OUTPUTS

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        tension = p["B"] * (u["v1"] + u["v2"])
        return {"F1": -tension, "F2": -tension, "F": tension}


@register
class FixedPosition(Component):
    """A fixed point: its port ``P`` stands still at ``x0`` whatever force acts on it (Hopsan's
    MechanicFixedPosition, [Hopsan2026]). The force it takes is the force of what is joined to it."""

    PARAMETERS = {"x0": Param(0.0, "m", "where the point is, along its outward direction")}
    INPUTS = {"F": Port("N", "force acting on the point, outward", default=0.0)}
    MECHANICAL = {"P": Mechanical("x", "v", "F", "the fixed point (outward)")}
    OUTPUTS = {
        "x": Output("m", "position (always x0)"),
        "v": Output("m/s", "velocity (always 0)"),
    }

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"x": p["x0"] + 0.0 * t, "v": 0.0 * t}


#: Scale of the wall's contact force in its residual [m/N] (any value > 0 has the same solution).
_CONTACT_COMPLIANCE = 1e-6


class _MasslessEnd(Component):
    """An end whose position is an algebraic unknown (solved with the forces of its nodes: its residual is the
    subclass's) and whose velocity is that position's rate: the rate of the state ``x_f`` that follows it with
    the time constant ``tau``, :math:`v = (x - x_f)/\tau`. Its outputs read no input, so no loop runs through
    them; its guess for the position is where ``x_f`` is."""

    TAU = Param(1e-6, "s", "time constant of the end's velocity (the rate of its position)", min=0.0,
                min_inclusive=False)

    @staticmethod
    def _velocity(x: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        return (x["x"] - x["x_f"]) / p["tau"]

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"x_f": y["v"]}

    def guess_equations(self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> dict[str, Any]:
        return {"x": x["x_f"]}


@register
class Wall(_MasslessEnd):
    r"""A wall and the free end that meets it: the end of whatever is joined to port ``P`` is free (it takes no
    force) while it is away from the wall, and is held at the wall while pressed against it; it leaves the wall
    as soon as it is pulled away (a unilateral contact).

    The contact's conditions (:func:`~hydroservo.laws.stops.contact_residual`):

    .. math:: x \ge x_{stop},\quad F_w = B\,v - F \ge 0,\quad (x - x_{stop})\,F_w = 0

    with ``x``, ``v`` the end's outward position and velocity (outward: away from the wall), ``F`` the force of
    what is joined to it (outward) and ``F_w`` the wall's push. Away from the wall the end is massless and
    only its damping ``B`` against the surroundings holds it: :math:`B v = F` (with ``B`` = 0, the force on it
    is zero: a spring joined there is relaxed and moves with its other end). Hopsan's MechanicFreeLengthWall
    ([Hopsan2026] Mechanic/Linear/MechanicFreeLengthWall.hpp) is this law: its end, a first-order filter of the
    node's wave variable through B + Z_c, is clamped at the stop with zero velocity while the wave variable
    presses it there, and released when it would move out.

    The end's position is an algebraic unknown (solved with the forces of the node each time the model is
    evaluated: :mod:`hydroservo.system.implicit`); its velocity, which a free massless end has only as the
    rate of that position, is the rate of the state ``x_f`` that follows the position with the time constant
    ``tau`` (a microsecond): :math:`v = (x - x_f)/\tau`. A force port that reads the velocity (a damper)
    therefore sees the end's motion exactly, the position being ``tau`` v ahead of ``x_f``.
    """

    PARAMETERS = {
        "B": Param(0.0, "N*s/m", "damping of the free end against its surroundings, away from the wall", min=0.0),
        "x_stop": Param(0.0, "m", "position of the wall, along the port's outward direction"),
        "x0": Param(0.0, "m", "initial position of the end (at least x_stop)"),
        "tau": _MasslessEnd.TAU,
    }
    STATES = {"x_f": State("m", "the end's position, followed with the time constant tau", initial="x0", nominal=0.1)}
    ALGEBRAIC = {"x": Algebraic("m", "position of the end, outward (away from the wall)", nominal=0.1)}
    INPUTS = {"F": Port("N", "force on the end, outward (pulling it away from the wall)", default=0.0)}
    MECHANICAL = {"P": Mechanical("x", "v", "F", "the free end (outward: away from the wall)")}
    OUTPUTS = {
        "x": Output("m", "position of the end, outward"),
        "v": Output("m/s", "velocity of the end, outward"),
    }

    @staticmethod
    def _push(x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        """The wall's push on the end, B v - F (the force it takes to hold the end where it is)."""
        return p["B"] * Wall._velocity(x, p) - u["F"]

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"x": x["x"], "v": self._velocity(x, p)}

    def residual_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"x": contact_residual(x["x"] - p["x_stop"], self._push(x, u, p), _CONTACT_COMPLIANCE)}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """The end meeting or leaving the wall (where the residual's two branches cross)."""
        return {"contact": (x["x"] - p["x_stop"] - _CONTACT_COMPLIANCE * self._push(x, u, p), 1e-3)}


@register
class RigidLink(_MasslessEnd):
    r"""A massless rigid link: its ends carry one force (Hopsan's MechanicTranslationalLosslessConnector,
    [Hopsan2026] Mechanic/Linear/MechanicTranslationalLosslessConnector.hpp).

    End 2 is at ``x``, end 1 at ``length - x`` (each outward), and the forces pulling its ends outward are equal at
    every instant, :math:`F_2 = F_1` (no mass, no friction: what one side presses on it the other takes). Hopsan's
    connector is this law: a Q component whose velocity v_2 = (c_1 - c_2)/(Z_1 + Z_2) makes its two forces
    c_i + Z_i v_i equal at each step, its ends x_1 = L - x_2.

    As the Wall's free end, the link's position is an algebraic unknown (solved with the forces of its nodes each
    time the model is evaluated: :mod:`hydroservo.system.implicit`), and its velocity the rate of the state
    ``x_f`` that follows it with the time constant ``tau`` (a microsecond): :math:`v = (x - x_f)/\tau`. Each end
    needs something that presses on it with a force depending on where the link is (a spring, a cylinder); two
    force sources alone leave its position undetermined, and the model unsolvable.
    """

    PARAMETERS = {
        "length": Param(0.0, "m", "end 1's position plus end 2's (each outward)"),
        "x0": Param(0.0, "m", "initial position of end 2"),
        "tau": _MasslessEnd.TAU,
    }
    STATES = {"x_f": State("m", "the link's position, followed with the time constant tau", initial="x0", nominal=0.1)}
    ALGEBRAIC = {"x": Algebraic("m", "position of end 2, outward", nominal=0.1)}
    INPUTS = {
        "F": Port("N", "force on end 2, outward (+x)", default=0.0),
        "F_P1": Port("N", "force on end 1, outward (-x)", default=0.0),
    }
    MECHANICAL = {
        "P1": Mechanical("x_P1", "v_P1", "F_P1", "end 1 (outward is -x)"),
        "P2": Mechanical("x", "v", "F", "end 2 (outward is +x)"),
    }
    OUTPUTS = {
        "x": Output("m", "position of end 2, outward"),
        "v": Output("m/s", "velocity of end 2, outward"),
        "x_P1": Output("m", "position of end 1, outward (length - x)"),
        "v_P1": Output("m/s", "velocity of end 1, outward (-v)"),
    }

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        v = self._velocity(x, p)
        return {"x": x["x"], "v": v, "x_P1": p["length"] - x["x"], "v_P1": -v}

    def residual_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"x": u["F"] - u["F_P1"]}


@register
class ForceSource(Component):
    """A force from a signal: its port ``P`` pushes outward on what it is joined to with the input ``u``
    (Hopsan's MechanicForceTransformer, [Hopsan2026], whose signal is the force it presses on its node).

    With the input ``B`` the source stands behind a damper to ground: F = u - B v, ``v`` the port's outward
    velocity (Hopsan's MechanicTranslationalCSource, [Hopsan2026] Mechanic/Linear/MechanicTranslationalCSource.hpp,
    a wave variable ``in_c`` and an impedance ``in_z``: its node's force c + Z_x v_Q, v_Q the velocity of the
    component joined to it, towards the source)."""

    INPUTS = {
        "u": Port("N", "force pushing outward on what port P is joined to", default=0.0),
        "B": Port("N*s/m", "damping behind the source, to ground (F = u - B v)", default=0.0),
        "x": Port("m", "outward displacement of port P", default=0.0),
        "v": Port("m/s", "outward velocity of port P", default=0.0),
    }
    MECHANICAL = {"P": Mechanical("x", "v", "F", "where the force acts (outward)")}
    OUTPUTS = {"F": Output("N", "force on what port P is joined to, outward")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"F": u["u"] - u["B"] * u["v"]}


@register
class VelocitySource(Component):
    """A velocity from a signal: its port ``P`` moves outward at the input ``u``, from ``x0``, whatever force it
    takes (Hopsan's MechanicVelocityTransformer, [Hopsan2026] Mechanic/Linear/MechanicVelocityTransformer.hpp).

    Option ``position``: ``"integral"`` (the default) integrates the velocity from ``x0``, as Hopsan's does with
    its position input unconnected; ``"input"`` takes the position from the input ``x_in`` instead, as Hopsan's
    does with it connected (position and velocity are then whatever the two signals are: Hopsan leaves their
    kinematic relationship to the model's author)."""

    PARAMETERS = {"x0": Param(0.0, "m", "initial position (option position = 'integral')")}
    STATES = {"x": State("m", "position", initial="x0", nominal=0.1)}
    INPUTS = {
        "u": Port("m/s", "velocity imposed outward", default=0.0),
        "F": Port("N", "force acting on port P, outward", default=0.0),
        "x_in": Port("m", "position imposed outward (option position = 'input')", default=0.0),
    }
    MECHANICAL = {"P": Mechanical("x", "v", "F", "the moving point (outward)")}
    OUTPUTS = {
        "x": Output("m", "position"),
        "v": Output("m/s", "velocity"),
    }
    OPTIONS = {"position": Option("integral", ("integral", "input"), "the position: the velocity's integral, or the input x_in")}

    def options_changed(self) -> None:
        """With the position an input, no state."""
        self.STATES = {} if self.option("position") == "input" else dict(type(self).STATES)  # type: ignore[misc]

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        position = u["x_in"] if self.option("position") == "input" else x["x"]
        return {"x": position, "v": u["u"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"x": u["u"]} if self.option("position") == "integral" else {}
