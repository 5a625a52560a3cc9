r"""The spool stage of a two-stage servovalve from its geometry: real openings, port flows, flow forces, lapped leakage.

[GordicND] sections 2.5-2.6. The four metering orifices are numbered as in
its Fig. 6: 1 supply to port L1, 2 supply to port L2, 3 port L2 to return,
4 port L1 to return; orifices 1 and 3 open for positive spool travel
:math:`y`, 2 and 4 for negative. An orifice's axial opening is
:math:`j_i = (-1)^{i+1} y + y_{0i}` (positive: open; :math:`y_{0i}` its
underlap, negative for an overlap); its real opening (eq. 44) counts the
radial clearance :math:`\delta` and the rounded edges of spool and bushing
(:math:`h = r_s + r_b`), so a "closed" edge at :math:`j = 0` still has
:math:`\sqrt{(\delta + h)^2 + h^2} - h`. An overlapped orifice
(:math:`j < 0`) passes only the leakage of :func:`lapped_leakage`.

Reading of the extracted eqs. (44)-(46): eq. (46) prints
:math:`j = y - y_{0i}(-1)^{i+1}`, which with an underlap would put the
opening's minimum away from the edge; the opening is measured from the edge,
:math:`|j| = |(-1)^{i+1}y + y_{0i}|`, which is the same for the zero laps of
Table 1. The transient term of eq. (43), printed with one sign for all four
orifices, is taken with Merritt's signs (below).

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hydroservo import backend as bk

__all__ = [
    "SIGNS",
    "real_opening",
    "orifice_drops",
    "port_flows",
    "steady_flow_force",
    "transient_flow_force",
    "lapped_leakage",
]

#: (-1)^(i+1) for orifices 1..4: +1 where positive spool travel opens the orifice.
SIGNS = (1.0, -1.0, 1.0, -1.0)


def real_opening(y: Any, i: int, delta: Any, r_s: Any, r_b: Any, y_0: Any = 0.0) -> Any:
    r"""Real opening of spool orifice ``i`` (1-4), eq. (44): the distance between the rounded edges across the clearance [m].

    .. math:: y_i = \sqrt{(\delta + h)^2 + (|j| + h)^2} - h \quad (j \ge 0), \qquad 0 \quad (j < 0),
              \qquad h = r_s + r_b,\; j = (-1)^{i+1} y + y_{0i}

    Parameters
    ----------
    y : array_like
        Spool displacement [m].
    i : int
        Orifice number, 1 to 4 (module notes) [-].
    delta : array_like
        Radial clearance of the spool in its bushing [m].
    r_s, r_b : array_like
        Radii of the spool's and the bushing's control edges [m].
    y_0 : array_like
        Null lap of the orifice, positive for an underlap [m].

    Returns
    -------
    array_like
        :math:`y_i` [m].

    References
    ----------
    [GordicND] eqs. (44)-(46), after Shearer (1980).

    Examples
    --------
    Table 1 (4 um clearance, 10 um edge radii): 11.2 um at the edge, about the axial opening further on (um):

    >>> [round(float(real_opening(y, 1, 4e-6, 10e-6, 10e-6)) * 1e6, 2) for y in (0.0, 100e-6, -5e-6)]
    [11.24, 102.38, 0.0]
    """
    h = r_s + r_b
    j = SIGNS[i - 1] * y + y_0
    return bk.if_else(j >= 0, bk.sqrt((delta + h) ** 2 + (j + h) ** 2) - h, 0.0)


def orifice_drops(p_s: Any, p_0: Any, p_L1: Any, p_L2: Any) -> tuple[Any, Any, Any, Any]:
    r"""Pressure drops across the four spool orifices, eq. (47): :math:`p_s - p_{L1}`, :math:`p_s - p_{L2}`, :math:`p_{L2} - p_0`, :math:`p_{L1} - p_0` [Pa].

    Parameters
    ----------
    p_s, p_0 : array_like
        Supply and return pressures [Pa].
    p_L1, p_L2 : array_like
        Pressures of the actuator ports L1 and L2 [Pa].

    Returns
    -------
    tuple of array_like
        :math:`(\Delta p_1, \Delta p_2, \Delta p_3, \Delta p_4)` [Pa].

    References
    ----------
    [GordicND] eq. (47).

    Examples
    --------
    >>> [float(d) / 1e5 for d in orifice_drops(210e5, 1e5, 105.5e5, 105.5e5)]
    [104.5, 104.5, 104.5, 104.5]
    """
    return p_s - p_L1, p_s - p_L2, p_L2 - p_0, p_L1 - p_0


def port_flows(openings: Any, drops: Any, K_t: Any, f: Any, rho: Any, leakage: Any = (0.0, 0.0, 0.0, 0.0)) -> tuple[Any, Any]:
    r"""Flows into the actuator ports, eqs. (49)-(51): :math:`Q_{L1} = Q_1 - Q_4 + Q_{l1} - Q_{l4}`, :math:`Q_{L2} = Q_3 - Q_2 + Q_{l3} - Q_{l2}` [m^3/s].

    .. math:: Q_i = K_{ti} f y_i \sqrt{2/\rho}\,\sqrt{\Delta p_i}

    (``Q_L2`` is counted out of port L2 towards return, as in eq. 50, so that
    with no load :math:`Q_{L1} = Q_{L2}` and eq. (58),
    :math:`Q_{SV} = (Q_{L1} + Q_{L2})/2`, is the valve's flow.)

    Parameters
    ----------
    openings : sequence of 4 array_like
        Real openings :math:`y_i` (:func:`real_opening`) [m].
    drops : sequence of 4 array_like
        :math:`\Delta p_i` (:func:`orifice_drops`) [Pa].
    K_t : array_like
        Flow coefficient of the orifices [-].
    f : array_like
        Area gradient [m].
    rho : array_like
        Density [kg/m^3].
    leakage : sequence of 4 array_like
        Leakage :math:`Q_{li}` through the closed orifices (:func:`lapped_leakage`) [m^3/s].

    Returns
    -------
    (Q_L1, Q_L2) : tuple of array_like
        [m^3/s].

    References
    ----------
    [GordicND] eqs. (49)-(51), (58).

    Examples
    --------
    The rated opening of about 0.44 mm at no load (L/min):

    >>> y = [real_opening(0.44e-3, i, 4e-6, 10e-6, 10e-6) for i in (1, 2, 3, 4)]
    >>> QL1, QL2 = port_flows(y, orifice_drops(210e5, 1e5, 105.5e5, 105.5e5), 0.611, 4.8e-3, 871.0)
    >>> round(float(QL1) * 6e4, 2), round(float(QL2) * 6e4, 2)
    (12.01, 12.01)
    """
    c = K_t * f * bk.sqrt(2.0 / rho)
    Q = [c * openings[k] * bk.sqrt(bk.fmax(drops[k], 0.0)) for k in range(4)]
    return Q[0] - Q[3] + leakage[0] - leakage[3], Q[2] - Q[1] + leakage[2] - leakage[1]


def steady_flow_force(openings: Any, drops: Any, K_t: Any, K_c: Any, f: Any, alpha: Any) -> Any:
    r"""Steady axial flow force on the spool, the first term of eq. (43) [N].

    .. math:: F_{a,s} = -\sum_{i=1}^4 (-1)^i\, 2\frac{K_{ti}^2}{K_{ci}} f y_i \cos\alpha_i\,\Delta p_i

    The momentum of the jets leaving the metering orifices at the angle
    :math:`\alpha_i`; with the signs of eq. (39) it resists the opening (it
    tends to close the valve).

    Parameters
    ----------
    openings, drops : sequences of 4 array_like
        :math:`y_i` [m] and :math:`\Delta p_i` [Pa].
    K_t, K_c : array_like
        Flow and contraction coefficients [-] (Von Mises: 0.611, 0.673).
    f : array_like
        Area gradient [m].
    alpha : array_like
        Jet angle [rad] (Von Mises: 69 deg).

    Returns
    -------
    array_like
        :math:`F_{a,s}` [N], positive against positive spool travel.

    References
    ----------
    [GordicND] eq. (43); [Merritt1967].

    Examples
    --------
    >>> y = [real_opening(0.44e-3, i, 4e-6, 10e-6, 10e-6) for i in (1, 2, 3, 4)]
    >>> F = steady_flow_force(y, orifice_drops(210e5, 1e5, 105.5e5, 105.5e5), 0.611, 0.673, 4.8e-3, np.radians(69))
    >>> round(float(F), 2)  # N
    17.57
    """
    coefficient = 2.0 * K_t**2 / K_c * f * bk.cos(alpha)
    return -sum((-1.0) ** i * coefficient * openings[i - 1] * drops[i - 1] for i in (1, 2, 3, 4))


def transient_flow_force(y: Any, v: Any, drops: Any, K_t: Any, f: Any, rho: Any, l_1: Any, l_2: Any) -> Any:
    r"""Transient axial flow force on the spool: the oil between the orifices accelerated as the opening changes [N].

    .. math:: F_{a,t} = \left(l_2\,K_t\sqrt{\Delta p_{out}} - l_1\,K_t\sqrt{\Delta p_{in}}\right)\sqrt{2\rho}\,f\,\dot y

    with :math:`\Delta p_{in}` across the open supply orifice (1 for
    :math:`y > 0`, 2 for :math:`y < 0`) and :math:`\Delta p_{out}` across the
    open return orifice (3, or 4). Eq. (43) as extracted prints the
    transient term with one sign for all four orifices, which makes both
    lengths destabilising; Merritt's derivation, which it follows, gives the
    meter-out length a damping and the meter-in length an anti-damping
    force, so the net is damping when :math:`l_2 > l_1` (Table 1: 9.2 against
    5.4 mm). With the signs of eq. (39), positive resists the motion.

    Parameters
    ----------
    y, v : array_like
        Spool displacement [m] and velocity [m/s].
    drops : sequence of 4 array_like
        :math:`\Delta p_i` [Pa].
    K_t : array_like
        Flow coefficient [-].
    f : array_like
        Area gradient [m].
    rho : array_like
        Density [kg/m^3].
    l_1, l_2 : array_like
        Axial lengths from the supply port and from the return port to the actuator port (damping lengths) [m].

    Returns
    -------
    array_like
        :math:`F_{a,t}` [N].

    References
    ----------
    [GordicND] eq. (43), with the signs of [Merritt1967] (transient flow force, damping length).

    Examples
    --------
    >>> F = transient_flow_force(0.2e-3, 0.01, orifice_drops(210e5, 1e5, 105.5e5, 105.5e5), 0.611, 4.8e-3, 871.0, 5.4e-3, 9.2e-3)
    >>> round(float(F), 4)  # N at 10 mm/s
    0.015
    """
    pos = y >= 0
    d_in = bk.if_else(pos, drops[0], drops[1])
    d_out = bk.if_else(pos, drops[2], drops[3])
    root_out, root_in = bk.sqrt(bk.fmax(d_out, 0.0)), bk.sqrt(bk.fmax(d_in, 0.0))
    return (l_2 * root_out - l_1 * root_in) * K_t * bk.sqrt(2.0 * rho) * f * v


def lapped_leakage(L: Any, dp: Any, K_t: Any, f: Any, rho: Any, eta: Any, delta: Any, r_s: Any, r_b: Any, d_s: Any) -> Any:
    r"""Leakage through an overlapped (closed) spool orifice of overlap length ``L``, eqs. (52)-(56) [m^3/s].

    Mookherjee et al.'s short, intermediate and long orifice, by the overlap
    against the flow's development:

    .. math::
        q Q^2 &= \Delta p && L < (q/s)^2 Q\\
        s L^{1/2} Q^{3/2} &= \Delta p && (q/s)^2 Q \le L < y_d\\
        s y_d^{1/2} Q^{3/2} + w (L - y_d) Q &= \Delta p && L \ge y_d

    with :math:`q = \rho/(2 K_t^2 f^2 (\sqrt{(\delta + h)^2 + h^2} - h)^2)`,
    :math:`s = 23(\rho\eta)^{1/2}/(f^{3/2}\delta^{5/2})`, :math:`w = 12\eta/(f\delta^3)`
    and the transition length :math:`y_d = 0.075\,\delta Q/(\pi d_s \nu)`. Each
    form is explicit in :math:`Q` (the long one a quadratic, since
    :math:`y_d` grows with :math:`Q`), and they meet continuously at the
    regime limits. The sign of the flow is that of :math:`\Delta p`.

    Parameters
    ----------
    L : array_like
        Overlap length, :math:`|(-1)^i y + y_{0i}|` for a closed orifice [m].
    dp : array_like
        Pressure drop across the orifice [Pa].
    K_t : array_like
        Flow coefficient [-].
    f : array_like
        Area gradient [m].
    rho : array_like
        Density [kg/m^3].
    eta : array_like
        Dynamic viscosity [Pa*s].
    delta : array_like
        Radial clearance [m].
    r_s, r_b : array_like
        Edge radii [m].
    d_s : array_like
        Spool diameter [m].

    Returns
    -------
    array_like
        Leakage flow [m^3/s].

    References
    ----------
    [GordicND] eqs. (52)-(56), after Mookherjee et al. (2001).

    Examples
    --------
    Table 1's spool 10 um and 100 um into the overlap, 104.5 bar across (L/min):

    >>> [round(float(lapped_leakage(L, 104.5e5, 0.611, 4.8e-3, 871.0, 0.012, 4e-6, 10e-6, 10e-6, 4.62e-3)) * 6e4, 4)
    ...  for L in (10e-6, 100e-6)]
    [0.0536, 0.0129]
    """
    h = r_s + r_b
    a0 = bk.sqrt((delta + h) ** 2 + h**2) - h
    q = rho / (2.0 * K_t**2 * f**2 * a0**2)
    s = 23.0 * bk.sqrt(rho * eta) / (f**1.5 * delta**2.5)
    w = 12.0 * eta / (f * delta**3)
    k = 0.075 * delta / (np.pi * d_s * (eta / rho))  # y_d = k Q
    P = bk.fabs(dp)
    L = bk.fmax(L, 0.0)
    Q_short = bk.sqrt(P / q)
    Q_mid = (P / (s * bk.sqrt(bk.fmax(L, 1e-30)))) ** (2.0 / 3.0)
    A = s * bk.sqrt(k) - w * k  # the long form: A Q^2 + w L Q - P = 0
    Q_long = 2.0 * P / (w * L + bk.sqrt((w * L) ** 2 + 4.0 * A * P))
    Q = bk.if_else(L < (q / s) ** 2 * Q_short, Q_short, bk.if_else(L < k * Q_mid, Q_mid, Q_long))
    return bk.if_else(dp >= 0, Q, -Q)
