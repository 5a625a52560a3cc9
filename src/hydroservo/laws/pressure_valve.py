r"""Pressure-controlled valves: how far a poppet or spool opens against its spring.

A check, relief, counterbalance or pressure-reducing valve holds a spring
against a pilot pressure. It starts to open when the pilot pressure reaches the
cracking (set) pressure :math:`p_c` and is fully open when it exceeds it by
the pressure-override :math:`\Delta p_o` of the catalogue's pressure-flow
curve; in between the opening grows linearly ([Merritt1967], the
spring-loaded poppet at quasi-static equilibrium, flow forces lumped into
:math:`\Delta p_o`). hydroservo rounds the two corners of the linear ramp
with a cubic (:func:`opening_fraction`) so that the flow has a continuous
slope, which implicit solvers need; the ramp's end points are unchanged.

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.
"""

from __future__ import annotations

from typing import Any

from hydroservo import backend as bk

__all__ = ["opening_fraction", "linear_opening", "pressure_valve_coefficient"]


def linear_opening(p: Any, p_c: Any, dp_o: Any) -> Any:
    r"""Opening fraction of a spring-loaded valve, the linear ramp :math:`\min(\max((p - p_c)/\Delta p_o, 0), 1)` [-].

    Parameters
    ----------
    p : array_like
        Pilot pressure (pressure difference across a check valve) [Pa].
    p_c : array_like
        Cracking pressure [Pa].
    dp_o : array_like
        Pressure rise over cracking to full opening [Pa], > 0.

    Returns
    -------
    array_like
        Opening fraction, 0 closed to 1 fully open.

    References
    ----------
    [Merritt1967] (spring-loaded poppet and spool valves at quasi-static equilibrium).

    Examples
    --------
    >>> float(linear_opening(105e5, 100e5, 10e5))
    0.5
    """
    return bk.fmin(bk.fmax((p - p_c) / dp_o, 0.0), 1.0)


def opening_fraction(p: Any, p_c: Any, dp_o: Any) -> Any:
    r"""Opening fraction with rounded corners: the cubic :math:`3s^2 - 2s^3` of the linear ramp :math:`s` [-].

    Equal to :func:`linear_opening` at 0, 1/2 and 1; its slope is continuous
    (zero at both ends, 1.5 times the ramp's in the middle).

    Parameters
    ----------
    p : array_like
        Pilot pressure [Pa].
    p_c : array_like
        Cracking pressure [Pa].
    dp_o : array_like
        Pressure rise over cracking to full opening [Pa], > 0.

    Returns
    -------
    array_like
        Opening fraction, 0 closed to 1 fully open.

    References
    ----------
    [Merritt1967], as :func:`linear_opening`; the rounding is hydroservo's (module notes).

    Examples
    --------
    >>> [round(float(opening_fraction(p, 100e5, 10e5)), 3) for p in (99e5, 102.5e5, 105e5, 111e5)]
    [0.0, 0.156, 0.5, 1.0]
    """
    s = linear_opening(p, p_c, dp_o)
    return s * s * (3.0 - 2.0 * s)


def pressure_valve_coefficient(over: Any, dp: Any, k_cs: Any, k_cf: Any, p_nom: Any = 7e6) -> Any:
    r"""Static flow coefficient of a pressure-control valve, :math:`K = \Delta p_{over}/(C_s + C_f \max(\Delta p, 0))` [m^3/s/Pa^0.5].

    The spool opens with the pressure by which the pilot exceeds the setting
    (``over``: :math:`p_{in} - p_{crack}` for a relief valve, :math:`p_{set} - p_{out}`
    for a pressure-reducing one) against the spring, :math:`C_s = \sqrt{p_{nom}}/k_{cs}`,
    and the flow forces, which grow with the drop across it,
    :math:`C_f = 1/(k_{cf}\sqrt{p_{nom}})`. The flow is then turbulent,
    :math:`Q = K\sqrt{\Delta p}`. Near cracking the pressure-flow gradient is
    :math:`dQ/dp = k_{cs}\sqrt{\Delta p/p_{nom}}`: ``k_cs`` is the gradient of the
    catalogue's p-Q curve at the nominal drop ``p_nom``. The caller bounds
    :math:`K` to :math:`[0, q_{nom}/\sqrt{p_{nom}}]` (closed, fully open).

    Parameters
    ----------
    over : array_like
        Pilot pressure above the setting [Pa] (negative: closed).
    dp : array_like
        Pressure drop across the valve [Pa].
    k_cs : array_like
        Steady-state characteristic of the spring [m^3/s/Pa].
    k_cf : array_like
        Steady-state characteristic of the flow forces [m^3/s/Pa].
    p_nom : array_like
        Nominal pressure drop of the characteristics [Pa] (Hopsan's 7 MPa).

    Returns
    -------
    array_like
        Flow coefficient [m^3/s/Pa^0.5] (unbounded).

    References
    ----------
    [Hopsan2026] HydraulicPressureReliefValve and HydraulicPressureReducingValve (their
    steady-state opening ``xs`` in the limit of a small time step).

    Examples
    --------
    A 200 bar relief valve 10 bar over its setting, 200 bar across it:

    >>> k = pressure_valve_coefficient(10e5, 210e5, 1e-8, 1e-8)
    >>> round(float(k) * (210e5) ** 0.5 * 6e4, 1)  # L/min
    259.8
    """
    Cs = bk.sqrt(p_nom) / k_cs
    Cf = 1.0 / (k_cf * bk.sqrt(p_nom))
    return over / (Cs + Cf * bk.fmax(dp, 0.0))
