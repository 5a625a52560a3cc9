"""A rigid body on one axis: Newton's second law, for a translating mass and a rotating inertia alike."""

from __future__ import annotations

from typing import Any

__all__ = ["rigid_body_acceleration"]


def rigid_body_acceleration(
    load: Any, x: Any, inertia: Any, k_spring: Any = 0.0, x_spring: Any = 0.0, friction: Any = 0.0
) -> Any:
    r"""Acceleration of a rigid body on one axis under a load, a spring to ground and friction.

    .. math:: I\,\ddot x = F - F_f - k\,(x - x_s)

    Translation (``x`` [m], ``inertia`` a mass [kg], forces [N]) or rotation (``x`` an angle [rad],
    ``inertia`` a moment of inertia [kg*m^2], torques [N*m]): the same law. Hopsan's
    MechanicTranslationalMass and MechanicRotationalInertia ([Hopsan2026]
    Mechanic/Translational/MechanicTranslationalMass.hpp, Mechanic/Rotational/MechanicRotationalInertia.hpp)
    are this law discretised (their transfer function :math:`1/(I s^2 + B s + k)` from the net load to the
    position, the viscous friction :math:`F_f = B\dot x`).

    Parameters
    ----------
    load : array_like
        Sum of the forces [N] (torques [N*m]) acting on the body along +x.
    x : array_like
        Position [m] (angle [rad]).
    inertia : array_like
        Mass [kg] (moment of inertia [kg*m^2]), positive.
    k_spring : array_like
        Stiffness of a spring to ground [N/m] ([N*m/rad]).
    x_spring : array_like
        Where that spring is relaxed [m] ([rad]).
    friction : array_like
        Friction force [N] (torque [N*m]) opposing the motion, counted along +x.

    Returns
    -------
    array_like
        Acceleration [m/s^2] ([rad/s^2]).

    References
    ----------
    [Hopsan2026] Mechanic/Translational/MechanicTranslationalMass.hpp and
    Mechanic/Rotational/MechanicRotationalInertia.hpp (this law, discretised; Newton's second law itself needs
    no citation).

    Examples
    --------
    >>> rigid_body_acceleration(10.0, 0.0, 2.0)
    5.0
    >>> rigid_body_acceleration(10.0, 0.1, 2.0, k_spring=100.0, friction=2.0)
    -1.0
    """
    return (load - friction - k_spring * (x - x_spring)) / inertia
