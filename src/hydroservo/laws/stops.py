"""End stops: the force that keeps a moving part within its travel."""

from __future__ import annotations

from typing import Any

from hydroservo import backend as bk

__all__ = ["end_stop_force", "contact_residual"]


def end_stop_force(x: Any, v: Any, x_min: Any, x_max: Any, k: Any, c: Any) -> Any:
    r"""Force of end stops modelled as a spring-damper acting beyond the travel.

    .. math:: F = -k\,(\max(x - x_{max}, 0) + \min(x - x_{min}, 0)) - c\,\dot x\,[x < x_{min} \lor x > x_{max}]

    A penalty method: stiff enough (1e9 N/m, 1e6 N s/m: 0.1 mm under 100 kN), it is a hard stop for any
    practical load and keeps the equations continuous, which an implicit solver needs. Hopsan clamps the
    position instead and zeroes the velocity (an inelastic stop), which a fixed-step scheme allows; the two
    agree as the stiffness grows.

    Parameters
    ----------
    x : array_like
        Position [m].
    v : array_like
        Velocity [m/s].
    x_min, x_max : array_like
        The ends of the travel [m].
    k : array_like
        Stiffness of the stops [N/m].
    c : array_like
        Damping of the stops, acting only beyond them [N*s/m].

    Returns
    -------
    array_like
        Force on the moving part in +x [N]: zero within the travel.

    References
    ----------
    [Hopsan2026] (MechanicTranslationalMass, HydraulicCylinderC: the stops it stands for).

    Examples
    --------
    >>> abs(float(end_stop_force(0.5, 1.0, 0.0, 1.0, 1e9, 1e6)))  # within the travel
    0.0
    >>> round(float(end_stop_force(1.0 + 1e-4, 0.0, 0.0, 1.0, 1e9, 1e6)))  # 0.1 mm beyond the high end [N]
    -100000
    """
    over = bk.fmax(x - x_max, 0.0)
    under = bk.fmin(x - x_min, 0.0)
    beyond = bk.if_else(over - under > 0, 1.0, 0.0)
    return -k * (over + under) - c * v * beyond


def contact_residual(gap: Any, force: Any, compliance: Any) -> Any:
    r"""Residual of a unilateral contact (Signorini's conditions): zero where the contact holds.

    .. math:: r = \min(g,\; c\,F_w), \qquad g \ge 0,\; F_w \ge 0,\; g\,F_w = 0

    A point that may leave a wall but not go through it: either it is away from the wall (gap :math:`g > 0`)
    and the wall pushes on it with no force, or it touches the wall (:math:`g = 0`) and the wall pushes it out
    with :math:`F_w \ge 0`. The minimum of the two (the force made a length by ``compliance``, a scale only:
    any :math:`c > 0` has the same zeros) vanishes exactly where both conditions hold. As an equation for the
    point's position it is piecewise linear where the force is, so Newton's method solves it exactly in a
    few steps. Hopsan's MechanicFreeLengthWall clamps its end at the stop while the force on it presses it
    there and lets it go when the force pulls it away: the same conditions, met once per time step.

    Parameters
    ----------
    gap : array_like
        Distance from the wall [m], positive away from it.
    force : array_like
        Force the wall must exert on the point to hold it where it is, positive pushing it away [N].
    compliance : array_like
        Scale of the force, a length per force [m/N] (> 0; it does not change the solution).

    Returns
    -------
    array_like
        The residual [m]: zero where the point is free with no force, or at the wall pressed against it.

    References
    ----------
    [Hopsan2026] Mechanic/Linear/MechanicFreeLengthWall.hpp (the law it stands for).

    Examples
    --------
    >>> float(contact_residual(0.2, 0.0, 1e-6))  # away from the wall, no force: holds
    0.0
    >>> float(contact_residual(0.0, 50.0, 1e-6))  # at the wall, pressed against it: holds
    0.0
    >>> round(float(contact_residual(0.0, -50.0, 1e-6)), 9)  # at the wall but pulled away: violated [m]
    -5e-05
    """
    return bk.fmin(gap, compliance * force)
