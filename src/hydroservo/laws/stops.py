"""End stops: the force that keeps a moving part within its travel."""

from __future__ import annotations

from typing import Any

from hydroservo import backend as bk

__all__ = ["end_stop_force"]


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
