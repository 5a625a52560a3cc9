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

__all__ = ["opening_fraction", "linear_opening"]


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
    :func:`linear_opening`; the rounding is hydroservo's (module notes).

    Examples
    --------
    >>> [round(float(opening_fraction(p, 100e5, 10e5)), 3) for p in (99e5, 102.5e5, 105e5, 111e5)]
    [0.0, 0.156, 0.5, 1.0]
    """
    s = linear_opening(p, p_c, dp_o)
    return s * s * (3.0 - 2.0 * s)
