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

__all__ = [
    "opening_fraction",
    "linear_opening",
    "seat_opening",
    "pressure_valve_coefficient",
    "hysteresis_half_width",
    "valve_hysteresis",
    "spool_balance_rate",
    "spool_mass_acceleration",
    "flow_force_gradient",
    "limited_lag_rate",
    "limited_rate",
    "STOP_RELAXATION",
]

#: The time constant with which :func:`limited_lag_rate` settles on a bound, as a fraction of the lag's own [-]:
#: small enough that the lag reaches its bound within 0.1 % of ``tau`` later than in finite time, large enough
#: that an implicit step of any length has a unique solution there.
STOP_RELAXATION = 1e-3


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


def seat_opening(p: Any, p_c: Any) -> Any:
    r"""Opening of a seat that opens fully once the pilot pressure exceeds cracking: 1 for :math:`p > p_c`, else 0 [-].

    The limit :math:`\Delta p_o \to 0` of :func:`linear_opening`: Hopsan's check valves open so
    ([Hopsan2026] Hydraulic/Restrictors/HydraulicCheckValve.hpp, flow :math:`K_s\sqrt{p_1 - p_2}` while
    :math:`p_1 > p_2`, none otherwise; their wave variables stand for the port pressures). With
    :math:`p_c = 0` and the turbulent law the flow is still continuous (it vanishes as
    :math:`\sqrt{\Delta p}` at the seat); with :math:`p_c > 0` it jumps at cracking.

    Parameters
    ----------
    p : array_like
        Pilot pressure (the pressure drop over a check valve) [Pa].
    p_c : array_like
        Cracking pressure [Pa].

    Returns
    -------
    array_like
        0 closed, 1 fully open.

    References
    ----------
    [Hopsan2026] Hydraulic/Restrictors/HydraulicCheckValve.hpp.

    Examples
    --------
    >>> [float(seat_opening(p, 0.0)) for p in (-1.0, 0.0, 1.0)]
    [0.0, 0.0, 1.0]
    """
    return bk.if_else(p > p_c, 1.0, 0.0)


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


def hysteresis_half_width(p_h: Any, dp: Any, k_cs: Any, k_cf: Any, p_nom: Any = 7e6) -> Any:
    r"""Half the width of a pressure-control valve's hysteresis band in its flow coefficient [m^3/s/Pa^0.5].

    A hysteresis of ``p_h`` in the pilot pressure is, in the flow coefficient
    of :func:`pressure_valve_coefficient`, a band of width
    :math:`p_h/(C_s + C_f\max(\Delta p, 0))`: the same pressure band seen
    through the spring and the flow forces that the static opening is seen
    through. Its half: :math:`p_h/(2(C_s + C_f\max(\Delta p, 0)))`.

    Parameters
    ----------
    p_h : array_like
        Width of the hysteresis in the pilot pressure [Pa], >= 0.
    dp : array_like
        Pressure drop across the valve [Pa].
    k_cs : array_like
        Steady-state characteristic of the spring [m^3/s/Pa].
    k_cf : array_like
        Steady-state characteristic of the flow forces [m^3/s/Pa].
    p_nom : array_like
        Nominal pressure drop of the characteristics [Pa].

    Returns
    -------
    array_like
        Half-width [m^3/s/Pa^0.5].

    References
    ----------
    [Hopsan2026] Hydraulic/Valves/PressureControlValves/HydraulicPressureReliefValve.hpp (``xh = ph/(b1+b2)``,
    in the limit of a small time step where ``b2`` vanishes).

    Examples
    --------
    A band of 5 bar about a valve 100 bar across, in its flow coefficient (half the opening 5 bar over the
    setting gives, :func:`pressure_valve_coefficient`):

    >>> round(float(hysteresis_half_width(5e5, 100e5, 1e-8, 1e-8)) * 1e9, 3)  # (m^3/s)/Pa^0.5, x 1e9
    389.081
    """
    return 0.5 * pressure_valve_coefficient(p_h, dp, k_cs, k_cf, p_nom)


def valve_hysteresis(target: Any, K: Any, half_width: Any) -> Any:
    r"""The static opening a valve's spool follows through a hysteresis (backlash) band [unit of K].

    The spool's lag does not follow the static opening :math:`K_s` itself but
    :math:`K_s` held within :math:`\pm w` of where the spool is:

    .. math:: K_h = \min(\max(K, K_s - w), K_s + w)

    so the spool stays put while :math:`|K_s - K| \le w` and then follows
    :math:`K_s \mp w`: a pressure rising to open the valve opens it
    :math:`p_h/2` later than without hysteresis, a pressure falling to close it
    closes it :math:`p_h/2` earlier. With :func:`limited_lag_rate`,
    :math:`\tau\dot K = K_h - K` is a lag driven by the dead zone of
    :math:`K_s - K` of half-width :math:`w`. With :math:`w = 0`, :math:`K_h = K_s`.

    Parameters
    ----------
    target : array_like
        Static opening :math:`K_s` [any unit].
    K : array_like
        The spool's present opening [unit of target].
    half_width : array_like
        Half the band, :math:`w` >= 0 [unit of target] (:func:`hysteresis_half_width`).

    Returns
    -------
    array_like
        :math:`K_h` [unit of target].

    References
    ----------
    [Hopsan2026] HopsanCore/include/ComponentUtilities/ValveHysteresis.h (``getValue(xs, xh, xd)``, here with
    the spool's present opening for Hopsan's previous one, the same in the limit of a small time step), used by
    HydraulicPressureReliefValve.hpp and the other pressure-control valves.

    Examples
    --------
    >>> [float(valve_hysteresis(Ks, 1.0, 0.5)) for Ks in (0.0, 0.8, 1.2, 2.0)]
    [0.5, 1.0, 1.0, 1.5]
    """
    return bk.fmin(bk.fmax(K, target - half_width), target + half_width)


def spool_mass_acceleration(balance_rate: Any, dK: Any, tau_m: Any) -> Any:
    r"""Acceleration of a pressure-control valve's flow coefficient when its spool has mass [m^3/s/Pa^0.5/s^2].

    A spool of mass :math:`M_v`, damped by :math:`B_v`, under the force :math:`F(x)` of its pilot, spring and flow
    forces: :math:`M_v\ddot x + B_v\dot x = F(x)`. Without mass it moves at :math:`F/B_v`, the rate
    :math:`r` of :func:`spool_balance_rate` (in the flow coefficient :math:`K = c\,x`); with mass its velocity
    relaxes to that rate with the mechanical time constant :math:`\tau_m = M_v/B_v`:

    .. math:: \ddot K = \frac{r - \dot K}{\tau_m}

    (the force balance divided by :math:`B_v`; [Hopsan2026] Hydraulic/Special/HydraulicPressureRelief2ValveG.hpp,
    whose spool is the transfer function :math:`A_v/(M_v s^2 + B_v s + k_e)`).

    Parameters
    ----------
    balance_rate : array_like
        The massless spool's rate, :func:`spool_balance_rate` [m^3/s/Pa^0.5/s].
    dK : array_like
        The rate of the flow coefficient, a state [m^3/s/Pa^0.5/s].
    tau_m : array_like
        :math:`M_v/B_v` [s], > 0.

    Returns
    -------
    array_like
        :math:`\ddot K` [m^3/s/Pa^0.5/s^2].

    References
    ----------
    [Hopsan2026] Hydraulic/Special/HydraulicPressureRelief2ValveG.hpp.

    Examples
    --------
    >>> float(spool_mass_acceleration(2.0, 1.0, 0.5))
    2.0
    """
    return (balance_rate - dK) / tau_m


def flow_force_gradient(c_v: Any, dp: Any, rho: Any, phi: Any) -> Any:
    r"""Steady flow force on a spool per metre of an edge's opening, :math:`2 C_q w\cos\varphi\,|\Delta p|` [N/m].

    The jet through an opening :math:`x` of a metering edge of width :math:`w`
    leaves at the angle :math:`\varphi` to the spool's axis and pulls the
    spool towards closing with :math:`F = 2 C_q w x \cos\varphi\,|\Delta p|`
    ([Merritt1967], the steady flow force); in terms of the edge's flow
    coefficient :math:`c_v = C_q w\sqrt{2/\rho}` (:func:`hydroservo.laws.four_way.edge_flow`),
    :math:`C_q w = c_v\sqrt{\rho/2}`.

    Parameters
    ----------
    c_v : array_like
        Flow coefficient of the edge [m^2/s/Pa^0.5].
    dp : array_like
        Pressure drop across the edge [Pa] (its magnitude is taken).
    rho : array_like
        Oil density [kg/m^3].
    phi : array_like
        Jet angle to the spool's axis [rad] (69 deg for a sharp edge at a large opening).

    Returns
    -------
    array_like
        :math:`dF/dx` [N/m]: the flow force is this times the opening.

    References
    ----------
    [Merritt1967] (the steady flow force on a spool valve); [Hopsan2026]
    Hydraulic/Valves/HydraulicPressureControlValve33.hpp (its spool's flow forces).

    Examples
    --------
    An edge of C_q w = 0.67 x 3 mm across 100 bar at 69 deg, per millimetre of opening:

    >>> c_v = 0.67 * 0.003 * (2.0 / 870.0) ** 0.5
    >>> round(float(flow_force_gradient(c_v, 100e5, 870.0, 1.2043)) * 1e-3, 2)  # N per mm
    14.41
    """
    return 2.0 * bk.cos(phi) * c_v * bk.sqrt(rho / 2.0) * bk.fabs(dp)


def limited_lag_rate(K: Any, target: Any, tau: Any, K_max: Any, relax: Any = STOP_RELAXATION) -> Any:
    r"""Rate of a first-order lag whose output stops at its bounds :math:`[0, K_{max}]`, without wind-up [1/s × unit of K].

    Away from the bounds, :math:`\tau\dot K = K_s - K`. Hopsan's limited filter
    (``FirstOrderTransferFunction`` with a minimum and a maximum, [Hopsan2026])
    clamps the output and its memory at a bound, so a closing lag reaches 0 in
    finite time and stays there while the target is below it. As an ODE that
    law is discontinuous on the bound: just above 0 the rate is
    :math:`K_s/\tau`, on it 0. An implicit step that predicts a value in
    :math:`(0, h|K_s|/\tau)` then has no solution, and CVODES' Newton corrector
    fails at any step length (measured on Hopsan's Position Servo at rtol
    1e-7 and tighter). Here the approach to a bound is relaxed over the last
    stretch :math:`K < |K_s|\,\delta/(\tau - \delta)`, with :math:`\delta =`
    ``relax`` :math:`\tau`:

    .. math:: \dot K = \min\Big(\max\big(\tfrac{K_s - K}{\tau},\;
              -\tfrac{\max(K, 0)}{\delta}\big),\; \tfrac{\max(K_{max} - K, 0)}{\delta}\Big)

    The rate is continuous and never increases with :math:`K` (so an implicit
    step has exactly one solution); outside the bounds it is zero toward
    them, as the clamp's; the lag arrives at a bound about :math:`\delta` later
    than the clamped one.

    Parameters
    ----------
    K : array_like
        Output of the lag, its state [any unit; m^3/s/Pa^0.5 for a valve's flow coefficient].
    target : array_like
        Static value it follows, :math:`K_s`, which may lie outside the bounds [unit of K].
    tau : array_like
        Time constant [s], > 0.
    K_max : array_like
        Upper bound, > 0 [unit of K].
    relax : float
        :math:`\delta/\tau` [-], in (0, 1).

    Returns
    -------
    array_like
        :math:`\dot K` [unit of K / s].

    References
    ----------
    [Hopsan2026] FirstOrderTransferFunction (limited output) in HydraulicPressureReliefValve and
    HydraulicPressureReducingValve; the relaxation on the bound is hydroservo's.

    Examples
    --------
    Closing: the lag's rate above the bound, zero on it, and no wind-up below it:

    >>> [float(limited_lag_rate(K, -1.0, 1e-3, 2.0)) + 0.0 for K in (1.0, 0.0, -0.5)]
    [-2000.0, 0.0, 0.0]
    >>> round(float(limited_lag_rate(1e-4, -1.0, 1e-3, 2.0)), 6)  # the last 0.1 % of the way: relaxed
    -100.0
    """
    return limited_rate(K, (target - K) / tau, K_max, relax * tau)


def limited_rate(K: Any, rate: Any, K_max: Any, delta: Any) -> Any:
    r"""A state's rate stopped at its bounds :math:`[0, K_{max}]` without wind-up, relaxed over ``delta`` [unit of K / s].

    .. math:: \dot K = \min\Big(\max\big(r,\; -\tfrac{\max(K, 0)}{\delta}\big),\;
              \tfrac{\max(K_{max} - K, 0)}{\delta}\Big)

    the clamp of :func:`limited_lag_rate` for any free rate :math:`r` (there
    :math:`r = (K_s - K)/\tau` and :math:`\delta` = ``relax`` :math:`\tau`).

    Parameters
    ----------
    K : array_like
        The state [any unit].
    rate : array_like
        Its rate away from the bounds, :math:`r` [unit of K / s].
    K_max : array_like
        Upper bound, > 0 [unit of K].
    delta : array_like
        Time constant of the approach to a bound [s], > 0; a small fraction of the state's own time constant.

    Returns
    -------
    array_like
        :math:`\dot K` [unit of K / s].

    References
    ----------
    [Hopsan2026] (its limited integrators and filters, which clamp a state and its memory at a bound), as
    :func:`limited_lag_rate`; the relaxation on the bound is hydroservo's.

    Examples
    --------
    >>> [float(limited_rate(K, -5.0, 2.0, 1e-3)) + 0.0 for K in (1.0, 0.0, 2.5)]
    [-5.0, 0.0, -5.0]
    """
    return bk.fmin(bk.fmax(rate, -bk.fmax(K, 0.0) / delta), bk.fmax(K_max - K, 0.0) / delta)


def spool_balance_rate(over: Any, dp: Any, K: Any, k_cs: Any, k_cf: Any, p_nom: Any, tau: Any) -> Any:
    r"""Rate of a pressure-control valve's flow coefficient from the force balance of a damped, massless spool [m^3/s/Pa^0.5/s].

    The spool at opening :math:`x` is pushed by the pilot's excess pressure on
    its area :math:`A_v`, held by its spring :math:`k_s` and by the steady flow
    force :math:`2 C_q w \cos\varphi\,\Delta p\,x` of the jet through its
    opening (port width :math:`w`, jet angle :math:`\varphi`), and damped by
    :math:`B_v` ([Merritt1967], the steady flow force on a spool; [Hopsan2026]
    Hydraulic/Special/HydraulicPressureReliefValveG.hpp):

    .. math:: B_v\dot x = A_v\,\Delta p_{over} - (k_s + 2 C_q w\cos\varphi\,\Delta p)\,x

    With the flow coefficient :math:`K = C_q w\sqrt{2/\rho}\,x` of the
    opening (:math:`Q = K\sqrt{\Delta p}`) this is, in the characteristics of
    :func:`pressure_valve_coefficient` (:math:`C_s = \sqrt{p_{nom}}/k_{cs}`,
    :math:`C_f = 1/(k_{cf}\sqrt{p_{nom}})`),

    .. math:: C_s\tau\dot K = \Delta p_{over} - (C_s + C_f\,\Delta p)\,K

    with :math:`C_s = k_s/(C_q w\sqrt{2/\rho}A_v)`,
    :math:`C_f = 2\cos\varphi/(\sqrt{2/\rho}A_v)` and :math:`\tau = B_v/k_s`:
    the static opening is :func:`pressure_valve_coefficient`'s, but the
    spool's time constant :math:`\tau C_s/(C_s + C_f\Delta p)` shortens as
    the flow forces stiffen it. The drop :math:`\Delta p` is taken with its
    sign, as Hopsan's law takes it. The caller bounds :math:`K` (:func:`limited_rate`).

    Parameters
    ----------
    over : array_like
        Pilot pressure above the setting [Pa].
    dp : array_like
        Pressure drop across the valve [Pa].
    K : array_like
        Flow coefficient, the spool's state [m^3/s/Pa^0.5].
    k_cs, k_cf : array_like
        Steady-state characteristics of the spring and the flow forces [m^3/s/Pa].
    p_nom : array_like
        Nominal pressure drop of the characteristics [Pa].
    tau : array_like
        Time constant of the spool against its spring alone, :math:`B_v/k_s` [s].

    Returns
    -------
    array_like
        :math:`\dot K` [m^3/s/Pa^0.5/s] (unbounded).

    References
    ----------
    [Hopsan2026] Hydraulic/Special/HydraulicPressureReliefValveG.hpp and HydraulicPressureReducingValveG.hpp (the
    spool's equation, discretised there by the bilinear transform); [Merritt1967] (flow forces).

    Examples
    --------
    At the static opening the rate vanishes:

    >>> k = pressure_valve_coefficient(10e5, 210e5, 1e-8, 1e-8)
    >>> abs(float(spool_balance_rate(10e5, 210e5, k, 1e-8, 1e-8, 7e6, 0.01))) < 1e-12
    True
    """
    Cs = bk.sqrt(p_nom) / k_cs
    Cf = 1.0 / (k_cf * bk.sqrt(p_nom))
    return (over - (Cs + Cf * dp) * K) / (Cs * tau)
