r"""Gas-loaded accumulators: the polytropic gas spring behind the oil.

The gas, pre-charged to :math:`p_0` in the whole volume :math:`V_0`, is
compressed polytropically once the oil pressure exceeds the pre-charge:

.. math:: p\,V_g^{\kappa} = p_0 V_0^{\kappa} \quad\text{(absolute pressures)}, \qquad
          V_g = V_0 \left(\frac{p_0}{p}\right)^{1/\kappa}

with :math:`\kappa` = 1 for slow (isothermal) and 1.4 for fast (adiabatic)
cycles of nitrogen. The oil volume is :math:`V_0 - V_g`; its pressure rises
with the oil flow :math:`Q` in at the rate :math:`\dot p = Q/C` with the
capacitance :math:`C = dV_{oil}/dp` (:func:`gas_capacitance`). Below the
pre-charge the accumulator is empty and only the oil at its port is
compressed. [Hopsan2026] (HydraulicAckumulator) uses the same gas law.

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units;
pressures gauge, turned absolute inside.
"""

from __future__ import annotations

from typing import Any

from hydroservo import backend as bk
from hydroservo.units import VACUUM

__all__ = ["gas_volume", "gas_capacitance", "gas_pressure"]


def gas_volume(p: Any, p0: Any, V0: Any, kappa: Any) -> Any:
    r"""Gas volume of an accumulator at oil pressure ``p``, :math:`V_0 (p_0/p)^{1/\kappa}` (absolute), :math:`V_0` below pre-charge [m^3].

    Parameters
    ----------
    p : array_like
        Oil pressure, gauge [Pa].
    p0 : array_like
        Gas pre-charge pressure, gauge [Pa].
    V0 : array_like
        Gas volume at pre-charge (the accumulator's size) [m^3].
    kappa : array_like
        Polytropic exponent [-].

    Returns
    -------
    array_like
        Gas volume [m^3].

    References
    ----------
    Polytropic process of an ideal gas; [Hopsan2026] HydraulicAckumulator.

    Examples
    --------
    A 1 L accumulator pre-charged to 90 bar, at 180 bar, isothermal: about half full
    (absolute pressures):

    >>> round(float(gas_volume(180e5, 90e5, 1e-3, 1.0)) * 1e3, 4)  # L
    0.5028
    """
    p_abs = bk.fmax(p, p0) - VACUUM
    return V0 * ((p0 - VACUUM) / p_abs) ** (1.0 / kappa)


def gas_capacitance(p: Any, p0: Any, V0: Any, kappa: Any) -> Any:
    r"""Capacitance of the gas spring above pre-charge, :math:`dV_{oil}/dp = V_g/(\kappa\,p)` (absolute) [m^3/Pa].

    Parameters
    ----------
    p : array_like
        Oil pressure, gauge [Pa], at or above the pre-charge.
    p0 : array_like
        Gas pre-charge pressure, gauge [Pa].
    V0 : array_like
        Gas volume at pre-charge [m^3].
    kappa : array_like
        Polytropic exponent [-].

    Returns
    -------
    array_like
        Capacitance [m^3/Pa].

    References
    ----------
    [Hopsan2026] HydraulicAckumulator; the derivative of :func:`gas_volume`.

    Examples
    --------
    >>> round(float(gas_capacitance(90e5, 90e5, 1e-3, 1.4)) * 1e11, 2)  # cm^3/bar at pre-charge
    7.85
    """
    return gas_volume(p, p0, V0, kappa) / (kappa * (bk.fmax(p, p0) - VACUUM))


def gas_pressure(V_g: Any, p0: Any, V0: Any, kappa: Any) -> Any:
    r"""Gas pressure of an accumulator whose gas occupies ``V_g``, :math:`p_0 (V_0/V_g)^{\kappa}` (absolute) [Pa, gauge].

    The inverse of :func:`gas_volume` above the pre-charge.

    Parameters
    ----------
    V_g : array_like
        Gas volume [m^3], > 0 (at most ``V0``: the gas at pre-charge fills the accumulator).
    p0 : array_like
        Gas pre-charge pressure, gauge [Pa].
    V0 : array_like
        Gas volume at pre-charge [m^3].
    kappa : array_like
        Polytropic exponent [-].

    Returns
    -------
    array_like
        Gas pressure, gauge [Pa].

    References
    ----------
    Polytropic process of an ideal gas; [Hopsan2026] Hydraulic/Volumes&Lines/HydraulicAckumulator.hpp.

    Examples
    --------
    >>> v = float(gas_volume(180e5, 90e5, 1e-3, 1.2))
    >>> round(float(gas_pressure(v, 90e5, 1e-3, 1.2)) / 1e5, 6)
    180.0
    """
    return (p0 - VACUUM) * (V0 / V_g) ** kappa + VACUUM
