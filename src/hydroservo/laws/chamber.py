r"""Pressure in a compressible volume: the continuity law of every chamber, line and volume.

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.
Citation keys in brackets are those of :mod:`hydroservo.references`.
"""

from __future__ import annotations

from typing import Any

from hydroservo import backend as bk

__all__ = ["pressure_rate", "cylinder_volumes", "check_valve_floor"]


def pressure_rate(E: Any, V: Any, Q: Any) -> Any:
    r"""Rate of change of the pressure in a volume, :math:`\dot p = \frac{E}{V} Q`.

    Parameters
    ----------
    E : array_like
        (Effective) bulk modulus of the fluid in the volume [Pa].
    V : array_like
        Volume [m^3].
    Q : array_like
        Net flow into the volume, compression flows included (for a cylinder
        chamber :math:`Q - A\dot x`) [m^3/s].

    Returns
    -------
    array_like
        :math:`\dot p` [Pa/s].

    References
    ----------
    [Efe2014] eqs. (3.17), (3.32)-(3.41); [FlightSimulatorND] eqs. (3-17), (3-19); [Merritt1967].

    Examples
    --------
    >>> float(pressure_rate(1.4e9, 1e-3, 1e-4))  # 6 L/min into 1 L of oil
    140000000.0
    """
    return E / V * Q


def cylinder_volumes(V_A0: Any, V_B0: Any, A_A: Any, A_B: Any, x: Any, k_V: Any = 1.0) -> tuple[Any, Any]:
    r"""Chamber volumes of a double-acting cylinder, :math:`V_A = V_{A0} + k_V A_A x`, :math:`V_B = V_{B0} - k_V A_B x`.

    Parameters
    ----------
    V_A0, V_B0 : array_like
        Volumes at :math:`x = 0`, dead volumes and lines included [m^3].
    A_A, A_B : array_like
        Piston and annulus areas [m^2].
    x : array_like
        Piston position, positive extending (enlarging A) [m].
    k_V : array_like
        1: the volumes follow the piston; 0: frozen at :math:`V_{A0}, V_{B0}`
        (the final model of [FlightSimulatorND] section 3.2.2) [-].

    Returns
    -------
    (V_A, V_B) : tuple of array_like
        [m^3].

    References
    ----------
    [Efe2014] eqs. (3.33)-(3.36); [FlightSimulatorND] eqs. (3-31), (3-32).

    Examples
    --------
    >>> cylinder_volumes(1e-3, 1e-3, 2e-3, 1e-3, 0.1)
    (0.0012000000000000001, 0.0009)
    """
    return V_A0 + k_V * A_A * x, V_B0 - k_V * A_B * x


def check_valve_floor(p: Any, dp: Any, p_floor: Any) -> Any:
    r"""Pressure rate with replenishing check valves of instantaneous response: a chamber at or below ``p_floor`` cannot lose pressure.

    Parameters
    ----------
    p : array_like
        Chamber pressure [Pa].
    dp : array_like
        Pressure rate without the check valve [Pa/s].
    p_floor : array_like
        Pressure at which the check valve opens (the replenishing supply) [Pa].

    Returns
    -------
    array_like
        Pressure rate [Pa/s].

    References
    ----------
    [FlightSimulatorND] eqs. (3-29), (3-30).

    Examples
    --------
    >>> float(check_valve_floor(0.0, -5.0, 0.0)), float(check_valve_floor(1e5, -5.0, 0.0))
    (0.0, -5.0)
    """
    return bk.if_else(p <= p_floor, bk.fmax(dp, 0.0), dp)


def cavity_pressure(p_state: Any, p_floor: Any) -> Any:
    r"""The pressure a cavitating chamber's ports see: :math:`p = \max(p_{state}, p_{floor})`.

    The pressure state integrates the continuity equation without a floor; below ``p_floor`` (where the oil
    releases gas or vapour, near vacuum) it stands for a cavity (:func:`cavity_volume`) that the inflow must
    refill before the pressure rises again. Hopsan's cylinders and volumes behave so, passing max(p, 0) to the
    components around them.

    Parameters
    ----------
    p_state : array_like
        Pressure state [Pa].
    p_floor : array_like
        Pressure at which the chamber cavitates [Pa].

    Returns
    -------
    array_like
        The pressure the ports see [Pa].

    References
    ----------
    [Hopsan2026] (HydraulicCylinderC, HydraulicVolume: pressures below zero passed on as zero).

    Examples
    --------
    >>> float(cavity_pressure(-1e6, 0.0)), float(cavity_pressure(2e6, 0.0))
    (0.0, 2000000.0)
    """
    return bk.fmax(p_state, p_floor)


def cavity_volume(p_state: Any, p_floor: Any, V: Any, E: Any) -> Any:
    r"""The cavity a chamber's pressure state stands for below its floor: :math:`V\,\max(p_{floor} - p_{state}, 0)/E`.

    Parameters
    ----------
    p_state : array_like
        Pressure state [Pa].
    p_floor : array_like
        Pressure at which the chamber cavitates [Pa].
    V : array_like
        Chamber volume [m^3].
    E : array_like
        Effective bulk modulus [Pa].

    Returns
    -------
    array_like
        Cavity volume [m^3].

    References
    ----------
    [Hopsan2026] (HydraulicCylinderC, HydraulicVolume).

    Examples
    --------
    >>> float(cavity_volume(-1e6, 0.0, 1e-3, 1e9))  # 1 L, 10 bar below the floor: 1 cm^3
    1e-06
    """
    return V * bk.fmax(p_floor - p_state, 0.0) / E
