"""Friction laws for piston and load motion."""

from __future__ import annotations

from typing import Any

from hydroservo import backend as bk

__all__ = ["stribeck", "aerodynamic_drag"]


def stribeck(
    v: Any,
    sigma: Any,
    F_c0: Any,
    F_s0: Any,
    c_s: Any,
    v_reg: Any = 0.0,
) -> Any:
    r"""Stribeck friction force.

    .. math:: F_f(\dot x) = \sigma \dot x + \operatorname{sign}(\dot x)
              \left[F_{c0} + F_{s0} \exp\left(-\frac{|\dot x|}{c_s}\right)\right]

    Parameters
    ----------
    v : array_like
        Sliding velocity [m/s].
    sigma : float
        Viscous friction coefficient [N s/m] (``F_v`` in [Efe2014] Table 5.2).
    F_c0 : float
        Coulomb friction force [N].
    F_s0 : float
        Static friction in excess of Coulomb friction [N].
    c_s : float
        Stribeck velocity [m/s].
    v_reg : float, optional
        Velocity [m/s] over which ``sign`` is smoothed as ``tanh(v/v_reg)``;
        0 (the default) gives the discontinuous law as published. Simulations
        need a positive value: the components default to 1 % of ``c_s``, so
        that the smoothing is confined well inside the Stribeck region.

    Returns
    -------
    Friction force opposing the motion [N].

    References
    ----------
    [Efe2014] eq. (3.47); parameters of Table 5.2.

    Examples
    --------
    [Efe2014] Table 5.2, simulated column (c_s = 0.01, F_v = 280, F_c0 = 78, F_s0 = 5):

    >>> round(float(stribeck(0.165, 280.0, 78.0, 5.0, 0.01)), 2)
    124.2
    >>> round(float(stribeck(0.01, 280.0, 78.0, 5.0, 0.01)), 2)
    82.64
    """
    if bk.is_symbolic(v, v_reg) or not _is_zero(v_reg):
        sgn = bk.tanh(v / v_reg)
    else:
        sgn = bk.sign(v)
    return sigma * v + sgn * (F_c0 + F_s0 * bk.exp(-bk.fabs(v) / c_s))


def aerodynamic_drag(v: Any, rho: Any, CdA: Any) -> Any:
    r"""Aerodynamic drag of a body moving through still air.

    .. math:: F_d = \tfrac{1}{2}\,\rho\,C_d A\,v\,|v|

    Parameters
    ----------
    v : array_like
        Speed of the body through the air [m/s].
    rho : float
        Density of the air [kg/m^3].
    CdA : float
        Drag coefficient times the frontal area (effective frontal area) [m^2].

    Returns
    -------
    Drag force opposing the motion [N].

    References
    ----------
    [Hopsan2026] Special/MechanicVehicle1D.hpp (its aerodynamic drag fd).

    Examples
    --------
    >>> round(float(aerodynamic_drag(20.0, 1.25, 0.5)), 1)  # a car at 72 km/h [N]
    125.0
    """
    return 0.5 * rho * CdA * v * bk.fabs(v)


def _is_zero(x: Any) -> bool:
    try:
        return float(x) == 0.0
    except TypeError:
        return False
