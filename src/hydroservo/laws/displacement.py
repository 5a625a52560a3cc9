r"""Displacement machines: the flow and torque of pumps and motors, their leakage, a pressure compensator.

A pump or motor of displacement :math:`D` per radian turning at :math:`\omega`
displaces :math:`D\omega`; leakage past its pistons or gears is laminar,
proportional to the pressure across it ([Merritt1967], hydraulic pumps and
motors: the ideal machine with internal and external leakage coefficients).
Writing :math:`D` per radian keeps the laws in SI; a catalogue's
displacement per revolution is :math:`2\pi` times larger (give it with its unit,
``"25 cm^3/rev"``).

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.
"""

from __future__ import annotations

from typing import Any

from hydroservo import backend as bk

__all__ = [
    "displaced_flow",
    "leakage_flow",
    "motor_torque",
    "compensator_displacement",
    "floored_port_flow",
    "regulator_rates",
]


def displaced_flow(D: Any, omega: Any, eps: Any = 1.0) -> Any:
    r"""Geometric flow of a displacement machine, :math:`Q = \varepsilon D \omega` [m^3/s].

    Parameters
    ----------
    D : array_like
        Displacement per radian [m^3/rad] (per revolution / 2π).
    omega : array_like
        Shaft speed [rad/s].
    eps : array_like
        Displacement setting of a variable machine, 0 to 1 [-].

    Returns
    -------
    array_like
        Flow [m^3/s].

    References
    ----------
    [Merritt1967] (hydraulic pumps and motors: ideal displacement flow).

    Examples
    --------
    25 cm^3/rev at 1500 rpm:

    >>> import math
    >>> round(float(displaced_flow(25e-6 / (2 * math.pi), 1500 * 2 * math.pi / 60)) * 6e4, 3)  # L/min
    37.5
    """
    return eps * D * omega


def leakage_flow(C: Any, dp: Any) -> Any:
    r"""Laminar leakage of a displacement machine, :math:`Q_L = C\,\Delta p` [m^3/s].

    Parameters
    ----------
    C : array_like
        Leakage coefficient [m^3/s/Pa].
    dp : array_like
        Pressure difference driving the leakage [Pa].

    Returns
    -------
    array_like
        Leakage flow [m^3/s].

    References
    ----------
    [Merritt1967] (hydraulic pumps and motors: internal and external leakage coefficients).

    Examples
    --------
    >>> round(float(leakage_flow(1e-12, 200e5)) * 6e4, 3)  # L/min at 200 bar
    1.2
    """
    return C * dp


def motor_torque(D: Any, dp: Any, eta_hm: Any = 1.0) -> Any:
    r"""Torque of a hydraulic motor, :math:`T = \eta_{hm} D\,(p_A - p_B)` [N m].

    Parameters
    ----------
    D : array_like
        Displacement per radian [m^3/rad].
    dp : array_like
        Pressure difference across the motor, inlet minus outlet [Pa].
    eta_hm : array_like
        Hydromechanical efficiency [-].

    Returns
    -------
    array_like
        Torque [N m].

    References
    ----------
    [Merritt1967] (hydraulic motors: torque :math:`D_m P_L`).

    Examples
    --------
    >>> import math
    >>> round(float(motor_torque(50e-6 / (2 * math.pi), 100e5)), 2)  # 50 cm^3/rev at 100 bar
    79.58
    """
    return eta_hm * D * dp


def compensator_displacement(p: Any, p_c: Any, dp_band: Any) -> Any:
    r"""Static displacement of a pressure-compensated pump, 1 below ``p_c``, falling linearly to 0 at ``p_c + dp_band`` [-].

    The compensator spool destrokes the pump as the outlet pressure rises past
    its setting, holding the pressure while the flow demand is met
    ([JelaliKroll2004], pressure-controlled variable-displacement pumps).

    Parameters
    ----------
    p : array_like
        Outlet pressure [Pa].
    p_c : array_like
        Compensator setting: the pressure at which destroking begins [Pa].
    dp_band : array_like
        Pressure rise from full to zero displacement [Pa], > 0.

    Returns
    -------
    array_like
        Displacement setting, 0 to 1.

    References
    ----------
    [JelaliKroll2004] (pressure-compensated pumps); the linear band is the usual catalogue characteristic.

    Examples
    --------
    >>> [float(compensator_displacement(p, 200e5, 10e5)) for p in (150e5, 205e5, 220e5)]
    [1.0, 0.5, 0.0]
    """
    return bk.fmin(bk.fmax((p_c + dp_band - p) / dp_band, 0.0), 1.0)


def floored_port_flow(q: Any, p_in: Any, p_out: Any, p_floor: Any, p_reg: Any) -> Any:
    r"""The flow of a machine that cannot draw a port below ``p_floor``: the flow :math:`Q` from port 1 to port 2
    (positive: port 1 is the inlet) scaled by a gate of the inlet's pressure,

    .. math:: Q_{floor} = \max(Q, 0)\,g(p_1) + \min(Q, 0)\,g(p_2), \qquad
              g(p) = s\!\left(\frac{p - p_{floor}}{p_{reg}}\right),\ s(x) = x^2 (3 - 2x) \text{ on } [0, 1]

    so that a machine drawing from an emptied volume takes only what flows into it, the volume held within
    ``p_reg`` of the floor. The continuous form of Hopsan's pumps, which clamp their flow so that neither port's
    pressure falls below zero ([Hopsan2026] Hydraulic/Pumps&Motors/HydraulicFixedDisplacementPump.hpp and
    HydraulicVariableDisplacementPump.hpp: ``q2 = min(max(q2, -c2/Zc2), c1/Zc1)``); the gate rises from 0 to 1
    over ``p_reg`` with a continuous slope, as an implicit solver needs.

    Parameters
    ----------
    q : array_like
        Flow the machine would deliver, port 1 to port 2 [m^3/s].
    p_in, p_out : array_like
        Pressures at port 1 and port 2 [Pa].
    p_floor : array_like
        Pressure below which a port cannot be drawn [Pa] (vacuum: -101325 Pa gauge).
    p_reg : array_like
        Pressure over which the gate opens [Pa].

    Returns
    -------
    array_like
        Flow [m^3/s].

    References
    ----------
    [Hopsan2026] Hydraulic/Pumps&Motors/HydraulicFixedDisplacementPump.hpp,
    HydraulicVariableDisplacementPump.hpp (the flow clamp whose continuous form this is).

    Examples
    --------
    >>> float(floored_port_flow(1e-3, 2e5, 1e6, -101325.0, 100.0))  # the inlet well above the floor: all of it
    0.001
    >>> float(floored_port_flow(1e-3, -101325.0 + 50.0, 1e6, -101325.0, 100.0))  # half-way up the gate
    0.0005
    >>> abs(float(floored_port_flow(-1e-3, 2e5, -101325.0, -101325.0, 100.0)))  # reversed, port 2 at its floor
    0.0
    """

    def gate(p: Any) -> Any:
        x = bk.clip((p - p_floor) / p_reg, 0.0, 1.0)
        return x * x * (3.0 - 2.0 * x)

    return bk.fmax(q, 0.0) * gate(p_in) + bk.fmin(q, 0.0) * gate(p_out)


def regulator_rates(
    y: Any, v: Any, w: Any, u: Any, g1: Any, g2: Any, w1: Any, y_min: Any, y_max: Any, v_min: Any, v_max: Any,
    tau_d: Any, delta: Any,
) -> tuple[Any, Any, Any]:
    r"""Rates of a pump regulator's second-order filter with a lead, its output and its rate limited, without
    wind-up: :math:`(\dot y, \dot v, \dot w)` [unit of y / s, unit of y / s², unit of u / s].

    The filter is

    .. math:: g_1\ddot y + \dot y + g_2 y = u + \dot u/\omega_1,
              \qquad y \in [y_{min}, y_{max}],\quad \dot y \in [v_{min}, v_{max}]

    Hopsan's regulator of HydraulicPressureControlledPump ([Hopsan2026] Hydraulic/Pumps&Motors/
    HydraulicPressureControlledPump.hpp, its ``fltppu``) is the bilinear transform of
    :math:`(1 + s/\omega_1)/(g_1 s^2 + s + g_2)` with its coefficients of the current step, whose output and
    memory it clamps to the bounds of :math:`y` and of its rate: at a bound the filter's past is the clamped
    one, so its state is :math:`(y, \dot y)` held there, and it leaves the bound as soon as its free
    acceleration turns back. As an ODE the states are :math:`y` and its rate :math:`v`, each stopped at its
    bounds as :func:`hydroservo.laws.pressure_valve.limited_rate` (within :math:`\delta`):
    :math:`\dot y = v` clipped to :math:`[v_{lo}, v_{hi}]`, :math:`v_{hi} = \min(v_{max}, (y_{max} - y)/\delta)`,
    :math:`v_{lo} = \max(v_{min}, (y_{min} - y)/\delta)`, and :math:`\dot v = (u + \dot u/\omega_1 - \dot y
    - g_2 y)/g_1` limited to :math:`(v_{lo} - v)/\delta` and :math:`(v_{hi} - v)/\delta` (continuous, never
    increasing with :math:`v`, so an implicit step has one solution). The input's rate is that of a lag
    :math:`w` of it, :math:`\dot u \approx (u - w)/\tau_d` (a step of :math:`u` gives :math:`v` its jump
    :math:`\Delta u/(\omega_1 g_1)` over :math:`\tau_d`).

    Parameters
    ----------
    y : array_like
        Filter output, its state [any unit].
    v : array_like
        Its rate, a state [unit of y / s].
    w : array_like
        The input lagged by ``tau_d``, a state [unit of u].
    u : array_like
        Input [unit of y / s].
    g1 : array_like
        Coefficient of :math:`\ddot y` [s], > 0.
    g2 : array_like
        Coefficient of :math:`y` [1/s].
    w1 : array_like
        Lead frequency [rad/s], > 0.
    y_min, y_max : array_like
        Bounds of :math:`y` [unit of y].
    v_min, v_max : array_like
        Bounds of its rate [unit of y / s], :math:`v_{min} \le 0 \le v_{max}`.
    tau_d : array_like
        Time constant of the input's lag [s], > 0, small against :math:`1/\omega_1`.
    delta : array_like
        Time constant of the approach to a bound [s], > 0, small against :math:`g_1`.

    Returns
    -------
    tuple
        :math:`\dot y` [unit of y / s], :math:`\dot v` [unit of y / s²], :math:`\dot w` [unit of u / s].

    References
    ----------
    [Hopsan2026] Hydraulic/Pumps&Motors/HydraulicPressureControlledPump.hpp (the limited filter); the
    realisation, the input's lag and the relaxation on the bounds are hydroservo's.

    Examples
    --------
    At rest the free filter accelerates with :math:`(u - g_2 y)/g_1`; at its upper bound it holds:

    >>> [float(r) for r in regulator_rates(1.0, 0.0, 10.0, 10.0, 0.5, 1.0, 5.0, 0.0, 2.0, -100.0, 100.0, 1e-4, 1e-6)]
    [0.0, 18.0, 0.0]
    >>> [float(r) + 0.0 for r in regulator_rates(2.0, 0.0, 10.0, 10.0, 0.5, 1.0, 5.0, 0.0, 2.0, -100.0, 100.0, 1e-4,
    ...                                          1e-6)]
    [0.0, 0.0, 0.0]
    """
    udot = (u - w) / tau_d
    v_hi = bk.fmin(v_max, (y_max - y) / delta)
    v_lo = bk.fmax(v_min, (y_min - y) / delta)
    ydot = bk.fmin(bk.fmax(v, v_lo), v_hi)
    free = (u + udot / w1 - ydot - g2 * y) / g1
    vdot = bk.fmin(bk.fmax(free, (v_lo - v) / delta), (v_hi - v) / delta)
    return ydot, vdot, udot
