r"""Spool dynamics: how a valve's spool follows its command, from a catalogue lag to rate limits and delay.

Normalised spool position :math:`s` (1 at full stroke) and velocity
:math:`v = \dot s`; the command :math:`u` is normalised the same way. Pure,
vectorised functions (NumPy arrays or CasADi expressions). Citation keys in
brackets are those of :mod:`hydroservo.references`.

The rate-limited model of [FerreiraND] Fig. 11, re-derived
----------------------------------------------------------
The figure is a second-order loop drawn with its velocity and acceleration as
signals, so that each can be limited:

.. math::
    v_d = \frac{\omega_n}{2\xi}(u - s), \quad
    v_l = \frac{2L_v}{\pi}\arctan\frac{\pi v_d}{2L_v}, \quad
    \dot v = \operatorname{sat}_{L_a}\bigl(2\xi\omega_n (v_l - v)\bigr), \quad
    \dot s = v

Without limits this is :math:`\ddot s = \omega_n^2(u - s) - 2\xi\omega_n\dot s`.
Both limiters have unit gain at the origin, as the paper requires: the
velocity limiter is the arctangent shape bounded by :math:`\pm L_v` (the
paper's best choice, "in action from small velocities"), the acceleration
limiter a hard saturation at :math:`\pm L_a`.

The pure delay
--------------
A pure delay :math:`\Delta t` (section 6.2 of [FerreiraND]) is not an ordinary
differential equation; a system replaces it by a Padé approximant
(:func:`pade1_delay`, :func:`pade2_delay`). The (2, 2) approximant has gain
exactly one and phase :math:`-2\arctan\frac{\omega\Delta t/2}{1 - (\omega\Delta t)^2/12}`,
within 0.06 deg of the delay's at 200 Hz and 0.4 deg at 300 Hz for the
published 0.76 ms. Frequency responses apply the delay exactly, as a phase
:math:`-\omega\Delta t`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.laws.orifice import signed_sqrt

__all__ = [
    "first_order_spool_rate",
    "second_order_spool_acceleration",
    "rate_limited_spool_acceleration",
    "damping_orifice_flow",
    "pade1_delay",
    "pade2_delay",
]


def first_order_spool_rate(u: Any, s: Any, tau: Any) -> Any:
    r"""Spool velocity of a first-order lag with the command saturated to the stroke.

    .. math:: \tau\,\dot s + s = \operatorname{sat}_{[-1, 1]}(u)

    ``tau`` is the catalogue :math:`T_{63}`: the step response of a first-order
    lag reaches 63 % after one time constant. [Efe2014] eq. (3.27) writes the
    forcing without the factor :math:`1/\tau`, which would give a DC gain of
    :math:`\tau` (eq. 3.29); a valve command is meant to have unit gain, so the
    unit-gain form is used.

    Parameters
    ----------
    u : array_like
        Normalised command [-].
    s : array_like
        Normalised spool position [-].
    tau : array_like
        Time constant [s].

    Returns
    -------
    array_like
        :math:`\dot s` [1/s].

    References
    ----------
    [Efe2014] eqs. (3.24)-(3.28), Fig. 3.5.

    Examples
    --------
    >>> float(first_order_spool_rate(2.0, 0.5, 0.01))  # command saturated at 1
    50.0
    """
    return (bk.clip(u, -1.0, 1.0) - s) / tau


def second_order_spool_acceleration(u: Any, s: Any, v: Any, omega_n: Any, zeta: Any) -> Any:
    r"""Spool acceleration of a second-order lag with the command saturated to the stroke.

    .. math:: \ddot s = \omega_n^2(\operatorname{sat}_{[-1, 1]}(u) - s) - 2\zeta\omega_n \dot s

    Parameters
    ----------
    u : array_like
        Normalised command [-].
    s : array_like
        Normalised spool position [-].
    v : array_like
        Normalised spool velocity [1/s].
    omega_n : array_like
        Natural angular frequency [rad/s].
    zeta : array_like
        Damping ratio [-].

    Returns
    -------
    array_like
        :math:`\ddot s` [1/s^2].

    References
    ----------
    [FerreiraND] section 6 (the core of Fig. 11 without its limits); [JelaliKroll2004].

    Examples
    --------
    >>> float(second_order_spool_acceleration(1.0, 0.0, 0.0, 100.0, 0.7))
    10000.0
    """
    return omega_n**2 * (bk.clip(u, -1.0, 1.0) - s) - 2.0 * zeta * omega_n * v


def rate_limited_spool_acceleration(u: Any, s: Any, v: Any, omega_n: Any, zeta: Any, L_v: Any, L_a: Any) -> Any:
    r"""Spool acceleration of the rate-limited second order of [FerreiraND] Fig. 11 (module notes).

    Parameters
    ----------
    u : array_like
        Normalised command [-].
    s : array_like
        Normalised spool position [-].
    v : array_like
        Normalised spool velocity [1/s].
    omega_n : array_like
        Natural angular frequency [rad/s].
    zeta : array_like
        Damping ratio (the paper's :math:`\xi`) [-].
    L_v : array_like
        Velocity limit [1/s].
    L_a : array_like
        Acceleration limit [1/s^2].

    Returns
    -------
    array_like
        :math:`\ddot s` [1/s^2].

    References
    ----------
    [FerreiraND] Fig. 11 and section 6.1.

    Examples
    --------
    Far from the command the velocity limit holds the spool at L_v:

    >>> float(rate_limited_spool_acceleration(1.0, 0.0, 125.0, 1007.0, 0.48, 125.0, 81184.0)) < 0
    True
    """
    v_d = omega_n / (2.0 * zeta) * (u - s)
    v_l = 2.0 * L_v / np.pi * bk.atan(np.pi * v_d / (2.0 * L_v))
    return bk.clip(2.0 * zeta * omega_n * (v_l - v), -L_a, L_a)


def damping_orifice_flow(F: Any, A_c: Any, p_C: Any, K_d: Any, p_tr: Any = 0.0) -> Any:
    r"""Flow out of the end chamber of a massless spool or poppet through its damping orifice [m^3/s].

    A spool without mass is in force balance at every instant: the pressure in its end chamber (area
    :math:`A_c`) is the one that balances the other forces on it, :math:`p_c = F/A_c` (``F`` the force of the
    pilot pressures less the spring's, pushing the spool into the chamber). The chamber's oil leaves through
    a damping orifice to the port C at :math:`p_C`, turbulent:

    .. math:: Q = K_d\,\frac{p_c - p_C}{((p_c - p_C)^2 + p_{tr}^2)^{1/4}}, \qquad \dot x = Q/A_c

    (:func:`hydroservo.laws.orifice.signed_sqrt`, regularised below :math:`p_{tr}`), so the spool moves at the
    speed at which its orifice lets the oil out or in: the damping of Hopsan's poppet and shuttle valves
    ([Hopsan2026] Hydraulic/Valves/Hydraulic22PoppetValve.hpp, Hydraulic/Valves/Hydraulic33ShuttleValve.hpp).

    Parameters
    ----------
    F : array_like
        Net force pushing the spool into its chamber [N].
    A_c : array_like
        Area of the end chamber [m^2], > 0.
    p_C : array_like
        Pressure beyond the damping orifice [Pa].
    K_d : array_like
        Flow coefficient of the damping orifice, C_q A_d sqrt(2/rho) [m^3/s/Pa^0.5].
    p_tr : array_like
        Transition pressure of the regularisation [Pa]; 0 for the turbulent law (NumPy input only).

    Returns
    -------
    array_like
        Flow out of the chamber [m^3/s]; the spool's velocity is this over A_c.

    References
    ----------
    [Hopsan2026] Hydraulic/Valves/Hydraulic22PoppetValve.hpp (its spring chamber and damping orifice d_d).

    Examples
    --------
    100 N on a 1 cm² chamber: 10 bar above a drain at 0 pushes the oil out through K_d = 1e-9:

    >>> round(float(damping_orifice_flow(100.0, 1e-4, 0.0, 1e-9)) * 1e6, 4)  # cm^3/s
    1.0
    """
    return K_d * signed_sqrt(F / A_c - p_C, p_tr)


def pade1_delay(s: Any, w1: Any, delay: Any) -> tuple[Any, Any]:
    r"""The (1, 1) Padé approximant of a pure delay, :math:`(1 - as)/(1 + as)`, :math:`a = \Delta t/2`.

    Realised with one state :math:`w_1`: :math:`\dot w_1 = (s - w_1)/a`,
    output :math:`2w_1 - s`.

    Parameters
    ----------
    s : array_like
        Signal before the delay [-].
    w1 : array_like
        State of the approximant [-].
    delay : array_like
        Delay :math:`\Delta t` [s], > 0.

    Returns
    -------
    (y, dw1) : tuple of array_like
        The delayed signal [-] and :math:`\dot w_1` [1/s].

    References
    ----------
    [FerreiraND] section 6.2 (the delay); the approximant: [JelaliKroll2004].

    Examples
    --------
    >>> pade1_delay(1.0, 1.0, 1e-3)  # at rest the output equals the input
    (1.0, 0.0)
    """
    a = delay / 2.0
    return 2.0 * w1 - s, (s - w1) / a


def pade2_delay(s: Any, w1: Any, w2: Any, delay: Any) -> tuple[Any, Any, Any]:
    r"""The (2, 2) Padé approximant of a pure delay, :math:`(1 - as + bs^2)/(1 + as + bs^2)`.

    :math:`a = \Delta t/2`, :math:`b = \Delta t^2/12`; realised with
    :math:`\dot w_1 = w_2`, :math:`\dot w_2 = (s - w_1 - a w_2)/b`, output
    :math:`s - 2a w_2`.

    Parameters
    ----------
    s : array_like
        Signal before the delay [-].
    w1 : array_like
        First state of the approximant [-].
    w2 : array_like
        Second state of the approximant [1/s].
    delay : array_like
        Delay :math:`\Delta t` [s], > 0.

    Returns
    -------
    (y, dw1, dw2) : tuple of array_like
        The delayed signal [-], :math:`\dot w_1` [1/s] and :math:`\dot w_2` [1/s^2].

    References
    ----------
    [FerreiraND] section 6.2 (the delay); the approximant: [JelaliKroll2004].

    Examples
    --------
    >>> pade2_delay(0.5, 0.5, 0.0, 1e-3)  # at rest the output equals the input
    (0.5, 0.0, 0.0)
    """
    a = delay / 2.0
    b = delay**2 / 12.0
    return s - delay * w2, w2, (s - w1 - a * w2) / b
