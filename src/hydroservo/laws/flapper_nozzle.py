r"""Flapper-nozzle pilot stage of a two-stage servovalve driving the main spool.

Two descriptions: the linear spool stage of [FlightSimulatorND]
(:func:`spool_jerk`), and the flows and pressures of the stage of
[GordicND] section 2.4: the constant orifices and the nozzles as turbulent
restrictions (:func:`orifice_conductance`, :func:`nozzle_conductance`,
eqs. 23-27, 35-37), the nozzle pressures in closed form with the spool's
displacement flow (:func:`nozzle_pressures`, eqs. 33-34) and the null gap
that the assembly rule sets (:func:`null_gap`).

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.
Citation keys in brackets are those of :mod:`hydroservo.references`.

Re-derivation of [FlightSimulatorND] eq. (3-16)
-----------------------------------------------
The extraction dropped the derivative dots. From eqs. (3-9) to (3-12) without
flow forces, :math:`A_v P_{Lv} = M_v s^2 x_v` and
:math:`P_{Lv}(K_{ce} + V_v s/4\beta) = K_2 x_f - A_v s x_v`, hence

.. math:: x_v\left(\frac{s^3}{\omega_h^2} + \frac{2\delta_h}{\omega_h}s^2 + s\right)
          = \frac{K_2}{A_v} x_f,
          \quad \omega_h^2 = \frac{4\beta A_v^2}{M_v V_v},
          \quad \delta_h = \frac{\omega_h K_{ce} M_v}{2A_v^2}

(eq. 3-14 with D = E = 0), i.e.
:math:`\dddot x_v = \frac{K_2}{A_v}\omega_h^2 x_f - 2\delta_h\omega_h\ddot x_v - \omega_h^2\dot x_v`.
The analog pot values of Appendix D confirm each coefficient: P101 =
:math:`K_2\omega_h^2/(10^{10}A_v)` = 0.6375, P38 = :math:`2\delta_h\omega_h/10^4` = 0.388,
P15 = :math:`\omega_h^2/10^7` = 0.376. The spool is an integrator of flapper
displacement: it stops only when :math:`x_f = 0`, which the torque motor
reaches when :math:`K_1 I_s = K_w x_v` (section 5.2.1).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hydroservo import backend as bk

__all__ = [
    "spool_jerk",
    "orifice_conductance",
    "nozzle_conductance",
    "nozzle_pressures",
    "null_drain_pressure",
    "null_gap",
]


def spool_jerk(x_f: Any, v_v: Any, a_v: Any, K2: Any, Av: Any, omega_h: Any, delta_h: Any) -> Any:
    r"""Main-spool jerk driven by the flapper-nozzle flow, [FlightSimulatorND] eq. (3-16) re-derived.

    .. math:: \dddot x_v = \frac{K_2}{A_v}\omega_h^2 x_f - 2\delta_h\omega_h\ddot x_v - \omega_h^2\dot x_v

    Flow forces (terms D and E of eq. 3-15) are left out, as in the
    dissertation's final model (its Appendix A found them negligible).

    Parameters
    ----------
    x_f : array_like
        Flapper displacement [m].
    v_v : array_like
        Spool velocity [m/s].
    a_v : array_like
        Spool acceleration [m/s^2].
    K2 : array_like
        Flapper-nozzle flow gain [m^2/s].
    Av : array_like
        Spool end area [m^2].
    omega_h : array_like
        Natural frequency of the spool stage [rad/s].
    delta_h : array_like
        Damping ratio of the spool stage [-].

    Returns
    -------
    array_like
        :math:`\dddot x_v` [m/s^3].

    References
    ----------
    [FlightSimulatorND] eqs. (3-9)-(3-16) and Appendix D.

    Examples
    --------
    With the flapper centred and the spool at rest nothing moves:

    >>> float(spool_jerk(0.0, 0.0, 0.0, 0.12, 7.1e-5, 1940.0, 1.0))
    0.0
    """
    wh2 = omega_h**2
    return K2 / Av * wh2 * x_f - 2.0 * delta_h * omega_h * a_v - wh2 * v_v


def orifice_conductance(K: Any, d: Any, rho: Any) -> Any:
    r"""Turbulent conductance of a round orifice, :math:`a = K\,\frac{\pi d^2}{4}\sqrt{2/\rho}` [m^3/s/Pa^0.5].

    The flow is :math:`a\sqrt{\Delta p}` (:func:`hydroservo.laws.orifice.turbulent_flow`).

    Parameters
    ----------
    K : array_like
        Flow (discharge) coefficient [-].
    d : array_like
        Diameter [m].
    rho : array_like
        Density [kg/m^3].

    Returns
    -------
    array_like
        :math:`a` [m^3/s/Pa^0.5].

    References
    ----------
    [GordicND] eqs. (23)-(25), (35).

    Examples
    --------
    A 0.18 mm orifice, K = 0.8, 871 kg/m^3 (mm^3/s per bar^0.5):

    >>> round(float(orifice_conductance(0.8, 0.18e-3, 871.0)) * 1e9 * 316.23, 1)
    308.5
    """
    return K * np.pi * d**2 / 4.0 * bk.sqrt(2.0 / rho)


def nozzle_conductance(K_n: Any, d_n: Any, gap: Any, rho: Any) -> Any:
    r"""Turbulent conductance of a flapper-nozzle restriction, :math:`b = K_n\,\pi d_n\,x_n\sqrt{2/\rho}` [m^3/s/Pa^0.5].

    The curtain area between the nozzle rim and the flapper, :math:`\pi d_n x_n`
    with the gap :math:`x_n = x_0 \mp x`.

    Parameters
    ----------
    K_n : array_like
        Flow coefficient of the restriction [-].
    d_n : array_like
        Nozzle diameter [m].
    gap : array_like
        Distance from the flapper tip to the nozzle [m].
    rho : array_like
        Density [kg/m^3].

    Returns
    -------
    array_like
        :math:`b` (or :math:`c`) [m^3/s/Pa^0.5].

    References
    ----------
    [GordicND] eqs. (26)-(27), (36)-(37).

    Examples
    --------
    >>> round(float(nozzle_conductance(0.65, 0.28e-3, 38.5e-6, 871.0)) / float(orifice_conductance(0.8, 0.18e-3, 871.0)), 3)
    1.081
    """
    return K_n * np.pi * d_n * gap * bk.sqrt(2.0 / rho)


def nozzle_pressures(p_s: Any, p_d: Any, a: Any, b: Any, c: Any, d: Any) -> tuple[Any, Any]:
    r"""Left and right nozzle pressures of a flapper-nozzle stage, with the spool's displacement flow, [GordicND] eqs. (33)-(34).

    .. math::
        p_l &= \frac{a^2 p_s + b^2 p_d}{a^2 + b^2} + \frac{d^2 (b^2 - a^2)}{(a^2 + b^2)^2}
               - \frac{2 a b d}{(a^2 + b^2)^2}\sqrt{(a^2 + b^2)(p_s - p_d) - d^2}\\
        p_r &= \frac{a^2 p_s + c^2 p_d}{a^2 + c^2} + \frac{d^2 (c^2 - a^2)}{(a^2 + c^2)^2}
               + \frac{2 a c d}{(a^2 + c^2)^2}\sqrt{(a^2 + c^2)(p_s - p_d) - d^2}

    Re-derived: on the left, what the constant orifice passes feeds the
    nozzle and the spool end that grows as the spool moves right,
    :math:`a\sqrt{p_s - p_l} = b\sqrt{p_l - p_d} + d` (eq. 20 without
    compressibility and leakage); with :math:`u^2 + w^2 = p_s - p_d` for the
    two roots this is a quadratic in :math:`w = \sqrt{p_l - p_d}`, whose
    positive root gives eq. (33). On the right the spool end shrinks
    (:math:`-d`), eq. (34). The root is real while :math:`|d|` is below
    :math:`a\sqrt{p_s - p_d}` (the orifice's flow at the full drop); beyond
    it the spool moves faster than the stage can feed it, and the square
    root is clipped at zero.

    Parameters
    ----------
    p_s, p_d : array_like
        Supply and drain-compartment pressures [Pa].
    a : array_like
        Conductance of each constant orifice (:func:`orifice_conductance`) [m^3/s/Pa^0.5].
    b, c : array_like
        Conductances of the left and right nozzles (:func:`nozzle_conductance`) [m^3/s/Pa^0.5].
    d : array_like
        Displacement flow of the spool, :math:`A_s\dot y` (eq. 38) [m^3/s].

    Returns
    -------
    (p_l, p_r) : tuple of array_like
        Nozzle pressures [Pa].

    References
    ----------
    [GordicND] eqs. (20)-(21), (33)-(38).

    Examples
    --------
    Matched orifice and nozzles, spool at rest: each nozzle at the mean of supply and drain.

    >>> pl, pr = nozzle_pressures(210e5, 10e5, 1e-9, 1e-9, 1e-9, 0.0)
    >>> float(pl) / 1e5, float(pr) / 1e5
    (110.0, 110.0)
    """
    P = p_s - p_d
    ab, ac = a**2 + b**2, a**2 + c**2
    root_l = bk.sqrt(bk.fmax(ab * P - d**2, 0.0))
    root_r = bk.sqrt(bk.fmax(ac * P - d**2, 0.0))
    p_l = (a**2 * p_s + b**2 * p_d) / ab + d**2 * (b**2 - a**2) / ab**2 - 2.0 * a * b * d / ab**2 * root_l
    p_r = (a**2 * p_s + c**2 * p_d) / ac + d**2 * (c**2 - a**2) / ac**2 + 2.0 * a * c * d / ac**2 * root_r
    return p_l, p_r


def null_drain_pressure(p_s: Any, p_n: Any, p_0: Any, a: Any, a_d: Any) -> Any:
    r"""Drain-compartment pressure at null: both nozzles' flows leave through the drain orifice.

    .. math:: 2a\sqrt{p_s - p_n} = a_d\sqrt{p_d - p_0}
              \quad\Rightarrow\quad p_d = p_0 + \left(\frac{2a}{a_d}\right)^2 (p_s - p_n)

    Parameters
    ----------
    p_s : array_like
        Supply pressure [Pa].
    p_n : array_like
        Nozzle pressure at null [Pa].
    p_0 : array_like
        Return (reservoir) pressure [Pa].
    a : array_like
        Conductance of each constant orifice [m^3/s/Pa^0.5].
    a_d : array_like
        Conductance of the drain orifice [m^3/s/Pa^0.5].

    Returns
    -------
    array_like
        :math:`p_d` [Pa].

    References
    ----------
    [GordicND] eqs. (22)-(25) at null, without compressibility.

    Examples
    --------
    >>> round(float(null_drain_pressure(140e5, 70e5, 1e5, 1.0, 4.0)) / 1e5, 3)
    18.5
    """
    return p_0 + (2.0 * a / a_d) ** 2 * (p_s - p_n)


def null_gap(p_s: Any, p_n: Any, p_d: Any, a: Any, K_n: Any, d_n: Any, rho: Any) -> Any:
    r"""Gap between the centred flapper and each nozzle that puts the nozzles at ``p_n``, [GordicND] section 3.

    The assembly rule of the source: at 140 bar supply, with the flapper
    centred, both nozzles sit at 70 bar. The constant orifice and the nozzle
    then pass the same flow, :math:`a\sqrt{p_s - p_n} = b\sqrt{p_n - p_d}`, so

    .. math:: x_0 = \frac{a}{K_n \pi d_n\sqrt{2/\rho}}\sqrt{\frac{p_s - p_n}{p_n - p_d}}

    Parameters
    ----------
    p_s, p_n, p_d : array_like
        Supply, nozzle and drain-compartment pressures [Pa].
    a : array_like
        Conductance of each constant orifice [m^3/s/Pa^0.5].
    K_n : array_like
        Flow coefficient of the flapper-nozzle restriction [-].
    d_n : array_like
        Nozzle diameter [m].
    rho : array_like
        Density [kg/m^3].

    Returns
    -------
    array_like
        :math:`x_0` [m].

    References
    ----------
    [GordicND] section 3 (the assembly requirement), eqs. (23), (26).

    Examples
    --------
    >>> a = orifice_conductance(0.8, 0.18e-3, 871.0)
    >>> round(float(null_gap(140e5, 70e5, 10e5, a, 0.65, 0.28e-3, 871.0)) * 1e6, 2)  # um
    38.46
    """
    return a / (K_n * np.pi * d_n * bk.sqrt(2.0 / rho)) * bk.sqrt((p_s - p_n) / (p_n - p_d))
